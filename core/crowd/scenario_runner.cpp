#include "core/crowd/scenario_runner.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <unordered_map>

#include "core/common/rng.hpp"
#include "core/crowd/bt_nodes.hpp"
#include "core/geometry/planar.hpp"

namespace socsim::crowd {

namespace {

// The default behaviour of an agent without a tree: HuNavSim's regular navigation over its goals.
constexpr const char* kRegularNavigation = R"(<root BTCPP_format="4" main_tree_to_execute="RegularNavigation">
  <BehaviorTree ID="RegularNavigation">
    <Fallback>
      <Sequence>
        <Inverter><IsGoalReached agent_id="{id}"/></Inverter>
        <RegularNav agent_id="{id}" time_step="{dt}"/>
      </Sequence>
      <UpdateGoal agent_id="{id}"/>
    </Fallback>
  </BehaviorTree>
</root>)";

std::string shortest_decimal(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// An ambient agent's tree: follow its group's velocity field. Built as elements from the typed
// group (the tolerance in its shortest exact decimal form), never written out as text.
world::XmlElement ambient_tree(const std::string& field, double tolerance) {
  world::XmlElement follow;
  follow.name = "FollowVelocityField";
  follow.attributes = {{"agent_id", "{id}"},
                       {"time_step", "{dt}"},
                       {"field", field},
                       {"tolerance", shortest_decimal(tolerance)}};
  world::XmlElement tree;
  tree.name = "BehaviorTree";
  tree.attributes = {{"ID", "Ambient"}};
  tree.children.push_back(std::move(follow));
  world::XmlElement root;
  root.name = "root";
  root.attributes = {{"BTCPP_format", "4"}, {"main_tree_to_execute", "Ambient"}};
  root.children.push_back(std::move(tree));
  return root;
}

// Prefixes every field error of `e` with the program pointer (keeps XML lines and columns).
Error at_pointer(Error e, const std::string& pointer) {
  e.within(pointer);
  e.detail = pointer + ": " + e.detail;
  return e;
}

class Builder {
 public:
  Builder(const world::World* world, const Program& program, const RunnerOptions& options)
      : world_(world), program_(program), options_(options), spawn_rng_(options.seed ^ fnv1a64("spawn")) {}

  void error(const std::string& pointer, const std::string& message) {
    errors_.push_back(FieldError{pointer, message});
  }
  void error(const Error& e, const std::string& pointer) {
    for (const FieldError& f : at_pointer(e, pointer).errors) errors_.push_back(f);
  }
  [[nodiscard]] bool ok() const { return errors_.empty(); }
  [[nodiscard]] Error failure() const {
    std::string detail = "invalid scenario program";
    if (!errors_.empty()) {
      detail = errors_.front().pointer + ": " + errors_.front().message;
      if (errors_.front().line > 0) detail += " (line " + std::to_string(errors_.front().line) + ")";
      if (errors_.size() > 1) detail += " (and " + std::to_string(errors_.size() - 1) + " more)";
    }
    return Error(ErrorCode::kValidation, detail, errors_);
  }

  std::optional<Vec2> point(const ProgramPoint& p, const BtEnvironment& env) {
    if (const auto* v = std::get_if<Vec2>(&p.where)) return *v;
    const std::string& name = std::get<std::string>(p.where);
    if (auto problem = env.check_place(name, "place")) {
      error(p.pointer, *problem);
      return std::nullopt;
    }
    return env.place(name)->point;
  }

  std::optional<geometry::Polygon> region(const ProgramRegion& r, const BtEnvironment& env) {
    if (const auto* ring = std::get_if<std::vector<Vec2>>(&r.where)) {
      geometry::Polygon poly;
      for (const Vec2& v : *ring) poly.outer.push_back({v.x, v.y});
      if (std::abs(geometry::area(poly)) < 1e-6) {
        error(r.pointer, "polygon has no area");
        return std::nullopt;
      }
      return poly;
    }
    const std::string& name = std::get<std::string>(r.where);
    if (auto problem = env.check_place(name, "region")) {
      error(r.pointer, *problem);
      return std::nullopt;
    }
    return *env.place(name)->region;
  }

  // A random free spot in one of the regions: inside, in a zone, `radius` from walls and from
  // agents already placed. Nullopt after many failed draws.
  std::optional<Vec2> spawn(const std::vector<geometry::Polygon>& regions, double radius,
                            const CrowdSimulation& sim) {
    std::vector<double> areas;
    for (const geometry::Polygon& p : regions) areas.push_back(std::abs(geometry::area(p)));
    for (int attempt = 0; attempt < 400; ++attempt) {
      const geometry::Polygon& poly = regions[spawn_rng_.weighted(areas)];
      const geometry::Box box = geometry::bounds(poly.outer);
      const Vec2 p{spawn_rng_.uniform(box.min.x, box.max.x), spawn_rng_.uniform(box.min.y, box.max.y)};
      if (!geometry::contains(poly, {p.x, p.y})) continue;
      if (world_ != nullptr && !world_->zone_at({p.x, p.y})) continue;
      bool free = true;
      for (const WallSegment& w : sim.walls()) {
        if (point_segment_distance(p, w.a, w.b) < radius + 0.05) {
          free = false;
          break;
        }
      }
      if (!free || occupied(p, radius)) continue;
      place(p, radius);
      return p;
    }
    return std::nullopt;
  }
  void place(Vec2 p, double radius) { placed_[cell_key(p)].push_back({p, radius}); }

  const world::World* world_;
  const Program& program_;
  const RunnerOptions& options_;
  Rng spawn_rng_;
  std::vector<FieldError> errors_;

 private:
  static std::uint64_t cell_key(Vec2 p) {
    return (static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(p.x))) << 32) ^
           (static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(p.y))) & 0xffffffffu);
  }
  bool occupied(Vec2 p, double radius) const {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        auto it = placed_.find(cell_key({p.x + dx, p.y + dy}));
        if (it == placed_.end()) continue;
        for (const auto& [q, r] : it->second)
          if (std::hypot(p.x - q.x, p.y - q.y) < radius + r + 0.05) return true;
      }
    }
    return false;
  }
  std::unordered_map<std::uint64_t, std::vector<std::pair<Vec2, double>>> placed_;
};

}  // namespace

