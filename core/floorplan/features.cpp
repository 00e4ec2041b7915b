#include "core/floorplan/features.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/floorplan/placer.hpp"
#include "core/floorplan/rooms.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/footprint.hpp"

namespace socsim::floorplan {
namespace {

using F = Feature;

enum class How {
  kCounterLane,  // a counter with its queue lane (towards the door; check-outs: into the room)
  kGateLine,     // gate posts in a line across the room, 0.9 m passages between them
  kWall,         // against a wall, facing into the room
  kFree,         // free-standing, on a grid with aisles
};

struct Spec {
  Feature feature;
  std::string_view type;
  std::vector<std::string> affordances;
  How how;
  std::vector<std::string_view> rooms;  // room types that take it, best first
  double aisle = 0.9;                   // m between free-standing pieces
};

const std::vector<Spec>& specs() {
  static const std::vector<Spec> s = {
      {F::kCounter,
       "counter",
       {"serve", "queue_target"},
       How::kCounterLane,
       {"lobby", "reception", "ticket_hall", "foyer", "cafe", "dining_hall", "restaurant", "concourse",
        "library_hall", "waiting_room", "sales_floor"}},
      {F::kCheckout,
       "counter",
       {"pay", "queue_target"},
       How::kCounterLane,
       {"sales_floor", "shop_unit", "cafe", "restaurant", "dining_hall", "lobby", "foyer"}},
      {F::kGate,
       "ticket_gate",
       {"pass_gate"},
       How::kGateLine,
       {"ticket_hall", "concourse", "foyer", "lobby", "entrance_hall", "sports_hall", "main_hall"}},
      {F::kElevator,
       "elevator",
       {"ride"},
       How::kWall,
       {"lobby", "ticket_hall", "concourse", "foyer", "mall_concourse", "corridor", "hallway", "platform"}},
      {F::kStair,
       "stairs",
       {"climb"},
       How::kWall,
       {"lobby", "ticket_hall", "concourse", "foyer", "mall_concourse", "platform", "corridor", "hallway"}},
      {F::kEscalator,
       "escalator",
       {"ride"},
       How::kWall,
       {"ticket_hall", "concourse", "mall_concourse", "foyer", "platform", "lobby"}},
      {F::kTable,
       "table",
       {"eat", "sit"},
       How::kFree,
       {"dining_hall", "restaurant", "cafe", "reading_room", "main_hall", "break_room", "staff_room",
        "day_room", "lobby", "concourse"},
       1.3},
      {F::kSeat,
       "chair",
       {"sit", "wait"},
       How::kFree,
       {"waiting_room", "lobby", "foyer", "concourse", "gate_area", "platform", "day_room", "main_hall",
        "living_room", "reading_room", "ticket_hall"},
       0.5},
      {F::kDesk,
       "desk",
       {"work", "sit"},
       How::kFree,
       {"open_office", "classroom", "reading_room", "seminar_room", "private_office", "study"},
       1.1},
      {F::kBed,
       "bed",
       {"lie", "sleep"},
       How::kWall,
       {"patient_room", "bedroom", "hotel_room", "resident_room", "ward"}},
      {F::kShelf,
       "shelf",
       {"browse", "pick"},
       How::kFree,
       {"sales_floor", "library_stacks", "reading_room", "stock_room", "storage"},
       1.3},
      {F::kRack, "rack", {"store", "pick"}, How::kFree, {"warehouse_floor", "stock_room", "storage"}, 1.4},
      {F::kScreen,
       "screen",
       {"watch"},
       How::kWall,
       {"auditorium", "lecture_hall", "meeting_room", "concourse", "ticket_hall", "main_hall", "foyer"}},
      {F::kStage,
       "stage",
       {"perform"},
       How::kWall,
       {"auditorium", "main_hall", "arena_floor", "dining_hall", "foyer"}},
      {F::kBar,
       "bar_counter",
       {"serve", "drink"},
       How::kWall,
       {"bar", "cafe", "restaurant", "foyer", "dining_hall", "lobby"}},
      {F::kLocker,
       "locker",
       {"store"},
       How::kWall,
       {"changing_room", "locker_room", "staff_room", "break_room", "corridor", "hallway"}},
  };
  return s;
}

const Spec* spec_for(Feature f) {
  for (const auto& s : specs())
    if (s.feature == f) return &s;
  return nullptr;
}

struct ObjectStyle {
  std::string_view type;
  std::vector<std::string> affordances;
  std::vector<std::string_view> rooms;
};

const std::vector<ObjectStyle>& object_styles() {
  static const std::vector<ObjectStyle> s = {
      {"coffee_machine",
       {"drink"},
       {"kitchenette", "break_room", "staff_room", "kitchen", "cafe", "lobby", "concourse", "foyer"}},
      {"water_dispenser",
       {"drink"},
       {"lobby", "waiting_room", "concourse", "corridor", "break_room", "foyer"}},
      {"vending_machine", {"buy"}, {"concourse", "lobby", "ticket_hall", "break_room", "corridor", "foyer"}},
      {"music_system", {"listen"}, {"living_room", "main_hall", "dining_hall", "day_room", "lobby", "foyer"}},
      {"tv", {"watch"}, {"living_room", "day_room", "waiting_room", "lobby", "break_room"}},
      {"piano", {"play", "listen"}, {"main_hall", "living_room", "foyer", "lobby", "day_room"}},
      {"printer", {"print"}, {"open_office", "private_office", "reception"}},
      {"fridge", {"store_food"}, {"kitchen", "kitchenette", "break_room", "staff_room"}},
      {"microwave", {"heat_food"}, {"kitchenette", "break_room", "staff_room", "kitchen"}},
      {"ticket_machine", {"buy_ticket", "queue_target"}, {"ticket_hall", "concourse", "foyer", "lobby"}},
      {"info_board", {"read"}, {"ticket_hall", "concourse", "lobby", "foyer", "platform"}},
  };
  return s;
}

bool is_public_room(std::string_view t) {
  return is_hall_type(t) || t == "lobby" || t == "reception" || t == "foyer" || t == "ticket_hall" ||
         t == "main_hall" || t == "waiting_room" || t == "living_room" || t == "day_room";
}

// Zones in the order a feature or object should try them: its room types in order, then the
// other rooms largest first (toilets, stores and rooms too small to stand in last).
std::vector<std::size_t> zone_order(std::span<const Zone> zones,
                                    const std::vector<std::string_view>& preferred, bool corridors) {
  std::vector<std::size_t> out;
  for (std::string_view t : preferred)
    for (std::size_t z = 0; z < zones.size(); ++z)
      if (canonical_room_type(zones[z].type) == t && std::find(out.begin(), out.end(), z) == out.end())
        out.push_back(z);
  std::vector<std::size_t> rest;
  for (std::size_t z = 0; z < zones.size(); ++z) {
    const std::string t = canonical_room_type(zones[z].type);
    if (std::find(out.begin(), out.end(), z) != out.end()) continue;
    if (!corridors && is_corridor_type(t)) continue;
    if (is_toilet_type(t) || t == "storage") continue;
    rest.push_back(z);
  }
  std::stable_sort(rest.begin(), rest.end(), [&](std::size_t a, std::size_t b) {
    const bool pa = is_public_room(canonical_room_type(zones[a].type));
    const bool pb = is_public_room(canonical_room_type(zones[b].type));
    if (pa != pb) return pa;
    return geometry::area(zones[a].polygon) > geometry::area(zones[b].polygon);
  });
  out.insert(out.end(), rest.begin(), rest.end());
  return out;
}

std::string unique_suffix(const Furnishing& f, const Zone& z, const std::string& base) {
  std::set<std::string> names;
  for (const auto& e : f.entities) names.insert(e.name);
  for (int k = 1;; ++k) {
    const std::string s = numbered(base, k);
    if (!names.count(z.name + "_" + s)) return s;
  }
}

// One piece of a feature in zone `z`; false when it does not fit there.
bool place_one(const Spec& spec, const Zone& z, std::span<const Zone> zones, std::span<const DoorSpec> doors,
               const FurnishingRules& rules, Furnishing& f) {
  auto placer = placer_for(z, zones, doors, f);
  if (!placer) return false;
  const std::string type(spec.type);
  const std::string base(to_string(spec.feature));
  for (int turn : {0, 1, 3, 2}) {
    Placer q = placer->turned((placer->side() + turn) % 4);
    const double L = q.len(), D = q.depth();
    switch (spec.how) {
      case How::kWall:
        if (q.entity(type, unique_suffix(f, z, base), {{L / 2, D}}, kPi, spec.affordances)) return true;
        break;
      case How::kCounterLane: {
        const bool inward = spec.feature == F::kCheckout;
        const double v = inward ? 1.8 : std::min(D - 0.8, std::max(3.2, D * 0.7));
        const double lane = inward ? std::clamp(D * 0.3, 1.5, 3.5) : 4.0;
        for (double frac : {0.5, 0.25, 0.75, 0.12, 0.88, 0.38, 0.62}) {
          if (q.counter_with_queue(type, unique_suffix(f, z, base), L * frac, v, lane, inward,
                                   rules.queue_lane_width, spec.affordances))
            return true;
        }
        break;
      }
      case How::kGateLine:
      case How::kFree:
        break;
    }
  }
  return false;
}

// Free-standing pieces on a grid; how many were placed.
int place_free(const Spec& spec, const Zone& z, std::span<const Zone> zones, std::span<const DoorSpec> doors,
               int wanted, Furnishing& f) {
  auto placer = placer_for(z, zones, doors, f);
  if (!placer) return 0;
  const Footprint fp = footprint_of(spec.type);
  const double du = fp.width + spec.aisle, dv = fp.depth + spec.aisle;
  int placed = 0;
  for (double shift : {0.0, 0.5}) {
    if (placed >= wanted) break;
    const double L = placer->len(), D = placer->depth();
    placed += placer->grid(std::string(spec.type), std::string(to_string(spec.feature)), 0.3 + shift * du,
                           1.2 + shift * dv, L - 0.3, D - 0.3, du, dv, wanted - placed, 0, spec.affordances);
  }
  return placed;
}

// Gate posts in a line across the room; how many were placed.
int place_gates(const Spec& spec, const Zone& z, std::span<const Zone> zones, std::span<const DoorSpec> doors,
                int wanted, Furnishing& f) {
  auto placer = placer_for(z, zones, doors, f);
  if (!placer) return 0;
  constexpr double kPitch = 1.2;  // 0.3 m post + 0.9 m passage
  for (int turn : {0, 1, 3}) {
    Placer q = placer->turned((placer->side() + turn) % 4);
    const double L = q.len(), D = q.depth();
    const int n = std::min(wanted, static_cast<int>(std::floor((L - 1.6) / kPitch)) + 1);
    if (n <= 0) continue;
    for (double at : {0.5, 0.4, 0.6, 0.3, 0.7}) {
      const double v = D * at;
      const double u0 = (L - (n - 1) * kPitch) / 2;
      std::vector<Point> spots;
      for (int k = 0; k < n; ++k) {
        const auto p = q.fit(std::string(spec.type), u0 + k * kPitch, v, 0.0);
        if (!p || std::abs(p->x - (u0 + k * kPitch)) > 1e-9 || std::abs(p->y - v) > 1e-9) break;
        spots.push_back(*p);
      }
      if (static_cast<int>(spots.size()) < n) continue;
      const std::size_t before = f.entities.size();
      for (int k = 0; k < n; ++k) {
        const Point w =
            q.frame().at(spots[static_cast<std::size_t>(k)].x, spots[static_cast<std::size_t>(k)].y);
        f.entities.push_back({std::string(spec.type),
                              z.name + "_" + unique_suffix(f, z, "gate"),
                              {w.x, w.y, q.frame().yaw(0.0)},
                              spec.affordances});
      }
      if (q.walkable()) return n;
      f.entities.resize(before);
    }
  }
  return 0;
}

void remove_extra(Feature feature, int keep, Furnishing& f) {
  int seen = 0;
  std::vector<std::string> gone;
  for (const auto& e : f.entities)
    if (entity_is(feature, e.type, e.affordances) && ++seen > keep) gone.push_back(e.name);
  const std::set<std::string> out(gone.begin(), gone.end());
  std::erase_if(f.entities, [&](const EntitySpec& e) { return out.count(e.name) > 0; });
  std::erase_if(f.rois, [&](const Roi& r) {
    return r.name.ends_with("_queue") && out.count(r.name.substr(0, r.name.size() - 6)) > 0;
  });
}

std::string plural(Feature f, int n) {
  return std::to_string(n) + " " + std::string(n == 1 ? info(f).key : info(f).plural);
}

}  // namespace

std::string room_type_for(const NamedRoom& room) {
  if (!room.type.empty() && find_room_type(room.type)) return canonical_room_type(room.type);
  const std::string name = snake_case(room.name);
  if (find_room_type(name)) return canonical_room_type(name);
  // The last words name the kind of room ("maternity ward", "staff break room").
  for (std::size_t from = name.find('_'); from != std::string::npos; from = name.find('_', from + 1)) {
    const std::string tail = name.substr(from + 1);
    if (find_room_type(tail)) return canonical_room_type(tail);
  }
  return room.type.empty() ? name : room.type;
}

Status apply_room_requirements(SceneGraph& g, const WorldRequirements& r, bool given,
                               std::vector<std::string>* notes) {
  std::vector<FieldError> errors;
  std::string circulation = g.rooms.empty() ? std::string() : g.rooms.front().name;
  for (const auto& room : g.rooms)
    if (is_circulation_type(room.type)) {
      circulation = room.name;
      break;
    }
  auto count_type = [&](const std::string& type) {
    return static_cast<int>(std::count_if(g.rooms.begin(), g.rooms.end(), [&](const SceneRoom& x) {
      return x.type == type || x.name == type;
    }));
  };
  auto add = [&](const std::string& type, const std::string& preferred_name, int n) {
    for (int k = 0; k < n; ++k) {
      std::string name = preferred_name;
      for (int i = 2;
           std::any_of(g.rooms.begin(), g.rooms.end(), [&](const SceneRoom& x) { return x.name == name; });
           ++i)
        name = numbered(preferred_name, i);
      g.rooms.push_back({name, type, std::nullopt});
      if (!circulation.empty() && circulation != name) g.adjacency.emplace_back(circulation, name);
      if (circulation.empty()) circulation = name;
      if (notes) notes->push_back("added room '" + name + "' (" + type + ") that the request names");
    }
  };
  for (std::size_t i = 0; i < r.rooms.size(); ++i) {
    const NamedRoom& room = r.rooms[i];
    const std::string type = room_type_for(room);
    const int have = count_type(type);
    if (have >= room.count) continue;
    if (given) {
      errors.push_back({"/requirements/rooms/" + std::to_string(i),
                        "the scene graph has " + std::to_string(have) + " room" + (have == 1 ? "" : "s") +
                            " of type '" + type + "' for '" + room.name + "' (" + std::to_string(room.count) +
                            " asked for); add them to the scene graph"});
      continue;
    }
    add(type, find_room_type(type) ? type : snake_case(room.name), room.count - have);
  }
  for (std::size_t i = 0; i < r.features.size(); ++i) {
    const FeatureCount& fc = r.features[i];
    std::string type;
    if (fc.feature == F::kToilet) type = g.domain == "residential" ? "bathroom" : "toilet";
    if (fc.feature == F::kPlatform) type = "platform";
    if (fc.feature == F::kGate && g.domain == "airport") type = "gate_area";
    if (type.empty()) continue;
    const int have = count_type(type);
    if (have == fc.count || (fc.at_least && have >= fc.count)) continue;
    if (given) {
      errors.push_back({"/requirements/features/" + std::to_string(i),
                        "the scene graph has " + std::to_string(have) + " rooms of type '" + type + "' but " +
                            std::to_string(fc.count) + " " + std::string(info(fc.feature).plural) +
                            " are asked for"});
      continue;
    }
    if (have < fc.count) {
      add(type, type, fc.count - have);
      continue;
    }
    // Fewer than the programme has: the last ones go, with their doors.
    int extra = have - fc.count;
    for (auto it = g.rooms.rbegin(); it != g.rooms.rend() && extra > 0;) {
      if (it->type != type) {
        ++it;
        continue;
      }
      const std::string name = it->name;
      std::erase_if(g.adjacency, [&](const auto& e) { return e.first == name || e.second == name; });
      it = std::make_reverse_iterator(g.rooms.erase(std::next(it).base()));
      if (g.entrance == name) g.entrance = circulation;
      if (notes)
        notes->push_back("left out room '" + name + "': " + plural(fc.feature, fc.count) + " asked for");
      --extra;
    }
  }
  if (g.rooms.size() > kMaxSceneRooms)
    errors.push_back({"/requirements", "the requirements bring the plan to " +
                                           std::to_string(g.rooms.size()) + " rooms; at most " +
                                           std::to_string(kMaxSceneRooms)});
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "the scene graph does not hold what the requirements ask for",
                std::move(errors));
  return {};
}

