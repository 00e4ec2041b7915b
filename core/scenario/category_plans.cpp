// The seven Table II planners of the offline generator. Each reads the world through the probe,
// picks its places (the prompt's first, else what the category needs, with a stated fallback),
// decides who takes part and writes spotlight agents and ambient groups into the draft.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/geometry/planar.hpp"
#include "core/scenario/offline_plan.hpp"

namespace socsim::scenario {

namespace {

using C = Category;
constexpr double kForever = 86400.0;  // s: "until the scenario ends" for waits and sits

double round1(double v) {
  return std::round(v * 10.0) / 10.0;
}
std::string num(double v) {
  return format_number(round1(v));
}

// Join the lane's queue, advance, and be served at the counter one at a time (queuing and reception).
void queue_and_serve(TreeXml& t, const std::string& lane, const std::string& counter, double service,
                     double spread) {
  t.leaf("JoinQueue", {{"agent_id", "{id}"},
                       {"time_step", "{dt}"},
                       {"queue", lane},
                       {"spacing", "0.7"},
                       {"position", "{place}"}});
  t.leaf("ServeAtCounter", {{"agent_id", "{id}"},
                            {"counter", counter},
                            {"queue", lane},
                            {"service_time", num(service)},
                            {"service_spread", num(spread)}});
}
std::size_t sum(const std::vector<People>& people) {
  std::size_t n = 0;
  for (const People& p : people) n += p.count;
  return n;
}
bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}
std::string plural(const std::string& role, std::size_t n) {
  if (n == 1) return role;
  if (role == "child") return "children";
  if (role == "staff" || role == "elderly" || role == "security") return role;
  return role + "s";
}
bool staff_like(const std::string& role) {
  return role == "nurse" || role == "doctor" || role == "staff" || role == "worker" ||
         role == "receptionist" || role == "security";
}

// Splits people into the first n (spotlight) and the rest, role by role in proportion.
std::pair<std::vector<People>, std::vector<People>> split_people(const std::vector<People>& people,
                                                                 std::size_t n) {
  std::vector<People> first, rest;
  const std::size_t total = sum(people);
  std::size_t given = 0;
  for (std::size_t k = 0; k < people.size(); ++k) {
    std::size_t share = total == 0 ? 0 : people[k].count * n / total;
    if (k + 1 == people.size()) share = std::min(people[k].count, n - std::min(n, given));
    share = std::min(share, people[k].count);
    given += share;
    if (share > 0) first.push_back(People{people[k].role, share, people[k].explicit_count, people[k].phrase});
    if (people[k].count > share)
      rest.push_back(
          People{people[k].role, people[k].count - share, people[k].explicit_count, people[k].phrase});
  }
  // Rounding left places: give them to the first roles that still have people.
  for (std::size_t k = 0; given < n && k < rest.size();) {
    auto it =
        std::find_if(first.begin(), first.end(), [&](const People& p) { return p.role == rest[k].role; });
    if (it == first.end()) {
      first.push_back(People{rest[k].role, 0, rest[k].explicit_count, rest[k].phrase});
      it = first.end() - 1;
    }
    ++it->count;
    ++given;
    if (--rest[k].count == 0) rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(k));
  }
  return {first, rest};
}

// Zones people spend time in (no toilets), largest first.
std::vector<std::string> occupied_zones(const WorldProbe& p) {
  std::vector<std::string> out;
  for (const world::Zone& z : p.world().zones())
    if (!p.is_toilet(z.name)) out.push_back(z.name);
  std::stable_sort(out.begin(), out.end(), [&](const std::string& a, const std::string& b) {
    return p.zone_area(a) > p.zone_area(b);
  });
  return out;
}

// The zone and its neighbours through doors, circulation first, then by area.
std::vector<std::string> around(const WorldProbe& p, const std::string& zone, bool zone_first) {
  std::vector<std::string> n;
  for (const auto& [z, door] : p.neighbours(zone))
    if (!contains(n, z) && !p.is_toilet(z)) n.push_back(z);
  std::stable_sort(n.begin(), n.end(), [&](const std::string& a, const std::string& b) {
    if (p.is_circulation(a) != p.is_circulation(b)) return p.is_circulation(a);
    return p.zone_area(a) > p.zone_area(b);
  });
  std::vector<std::string> out;
  if (zone_first) out.push_back(zone);
  out.insert(out.end(), n.begin(), n.end());
  if (!zone_first) out.push_back(zone);
  return out;
}

std::string zone_of_place(WorldProbe& p, const ResolvedPlace& r) {
  if (r.kind == ResolvedPlace::Kind::kZone) return r.name;
  return p.zone_at(p.point(r.name));
}

// A waiting ROI (waiting zone, seating area) in the zone, "" when it has none.
std::string waiting_roi(const WorldProbe& p, const std::string& zone) {
  for (const std::string& r : p.rois_in(zone)) {
    auto pl = p.place(r);
    if (pl && (pl->type == "waiting_zone" || pl->type == "seating_area")) return r;
  }
  return "";
}

// Spawns each group of people over the regions; reports those that did not fit.
void spawn_people(Draft& d, const std::vector<People>& people, const std::vector<std::string>& regions,
                  const std::string& name, const std::string& tree, std::int64_t group, Category c) {
  for (const People& who : people) {
    std::size_t placed = 0;
    for (const auto& [region, n] : d.spread(regions, who.count)) {
      d.add_agents(name, who, region, n, tree, group, c);
      placed += n;
    }
    if (placed < who.count)
      d.note(std::to_string(who.count - placed) + " of the " + std::to_string(who.count) + " " +
             plural(who.role, who.count) + " (" + std::string(to_string(c)) + ") did not fit in " +
             (regions.empty() ? std::string("any region") : regions.front()) +
             " and its neighbours and were left out");
  }
}