ScenarioRunner::~ScenarioRunner() = default;

Result<std::unique_ptr<ScenarioRunner>> ScenarioRunner::create(const world::World* world,
                                                               const Program& program,
                                                               const RunnerOptions& options) {
  std::unique_ptr<ScenarioRunner> run(new ScenarioRunner());
  run->world_ = world;
  Builder b(world, program, options);

  // Roles, simulation, walls.
  RoleTable roles = RoleTable::defaults();
  if (auto ok = roles.apply_json(program.roles, "/roles"); !ok) return tl::unexpected(ok.error());
  const bool driven = !options.robots.empty();
  if ((program.robot || driven) && !roles.index_of("robot")) {
    RoleParameters robot = roles.at(*roles.index_of("adult"));
    robot.name = "robot";
    const double speed = program.robot ? program.robot->speed : options.robots.front().limits.max_speed;
    robot.speed = SpeedDistribution{speed, 0.0, 0.0, kMaxAgentSpeed};
    robot.radius = program.robot ? program.robot->radius : options.robots.front().radius;
    if (auto ok = roles.put(robot); !ok) return tl::unexpected(at_pointer(ok.error(), "/robot"));
  }
  SimulationConfig config;
  config.dt = program.dt;
  config.threads = std::max(1u, options.threads);
  config.seed = options.seed;
  if (program.body_stiffness.is_number()) config.body_stiffness = program.body_stiffness.get<double>();
  auto sim = CrowdSimulation::create(config, roles);
  if (!sim) return tl::unexpected(sim.error());
  run->sim_ = std::make_unique<CrowdSimulation>(std::move(*sim));
  CrowdSimulation& s = *run->sim_;
  if (world != nullptr)
    for (const world::Wall& w : world->walls())
      (void)s.add_wall({w.segment.a.x, w.segment.a.y}, {w.segment.b.x, w.segment.b.y});
  run->decision_every_ =
      static_cast<std::uint64_t>(std::max(1.0, std::round(program.decision_period / program.dt)));
  run->env_ = std::make_unique<BtEnvironment>(s, world, options.environment);
  BtEnvironment& env = *run->env_;

  // Velocity fields of the ambient groups (before trees: FollowVelocityField checks the names).
  std::vector<std::vector<geometry::Polygon>> starts(program.ambient_groups.size());
  for (std::size_t g = 0; g < program.ambient_groups.size(); ++g) {
    const AmbientGroup& group = program.ambient_groups[g];
    std::vector<geometry::Polygon> goals;
    for (const ProgramRegion& r : group.start)
      if (auto p = b.region(r, env)) starts[g].push_back(*p);
    for (const ProgramRegion& r : group.goal)
      if (auto p = b.region(r, env)) goals.push_back(*p);
    if (!b.ok()) continue;
    if (world == nullptr) {
      b.error(group.pointer, "ambient groups need a world (the field spans its bounding box)");
      continue;
    }
    Result<VelocityField> field = fail(ErrorCode::kInternal, "");
    if (group.field) {
      field = VelocityField::from_values(world->bounds(), group.field->width, group.field->height,
                                         group.field->values);
      if (!field) {
        b.error(field.error(), group.pointer + "/field");
        continue;
      }
    } else {
      // A thin inflation: the field is a coarse guide (the social force keeps agents off walls);
      // narrow passages must stay open at the field's resolution.
      const world::OccupancyGrid grid = world::OccupancyGrid::rasterise(
          *world, world::GridOptions{options.environment.navigation_resolution, 0.15,
                                     options.environment.navigation_max_cells});
      VelocityField::GeodesicSpec spec;
      spec.start = starts[g];
      spec.goal = goals;
      spec.width = spec.height = group.resolution;
      spec.speed = group.speed;
      spec.variation = group.variation;
      spec.seed = options.seed ^ fnv1a64("field:" + group.name);
      field = VelocityField::from_geodesic(grid, world->bounds(), spec);
      if (!field) {
        b.error(field.error(), group.pointer);
        continue;
      }
    }
    env.add_velocity_field(group.name, std::move(*field), std::move(goals));
  }
  if (!b.ok()) return tl::unexpected(b.failure());

  // Behaviour-tree documents: all loaded and checked before anything runs.
  run->registry_ = std::make_unique<BtRegistry>(behavior_registry(env));
  const BtLoadOptions load = behavior_load_options(env, options.base_dir);
  std::map<std::string, std::size_t> named;
  std::function<std::optional<std::pair<std::size_t, std::string>>(Result<BtDocument>, const ProgramTree&)>
      add_document;
  auto load_tree = [&](const ProgramTree& t) -> std::optional<std::pair<std::size_t, std::string>> {
    if (!t.ref.empty()) {
      auto it = named.find(t.ref);
      if (it == named.end()) {
        b.error(t.pointer, "no behavior_trees entry named '" + t.ref + "'");
        return std::nullopt;
      }
      return std::pair{it->second, std::string()};
    }
    return add_document(!t.xml.empty() ? BtDocument::parse(t.xml, *run->registry_, load)
                                       : BtDocument::load(options.base_dir / t.file, *run->registry_, load),
                        t);
  };
  add_document = [&](Result<BtDocument> doc,
                     const ProgramTree& t) -> std::optional<std::pair<std::size_t, std::string>> {
    if (!doc) {
      b.error(doc.error(), t.pointer);
      return std::nullopt;
    }
    if (!t.tree.empty() && doc->tree(t.tree) == nullptr) {
      b.error(t.pointer + "/tree", "no BehaviorTree with ID '" + t.tree + "' in the document");
      return std::nullopt;
    }
    run->documents_.push_back(std::move(*doc));
    return std::pair{run->documents_.size() - 1, t.tree};
  };
  for (const auto& [name, t] : program.behavior_trees)
    if (auto d = load_tree(t)) named[name] = d->first;
  auto regular = load_tree(ProgramTree{kRegularNavigation, {}, {}, {}, "/"});

  // Group membership by expanded agent index.
  std::map<std::size_t, std::int64_t> group_of;
  for (const ProgramGroup& g : program.groups)
    for (std::size_t k = 0; k < g.agents.size(); ++k) {
      if (group_of.count(g.agents[k]) != 0)
        b.error(g.pointer + "/agents/" + std::to_string(k),
                "agent " + std::to_string(g.agents[k]) + " is in two groups");
      group_of[g.agents[k]] = g.id;
    }

  // Spotlight agents.
  struct Pending {
    std::optional<std::pair<std::size_t, std::string>> tree;
    std::vector<Goal> goals;
    bool cyclic = true;
  };
  std::vector<Pending> pending;
  std::size_t index = 0;
  for (const ProgramAgent& a : program.agents) {
    std::vector<Goal> goals;
    for (const ProgramPoint& g : a.goals)
      if (auto p = b.point(g, env)) goals.push_back(Goal{*p, g.radius.value_or(a.goal_radius)});
    std::optional<std::pair<std::size_t, std::string>> tree = a.behavior ? load_tree(*a.behavior) : regular;
    std::vector<geometry::Polygon> spawn_regions;
    if (a.spawn)
      if (auto r = b.region(*a.spawn, env)) spawn_regions.push_back(*r);
    const auto role = roles.index_of(a.role);
    if (!role) b.error(a.pointer + "/role", "unknown role '" + a.role + "'");
    if (!b.ok()) {
      index += a.count;
      continue;
    }
    const double radius = a.radius.value_or(roles.at(*role).radius);
    // Whether the agent leaves at its last goal: as the program says, else when that goal is an
    // exit (a person walking to an exit goes out there, rather than standing in the way of
    // those behind).
    bool leaves = false;
    if (!a.cyclic_goals && !a.goals.empty()) {
      if (a.exit_at_goal) {
        leaves = *a.exit_at_goal;
      } else if (const auto* name = std::get_if<std::string>(&a.goals.back().where)) {
        const auto place = env.place(*name);
        leaves = place && place->type == "exit";
      }
    }
    for (std::size_t k = 0; k < a.count; ++k, ++index) {
      AgentSpec spec;
      spec.role = a.role;
      spec.desired_speed = a.speed;
      spec.radius = a.radius;
      spec.yaw = a.yaw;
      spec.tags = a.tags;
      spec.group_id = a.group_id;
      if (auto g = group_of.find(index); g != group_of.end()) {
        if (a.group_id >= 0 && a.group_id != g->second)
          b.error(a.pointer + "/group_id", "conflicts with the group listed in /groups");
        spec.group_id = g->second;
      }
      if (a.position) {
        spec.position = *a.position;
        b.place(*a.position, radius);
      } else if (auto p = b.spawn(spawn_regions, radius, s)) {
        spec.position = *p;
      } else {
        b.error(a.pointer + "/spawn", "no free spot for agent " + std::to_string(k + 1) + " of " +
                                          std::to_string(a.count) + " (region too small or blocked)");
        break;
      }
      if (!goals.empty()) spec.intent.goal_id = 0;
      auto id = s.add_agent(spec);
      if (!id) {
        b.error(id.error(), a.pointer);
        break;
      }
      run->agents_.push_back(RunnerAgent{*id, AgentKind::kSpotlight,
                                         a.count > 1 ? a.name + "#" + std::to_string(k) : a.name, a.pointer});
      pending.push_back(Pending{tree, goals, a.cyclic_goals});
      run->leaving_.push_back(leaves ? Leaving::kAtLastGoal : Leaving::kNever);
    }
  }
  if (!b.ok()) return tl::unexpected(b.failure());

  // Ambient agents.
  Rng speeds(options.seed ^ fnv1a64("ambient speeds"));
  for (std::size_t g = 0; g < program.ambient_groups.size(); ++g) {
    const AmbientGroup& group = program.ambient_groups[g];
    const auto role = roles.index_of(group.role);
    if (!role) {
      b.error(group.pointer + "/role", "unknown role '" + group.role + "'");
      continue;
    }
    const RoleParameters& rp = roles.at(*role);
    std::optional<std::pair<std::size_t, std::string>> tree =
        group.behavior ? load_tree(*group.behavior)
                       : add_document(BtDocument::from_element(ambient_tree(group.name, group.tolerance),
                                                               *run->registry_, load),
                                      ProgramTree{{}, {}, {}, {}, group.pointer});
    if (!b.ok()) continue;
    for (std::size_t k = 0; k < group.size; ++k) {
      const auto p = b.spawn(starts[g], rp.radius, s);
      if (!p) {
        b.error(group.pointer + "/start", "no free spot for agent " + std::to_string(k + 1) + " of " +
                                              std::to_string(group.size) + " in the start regions");
        break;
      }
      AgentSpec spec;
      spec.position = *p;
      spec.role = group.role;
      spec.desired_speed =
          std::clamp(speeds.normal(group.speed, rp.speed.sd), std::min(rp.speed.min, group.speed),
                     std::max(rp.speed.max, group.speed));
      auto id = s.add_agent(spec);
      if (!id) {
        b.error(id.error(), group.pointer);
        break;
      }
      run->agents_.push_back(
          RunnerAgent{*id, AgentKind::kAmbient, group.name + "#" + std::to_string(k), group.pointer});
      pending.push_back(Pending{tree, {}, false});
      run->leaving_.push_back(group.exit_at_goal ? Leaving::kWhenTreeSucceeds : Leaving::kNever);
    }
  }

  // Robot: the program's scripted one, or the driven ones of the options.
  std::optional<AgentId> robot;
  for (std::size_t k = 0; k < options.robots.size(); ++k) {
    const RobotSpec& r = options.robots[k];
    const std::string pointer = "/robots/" + std::to_string(k);
    AgentSpec spec;
    spec.position = {r.start.x, r.start.y};
    spec.yaw = r.start.yaw;
    spec.role = "robot";
    spec.desired_speed = 0.0;
    spec.radius = r.radius;
    auto id = s.add_agent(spec);
    if (!id) {
      b.error(id.error(), pointer);
      continue;
    }
    (void)s.set_driven(*id, r.presence);
    if (!robot && r.presence == Presence::kVisible) robot = *id;
    run->driven_robots_.push_back(*id);
    run->agents_.push_back(RunnerAgent{*id, AgentKind::kRobot, r.name, pointer});
    pending.push_back(Pending{std::nullopt, {}, false});
    run->leaving_.push_back(Leaving::kNever);
  }
  if (program.robot && !driven) {
    const ProgramRobot& r = *program.robot;
    for (const ProgramPoint& g : r.goals)
      if (auto p = b.point(g, env)) run->robot_goals_.push_back(Goal{*p, g.radius.value_or(r.goal_radius)});
    AgentSpec spec;
    spec.position = r.position;
    spec.role = "robot";
    spec.desired_speed = r.speed;
    spec.radius = r.radius;
    spec.yaw = r.yaw;
    auto id = s.add_agent(spec);
    if (!id)
      b.error(id.error(), r.pointer);
    else {
      robot = *id;
      run->agents_.push_back(RunnerAgent{*id, AgentKind::kRobot, "robot", r.pointer});
      pending.push_back(Pending{std::nullopt, run->robot_goals_, r.cyclic_goals});
      run->leaving_.push_back(Leaving::kNever);
      run->robot_cyclic_ = r.cyclic_goals;
    }
  }
  if (!b.ok()) return tl::unexpected(b.failure());

  env.sync_agents();
  env.set_robot(robot);
  std::vector<std::vector<Goal>> metric_goals;
  run->trees_.resize(pending.size());
  for (std::size_t i = 0; i < pending.size(); ++i) {
    const AgentId id(static_cast<std::uint32_t>(i));
    env.set_goal_list(id, pending[i].goals, pending[i].cyclic);
    metric_goals.push_back(pending[i].goals);
    if (!pending[i].tree) continue;
    const BtDocument& doc = run->documents_[pending[i].tree->first];
    BtTree t = doc.instantiate(pending[i].tree->second);
    t.blackboard().set("id", BtValue{static_cast<std::int64_t>(i)});
    t.blackboard().set("dt", BtValue{run->decision_period()});
    run->trees_[i] = std::move(t);
  }
  if (options.record_metrics)
    run->metrics_ = std::make_unique<MetricsRecorder>(std::move(metric_goals), robot);
  return run;
}

