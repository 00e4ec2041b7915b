#include "core/scenario/program_offline.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/scenario/intent_check.hpp"
#include "core/scenario/offline_plan.hpp"
#include "core/scenario/program_check.hpp"
#include "core/scenario/scenario_intent.hpp"

namespace socsim::scenario {

namespace {

constexpr double kAlarmWeight = 0.8;  // emergency words at least this strong apply to everyone

using C = Category;

std::vector<std::pair<std::string, double>> default_roles(const std::string& domain, Category c) {
  if (domain == "hospital") {
    switch (c) {
      case C::kQueuing:
      case C::kReception:
        return {{"patient", 0.6}, {"visitor", 0.4}};
      case C::kCoffeeBreak:
        return {{"nurse", 0.5}, {"doctor", 0.25}, {"staff", 0.25}};
      case C::kEmergency:
        return {{"patient", 0.35}, {"visitor", 0.35}, {"nurse", 0.3}};
      case C::kNormalOperation:
        return {{"nurse", 0.3}, {"doctor", 0.1}, {"patient", 0.3}, {"visitor", 0.3}};
      default:
        return {{"visitor", 1.0}};
    }
  }
  if (domain == "office") {
    switch (c) {
      case C::kQueuing:
      case C::kReception:
        return {{"visitor", 1.0}};
      case C::kEmergency:
      case C::kNormalOperation:
        return {{"worker", 0.8}, {"visitor", 0.2}};
      default:
        return {{"worker", 1.0}};
    }
  }
  if (domain == "residential") {
    if (c == Category::kEmergency || c == Category::kNormalOperation) return {{"resident", 1.0}};
    return {{"guest", 1.0}};
  }
  if (domain == "warehouse") return {{"worker", 1.0}};
  if (domain == "canteen" || domain == "retail") {
    if (c == Category::kCoffeeBreak) return {{"staff", 1.0}};
    return {{"customer", 1.0}};
  }
  if (domain == "school") return {{"student", 1.0}};
  if (domain == "airport") return {{"passenger", 1.0}};
  return {{"adult", 1.0}};
}

// Largest-remainder split of n over weights.
std::vector<std::size_t> apportion(std::size_t n, const std::vector<double>& weights) {
  std::vector<std::size_t> out(weights.size(), 0);
  double total = 0.0;
  for (double w : weights) total += w;
  if (total <= 0.0 || weights.empty()) return out;
  std::vector<std::pair<double, std::size_t>> rest;
  std::size_t given = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double exact = static_cast<double>(n) * weights[i] / total;
    out[i] = static_cast<std::size_t>(std::floor(exact));
    given += out[i];
    rest.emplace_back(exact - std::floor(exact), i);
  }
  std::stable_sort(rest.begin(), rest.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; given < n && k < rest.size(); ++k, ++given) ++out[rest[k].second];
  return out;
}

std::string trimmed(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a])) != 0) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1])) != 0) --b;
  return std::string(s.substr(a, b - a));
}

Json role_json(const std::string& role) {
  const auto p = role_profile(role);
  if (!p) return Json::object();
  return Json{{"speed", {{"mean", p->mean}, {"sd", p->sd}, {"min", p->min}, {"max", p->max}}},
              {"radius", p->radius}};
}

// The groups the prompt names (scenario_intent.hpp) replace the lexicon's role mentions: exactly
// those people, counted as written, each in the clause it was said in.
void take_groups(Intent& intent, const ScenarioIntent& named) {
  if (named.groups.empty() || intent.clauses.empty()) return;
  const auto tokens = tokenize(intent.prompt);
  for (Clause& c : intent.clauses) c.roles.clear();
  intent.crowd_size.reset();
  for (const PeopleGroup& g : named.groups) {
    std::size_t clause = 0;
    for (const Token& t : tokens) {
      if (t.offset > g.span.begin) break;
      clause = t.clause;
    }
    clause = std::min(clause, intent.clauses.size() - 1);
    RoleMention m;
    m.role = g.program_role;
    m.phrase = g.role;
    if (g.count.specified()) {
      m.count = g.count.people();
      m.count_phrase = g.count.phrase;
      m.approximate = g.count.kind != CountKind::kExact;
    }
    m.clause = clause;
    m.offset = g.span.begin;
    intent.clauses[clause].roles.push_back(std::move(m));
  }
}

