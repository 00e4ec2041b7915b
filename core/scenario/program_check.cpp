#include "core/scenario/program_check.hpp"

#include <cmath>
#include <map>

#include "core/crowd/bt_nodes.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/geometry/planar.hpp"

namespace socsim::scenario {

namespace {

// People a region can hold at most (1.5 per m² of floor 0.3 m in from its edges, about the densest
// random packing of 0.3 m bodies): more is impossible, whatever the seed.
std::size_t most_people(const geometry::Polygon& region) {
  const double area = std::abs(geometry::area(region));
  double perimeter = 0.0;
  for (const world::Segment& e : geometry::edges(region.outer)) perimeter += geometry::length(e);
  return static_cast<std::size_t>(std::floor(1.5 * std::max(0.0, area - perimeter * 0.3)));
}

std::string names(const std::vector<std::string>& list) {
  std::string out;
  for (std::size_t i = 0; i < list.size() && i < 12; ++i) out += (i == 0 ? "" : ", ") + list[i];
  if (list.size() > 12) out += ", …";
  return out.empty() ? "none" : out;
}

class Checker {
 public:
  Checker(const world::World& world, const ScenarioLimits& limits) : world_(world), limits_(limits) {}

  void add(std::string pointer, std::string message) {
    errors_.push_back(FieldError{std::move(pointer), std::move(message)});
  }
  void add(const Error& e, const std::string& prefix) {
    if (e.errors.empty()) {
      add(prefix, e.detail);
      return;
    }
    for (FieldError f : e.errors) {
      f.pointer = prefix + f.pointer;
      errors_.push_back(std::move(f));
    }
  }
  [[nodiscard]] bool ok() const { return errors_.empty(); }
  [[nodiscard]] Error failure() const {
    std::string detail = errors_.front().pointer + ": " + errors_.front().message;
    if (errors_.size() > 1) detail += " (and " + std::to_string(errors_.size() - 1) + " more)";
    return Error(ErrorCode::kValidation, detail, errors_);
  }

  void counts(const crowd::Program& p) {
    std::size_t spotlight = 0, ambient = 0;
    for (const crowd::ProgramAgent& a : p.agents) {
      if (a.count > limits_.max_agents)
        add(a.pointer + "/count", "count " + std::to_string(a.count) + " exceeds the limit of " +
                                      std::to_string(limits_.max_agents) + " agents");
      spotlight += a.count;
    }
    for (const crowd::AmbientGroup& g : p.ambient_groups) {
      if (g.size > limits_.max_agents)
        add(g.pointer + "/size", "size " + std::to_string(g.size) + " exceeds the limit of " +
                                     std::to_string(limits_.max_agents) + " agents");
      ambient += g.size;
    }
    if (spotlight > limits_.max_spotlight)
      add("/agents", std::to_string(spotlight) +
                         " spotlight agents (each runs its own behaviour tree); the limit is " +
                         std::to_string(limits_.max_spotlight) + " — put crowds in ambient_groups");
    if (spotlight + ambient > limits_.max_agents)
      add("", std::to_string(spotlight + ambient) + " agents in all (" + std::to_string(spotlight) +
                  " spotlight, " + std::to_string(ambient) + " ambient); the limit is " +
                  std::to_string(limits_.max_agents));
  }

  // Region of a program entry; null (with an error) when it names no ROI or zone.
  std::optional<geometry::Polygon> region(const crowd::ProgramRegion& r, const crowd::BtEnvironment& env) {
    if (const auto* ring = std::get_if<std::vector<crowd::Vec2>>(&r.where)) {
      geometry::Polygon poly;
      for (const crowd::Vec2& v : *ring) poly.outer.push_back({v.x, v.y});
      if (std::abs(geometry::area(poly)) < 1e-6) {
        add(r.pointer, "polygon has no area");
        return std::nullopt;
      }
      return poly;
    }
    const std::string& name = std::get<std::string>(r.where);
    if (auto problem = env.check_place(name, "region")) {
      add(r.pointer, *problem);
      return std::nullopt;
    }
    return *env.place(name)->region;
  }

  void point(const crowd::ProgramPoint& p, const crowd::BtEnvironment& env) {
    if (const auto* name = std::get_if<std::string>(&p.where))
      if (auto problem = env.check_place(*name, "place")) add(p.pointer, *problem);
  }

