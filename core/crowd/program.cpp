#include "core/crowd/program.hpp"

#include <cmath>

#include "core/common/json_check.hpp"

namespace socsim::crowd {

namespace {

constexpr double kCoord = 1.0e6;
constexpr std::size_t kMaxAgents = 200'000;

class Reader {
 public:
  JsonChecker c;

  std::optional<Vec2> point(const Json& v, const std::string& ptr) {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
      c.add(ptr, "must be [x, y] in metres");
      return std::nullopt;
    }
    const Vec2 p{v[0].get<double>(), v[1].get<double>()};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > kCoord || std::abs(p.y) > kCoord) {
      c.add(ptr, "coordinates must be finite and within ±1e6 m");
      return std::nullopt;
    }
    return p;
  }

  // "on_arrival": "exit" (true) or "stand" (false); nullopt when absent or wrong.
  std::optional<bool> on_arrival(const Json& a, const std::string& ptr) {
    const auto arrival = c.string(a, ptr, "on_arrival", false, 1, 16);
    if (!arrival) return std::nullopt;
    if (*arrival == "exit") return true;
    if (*arrival == "stand") return false;
    c.add(ptr + "/on_arrival", "must be 'exit' or 'stand'");
    return std::nullopt;
  }

  std::optional<ProgramPoint> target(const Json& v, const std::string& ptr) {
    if (v.is_string()) {
      if (v.get_ref<const std::string&>().empty()) {
        c.add(ptr, "place name must not be empty");
        return std::nullopt;
      }
      return ProgramPoint{v.get<std::string>(), std::nullopt, ptr};
    }
    if (v.is_array()) {
      auto p = point(v, ptr);
      if (!p) return std::nullopt;
      return ProgramPoint{*p, std::nullopt, ptr};
    }
    if (v.is_object()) {
      c.only_keys(v, ptr, {"position", "place", "radius"});
      ProgramPoint out{std::string(), c.number(v, ptr, "radius", false, 0.0, 1000.0), ptr};
      const bool has_pos = v.contains("position");
      const bool has_place = v.contains("place");
      if (has_pos == has_place) {
        c.add(ptr, "needs exactly one of 'position' and 'place'");
        return std::nullopt;
      }
      if (has_pos) {
        auto p = point(v["position"], JsonChecker::child(ptr, "position"));
        if (!p) return std::nullopt;
        out.where = *p;
      } else {
        auto s = c.string(v, ptr, "place", true, 1, 128);
        if (!s) return std::nullopt;
        out.where = *s;
      }
      return out;
    }
    c.add(ptr, "must be [x, y], a place name or {position|place, radius}");
    return std::nullopt;
  }

  std::optional<ProgramRegion> region(const Json& v, const std::string& ptr) {
    if (v.is_string() && !v.get_ref<const std::string&>().empty())
      return ProgramRegion{v.get<std::string>(), ptr};
    if (v.is_array() && v.size() >= 3) {
      std::vector<Vec2> ring;
      for (std::size_t k = 0; k < v.size(); ++k) {
        auto p = point(v[k], JsonChecker::child(ptr, k));
        if (!p) return std::nullopt;
        ring.push_back(*p);
      }
      return ProgramRegion{ring, ptr};
    }
    c.add(ptr, "must be a place name (ROI or zone) or a polygon of at least 3 [x, y] points");
    return std::nullopt;
  }

  std::vector<ProgramRegion> regions(const Json& obj, const std::string& ptr, const char* key,
                                     bool required) {
    std::vector<ProgramRegion> out;
    const Json* a = c.array(obj, ptr, key, required, 1000);
    if (a == nullptr) return out;
    if (required && a->empty()) c.add(JsonChecker::child(ptr, key), "needs at least one region");
    for (std::size_t k = 0; k < a->size(); ++k)
      if (auto r = region((*a)[k], JsonChecker::child(JsonChecker::child(ptr, key), k))) out.push_back(*r);
    return out;
  }