// When the world cannot hold the people the prompt counts, every counted group shrinks by the same
// factor (each keeps at least one person), so that no group named is left out because an earlier
// one took the room; the note says how many of whom.
std::optional<std::string> share_the_room(Intent& intent, const WorldProbe& probe) {
  std::size_t capacity = 0, asked = 0;
  for (const world::Zone& z : probe.world().zones())
    if (!probe.is_toilet(z.name)) capacity += probe.capacity(z.name);
  for (const Clause& c : intent.clauses)
    for (const RoleMention& m : c.roles) asked += m.count.value_or(0);
  if (asked <= capacity || asked == 0) return std::nullopt;
  const double factor = static_cast<double>(capacity) / static_cast<double>(asked);
  std::string who;
  for (Clause& c : intent.clauses)
    for (RoleMention& m : c.roles) {
      if (!m.count) continue;
      const std::size_t kept = std::max<std::size_t>(
          1, static_cast<std::size_t>(std::floor(static_cast<double>(*m.count) * factor)));
      who += (who.empty() ? "" : ", ") + std::to_string(kept) + " of " + std::to_string(*m.count) + " " +
             m.phrase;
      m.count = kept;
    }
  return "the building holds about " + std::to_string(capacity) + " people and the prompt counts " +
         std::to_string(asked) + ": every counted group was cut in proportion (" + who + ")";
}

}  // namespace

// --- Activity ------------------------------------------------------------------------------------

const ResolvedPlace* Activity::place() const {
  for (const auto& [m, r] : places)
    if (r) return &*r;
  return nullptr;
}

const PlaceMention* Activity::unresolved() const {
  for (const auto& [m, r] : places)
    if (!r) return &m;
  return nullptr;
}

// --- Draft ---------------------------------------------------------------------------------------

Draft::Draft(WorldProbe& p, NodeCatalogue& n, const Intent& i, const ProgramRequest& r,
             const ScenarioLimits& l)
    : probe(p), nodes(n), intent(i), request(r), limits(l) {}

std::vector<People> Draft::people(const Activity& a, std::size_t default_total, Rng& rng) const {
  std::vector<People> out;
  bool crowd = false;
  if (a.crowd && a.roles.empty()) {
    default_total = *a.crowd;
    crowd = true;
  }
  if (!a.roles.empty()) {
    std::size_t without = 0;
    for (const RoleMention& m : a.roles) without += m.count ? 0 : 1;
    const std::size_t share = without == 0 ? 0 : std::max<std::size_t>(1, default_total / without);
    for (const RoleMention& m : a.roles) {
      People p;
      p.role = m.role;
      p.explicit_count = m.count.has_value();
      p.count = m.count.value_or(share);
      p.phrase = m.count ? m.count_phrase + " " + m.phrase : m.phrase;
      if (p.count > 0) out.push_back(std::move(p));
    }
    return out;
  }
  const auto roles = default_roles(probe.domain(), a.category);
  std::vector<double> weights;
  for (const auto& [role, w] : roles) weights.push_back(w);
  // Seeded variety in the mix: ±25 % on each weight.
  for (double& w : weights) w *= rng.uniform(0.75, 1.25);
  const auto counts = apportion(default_total, weights);
  for (std::size_t k = 0; k < roles.size(); ++k)
    if (counts[k] > 0)
      out.push_back(
          People{roles[k].first, counts[k], crowd, crowd ? intent.crowd_phrase : std::string("default")});
  return out;
}