  void places(const crowd::Program& p, const crowd::BtEnvironment& env, const crowd::RoleTable& roles) {
    for (const crowd::ProgramAgent& a : p.agents) {
      if (!roles.index_of(a.role))
        add(a.pointer + "/role", "unknown role '" + a.role + "' (roles: " + names(roles.names()) +
                                     "; define others under /roles)");
      if (a.spawn) {
        if (auto poly = region(*a.spawn, env)) {
          const std::size_t most = most_people(*poly);
          const std::string where = std::holds_alternative<std::string>(a.spawn->where)
                                        ? "'" + std::get<std::string>(a.spawn->where) + "'"
                                        : std::string("the spawn polygon");
          if (a.count > most)
            add(a.pointer + "/count",
                std::to_string(a.count) + " agents do not fit in " + where + " (" +
                    std::to_string(static_cast<long>(std::lround(std::abs(geometry::area(*poly))))) +
                    " m², room for at most " + std::to_string(most) + ")");
        }
      } else if (a.position && world_.zone_at({a.position->x, a.position->y}) == std::nullopt) {
        add(a.pointer + "/position", "[" + std::to_string(a.position->x) + ", " +
                                         std::to_string(a.position->y) +
                                         "] is outside every zone of the world");
      }
      for (const crowd::ProgramPoint& g : a.goals) point(g, env);
    }
    for (const crowd::AmbientGroup& g : p.ambient_groups) {
      if (!roles.index_of(g.role))
        add(g.pointer + "/role", "unknown role '" + g.role + "' (roles: " + names(roles.names()) +
                                     "; define others under /roles)");
      std::size_t most = 0;
      bool all = true;
      for (const crowd::ProgramRegion& r : g.start) {
        if (auto poly = region(r, env))
          most += most_people(*poly);
        else
          all = false;
      }
      for (const crowd::ProgramRegion& r : g.goal) (void)region(r, env);
      if (all && g.size > most)
        add(g.pointer + "/size", std::to_string(g.size) +
                                     " agents do not fit in the start regions (room for at most " +
                                     std::to_string(most) + ")");
    }
    if (p.robot) {
      if (!world_.zone_at({p.robot->position.x, p.robot->position.y}))
        add("/robot/position", "the robot's position is outside every zone of the world");
      for (const crowd::ProgramPoint& g : p.robot->goals) point(g, env);
    }
  }

  void trees(const crowd::Program& p, crowd::BtEnvironment& env) {
    const crowd::BtRegistry registry = crowd::behavior_registry(env);
    const crowd::BtLoadOptions load = crowd::behavior_load_options(env);
    std::vector<std::string> entries;
    for (const auto& [name, t] : p.behavior_trees) entries.push_back(name);
    auto check = [&](const crowd::ProgramTree& t) {
      if (!t.ref.empty()) {
        if (std::find(entries.begin(), entries.end(), t.ref) == entries.end())
          add(t.pointer, "no behavior_trees entry named '" + t.ref + "' (entries: " + names(entries) + ")");
        return;
      }
      if (!t.file.empty()) {
        add(t.pointer + "/file",
            "tree files cannot be checked against the world here; give the XML inline ('xml')");
        return;
      }
      auto doc = crowd::BtDocument::parse(t.xml, registry, load);
      if (!doc) {
        add(doc.error(), t.pointer + "/xml");
        return;
      }
      if (!t.tree.empty() && doc->tree(t.tree) == nullptr)
        add(t.pointer + "/tree",
            "no BehaviorTree with ID '" + t.tree + "' in the document (IDs: " + names(doc->tree_ids()) + ")");
    };
    for (const auto& [name, t] : p.behavior_trees) check(t);
    for (const crowd::ProgramAgent& a : p.agents)
      if (a.behavior) check(*a.behavior);
    for (const crowd::AmbientGroup& g : p.ambient_groups)
      if (g.behavior) check(*g.behavior);
  }

 private:
  const world::World& world_;
  const ScenarioLimits& limits_;
  std::vector<FieldError> errors_;
};

}  // namespace

Status check_program(const Json& program, const world::World& world, const ScenarioLimits& limits) {
  auto checked = checked_program(program, world, limits);
  if (!checked) return tl::unexpected(checked.error());
  return {};
}

Result<crowd::Program> checked_program(const Json& program, const world::World& world,
                                       const ScenarioLimits& limits) {
  auto parsed = crowd::program_from_json(program);
  if (!parsed) return tl::unexpected(parsed.error());
  const crowd::Program& p = *parsed;
  Checker c(world, limits);
  c.counts(p);

  crowd::RoleTable roles = crowd::RoleTable::defaults();
  if (auto ok = roles.apply_json(p.roles, "/roles"); !ok) c.add(ok.error(), "");
  auto sim = crowd::CrowdSimulation::create(crowd::SimulationConfig{}, roles);
  if (!sim) {
    c.add(sim.error(), "/roles");
    return tl::unexpected(c.failure());
  }
  crowd::BtEnvironment env(*sim, &world);
  c.places(p, env, roles);
  // Field names the trees may use: one per ambient group (the real fields are built by the run).
  for (const crowd::AmbientGroup& g : p.ambient_groups) {
    auto field = crowd::VelocityField::from_values(world.bounds(), 1, 1, {crowd::Vec2{}});
    if (field) env.add_velocity_field(g.name, std::move(*field), {});
  }
  c.trees(p, env);
  if (!c.ok()) return tl::unexpected(c.failure());

  // Everything named exists: a dry run catches the rest (unreachable goals of velocity fields,
  // spawn regions without a free spot, group conflicts).
  crowd::RunnerOptions options;
  options.record_metrics = false;
  auto runner = crowd::ScenarioRunner::create(&world, p, options);
  if (!runner) return tl::unexpected(runner.error());
  return parsed;
}

}  // namespace socsim::scenario