void leftover_ambient(Draft& d, Category c, const std::vector<People>& rest,
                      const std::vector<std::string>& start, const std::vector<std::string>& goal,
                      const std::string& what, bool exit_at_goal, Rng& rng, Status& status) {
  for (const People& who : rest) {
    if (!status || who.count == 0 || start.empty() || goal.empty()) continue;
    Draft::Ambient g;
    g.name = std::string(to_string(c)) + "_" + who.role;
    g.role = who.role;
    g.start = start;
    g.goal = goal;
    g.size = who.count;
    g.speed = round1(rng.uniform(1.1, 1.4));
    g.variation = round1(rng.uniform(0.05, 0.25) * 100.0) / 100.0;
    g.exit_at_goal = exit_at_goal;
    g.explicit_count = who.explicit_count;
    g.description = std::to_string(who.count) + " " + plural(who.role, who.count) + " " + what;
    status = d.add_ambient(c, std::move(g));
  }
}

// One entry per role of a group's members (slots[at, at + size)), all spawned in `region`.
void add_group(Draft& d, const std::vector<People>& slots, std::size_t at, std::size_t size,
               const std::string& region, const std::string& name, const std::string& tree,
               std::int64_t group, Category c) {
  std::vector<People> roles;
  for (std::size_t k = at; k < at + size; ++k) {
    auto it =
        std::find_if(roles.begin(), roles.end(), [&](const People& p) { return p.role == slots[k].role; });
    if (it == roles.end())
      roles.push_back(slots[k]);
    else
      ++it->count;
  }
  for (const People& who : roles) {
    (void)d.spread({region}, who.count);
    d.add_agents(name, who, region, who.count, tree, group, c);
  }
}

// --- queue lanes -----------------------------------------------------------------------------

// Machines people queue at for something to drink or eat (not counters with staff).
bool is_poi_type(std::string_view type) {
  return type == "water_dispenser" || type == "coffee_machine" || type == "vending_machine";
}

const QueueLane* pick_lane(Draft& d, const Activity& a, Rng& rng, Category c, std::string& why) {
  const auto& lanes = d.probe.queue_lanes();
  if (lanes.empty()) return nullptr;
  if (const ResolvedPlace* r = a.place()) {
    const crowd::Vec2 at = d.probe.point(r->name);
    // A machine the prompt names ("for water", "at the coffee machine"): its own lane, else the
    // nearest lane of a machine of its type; never the counter's lane nearby.
    if (r->kind == ResolvedPlace::Kind::kEntity && is_poi_type(r->type)) {
      const QueueLane* best = nullptr;
      double best_d = std::numeric_limits<double>::infinity();
      for (const QueueLane& l : lanes) {
        if (l.counter.empty()) continue;
        const auto served = d.probe.place(l.counter);
        if (l.counter != r->name && (!served || served->type != r->type)) continue;
        const double dd = l.counter == r->name ? 0.0 : d.probe.walking_distance(at, l.head);
        if (dd < best_d) {
          best_d = dd;
          best = &l;
        }
      }
      if (best != nullptr) {
        why = best->counter == r->name
                  ? "the prompt's place '" + r->name + "' has this lane"
                  : "the lane of '" + best->counter + "', the nearest " + r->type + " with a queue lane";
        return best;
      }
      d.note("no " + r->type + " of the world has a queue lane: people wait by '" + r->name +
             "' without a strict order");
      return nullptr;
    }
    const QueueLane* best = nullptr;
    double best_d = 8.0;
    for (const QueueLane& l : lanes) {
      if (l.name == r->name || (!l.counter.empty() && l.counter == r->name)) {
        why = "the prompt's place '" + r->name + "' is this lane or its counter";
        return &l;
      }
      if (r->kind == ResolvedPlace::Kind::kZone && l.zone == r->name) {
        why = "the lane of the prompt's place '" + r->name + "'";
        return &l;
      }
      const double dd = d.probe.walking_distance(at, l.head);
      if (dd < best_d) {
        best_d = dd;
        best = &l;
      }
    }
    if (best != nullptr) {
      why = "the queue lane nearest the prompt's place '" + r->name + "' (" + num(best_d) + " m walk)";
      return best;
    }
    d.note("no queue lane within 8 m of '" + r->name + "'; " + std::string(to_string(c)) +
           " uses another lane");
  }
  // Reception lanes first (a hospital or office queue forms at the front desk), then lanes at
  // other counters, then lanes at machines (a corridor world's water dispenser, Fig. 6).
  std::vector<const QueueLane*> reception, counters, machines;
  for (const QueueLane& l : lanes) {
    const auto served = l.counter.empty() ? std::nullopt : d.probe.place(l.counter);
    if (l.name.find("reception") != std::string::npos || l.counter.find("reception") != std::string::npos)
      reception.push_back(&l);
    else if (served && is_poi_type(served->type))
      machines.push_back(&l);
    else
      counters.push_back(&l);
  }
  const auto& pool = !reception.empty() ? reception : !counters.empty() ? counters : machines;
  const QueueLane* pick = pool[rng.below(static_cast<std::uint32_t>(pool.size()))];
  const std::string kind = !reception.empty()  ? "a reception queue lane"
                           : !counters.empty() ? "a counter's queue lane"
                                               : "the queue lane of a machine";
  why = kind + " (seeded pick among " + std::to_string(pool.size()) + ")";
  return pick;
}

std::size_t lane_places(const QueueLane& l) {
  return static_cast<std::size_t>(std::floor(std::max(0.0, l.length - 0.7) / 0.7)) + 1;
}

// A POI to wait by when the world has no queue lane (water dispensers, coffee machines, counters).
std::optional<std::string> wait_poi(Draft& d, const Activity& a) {
  if (const ResolvedPlace* r = a.place())
    if (r->kind == ResolvedPlace::Kind::kEntity) return r->name;
  for (const std::string& e :
       d.probe.entities_of_type({"counter", "water_dispenser", "coffee_machine", "desk"}))
    return e;
  return std::nullopt;
}

// A point behind the counter (away from the lane's head) where a receptionist can stand.
std::optional<crowd::Vec2> behind_counter(const WorldProbe& p, const QueueLane& lane) {
  if (lane.counter.empty()) return std::nullopt;
  const crowd::Vec2 c = p.point(lane.counter);
  const double l = crowd::distance(c, lane.head);
  if (l < 1e-6) return std::nullopt;
  for (double back : {0.8, 0.65, 1.0}) {
    const crowd::Vec2 s{c.x + (c.x - lane.head.x) / l * back, c.y + (c.y - lane.head.y) / l * back};
    if (p.zone_at(s).empty()) continue;
    bool clear = true;
    for (const world::Wall& w : p.world().walls())
      if (geometry::distance(w.segment, world::Point{s.x, s.y}) < 0.45) clear = false;
    if (clear) return s;
  }
  return std::nullopt;
}

}  // namespace