void ScenarioRunner::decide() {
  BtEnvironment& env = *env_;
  const double now = sim_->time();
  env.begin_tick(now);
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    const AgentId id(static_cast<std::uint32_t>(i));
    if (!trees_[i] || !sim_->active(id)) continue;
    const BtStatus status = trees_[i]->tick(now);
    std::string leaf = trees_[i]->running_leaf();
    if (sim_->state(id).metadata.bt_node != leaf) (void)sim_->set_bt_node(id, std::move(leaf));
    if (status == BtStatus::kSuccess && (leaving_[i] == Leaving::kWhenTreeSucceeds ||
                                         (leaving_[i] == Leaving::kAtLastGoal && !env.current_goal(id))))
      (void)sim_->set_activity(id, Activity::kExited);
  }
  if (const auto robot = env.robot(); robot && sim_->active(*robot) && !robot_goals_.empty()) {
    const Vec2 p = sim_->position(*robot);
    if (robot_goal_ < robot_goals_.size()) {
      const Goal& g = robot_goals_[robot_goal_];
      if (std::hypot(p.x - g.position.x, p.y - g.position.y) <= g.radius) {
        ++robot_goal_;
        if (robot_goal_ >= robot_goals_.size() && robot_cyclic_) robot_goal_ = 0;
      }
    }
    if (robot_goal_ < robot_goals_.size()) {
      const Goal& g = robot_goals_[robot_goal_];
      env.move_to(*robot, g.position, g.radius, sim_->desired_speed(*robot), Activity::kWalking);
    } else {
      env.hold(*robot, Activity::kStanding);
    }
  }
  env.apply();
}