std::size_t Draft::take_spotlight(std::size_t wanted) {
  const std::size_t left = limits.max_spotlight > spotlight_ ? limits.max_spotlight - spotlight_ : 0;
  const std::size_t granted = std::min(wanted, left);
  spotlight_ += granted;
  return granted;
}

std::size_t Draft::room_left(const std::string& region) const {
  const std::size_t cap = probe.capacity(region);
  const auto it = used_room_.find(region);
  const std::size_t used = it == used_room_.end() ? 0 : it->second;
  return cap > used ? cap - used : 0;
}

std::vector<std::pair<std::string, std::size_t>> Draft::spread(const std::vector<std::string>& regions,
                                                               std::size_t n) {
  std::vector<std::pair<std::string, std::size_t>> out;
  std::set<std::string> seen;
  for (const std::string& r : regions) {
    if (n == 0) break;
    if (!seen.insert(r).second) continue;
    const std::size_t k = std::min(room_left(r), n);
    if (k == 0) continue;
    out.emplace_back(r, k);
    used_room_[r] += k;
    n -= k;
  }
  return out;
}

Result<std::string> Draft::add_tree(Category category, const std::string& base,
                                    const std::function<void(TreeXml&)>& body) {
  std::string name = base;
  for (int k = 2; std::any_of(trees_.begin(), trees_.end(), [&](const auto& t) { return t.first == name; });
       ++k)
    name = base + "_" + std::to_string(k);
  TreeXml t(nodes, category, name);
  if (alarm_s && category != Category::kEmergency) {
    t.open("ReactiveFallback").open("Sequence");
    t.leaf("TimeExpired", {{"seconds", format_number(*alarm_s)}, {"ts", "{dt}"}, {"only_once", "true"}});
    t.leaf("Evacuate", {{"agent_id", "{id}"}, {"speed_factor", "1.3"}});
    t.close();
    body(t);
    t.close();
  } else if (start_s && category != Category::kEmergency) {
    t.open("Sequence");
    t.leaf("TimeExpired", {{"seconds", format_number(*start_s)}, {"ts", "{dt}"}, {"only_once", "true"}});
    body(t);
    t.close();
  } else {
    body(t);
  }
  auto xml = t.finish();
  if (!xml) return tl::unexpected(xml.error());
  trees_.emplace_back(name, *xml);
  return name;
}

void Draft::add_agents(const std::string& name, const People& who, const std::string& spawn,
                       std::size_t count, const std::string& tree, std::int64_t group, Category category) {
  if (count == 0) return;
  Json j{{"name", name},     {"role", who.role},
         {"spawn", spawn},   {"count", count},
         {"behavior", tree}, {"tags", Json::array({std::string(to_string(category)), "spotlight"})}};
  if (group >= 0) j["group_id"] = group;
  agents_.push_back(Entry{std::move(j), count, who.explicit_count, false});
  if (std::find(roles_.begin(), roles_.end(), who.role) == roles_.end()) roles_.push_back(who.role);
}

void Draft::add_agent_at(const std::string& name, const std::string& role, crowd::Vec2 position,
                         const std::string& tree, Category category) {
  auto mm = [](double v) { return std::round(v * 1000.0) / 1000.0; };
  Json j{{"name", name},
         {"role", role},
         {"position", Json::array({mm(position.x), mm(position.y)})},
         {"behavior", tree},
         {"tags", Json::array({std::string(to_string(category)), "spotlight"})}};
  agents_.push_back(Entry{std::move(j), 1, false, true});
  if (std::find(roles_.begin(), roles_.end(), role) == roles_.end()) roles_.push_back(role);
}