// --- emergency ---------------------------------------------------------------------------------

Status plan_emergency(Draft& d, const Activity& a, Rng& rng) {
  WorldProbe& p = d.probe;
  const auto zones = occupied_zones(p);
  double area = 0.0;
  for (const std::string& z : zones) area += p.zone_area(z);
  const auto people = d.people(
      a,
      std::clamp<std::size_t>(static_cast<std::size_t>(std::lround(area * rng.uniform(0.04, 0.07))), 6, 40),
      rng);
  const auto [spot, rest] = split_people(people, d.take_spotlight(std::min<std::size_t>(sum(people), 30)));

  // The exit: the prompt's when it names one, else each agent's nearest (Evacuate without a name).
  std::string exit;
  if (const ResolvedPlace* r = a.place()) {
    for (const ExitPlace& x : p.exits())
      if (x.name == r->name || x.region == r->name) exit = x.name;
    if (exit.empty()) d.note("'" + r->name + "' is no exit; everyone takes the nearest exit");
  }
  std::vector<std::string> exit_regions;
  for (const ExitPlace& x : p.exits())
    if ((exit.empty() || x.name == exit) && !x.region.empty() && !contains(exit_regions, x.region))
      exit_regions.push_back(x.region);
  if (p.exits().empty()) {
    d.note(
        "the world has no door to the outside and no exit ROI: people gather in the largest zone instead of "
        "leaving");
  } else {
    for (const ExitPlace& x : p.exits())
      d.place_used(C::kEmergency, "exit", x.name,
                   exit.empty() ? "door to the outside or exit ROI; each agent takes the nearest (" +
                                      std::to_string(p.exits().size()) + " exits)"
                                : "named in the prompt");
  }
  const double alarm = d.alarm_s.value_or(0.0);
  Status status;
  // Everyone goes about their business in the zone they are in until the alarm, then leaves;
  // staff hurry (paper 001 Table II: evacuation, panic running, staff rushing).
  for (const People& who : spot) {
    const double factor =
        staff_like(who.role) ? 1.5 : (who.role == "patient" || who.role == "elderly" ? 1.1 : 1.3);
    // Spread over the zones by room left, largest first, seeded start.
    const std::size_t offset =
        zones.empty() ? 0 : rng.below(static_cast<std::uint32_t>(std::min<std::size_t>(zones.size(), 3)));
    std::vector<std::string> order;
    for (std::size_t k = 0; k < zones.size(); ++k) order.push_back(zones[(k + offset) % zones.size()]);
    std::size_t left = who.count;
    const std::size_t per_zone =
        std::max<std::size_t>(1, (who.count + order.size() - 1) / std::max<std::size_t>(1, order.size()));
    for (const std::string& z : order) {
      if (left == 0) break;
      const auto placed = d.spread({z}, std::min(left, per_zone));
      if (placed.empty()) continue;
      const std::size_t n = placed.front().second;
      auto tree = d.add_tree(C::kEmergency, "evacuate_" + z + "_" + who.role, [&](TreeXml& t) {
        t.open("ReactiveFallback").open("Sequence");
        t.leaf("TimeExpired", {{"seconds", num(alarm)}, {"ts", "{dt}"}, {"only_once", "true"}});
        if (p.exits().empty()) {
          t.leaf("GoTo", {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"goal", zones.front()}});
        } else {
          Attributes ev{{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"speed_factor", num(factor)}};
          if (!exit.empty()) ev.emplace_back("exit", exit);
          t.leaf("Evacuate", ev);
        }
        t.close();
        t.leaf("Wander", {{"agent_id", "{id}"},
                          {"time_step", "{dt}"},
                          {"region", z},
                          {"pause_min", "1"},
                          {"pause_max", "6"}});
        t.close();
      });
      if (!tree) return tl::unexpected(tree.error());
      d.add_agents("occupant_" + z, who, z, n, *tree, -1, C::kEmergency);
      left -= n;
    }
    // What did not fit zone by zone goes wherever there is room.
    if (left > 0) {
      std::vector<People> more{People{who.role, left, who.explicit_count, who.phrase}};
      leftover_ambient(d, C::kEmergency, more, zones, exit_regions, "evacuating to the nearest exit", true,
                       rng, status);
    }
  }
  if (!exit_regions.empty())
    leftover_ambient(
        d, C::kEmergency, rest, zones, exit_regions,
        "evacuating after the alarm to the nearest of " + std::to_string(exit_regions.size()) + " exits",
        true, rng, status);
  return status;
}

// --- queuing -----------------------------------------------------------------------------------