  std::vector<ProgramPoint> goals(const Json& obj, const std::string& ptr) {
    std::vector<ProgramPoint> out;
    const Json* a = c.array(obj, ptr, "goals", false, 10'000);
    if (a == nullptr) return out;
    for (std::size_t k = 0; k < a->size(); ++k)
      if (auto t = target((*a)[k], JsonChecker::child(JsonChecker::child(ptr, "goals"), k)))
        out.push_back(*t);
    return out;
  }

  std::optional<ProgramTree> tree(const Json& v, const std::string& ptr, bool allow_ref) {
    if (v.is_string()) {
      if (!allow_ref || v.get_ref<const std::string&>().empty()) {
        c.add(ptr, allow_ref ? "must name an entry of behavior_trees" : "must be an object {xml|file, tree}");
        return std::nullopt;
      }
      return ProgramTree{{}, {}, v.get<std::string>(), {}, ptr};
    }
    if (!v.is_object()) {
      c.add(ptr, "must be a behavior_trees name or {xml|file, tree}");
      return std::nullopt;
    }
    c.only_keys(v, ptr, {"xml", "file", "tree"});
    ProgramTree t;
    t.pointer = ptr;
    t.xml = c.string(v, ptr, "xml", false, 1, 1u << 20).value_or("");
    t.file = c.string(v, ptr, "file", false, 1, 4096).value_or("");
    t.tree = c.string(v, ptr, "tree", false, 1, 256).value_or("");
    if (t.xml.empty() == t.file.empty()) {
      c.add(ptr, "needs exactly one of 'xml' and 'file'");
      return std::nullopt;
    }
    return t;
  }

  std::optional<ProgramField> field(const Json& v, const std::string& ptr) {
    if (!v.is_object()) {
      c.add(ptr, "must be an object {values}");
      return std::nullopt;
    }
    c.only_keys(v, ptr, {"values"});
    const Json* values = c.array(v, ptr, "values", true, 4096);
    if (values == nullptr) return std::nullopt;
    const std::string vp = JsonChecker::child(ptr, "values");
    ProgramField f;
    f.width = static_cast<int>(values->size());
    if (f.width == 0 || !(*values)[0].is_array() || (*values)[0].empty()) {
      c.add(vp, "must be a non-empty array of columns, each an array of [vx, vy]");
      return std::nullopt;
    }
    f.height = static_cast<int>((*values)[0].size());
    if (f.height > 4096) {
      c.add(vp, "at most 4096 rows");
      return std::nullopt;
    }
    f.values.reserve(static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height));
    for (std::size_t i = 0; i < values->size(); ++i) {
      const Json& col = (*values)[i];
      const std::string cp = JsonChecker::child(vp, i);
      if (!col.is_array() || col.size() != static_cast<std::size_t>(f.height)) {
        c.add(cp, "every column must hold " + std::to_string(f.height) + " vectors");
        return std::nullopt;
      }
      for (std::size_t j = 0; j < col.size(); ++j) {
        const Json& e = col[j];
        if (!e.is_array() || e.size() != 2 || !e[0].is_number() || !e[1].is_number()) {
          c.add(JsonChecker::child(cp, j), "must be [vx, vy]");
          return std::nullopt;
        }
        const double vx = e[0].get<double>();
        const double vy = e[1].get<double>();
        if (!std::isfinite(vx) || !std::isfinite(vy) || std::abs(vx) > 8.0 || std::abs(vy) > 8.0) {
          c.add(JsonChecker::child(cp, j), "components must be finite and within ±8 m/s");
          return std::nullopt;
        }
        f.values.push_back({vx, vy});
      }
    }
    return f;
  }
};

}  // namespace