int count_in(const Furnishing& f, Feature feature) {
  int n = 0;
  for (const auto& e : f.entities) n += entity_is(feature, e.type, e.affordances);
  return n;
}

FeatureOutcome furnish_requirements(std::span<const Zone> zones, std::span<const DoorSpec> doors,
                                    const WorldRequirements& r, const FurnishingRules& rules, Furnishing& f) {
  FeatureOutcome out;
  for (const FeatureCount& fc : r.features) {
    const Spec* spec = spec_for(fc.feature);
    if (!spec) continue;  // doors, exits, rooms: laid out with the plan
    const int have = count_in(f, fc.feature);
    if (have > fc.count && !fc.at_least) {
      remove_extra(fc.feature, fc.count, f);
      out.notes.push_back("kept " + plural(fc.feature, fc.count) + " of the " + std::to_string(have) +
                          " furnished, as asked");
      continue;
    }
    int missing = fc.count - have;
    if (missing <= 0) continue;
    const bool corridors = spec->how == How::kWall;
    for (std::size_t z : zone_order(zones, spec->rooms, corridors)) {
      if (missing <= 0) break;
      if (spec->how == How::kFree) {
        missing -= place_free(*spec, zones[z], zones, doors, missing, f);
      } else if (spec->how == How::kGateLine) {
        missing -= place_gates(*spec, zones[z], zones, doors, missing, f);
      } else {
        while (missing > 0 && place_one(*spec, zones[z], zones, doors, rules, f)) --missing;
      }
    }
    const int now = fc.count - std::max(missing, 0);
    if (now > have)
      out.notes.push_back("added " + plural(fc.feature, now - have) + " to reach the " +
                          plural(fc.feature, fc.count) + " asked for");
    if (missing > 0)
      out.missing.push_back(std::to_string(now) + " of the " + plural(fc.feature, fc.count) +
                            " asked for fit");
  }
  for (const NamedObject& o : r.objects) {
    const ObjectStyle* style = nullptr;
    for (const auto& s : object_styles())
      if (s.type == o.type) style = &s;
    std::vector<std::string_view> rooms;
    const std::string wanted_room = snake_case(o.room);
    std::vector<std::size_t> order;
    if (!wanted_room.empty()) {
      for (std::size_t z = 0; z < zones.size(); ++z)
        if (zones[z].name == wanted_room ||
            canonical_room_type(zones[z].type) == canonical_room_type(wanted_room) ||
            zones[z].name.rfind(wanted_room + "_", 0) == 0)
          order.push_back(z);
      if (order.empty())
        out.notes.push_back("no room '" + o.room + "' for the " + o.name + "; placed where it fits");
    }
    if (style) rooms = style->rooms;
    for (std::size_t z : zone_order(zones, rooms, false))
      if (std::find(order.begin(), order.end(), z) == order.end()) order.push_back(z);
    const Spec spec{
        F::kExit, o.type, style ? style->affordances : std::vector<std::string>{"use"}, How::kWall, {}};
    int placed = 0;
    for (std::size_t z : order) {
      while (placed < o.count) {
        auto placer = placer_for(zones[z], zones, doors, f);
        if (!placer) break;
        bool ok = false;
        for (int turn : {0, 1, 3, 2}) {
          Placer q = placer->turned((placer->side() + turn) % 4);
          const std::string suffix = o.count == 1 && placed == 0 &&
                                             std::none_of(f.entities.begin(), f.entities.end(),
                                                          [&](const EntitySpec& e) {
                                                            return e.name == zones[z].name + "_" + o.type;
                                                          })
                                         ? o.type
                                         : unique_suffix(f, zones[z], o.type);
          if (q.entity(o.type, suffix, {{q.len() / 2, q.depth()}}, kPi, spec.affordances)) {
            ok = true;
            break;
          }
        }
        if (!ok) break;
        ++placed;
        out.notes.push_back("placed the " + o.name + " in '" + zones[z].name + "'");
      }
      if (placed >= o.count) break;
    }
    if (placed < o.count)
      out.missing.push_back(std::to_string(placed) + " of " + std::to_string(o.count) + " " + o.name +
                            " fit");
  }
  return out;
}

}  // namespace socsim::floorplan