Status plan_queuing(Draft& d, const Activity& a, Rng& rng) {
  WorldProbe& p = d.probe;
  std::string why;
  const QueueLane* lane = pick_lane(d, a, rng, C::kQueuing, why);
  if (lane == nullptr) {
    // No lane: wait by a POI, one after another as they arrive (no strict order).
    const auto poi = wait_poi(d, a);
    const std::string zone = poi ? p.zone_at(p.point(*poi)) : occupied_zones(p).front();
    d.note("the world has no queue lane (queue_lane ROI): people wait by " +
           (poi ? "'" + *poi + "'" : "'" + zone + "'") + " without a strict queue order");
    const auto people = d.people(a, 4 + rng.below(3), rng);
    const auto [spot, rest] = split_people(people, d.take_spotlight(std::min<std::size_t>(sum(people), 10)));
    auto tree = d.add_tree(C::kQueuing, "wait_by_" + (poi ? *poi : zone), [&](TreeXml& t) {
      t.open("Sequence");
      t.leaf("WaitAt", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"location", poi ? *poi : zone},
                        {"duration", num(rng.uniform(5.0, 10.0))},
                        {"face", poi ? *poi : ""}});
      t.leaf("Wander", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"region", zone},
                        {"pause_min", "2"},
                        {"pause_max", "8"}});
      t.close();
    });
    if (!tree) return tl::unexpected(tree.error());
    d.place_used(C::kQueuing, "wait by", poi ? *poi : zone, "fallback: no queue lane in the world");
    spawn_people(d, spot, around(p, zone, false), "waiting", *tree, -1, C::kQueuing);
    Status status;
    leftover_ambient(d, C::kQueuing, rest, around(p, zone, false), {zone}, "walking to " + zone, false, rng,
                     status);
    return status;
  }
  d.place_used(C::kQueuing, "queue lane", lane->name, why);
  const std::string counter = lane->counter.empty() ? lane->name : lane->counter;
  if (!lane->counter.empty())
    d.place_used(C::kQueuing, "counter", lane->counter, "the serving entity at the lane's head");
  const std::size_t places = lane_places(*lane);
  const std::size_t default_total = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::lround(static_cast<double>(places) * rng.uniform(0.8, 1.0))), 3, 10);
  const auto people = d.people(a, default_total, rng);
  const auto [spot, rest] = split_people(people, d.take_spotlight(std::min(sum(people), places + 3)));

  const std::string waiting = waiting_roi(p, lane->zone);
  const double service = round1(d.activity_s ? std::min(*d.activity_s, 120.0) : rng.uniform(4.0, 7.0));
  const double spread = round1(rng.uniform(0.5, 1.5));
  auto tree = d.add_tree(C::kQueuing, "queue_" + lane->name, [&](TreeXml& t) {
    t.open("Sequence");
    queue_and_serve(t, lane->name, counter, service, std::min(spread, service));
    if (!waiting.empty()) {
      t.open("Fallback");
      t.leaf("SitAt",
             {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"seat", waiting}, {"duration", num(kForever)}});
      t.leaf("WaitAt", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"location", waiting},
                        {"duration", num(kForever)},
                        {"face", counter}});
      t.close();
    } else {
      t.leaf("Wander", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"region", lane->zone},
                        {"pause_min", "2"},
                        {"pause_max", "8"}});
    }
    t.close();
  });
  if (!tree) return tl::unexpected(tree.error());
  if (!waiting.empty()) d.place_used(C::kQueuing, "after service", waiting, "waiting ROI in the lane's zone");
  // They come from the lane's room and the rooms next to it, so a line forms within seconds.
  spawn_people(d, spot, around(p, lane->zone, true), "queuer", *tree, -1, C::kQueuing);
  Status status;
  leftover_ambient(d, C::kQueuing, rest, around(p, lane->zone, false),
                   {waiting.empty() ? lane->zone : waiting}, "arriving to queue at " + counter, false, rng,
                   status);
  return status;
}

// --- reception / check-in ----------------------------------------------------------------------