Result<Program> program_from_json(const Json& j) {
  Reader r;
  JsonChecker& c = r.c;
  if (!j.is_object())
    return fail(ErrorCode::kValidation, "invalid program", {FieldError{"", "must be an object"}});
  c.only_keys(j, "",
              {"$schema", "version", "name", "dt", "decision_period", "roles", "behavior_trees", "agents",
               "groups", "ambient_groups", "robot", "body_stiffness"});
  Program p;
  if (auto v = c.integer(j, "", "version", false, 1, 1)) (void)v;
  p.name = c.string(j, "", "name", false, 0, 256).value_or("");
  p.dt = c.number(j, "", "dt", false, 0.001, 0.2).value_or(0.05);
  p.decision_period = c.number(j, "", "decision_period", false, 0.001, 10.0).value_or(p.dt * 2.0);
  if (j.contains("decision_period") || j.contains("dt")) {
    const double k = p.decision_period / p.dt;
    if (std::abs(k - std::round(k)) > 1e-6 || std::round(k) < 1.0)
      c.add("/decision_period", "must be a positive multiple of dt (" + std::to_string(p.dt) + " s)");
  }
  if (const Json* roles = c.object(j, "", "roles", false)) p.roles = *roles;
  if (j.contains("body_stiffness")) {
    if (auto k = c.number(j, "", "body_stiffness", false, 0.0, 5000.0)) p.body_stiffness = *k;
  }

  if (const Json* trees = c.object(j, "", "behavior_trees", false)) {
    for (const auto& [name, v] : trees->items()) {
      if (auto t = r.tree(v, JsonChecker::child("/behavior_trees", name), false))
        p.behavior_trees.emplace_back(name, *t);
    }
  }

  std::size_t total = 0;
  if (const Json* agents = c.array(j, "", "agents", false, 100'000)) {
    for (std::size_t k = 0; k < agents->size(); ++k) {
      const Json& a = (*agents)[k];
      const std::string ptr = "/agents/" + std::to_string(k);
      if (!a.is_object()) {
        c.add(ptr, "must be an object");
        continue;
      }
      c.only_keys(a, ptr,
                  {"name", "role", "position", "spawn", "count", "yaw", "speed", "radius", "group_id",
                   "goals", "cyclic_goals", "goal_radius", "on_arrival", "behavior", "tags"});
      ProgramAgent agent;
      agent.pointer = ptr;
      agent.name = c.string(a, ptr, "name", false, 0, 128).value_or("");
      agent.role = c.string(a, ptr, "role", false, 1, 64).value_or("adult");
      if (a.contains("position")) agent.position = r.point(a["position"], ptr + "/position");
      if (a.contains("spawn")) agent.spawn = r.region(a["spawn"], ptr + "/spawn");
      if (a.contains("position") == a.contains("spawn"))
        c.add(ptr, "needs exactly one of 'position' and 'spawn'");
      agent.count = static_cast<std::size_t>(c.integer(a, ptr, "count", false, 1, 100'000).value_or(1));
      if (agent.count > 1 && a.contains("position"))
        c.add(ptr + "/count", "several agents need a 'spawn' region");
      agent.yaw = c.number(a, ptr, "yaw", false, -1e3, 1e3);
      agent.speed = c.number(a, ptr, "speed", false, 0.0, 8.0);
      agent.radius = c.number(a, ptr, "radius", false, 0.05, 1.5);
      agent.group_id = c.integer(a, ptr, "group_id", false, -1, INT64_MAX / 2).value_or(-1);
      agent.goals = r.goals(a, ptr);
      agent.cyclic_goals = c.boolean(a, ptr, "cyclic_goals", false).value_or(true);
      agent.goal_radius = c.number(a, ptr, "goal_radius", false, 0.01, 100.0).value_or(0.3);
      agent.exit_at_goal = r.on_arrival(a, ptr);
      if (a.contains("behavior")) agent.behavior = r.tree(a["behavior"], ptr + "/behavior", true);
      if (const Json* tags = c.array(a, ptr, "tags", false, 64)) {
        for (std::size_t t = 0; t < tags->size(); ++t) {
          if ((*tags)[t].is_string())
            agent.tags.push_back((*tags)[t].get<std::string>());
          else
            c.add(ptr + "/tags/" + std::to_string(t), "must be a string");
        }
      }
      total += agent.count;
      p.agents.push_back(std::move(agent));
    }
  }

  if (const Json* groups = c.array(j, "", "groups", false, 10'000)) {
    for (std::size_t k = 0; k < groups->size(); ++k) {
      const Json& g = (*groups)[k];
      const std::string ptr = "/groups/" + std::to_string(k);
      if (!g.is_object()) {
        c.add(ptr, "must be an object {id, agents}");
        continue;
      }
      c.only_keys(g, ptr, {"id", "agents"});
      ProgramGroup group;
      group.pointer = ptr;
      group.id = c.integer(g, ptr, "id", true, 0, INT64_MAX / 2).value_or(0);
      if (const Json* members = c.array(g, ptr, "agents", true, 10'000)) {
        for (std::size_t m = 0; m < members->size(); ++m) {
          const Json& v = (*members)[m];
          if (!v.is_number_unsigned() || v.get<std::uint64_t>() >= total)
            c.add(ptr + "/agents/" + std::to_string(m),
                  "must be the index of an agent (0.." + std::to_string(total == 0 ? 0 : total - 1) + ")");
          else
            group.agents.push_back(v.get<std::size_t>());
        }
      }
      p.groups.push_back(std::move(group));
    }
  }

  if (const Json* ambient = c.array(j, "", "ambient_groups", false, 1000)) {
    for (std::size_t k = 0; k < ambient->size(); ++k) {
      const Json& a = (*ambient)[k];
      const std::string ptr = "/ambient_groups/" + std::to_string(k);
      if (!a.is_object()) {
        c.add(ptr, "must be an object");
        continue;
      }
      c.only_keys(a, ptr,
                  {"name", "description", "start", "goal", "size", "speed", "role", "resolution", "variation",
                   "tolerance", "on_arrival", "field", "behavior"});
      AmbientGroup g;
      g.pointer = ptr;
      g.name = c.string(a, ptr, "name", true, 1, 128).value_or("");
      g.description = c.string(a, ptr, "description", false, 0, 500).value_or("");
      for (const AmbientGroup& other : p.ambient_groups)
        if (!g.name.empty() && other.name == g.name)
          c.add(ptr + "/name", "duplicate ambient group name '" + g.name + "'");
      g.start = r.regions(a, ptr, "start", true);
      g.goal = r.regions(a, ptr, "goal", true);
      g.size = static_cast<std::size_t>(c.integer(a, ptr, "size", true, 0, 100'000).value_or(0));
      g.speed = c.number(a, ptr, "speed", false, 0.1, 8.0).value_or(1.34);
      g.role = c.string(a, ptr, "role", false, 1, 64).value_or("adult");
      g.resolution = static_cast<int>(c.integer(a, ptr, "resolution", false, 8, 1024).value_or(64));
      g.variation = c.number(a, ptr, "variation", false, 0.0, 1.5707963267948966).value_or(0.0);
      g.tolerance = c.number(a, ptr, "tolerance", false, 0.01, 10.0).value_or(0.5);
      g.exit_at_goal = r.on_arrival(a, ptr).value_or(true);
      if (a.contains("field")) g.field = r.field(a["field"], ptr + "/field");
      if (a.contains("behavior")) g.behavior = r.tree(a["behavior"], ptr + "/behavior", true);
      total += g.size;
      p.ambient_groups.push_back(std::move(g));
    }
  }

  if (const Json* robot = c.object(j, "", "robot", false)) {
    const std::string ptr = "/robot";
    c.only_keys(*robot, ptr, {"position", "yaw", "speed", "radius", "goals", "cyclic_goals", "goal_radius"});
    ProgramRobot rb;
    if (!robot->contains("position"))
      c.add(ptr + "/position", "is required");
    else if (auto pos = r.point((*robot)["position"], ptr + "/position"))
      rb.position = *pos;
    rb.yaw = c.number(*robot, ptr, "yaw", false, -1e3, 1e3);
    rb.speed = c.number(*robot, ptr, "speed", false, 0.0, 8.0).value_or(0.8);
    rb.radius = c.number(*robot, ptr, "radius", false, 0.05, 1.5).value_or(0.35);
    rb.goals = r.goals(*robot, ptr);
    rb.cyclic_goals = c.boolean(*robot, ptr, "cyclic_goals", false).value_or(false);
    rb.goal_radius = c.number(*robot, ptr, "goal_radius", false, 0.01, 100.0).value_or(0.3);
    p.robot = std::move(rb);
  }
  if (total > kMaxAgents) c.add("/agents", "at most " + std::to_string(kMaxAgents) + " agents in all");
  if (!c.ok()) return tl::unexpected(c.error("invalid scenario program"));
  return p;
}

Result<Program> program_from_text(std::string_view text) {
  auto j = parse_json_untrusted(text);
  if (!j) return tl::unexpected(j.error());
  return program_from_json(*j);
}

}  // namespace socsim::crowd