Status Draft::add_ambient(Category category, Ambient group) {
  if (group.size == 0) return {};
  std::string name = group.name;
  for (int k = 2; std::any_of(ambient_.begin(), ambient_.end(),
                              [&](const AmbientEntry& a) { return a.group.name == name; });
       ++k)
    name = group.name + "_" + std::to_string(k);
  group.name = name;
  std::size_t cap = 0;
  for (const std::string& s : group.start) cap += room_left(s);
  if (group.size > cap && group.explicit_count) {
    // A count the prompt gave is kept while the building holds it: the people who do not fit
    // where the activity happens start in the other rooms, largest first.
    std::vector<std::string> more;
    for (const world::Zone& z : probe.world().zones())
      if (!probe.is_toilet(z.name) &&
          std::find(group.start.begin(), group.start.end(), z.name) == group.start.end() &&
          std::find(group.goal.begin(), group.goal.end(), z.name) == group.goal.end() &&
          room_left(z.name) > 0)
        more.push_back(z.name);
    std::stable_sort(more.begin(), more.end(),
                     [&](const std::string& a, const std::string& b) { return room_left(a) > room_left(b); });
    // Last, the place they are going to (the party's hall, the café's seats): some are there
    // already. Not for people leaving the building, who would leave at once.
    if (!group.exit_at_goal)
      for (const std::string& z : group.goal)
        if (!probe.is_toilet(z) && room_left(z) > 0 &&
            std::find(group.start.begin(), group.start.end(), z) == group.start.end())
          more.push_back(z);
    std::size_t added = 0;
    for (const std::string& z : more) {
      if (cap >= group.size) break;
      group.start.push_back(z);
      cap += room_left(z);
      ++added;
    }
    if (added > 0)
      note("ambient group '" + name + "': its start regions hold too few of the " +
           std::to_string(group.size) + " people the prompt asks for; " + std::to_string(added) +
           " more rooms added as start regions");
  }
  if (group.size > cap) {
    note("ambient group '" + name + "': " + std::to_string(group.size) +
         " people do not fit in its start regions; " + std::to_string(cap) + " placed");
    group.size = cap;
  }
  if (group.size == 0) return {};
  AmbientEntry entry{group, "", ""};
  const bool alarm = alarm_s && category != Category::kEmergency;
  const std::optional<double> delay =
      category == Category::kEmergency ? alarm_s : (alarm_s ? std::nullopt : start_s);
  if (alarm || delay) {
    TreeXml t(nodes, category, "ambient_" + name);
    if (alarm) {
      t.open("ReactiveFallback").open("Sequence");
      t.leaf("TimeExpired", {{"seconds", format_number(*alarm_s)}, {"ts", "{dt}"}, {"only_once", "true"}});
      t.leaf("Evacuate", {{"agent_id", "{id}"}, {"speed_factor", "1.3"}});
      t.close();
      t.leaf("FollowVelocityField",
             {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"field", name}, {"tolerance", "0.5"}});
      t.close();
    } else {
      t.open("Sequence");
      t.leaf("TimeExpired", {{"seconds", format_number(*delay)}, {"ts", "{dt}"}, {"only_once", "true"}});
      t.leaf("FollowVelocityField",
             {{"agent_id", "{id}"}, {"time_step", "{dt}"}, {"field", name}, {"tolerance", "0.5"}});
      t.close();
    }
    auto xml = t.finish();
    if (!xml) return tl::unexpected(xml.error());
    entry.tree = "ambient_" + name;
    entry.xml = *xml;
  } else {
    nodes.use("FollowVelocityField", category);
  }
  // Book the start regions in proportion to what they hold.
  std::vector<double> rooms;
  for (const std::string& s : group.start) rooms.push_back(static_cast<double>(room_left(s)));
  const auto share = apportion(group.size, rooms);
  for (std::size_t k = 0; k < group.start.size(); ++k) used_room_[group.start[k]] += share[k];
  if (entry.group.size == 0) return {};
  if (std::find(roles_.begin(), roles_.end(), group.role) == roles_.end()) roles_.push_back(group.role);
  ambient_.push_back(std::move(entry));
  return {};
}

void Draft::place_used(Category category, const std::string& purpose, const std::string& name,
                       const std::string& why) {
  places_.push_back(Json{
      {"category", std::string(to_string(category))}, {"purpose", purpose}, {"place", name}, {"why", why}});
}