Status plan_reception(Draft& d, const Activity& a, Rng& rng) {
  WorldProbe& p = d.probe;
  std::string why;
  const QueueLane* lane = pick_lane(d, a, rng, C::kReception, why);
  auto people = d.people(a, 4 + rng.below(3), rng);
  // A receptionist named in the prompt stands behind the counter; the others are visitors.
  std::size_t receptionists = 0;
  for (auto it = people.begin(); it != people.end();) {
    if (it->role == "receptionist") {
      receptionists += it->count;
      it = people.erase(it);
    } else {
      ++it;
    }
  }
  // Depart through the exit nearest the counter.
  auto nearest_exit = [&](crowd::Vec2 from) -> const ExitPlace* {
    const ExitPlace* exit = nullptr;
    double best = std::numeric_limits<double>::infinity();
    for (const ExitPlace& x : p.exits()) {
      const double dd = p.walking_distance(from, x.point);
      if (dd < best) {
        best = dd;
        exit = &x;
      }
    }
    return exit;
  };
  if (lane == nullptr) {
    const auto poi = wait_poi(d, a);
    if (!poi) {
      d.note("the world has neither a queue lane nor a counter: reception is planned as normal operation");
      return plan_normal_operation(d, a, rng);
    }
    const ExitPlace* exit = nearest_exit(p.point(*poi));
    d.note("the world has no queue lane: visitors walk up to '" + *poi + "', wait there and leave");
    d.place_used(C::kReception, "counter", *poi, "fallback: no queue lane in the world");
    const std::string zone = p.zone_at(p.point(*poi));
    const auto [spot, rest] = split_people(people, d.take_spotlight(std::min<std::size_t>(sum(people), 10)));
    auto tree = d.add_tree(C::kReception, "check_in_" + *poi, [&](TreeXml& t) {
      t.open("Sequence");
      t.leaf("WaitAt", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"location", *poi},
                        {"duration", num(rng.uniform(4.0, 7.0))},
                        {"face", *poi}});
      if (exit != nullptr)
        t.leaf("Evacuate",
               {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"exit", exit->name}, {"speed_factor", "1"}});
      else
        t.leaf("Wander", {{"agent_id", "{id}"},
                          {"time_step", "{dt}"},
                          {"region", zone},
                          {"pause_min", "2"},
                          {"pause_max", "8"}});
      t.close();
    });
    if (!tree) return tl::unexpected(tree.error());
    spawn_people(d, spot, around(p, zone, false), "visitor", *tree, -1, C::kReception);
    // Those beyond the spotlight share arrive as a crowd and wait in the room.
    Status status;
    leftover_ambient(d, C::kReception, rest, around(p, zone, false), {zone},
                     "arriving to check in at " + *poi, false, rng, status);
    return status;
  }
  d.place_used(C::kReception, "queue lane", lane->name, why);
  const ExitPlace* exit = nearest_exit(lane->service);
  const std::string counter = lane->counter.empty() ? lane->name : lane->counter;
  if (!lane->counter.empty())
    d.place_used(C::kReception, "counter", lane->counter, "the serving entity at the lane's head");

  // The receptionist (one by default) faces the lane from behind the counter.
  if (receptionists == 0 && !lane->counter.empty() && !d.named_only) receptionists = 1;
  if (receptionists > 0) {
    auto tree = d.add_tree(C::kReception, "receptionist", [&](TreeXml& t) {
      t.open("Sequence");
      t.leaf("LookAtPoint", {{"agent_id", "{id}"}, {"goal", lane->name}});
      t.leaf("StopAndWait", {{"agent_id", "{id}"}, {"wait_duration", num(kForever)}});
      t.close();
    });
    if (!tree) return tl::unexpected(tree.error());
    std::size_t placed = 0;
    if (auto spot = behind_counter(p, *lane); spot && d.take_spotlight(1) == 1) {
      d.add_agent_at("receptionist", "receptionist", *spot, *tree, C::kReception);
      placed = 1;
    }
    if (placed < receptionists && d.named_only) {
      // Receptionists the prompt names all take part: the others wait by the counter facing the lane.
      const std::size_t n = d.take_spotlight(receptionists - placed);
      spawn_people(d, {People{"receptionist", n, true, "named in the prompt"}}, around(p, lane->zone, true),
                   "receptionist", *tree, -1, C::kReception);
      d.note(std::to_string(n) + " receptionist" + (n == 1 ? "" : "s") + " wait" + (n == 1 ? "s" : "") +
             " by '" + counter + "'" + (placed == 0 ? " (no free spot behind it)" : " (one fits behind it)"));
    } else if (placed == 0) {
      d.note("no free spot behind '" + counter + "' for a receptionist; the counter serves without one");
    } else if (receptionists > 1) {
      d.note("only one receptionist fits behind '" + lane->counter + "'");
    }
  }

  const std::size_t places = lane_places(*lane);
  const auto [spot, rest] = split_people(people, d.take_spotlight(std::min(sum(people), places + 3)));
  const double service = round1(d.activity_s ? std::min(*d.activity_s, 120.0) : rng.uniform(3.0, 6.0));
  // Approach (walk in from the neighbouring zones), queue, register at the counter, depart.
  auto tree = d.add_tree(C::kReception, "check_in_" + lane->name, [&](TreeXml& t) {
    t.open("Sequence");
    queue_and_serve(t, lane->name, counter, service, std::min(1.0, service));
    if (exit != nullptr) {
      if (!exit->region.empty() && exit->region != exit->name)
        t.leaf("GoTo",
               {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"goal", exit->region}, {"tolerance", "0.3"}});
      t.leaf("Evacuate",
             {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"exit", exit->name}, {"speed_factor", "1"}});
    } else {
      t.leaf("Wander", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"region", lane->zone},
                        {"pause_min", "2"},
                        {"pause_max", "8"}});
    }
    t.close();
  });
  if (!tree) return tl::unexpected(tree.error());
  if (exit != nullptr)
    d.place_used(C::kReception, "depart", exit->name, "the exit nearest the counter");
  else
    d.note("the world has no exit: visitors stay in '" + lane->zone + "' after checking in");
  // Visitors arrive from the neighbouring zones, so every one of them walks up to the counter.
  std::vector<std::string> from = around(p, lane->zone, false);
  spawn_people(d, spot, from, "visitor", *tree, -1, C::kReception);
  Status status;
  const std::string waiting = waiting_roi(p, lane->zone);
  leftover_ambient(d, C::kReception, rest, from, {waiting.empty() ? lane->zone : waiting},
                   "arriving to check in at " + counter, false, rng, status);
  return status;
}

// --- coffee break ------------------------------------------------------------------------------