void ScenarioRunner::step() {
  if (steps_ % decision_every_ == 0) {
    if (metrics_) {
      std::vector<double> radii(sim_->size());
      std::vector<std::uint8_t> active(sim_->size());
      for (std::size_t i = 0; i < sim_->size(); ++i) {
        radii[i] = sim_->radius(AgentId(static_cast<std::uint32_t>(i)));
        active[i] = sim_->active(AgentId(static_cast<std::uint32_t>(i))) ? 1 : 0;
      }
      metrics_->observe(sim_->time(), states(), radii, active, sim_->walls());
    }
    decide();
  }
  sim_->step();
  ++steps_;
}

void ScenarioRunner::run(double seconds, const FrameCallback& frame, unsigned frame_every) {
  const auto total = static_cast<std::uint64_t>(std::llround(std::max(0.0, seconds) / sim_->config().dt));
  frame_every = std::max(1u, frame_every);
  if (frame && steps_ == 0) {
    const auto s = states();
    frame(sim_->time(), s);
  }
  for (std::uint64_t k = 0; k < total; ++k) {
    step();
    if (frame && steps_ % frame_every == 0) {
      const auto s = states();
      frame(sim_->time(), s);
    }
  }
}

std::vector<PedestrianState> ScenarioRunner::states() const {
  std::vector<PedestrianState> out;
  out.reserve(sim_->size());
  for (std::size_t i = 0; i < sim_->size(); ++i)
    out.push_back(env_->state(AgentId(static_cast<std::uint32_t>(i))));
  return out;
}

BtTree* ScenarioRunner::tree(AgentId id) {
  if (id.value() >= trees_.size() || !trees_[id.value()]) return nullptr;
  return &*trees_[id.value()];
}

std::vector<std::string> ScenarioRunner::errors() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    if (!trees_[i]) continue;
    for (const std::string& e : trees_[i]->context().errors)
      out.push_back("agent " + std::to_string(i) + ": " + e);
  }
  return out;
}

RunMetrics ScenarioRunner::metrics() const {
  return metrics_ ? metrics_->finish() : RunMetrics{};
}

}  // namespace socsim::crowd