std::size_t Draft::total() const {
  std::size_t n = 0;
  for (const Entry& e : agents_) n += e.count;
  for (const AmbientEntry& a : ambient_) n += a.group.size;
  return n;
}

void Draft::fit(std::size_t bound) {
  const std::size_t before = total();
  if (before <= bound) return;
  std::size_t excess = before - bound;
  // Reduce a set of sizes by up to `excess` in proportion (largest first for the remainder).
  auto reduce = [&](std::vector<std::size_t*> sizes, std::size_t floor_each) {
    std::size_t spare = 0;
    for (std::size_t* s : sizes) spare += *s > floor_each ? *s - floor_each : 0;
    if (spare == 0 || excess == 0) return;
    const std::size_t cut = std::min(spare, excess);
    std::vector<double> weights;
    for (std::size_t* s : sizes)
      weights.push_back(static_cast<double>(*s > floor_each ? *s - floor_each : 0));
    const auto cuts = apportion(cut, weights);
    for (std::size_t k = 0; k < sizes.size(); ++k) *sizes[k] -= cuts[k];
    excess -= cut;
  };
  std::vector<std::size_t*> ambient_default, ambient_explicit, spot_default, spot_explicit;
  for (AmbientEntry& a : ambient_)
    (a.group.explicit_count ? ambient_explicit : ambient_default).push_back(&a.group.size);
  for (Entry& e : agents_)
    if (!e.positioned) (e.explicit_count ? spot_explicit : spot_default).push_back(&e.count);
  reduce(ambient_default, 0);
  reduce(spot_default, 1);
  reduce(ambient_explicit, 0);
  reduce(spot_explicit, 1);
  for (Entry& e : agents_) e.json["count"] = e.count;
  ambient_.erase(std::remove_if(ambient_.begin(), ambient_.end(),
                                [](const AmbientEntry& a) { return a.group.size == 0; }),
                 ambient_.end());
  while (excess > 0 && !agents_.empty()) {  // more entries than the bound: the last ones go
    excess -= std::min(excess, agents_.back().count);
    agents_.pop_back();
  }
  note("the scenario asked for " + std::to_string(before) + " people; scaled down to the bound of " +
       std::to_string(bound) + " (ambient crowds first, then default counts, then counts from the prompt)");
}

Json Draft::program(const std::string& name) const {
  Json roles = Json::object();
  for (const std::string& r : roles_) {
    if (is_builtin_role(r)) continue;
    const auto basis = role_basis.find(r);
    roles[r] = role_json(basis == role_basis.end() ? r : basis->second);
  }
  Json trees = Json::object();
  for (const auto& [n, xml] : trees_) trees[n] = Json{{"xml", xml}};
  for (const AmbientEntry& a : ambient_)
    if (!a.tree.empty()) trees[a.tree] = Json{{"xml", a.xml}};
  Json agents = Json::array();
  for (const Entry& e : agents_) agents.push_back(e.json);
  Json ambient = Json::array();
  for (const AmbientEntry& a : ambient_) {
    Json g{{"name", a.group.name},
           {"description", a.group.description},
           {"start", a.group.start},
           {"goal", a.group.goal},
           {"size", a.group.size},
           {"speed", a.group.speed},
           {"role", a.group.role},
           {"resolution", 64},
           {"variation", a.group.variation},
           {"tolerance", 0.5},
           {"on_arrival", a.group.exit_at_goal ? "exit" : "stand"}};
    if (!a.tree.empty()) g["behavior"] = a.tree;
    ambient.push_back(std::move(g));
  }
  return Json{{"version", 1},     {"name", name},
              {"dt", 0.05},       {"decision_period", 0.1},
              {"roles", roles},   {"behavior_trees", trees},
              {"agents", agents}, {"ambient_groups", ambient}};
}