Status plan_coffee_break(Draft& d, const Activity& a, Rng& rng) {
  WorldProbe& p = d.probe;
  // Points of interest to gather at: the prompt's place, else coffee machines, water dispensers,
  // tables of break rooms and kitchens, counters.
  std::vector<std::string> pois;
  std::string why;
  if (const ResolvedPlace* r = a.place()) {
    if (r->kind == ResolvedPlace::Kind::kEntity || r->kind == ResolvedPlace::Kind::kRoi) {
      pois.push_back(r->name);
      why = "the prompt's place";
    } else {
      const std::string zone = zone_of_place(p, *r);
      for (const std::string& e : p.entities_in(zone)) {
        auto pl = p.place(e);
        if (pl && (pl->type == "coffee_machine" || pl->type == "water_dispenser" || pl->type == "table" ||
                   pl->type == "coffee_table" || pl->type == "counter"))
          pois.push_back(e);
      }
      if (pois.empty()) {
        // A corridor or hall: gather at its ROI or the zone itself.
        const auto rois = p.rois_in(zone);
        pois.push_back(!rois.empty() ? rois.front() : r->name);
      }
      why = "in the prompt's place '" + r->name + "'";
    }
  }
  // The prompt's place takes the first group; further groups spread over the usual points.
  std::size_t fixed = pois.size();
  {
    std::vector<std::string> named = pois;
    // Coffee machines first, then water dispensers, then tables of break rooms and kitchens.
    const auto machines = p.entities_of_type({"coffee_machine"});
    pois = machines;
    fixed = std::min<std::size_t>(pois.size(), 1);
    for (const std::string& e : p.entities_of_type({"water_dispenser"})) pois.push_back(e);
    for (const std::string& e : p.entities_of_type({"table", "coffee_table"})) {
      const std::string z = p.zone_at(p.point(e));
      const auto zt = p.place(z);
      if (zt && (zt->type == "kitchenette" || zt->type == "break_room" || zt->type == "staff_room" ||
                 zt->type == "kitchen"))
        pois.push_back(e);
    }
    why = machines.empty() ? "water dispenser or break-room table (the world has no coffee machine)"
                           : "coffee machine, water dispenser or break-room table";
    if (pois.empty()) {
      for (const std::string& e : p.entities_of_type({"meeting_table", "counter"})) pois.push_back(e);
      why = "table or counter (the world has no coffee machine or water dispenser)";
    }
    if (pois.empty()) {
      for (const std::string& r : p.rois_of_kind("corridor")) pois.push_back(r);
      why = "corridor (the world has no coffee machine, water dispenser, table or counter)";
    }
    if (pois.empty()) {
      pois.push_back(occupied_zones(p).front());
      why = "the largest zone (the world has no point of interest for a break)";
    }
    if (named.empty() && why.find("(") != std::string::npos) d.note("coffee break: gathering at a " + why);
    if (!named.empty()) {
      for (const std::string& x : pois)
        if (!contains(named, x)) named.push_back(x);
      pois = named;
      fixed = 1;
      why = "the prompt's place '" + pois.front() + "', then " + why;
    }
  }
  // Seeded order of the other points, so groups spread over them.
  for (std::size_t k = pois.size(); k > fixed + 1; --k)
    std::swap(pois[k - 1], pois[fixed + rng.below(static_cast<std::uint32_t>(k - fixed))]);

  // Two or three groups of two to four by default.
  std::vector<std::size_t> planned(2 + rng.below(2));
  for (std::size_t& n : planned) n = 2 + rng.below(3);
  std::size_t default_total = 0;
  for (std::size_t n : planned) default_total += n;
  const auto people = d.people(a, default_total, rng);
  const auto [spot, rest] = split_people(people, d.take_spotlight(std::min<std::size_t>(sum(people), 24)));
  // Role slots in order, cut into groups of 2–4.
  std::vector<People> slots;
  for (const People& who : spot)
    for (std::size_t k = 0; k < who.count; ++k)
      slots.push_back(People{who.role, 1, who.explicit_count, who.phrase});
  std::size_t at = 0;
  std::size_t g = 0;
  const double chat = round1(d.activity_s.value_or(rng.uniform(40.0, 90.0)));
  Status status;
  std::set<std::string> used_pois;
  while (at < slots.size()) {
    std::size_t size = g < planned.size() && slots.size() == default_total
                           ? planned[g]
                           : std::min<std::size_t>(slots.size() - at, 2 + rng.below(3));
    size = std::min(size, slots.size() - at);
    if (slots.size() - at - size == 1) ++size;  // nobody chats alone
    const std::string poi = pois[g % pois.size()];
    const std::string poi_zone = p.zone_at(p.point(poi));
    // They are in the room or come from the neighbouring rooms and corridors, and walk on afterwards.
    std::vector<std::string> from = around(p, poi_zone, true);
    std::string walk = poi_zone;
    for (const std::string& z : from)
      if (p.is_circulation(z)) {
        walk = z;
        break;
      }
    const std::int64_t group = d.new_group();
    auto tree = d.add_tree(C::kCoffeeBreak, "coffee_break_group_" + std::to_string(group), [&](TreeXml& t) {
      t.open("Sequence");
      t.leaf("Gather", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"point", poi},
                        {"radius", "1.5"},
                        {"group_id", std::to_string(group)},
                        {"duration", num(chat)}});
      t.leaf("Wander", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"region", walk},
                        {"pause_min", "2"},
                        {"pause_max", "6"}});
      t.close();
    });
    if (!tree) return tl::unexpected(tree.error());
    if (used_pois.insert(poi).second) d.place_used(C::kCoffeeBreak, "gathering point", poi, why);
    // All members of a group start in the same region.
    std::string region;
    for (const std::string& z : from)
      if (d.room_left(z) >= size) {
        region = z;
        break;
      }
    if (region.empty()) {
      d.note("no room left near '" + poi + "' for a group of " + std::to_string(size));
      break;
    }
    add_group(d, slots, at, size, region, "coffee_break_" + std::to_string(group), *tree, group,
              C::kCoffeeBreak);
    at += size;
    ++g;
  }
  // Everyone else keeps walking through the corridors (Table II: continue walking).
  std::vector<std::string> corridors;
  for (const world::Zone& z : p.world().zones())
    if (p.is_circulation(z.name)) corridors.push_back(z.name);
  if (!corridors.empty()) {
    std::vector<std::string> goal;
    for (const ExitPlace& x : p.exits())
      if (!x.region.empty()) goal.push_back(x.region);
    if (goal.empty()) goal.push_back(occupied_zones(p).front());
    leftover_ambient(d, C::kCoffeeBreak, rest, corridors, goal, "walking past the break", true, rng, status);
  }
  return status;
}

// --- social / home party -----------------------------------------------------------------------

Status plan_social_party(Draft& d, const Activity& a, Rng& rng) {
  WorldProbe& p = d.probe;
  std::string room;
  if (const ResolvedPlace* r = a.place()) room = zone_of_place(p, *r);
  if (room.empty()) {
    const auto living = p.zones_of_type({"living_room", "lounge"});
    if (!living.empty()) room = living.front();
  }
  if (room.empty()) {
    for (const std::string& z : occupied_zones(p))
      if (!p.is_circulation(z)) {
        room = z;
        break;
      }
    if (room.empty()) room = occupied_zones(p).front();
    d.note("the world has no living room: the party is in '" + room + "', its largest room");
  }
  d.place_used(C::kSocialParty, "party room", room,
               a.place() != nullptr ? "the prompt's place" : "living room");
  // Cluster points: furniture and seating ROIs in the room, the room itself as a last resort.
  std::vector<std::string> points;
  for (const std::string& r : p.rois_in(room)) points.push_back(r);
  for (const std::string& e : p.entities_in(room)) points.push_back(e);
  if (points.size() < 2) points.push_back(room);
  for (std::size_t k = points.size(); k > 1; --k)
    std::swap(points[k - 1], points[rng.below(static_cast<std::uint32_t>(k))]);

  const double area = p.zone_area(room);
  const auto people =
      d.people(a,
               std::clamp<std::size_t>(
                   static_cast<std::size_t>(std::lround(area / 2.5 * rng.uniform(0.8, 1.1))), 4, 16),
               rng);
  const auto [spot, rest] = split_people(people, d.take_spotlight(std::min<std::size_t>(sum(people), 32)));
  std::vector<People> slots;
  for (const People& who : spot)
    for (std::size_t k = 0; k < who.count; ++k)
      slots.push_back(People{who.role, 1, who.explicit_count, who.phrase});
  const std::vector<std::string> from = around(p, room, true);
  std::size_t at = 0, g = 0;
  while (at < slots.size()) {
    std::size_t size = std::min<std::size_t>(slots.size() - at, 2 + rng.below(3));
    if (slots.size() - at - size == 1) ++size;
    const std::string first = points[g % points.size()];
    const std::string second = points[(g + 1) % points.size()];
    const std::int64_t group = d.new_group();
    const double talk = round1(d.activity_s.value_or(rng.uniform(15.0, 30.0)));
    auto tree = d.add_tree(C::kSocialParty, "party_group_" + std::to_string(group), [&](TreeXml& t) {
      t.open("Repeat", {{"num_cycles", "-1"}}).open("Sequence");
      t.leaf("Gather", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"point", first},
                        {"radius", "1.5"},
                        {"group_id", std::to_string(group)},
                        {"duration", num(talk)}});
      t.leaf("Wander", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"region", room},
                        {"duration", num(rng.uniform(4.0, 8.0))},
                        {"pause_min", "1"},
                        {"pause_max", "3"}});
      t.leaf("Gather", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"point", second},
                        {"radius", "1.5"},
                        {"group_id", std::to_string(group)},
                        {"duration", num(talk)}});
      t.close().close();
    });
    if (!tree) return tl::unexpected(tree.error());
    std::string region;
    for (const std::string& z : from)
      if (d.room_left(z) >= size) {
        region = z;
        break;
      }
    if (region.empty()) {
      d.note("no room left in or around '" + room + "' for more guests");
      break;
    }
    add_group(d, slots, at, size, region, "party_" + std::to_string(group), *tree, group, C::kSocialParty);
    at += size;
    ++g;
  }
  Status status;
  std::vector<std::string> arrive;
  for (const std::string& z : from)
    if (z != room) arrive.push_back(z);
  leftover_ambient(d, C::kSocialParty, rest, arrive.empty() ? from : arrive, {room},
                   "arriving at the party in " + room, false, rng, status);
  return status;
}

// --- bottleneck --------------------------------------------------------------------------------

Status plan_bottleneck(Draft& d, const Activity& a, Rng& rng) {
  WorldProbe& p = d.probe;
  const world::World& w = p.world();
  struct Option {
    const world::Door* door;
    std::string start, through;
    double score;
  };
  std::vector<Option> options;
  const ResolvedPlace* named = a.place();
  for (const world::Door& door : w.doors()) {
    if (!door.other) continue;
    for (int side = 0; side < 2; ++side) {
      const std::string s = w.zone(side == 0 ? door.zone : *door.other).name;
      const std::string o = w.zone(side == 0 ? *door.other : door.zone).name;
      if (p.is_toilet(s) || p.is_toilet(o)) continue;
      // Start rooms whose only inner door is this one send the whole crowd through it.
      const std::size_t inner = p.neighbours(s).size();
      double score = std::min(p.zone_area(s), 80.0) / (inner == 1 ? 1.0 : 3.0) / std::max(0.8, door.width);
      if (named != nullptr) {
        if (named->name == door.name)
          score += 1000.0;
        else if (named->kind == ResolvedPlace::Kind::kZone && named->name == s)
          score += 500.0;
        else if (named->kind == ResolvedPlace::Kind::kZone && named->name == o)
          score += 400.0;
      }
      options.push_back(Option{&door, s, o, score});
    }
  }
  if (options.empty()) {
    d.note("the world has no door between two rooms: no bottleneck possible; planned as normal operation");
    return plan_normal_operation(d, a, rng);
  }
  std::stable_sort(options.begin(), options.end(),
                   [](const Option& x, const Option& y) { return x.score > y.score; });
  std::size_t top = 1;
  while (top < std::min<std::size_t>(options.size(), 3) && options[top].score >= options[0].score * 0.8)
    ++top;
  const Option& o = options[rng.below(static_cast<std::uint32_t>(top))];
  if (named != nullptr && o.score < 400.0)
    d.note("'" + named->name + "' is no door between rooms; the crowd uses '" + o.door->name + "'");
  // Goal beyond the door: the room behind the far zone farthest from the door, else the far zone.
  const crowd::Vec2 door_at{o.door->pose.x, o.door->pose.y};
  std::string goal;
  double far = -1.0;
  for (const auto& [z, via] : p.neighbours(o.through)) {
    if (z == o.start || p.is_toilet(z)) continue;
    const double dd = crowd::distance(p.point(z), door_at);
    if (dd > far) {
      far = dd;
      goal = z;
    }
  }
  if (goal.empty()) goal = o.through;
  d.place_used(C::kBottleneck, "doorway", o.door->name,
               "door of width " + num(o.door->width) + " m, the only way out of '" + o.start + "' towards '" +
                   goal + "'");
  d.place_used(C::kBottleneck, "crowd start", o.start, "the room before the door");
  d.place_used(C::kBottleneck, "crowd goal", goal, "beyond the door");
  const std::size_t cap = p.capacity(o.start);
  const auto people = d.people(
      a,
      std::clamp<std::size_t>(
          static_cast<std::size_t>(std::lround(static_cast<double>(cap) * rng.uniform(0.6, 0.9))), 8, 60),
      rng);
  const double speed = round1(rng.uniform(1.3, 1.6));
  Status status;
  for (const People& who : people) {
    if (!status) break;
    Draft::Ambient g;
    g.name = "through_" + o.door->name + "_" + who.role;
    g.role = who.role;
    g.start = {o.start};
    g.goal = {goal};
    g.size = who.count;
    g.speed = speed;
    g.variation = 0.05;
    g.explicit_count = who.explicit_count;
    g.description = std::to_string(who.count) + " " + plural(who.role, who.count) + " rushing from " +
                    o.start + " through " + o.door->name + " to " + goal;
    status = d.add_ambient(C::kBottleneck, std::move(g));
  }
  return status;
}

// --- normal operation --------------------------------------------------------------------------