Json Draft::provenance() const {
  Json ambient = Json::array();
  for (const AmbientEntry& a : ambient_)
    ambient.push_back(Json{{"name", a.group.name},
                           {"description", a.group.description},
                           {"size", a.group.size},
                           {"role", a.group.role},
                           {"start", a.group.start},
                           {"goal", a.group.goal}});
  std::size_t spotlight = 0;
  for (const Entry& e : agents_) spotlight += e.count;
  return Json{{"places_used", places_},
              {"notes", notes_},
              {"spotlight_agents", spotlight},
              {"ambient_groups", ambient},
              {"agents_total", total()}};
}

// --- generator -----------------------------------------------------------------------------------

namespace {

std::vector<Activity> plan_activities(const Intent& intent, const world::World& world, Json& place_log) {
  std::vector<Activity> out;
  std::vector<std::size_t> orphan;  // clauses without a category but with roles or places
  for (const Clause& c : intent.clauses) {
    std::vector<std::pair<PlaceMention, std::optional<ResolvedPlace>>> places;
    for (const PlaceMention& m : c.places) {
      auto r = resolve_place(m, world);
      Json log{{"phrase", m.phrase}, {"preposition", m.preposition}, {"clause", c.index}};
      if (r)
        log["resolved"] = to_json(*r);
      else
        log["resolved"] = nullptr;
      place_log.push_back(std::move(log));
      places.emplace_back(m, std::move(r));
    }
    if (c.categories.empty()) {
      if (!c.roles.empty() || !places.empty()) {
        if (out.empty()) {
          orphan.push_back(c.index);
        } else {
          Activity& a = out.back();
          a.clauses.push_back(c.index);
          a.roles.insert(a.roles.end(), c.roles.begin(), c.roles.end());
          a.places.insert(a.places.end(), places.begin(), places.end());
        }
      }
      continue;
    }
    // An emergency said alongside another activity in one clause ("patients queue when the fire
    // alarm sounds") is the alarm of that activity (applied to every tree), not a second crowd.
    const CategoryScore* pick = &c.categories.front();
    if (pick->category == Category::kEmergency && c.categories.size() > 1 &&
        c.categories[1].score >= kAlarmWeight)
      pick = &c.categories[1];
    const CategoryScore& top = *pick;
    // A clause that repeats an activity without adding people or places joins it.
    auto same =
        std::find_if(out.begin(), out.end(), [&](const Activity& a) { return a.category == top.category; });
    if (same != out.end() && (c.roles.empty() || same->roles.empty()) &&
        (places.empty() || same->places.empty())) {
      same->clauses.push_back(c.index);
      same->score += top.score;
      same->roles.insert(same->roles.end(), c.roles.begin(), c.roles.end());
      same->places.insert(same->places.end(), places.begin(), places.end());
      continue;
    }
    Activity a;
    a.category = top.category;
    a.score = top.score;
    a.clauses.push_back(c.index);
    a.roles = c.roles;
    a.places = std::move(places);
    if (out.empty()) {
      // Clauses before the first category ("Five nurses, two doctors: a coffee break") belong to it.
      for (std::size_t o : orphan) {
        const Clause& oc = intent.clauses[o];
        a.roles.insert(a.roles.begin(), oc.roles.begin(), oc.roles.end());
        for (const PlaceMention& m : oc.places) a.places.emplace_back(m, resolve_place(m, world));
        a.clauses.insert(a.clauses.begin(), o);
      }
      orphan.clear();
    }
    out.push_back(std::move(a));
  }
  if (out.empty()) {
    Activity a;
    a.category = Category::kNormalOperation;
    for (const Clause& c : intent.clauses) {
      a.clauses.push_back(c.index);
      a.roles.insert(a.roles.end(), c.roles.begin(), c.roles.end());
      for (const PlaceMention& m : c.places) a.places.emplace_back(m, resolve_place(m, world));
    }
    out.push_back(std::move(a));
  }
  if (intent.crowd_size) {
    for (Activity& a : out)
      if (std::find(a.clauses.begin(), a.clauses.end(), intent.crowd_clause) != a.clauses.end())
        a.crowd = intent.crowd_size;
    if (std::none_of(out.begin(), out.end(), [](const Activity& a) { return a.crowd.has_value(); }))
      out.front().crowd = intent.crowd_size;
  }
  // Emergencies first: their alarm shapes every other tree; then by weight.
  std::stable_sort(out.begin(), out.end(), [](const Activity& x, const Activity& y) {
    const bool ex = x.category == Category::kEmergency, ey = y.category == Category::kEmergency;
    if (ex != ey) return ex;
    return x.score > y.score;
  });
  return out;
}

Status run_planner(Draft& d, const Activity& a, Rng& rng) {
  switch (a.category) {
    case Category::kEmergency:
      return plan_emergency(d, a, rng);
    case Category::kQueuing:
      return plan_queuing(d, a, rng);
    case Category::kSocialParty:
      return plan_social_party(d, a, rng);
    case Category::kCoffeeBreak:
      return plan_coffee_break(d, a, rng);
    case Category::kReception:
      return plan_reception(d, a, rng);
    case Category::kBottleneck:
      return plan_bottleneck(d, a, rng);
    case Category::kNormalOperation:
      return plan_normal_operation(d, a, rng);
  }
  return {};
}

}  // namespace