Status plan_normal_operation(Draft& d, const Activity& a, Rng& rng) {
  WorldProbe& p = d.probe;
  const auto zones = occupied_zones(p);
  double area = 0.0;
  for (const std::string& z : zones) area += p.zone_area(z);
  // Where people spend time: work areas and desks for staff, waiting and seating for visitors.
  std::vector<std::string> work, rest_places, circulation;
  for (const world::Roi& r : p.world().rois()) {
    if (r.kind == "work_area") work.push_back(r.name);
    if (r.kind == "waiting_zone" || r.kind == "seating_area") rest_places.push_back(r.name);
  }
  for (const std::string& z : zones) {
    if (p.is_circulation(z)) {
      circulation.push_back(z);
      continue;
    }
    const std::string type = p.place(z) ? p.place(z)->type : "";
    if (type == "nurse_station" || type == "treatment_room" || type == "private_office" ||
        type == "open_office" || type == "kitchen" || type == "loading_bay" || type == "meeting_room" ||
        type == "kitchenette")
      work.push_back(z);
    else
      rest_places.push_back(z);
  }
  if (const ResolvedPlace* r = a.place()) {
    const std::string zone = zone_of_place(p, *r);
    if (!zone.empty()) {
      work.insert(work.begin(), r->kind == ResolvedPlace::Kind::kEntity ? zone : r->name);
      rest_places.insert(rest_places.begin(), r->kind == ResolvedPlace::Kind::kEntity ? zone : r->name);
    }
  }
  if (work.empty()) work = zones;
  if (rest_places.empty()) rest_places = zones;
  if (circulation.empty()) circulation.push_back(zones.front());
  const auto people = d.people(
      a,
      std::clamp<std::size_t>(static_cast<std::size_t>(std::lround(area * rng.uniform(0.02, 0.04))), 4, 16),
      rng);
  const auto [spot, rest] = split_people(people, d.take_spotlight(std::min<std::size_t>(sum(people), 16)));
  const double stay = d.activity_s.value_or(0.0);
  for (const People& who : spot) {
    const auto& places = staff_like(who.role) ? work : rest_places;
    const std::string first = places[rng.below(static_cast<std::uint32_t>(places.size()))];
    const std::string second = places[rng.below(static_cast<std::uint32_t>(places.size()))];
    const std::string walk = circulation[rng.below(static_cast<std::uint32_t>(circulation.size()))];
    auto visit = [&](TreeXml& t, const std::string& place) {
      const auto pl = p.place(place);
      const double dwell = round1(stay > 0.0 ? stay : rng.uniform(15.0, 40.0));
      if (pl && pl->region != nullptr) {
        t.open("Fallback");
        t.leaf("SitAt",
               {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"seat", place}, {"duration", num(dwell)}});
        t.leaf("WaitAt", {{"agent_id", "{id}"},
                          {"time_step", "{dt}"},
                          {"location", place},
                          {"duration", num(dwell)},
                          {"face", ""}});
        t.close();
      } else {
        t.leaf("WaitAt", {{"agent_id", "{id}"},
                          {"time_step", "{dt}"},
                          {"location", place},
                          {"duration", num(dwell)},
                          {"face", ""}});
      }
    };
    auto tree = d.add_tree(C::kNormalOperation, "routine_" + who.role, [&](TreeXml& t) {
      t.open("Repeat", {{"num_cycles", "-1"}}).open("Sequence");
      visit(t, first);
      t.leaf("Wander", {{"agent_id", "{id}"},
                        {"time_step", "{dt}"},
                        {"region", walk},
                        {"duration", num(rng.uniform(5.0, 15.0))},
                        {"pause_min", "1"},
                        {"pause_max", "4"}});
      visit(t, second);
      t.close().close();
    });
    if (!tree) return tl::unexpected(tree.error());
    d.place_used(C::kNormalOperation, who.role + " routine", first,
                 staff_like(who.role) ? "work place" : "waiting or living place");
    if (second != first)
      d.place_used(C::kNormalOperation, who.role + " routine", second,
                   staff_like(who.role) ? "work place" : "waiting or living place");
    std::vector<std::string> spawn = zones;
    const std::size_t shift = rng.below(static_cast<std::uint32_t>(spawn.size()));
    std::rotate(spawn.begin(), spawn.begin() + static_cast<std::ptrdiff_t>(shift), spawn.end());
    spawn_people(d, {who}, spawn, who.role, *tree, -1, C::kNormalOperation);
  }
  // Everyday traffic: people coming in by the entrance and walking to the main rooms, and others
  // leaving (ambient velocity-field groups, Fig. 2).
  Status status;
  std::vector<std::string> entrances, entrance_zones;
  for (const ExitPlace& x : p.exits()) {
    if (!x.region.empty()) entrances.push_back(x.region);
    const std::string z = !x.region.empty() ? p.zone_at(p.point(x.region)) : p.zone_at(x.point);
    if (!z.empty() && !contains(entrance_zones, z)) entrance_zones.push_back(z);
  }
  std::vector<People> traffic = rest;
  if (traffic.empty() && !d.named_only && area >= 120.0 && !entrances.empty()) {
    double circ_area = 0.0;
    for (const std::string& z : circulation) circ_area += p.zone_area(z);
    const std::size_t n = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::lround(circ_area * rng.uniform(0.05, 0.1))), 4, 24);
    const auto roles = d.people(Activity{C::kNormalOperation, 0.0, {}, {}, {}, std::nullopt}, n, rng);
    traffic = roles;
  }
  if (!traffic.empty() && !entrances.empty()) {
    std::vector<std::string> inner;
    for (const std::string& z : rest_places)
      if (!contains(entrance_zones, z) && p.place(z) && p.place(z)->region != nullptr) inner.push_back(z);
    if (inner.empty()) inner = {circulation.front()};
    const std::string destination = inner[rng.below(static_cast<std::uint32_t>(inner.size()))];
    std::vector<People> in, out;
    for (const People& who : traffic) {
      const std::size_t half = who.count / 2;
      if (who.count - half > 0)
        in.push_back(People{who.role, who.count - half, who.explicit_count, who.phrase});
      if (half > 0) out.push_back(People{who.role, half, who.explicit_count, who.phrase});
    }
    leftover_ambient(d, C::kNormalOperation, in, entrance_zones, {destination},
                     "coming in and walking to " + destination, true, rng, status);
    leftover_ambient(d, C::kNormalOperation, out, circulation, entrances, "walking out through the entrance",
                     true, rng, status);
  }
  return status;
}

}  // namespace socsim::scenario