Result<GeneratedProgram> generate_program_offline(const world::World& world,
                                                  const knowledge::KnowledgeBase& knowledge,
                                                  const ProgramRequest& request,
                                                  const ScenarioLimits& limits) {
  std::vector<FieldError> errors;
  const std::string prompt = trimmed(request.prompt);
  if (prompt.empty())
    return fail(ErrorCode::kBadRequest, "the prompt is empty", {FieldError{"/prompt", "must not be empty"}});
  if (!(request.duration_s > 0.0) || request.duration_s > limits.max_duration_s)
    errors.push_back(FieldError{
        "/duration_s", "must be more than 0 and at most " + format_number(limits.max_duration_s) + " s"});
  if (request.agents && (*request.agents == 0 || *request.agents > limits.max_agents))
    errors.push_back(FieldError{"/agents", "must be between 1 and " + std::to_string(limits.max_agents)});
  if (world.zones().empty())
    errors.push_back(FieldError{"/world", "the world has no zones to place people in"});
  if (!errors.empty())
    return fail(ErrorCode::kValidation, errors.front().pointer + ": " + errors.front().message, errors);

  Intent intent = parse_intent(prompt);
  auto named = interpret_prompt(prompt);
  if (!named) return tl::unexpected(named.error());
  take_groups(intent, *named);
  WorldProbe probe(world);
  auto catalogue = NodeCatalogue::load(knowledge);
  if (!catalogue) return tl::unexpected(catalogue.error());
  Json place_log = Json::array();
  const std::optional<std::string> room_note = share_the_room(intent, probe);
  std::vector<Activity> activities = plan_activities(intent, world, place_log);

  Draft draft(probe, *catalogue, intent, request, limits);
  // A prompt that names people says who is there ("visitors check in at the front desk": visitors,
  // no receptionist nobody asked for); background people only when it asks ("busy", "others").
  draft.named_only = names_who_is_there(*named);
  for (const PeopleGroup& g : named->groups) draft.role_basis[g.program_role] = g.normalized_role;
  if (room_note) draft.note(*room_note);
  if (draft.named_only &&
      std::any_of(activities.begin(), activities.end(), [](const Activity& a) { return !a.roles.empty(); })) {
    // Activities nobody named takes part in would bring people of their own; an emergency among
    // them still sounds the alarm for everyone (below).
    const auto before = activities.size();
    std::erase_if(activities, [](const Activity& a) { return a.roles.empty(); });
    if (activities.size() < before)
      draft.note("activities without any of the people named were left out: the prompt names who is there");
  }
  Rng rng(request.seed);
  Rng timing = rng.fork("timing");
  const bool emergency_activity = std::any_of(activities.begin(), activities.end(), [](const Activity& a) {
    return a.category == Category::kEmergency;
  });
  const bool emergency_words = std::any_of(
      intent.categories.begin(), intent.categories.end(),
      [](const CategoryScore& c) { return c.category == Category::kEmergency && c.score >= kAlarmWeight; });
  if (emergency_activity || emergency_words) {
    // The alarm: when the prompt says, else a few seconds in (seeded) so the scene starts calm.
    draft.alarm_s = intent.timing.start_after_s.value_or(std::round(timing.uniform(3.0, 8.0) * 10.0) / 10.0);
    draft.alarm_s = std::min(*draft.alarm_s, std::max(0.0, request.duration_s - 1.0));
    if (!emergency_activity)
      draft.note("emergency words ('" + std::string(to_string(Category::kEmergency)) +
                 "') apply to everyone: the alarm sounds at " + format_number(*draft.alarm_s) +
                 " s and every agent evacuates");
  } else if (intent.timing.start_after_s) {
    draft.start_s = std::min(*intent.timing.start_after_s, std::max(0.0, request.duration_s - 1.0));
  }
  if (intent.timing.duration_s) draft.activity_s = intent.timing.duration_s;
  if (intent.categories.empty())
    draft.note("no category phrase of the lexicon matched the prompt; planned as normal operation");

  std::vector<std::string> categories;
  for (std::size_t i = 0; i < activities.size(); ++i) {
    const Activity& a = activities[i];
    if (auto ok = catalogue->retrieve(knowledge, a.category); !ok) return tl::unexpected(ok.error());
    Rng activity_rng = rng.fork("activity:" + std::to_string(i) + ":" + std::string(to_string(a.category)));
    if (auto ok = run_planner(draft, a, activity_rng); !ok) return tl::unexpected(ok.error());
    const std::string name(to_string(a.category));
    if (std::find(categories.begin(), categories.end(), name) == categories.end()) categories.push_back(name);
  }
  if (emergency_words && !emergency_activity) {
    if (auto ok = catalogue->retrieve(knowledge, Category::kEmergency); !ok)
      return tl::unexpected(ok.error());
    categories.push_back(std::string(to_string(Category::kEmergency)));
  }
  const std::size_t bound = std::min(limits.max_agents, request.agents.value_or(limits.max_agents));
  draft.fit(bound);

  Json program = draft.program(prompt.substr(0, 256));
  auto checked = checked_program(program, world, limits);
  if (!checked) {
    Error e = checked.error();
    e.code = ErrorCode::kInternal;
    e.detail = "the offline generator wrote a program the world rejects: " + e.detail;
    return tl::unexpected(std::move(e));
  }

  Json activity_log = Json::array();
  for (const Activity& a : activities) {
    Json roles = Json::array();
    for (const RoleMention& r : a.roles) roles.push_back(r.phrase);
    activity_log.push_back(Json{{"category", std::string(to_string(a.category))},
                                {"score", a.score},
                                {"clauses", a.clauses},
                                {"roles", roles}});
  }
  Json provenance = draft.provenance();
  provenance["generator"] = "offline";
  provenance["seed"] = request.seed;
  provenance["domain"] = probe.domain();
  provenance["categories"] = categories;
  provenance["intent"] = to_json(intent);
  provenance["scenario_intent"] = to_json(*named);
  provenance["added_groups"] = added_groups(program, *named, categories, probe.domain());
  provenance["activities"] = activity_log;
  provenance["place_mentions"] = place_log;
  provenance["knowledge"] = catalogue->provenance();
  Json timing_log = Json::object();
  if (draft.alarm_s) timing_log["alarm_s"] = *draft.alarm_s;
  if (draft.start_s) timing_log["start_s"] = *draft.start_s;
  if (draft.activity_s) timing_log["activity_s"] = *draft.activity_s;
  timing_log["duration_s"] = request.duration_s;
  provenance["timing"] = timing_log;
  provenance["agent_bound"] = bound;
  return GeneratedProgram{std::move(program), std::move(*checked), std::move(provenance),
                          std::move(categories)};
}

}  // namespace socsim::scenario
