#include "core/interop/agent_routes.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "core/geometry/planar.hpp"

namespace socsim::interop {

namespace {

using crowd::BtNodeSpec;
using crowd::BtValue;

std::optional<std::string> literal_text(const BtNodeSpec& spec, std::string_view port) {
  for (const auto& p : spec.ports) {
    if (p.name != port || p.key) continue;
    if (const auto* s = std::get_if<std::string>(&p.literal)) return *s;
    return std::nullopt;
  }
  return std::nullopt;
}

std::optional<double> literal_number(const BtNodeSpec& spec, std::string_view port) {
  for (const auto& p : spec.ports) {
    if (p.name != port || p.key) continue;
    if (const auto* d = std::get_if<double>(&p.literal)) return *d;
    if (const auto* i = std::get_if<std::int64_t>(&p.literal)) return static_cast<double>(*i);
    return std::nullopt;
  }
  return std::nullopt;
}

// Index k of a pointer "/<list>/k".
std::size_t entry_index(const std::string& pointer) {
  const auto slash = pointer.rfind('/');
  if (slash == std::string::npos) return 0;
  std::size_t k = 0;
  for (std::size_t i = slash + 1; i < pointer.size() && std::isdigit(static_cast<unsigned char>(pointer[i]));
       ++i)
    k = k * 10 + static_cast<std::size_t>(pointer[i] - '0');
  return k;
}

// Radius of the circle with the region's area: how close "inside the place" roughly is.
double region_radius(const crowd::Place& place) {
  if (place.region == nullptr) return 0.5;
  return std::max(0.3, std::sqrt(std::abs(geometry::area(*place.region)) / 3.141592653589793) * 0.8);
}

class RouteReader {
 public:
  RouteReader(crowd::ScenarioRunner& runner, const crowd::Program& program)
      : runner_(runner), env_(runner.environment()), program_(program) {}

  AgentRoute read(const crowd::RunnerAgent& a) {
    crowd::CrowdSimulation& sim = runner_.sim();
    const crowd::PedestrianState s = sim.state(a.id);
    AgentRoute r;
    r.id = a.id;
    r.kind = a.kind;
    r.name = a.name;
    r.pointer = a.pointer;
    r.entry = entry_index(a.pointer);
    r.role = s.role;
    r.start = {s.pose.x, s.pose.y};
    r.yaw = s.pose.yaw;
    r.radius = sim.radius(a.id);
    r.speed = sim.desired_speed(a.id);
    r.group_id = s.group_id;
    route_ = &r;
    if (a.kind == crowd::AgentKind::kRobot) {
      if (program_.robot) add_goals(program_.robot->goals, program_.robot->goal_radius);
      r.cyclic = program_.robot && program_.robot->cyclic_goals;
      return r;
    }
    crowd::BtTree* tree = runner_.tree(a.id);
    if (tree == nullptr) return r;
    bool goals_added = false;
    std::optional<double> chance;
    for (crowd::BtNode* node : tree->nodes()) {
      const BtNodeSpec& spec = node->spec();
      const std::string& t = spec.type;
      const std::size_t before = r.stops.size();
      if (t == "RandomChance") {
        chance = literal_number(spec, "probability");
        continue;
      }
      if (t == "RegularNav" || t == "UpdateGoal") {
        if (!goals_added) add_agent_goals(a);
        goals_added = true;
      } else if (t == "GoTo" || t == "SetGoal") {
        goto_stop(spec, a);
      } else if (t == "JoinQueue") {
        queue_stop(spec, std::nullopt);
      } else if (t == "ServeAtCounter") {
        queue_stop(spec, literal_number(spec, "service_time"));
      } else if (t == "AdvanceQueue") {
        queue_stop(spec, literal_number(spec, "advance_interval"));
      } else if (t == "WaitAt") {
        linger(literal_text(spec, "location"), literal_number(spec, "duration"));
      } else if (t == "SitAt") {
        linger(literal_text(spec, "seat"), literal_number(spec, "duration"));
      } else if (t == "Gather") {
        linger(literal_text(spec, "point"), literal_number(spec, "duration"));
      } else if (t == "Wander") {
        const auto d = literal_number(spec, "duration");
        const double pause = 0.5 * (literal_number(spec, "pause_min").value_or(1.0) +
                                    literal_number(spec, "pause_max").value_or(8.0));
        linger(literal_text(spec, "region"), d && *d > 0 ? d : std::optional<double>(pause));
      } else if (t == "StopAndWait") {
        if (const auto d = literal_number(spec, "wait_duration"); d && !r.stops.empty())
          r.stops.back().duration += *d;
      } else if (t == "Evacuate") {
        exit_stop(spec, r.start);
        r.cyclic = false;
      } else if (t == "FollowVelocityField") {
        field_stop(spec);
        r.cyclic = false;
      }
      if (r.stops.size() > before && chance) {
        for (std::size_t k = before; k < r.stops.size(); ++k) r.stops[k].probability = *chance;
      }
      if (r.stops.size() > before) chance.reset();
    }
    return r;
  }

 private:
  void add_goals(const std::vector<crowd::ProgramPoint>& goals, double default_radius) {
    for (const crowd::ProgramPoint& g : goals) {
      RouteStop stop;
      stop.radius = g.radius.value_or(default_radius);
      if (const auto* v = std::get_if<crowd::Vec2>(&g.where)) {
        stop.point = *v;
      } else {
        const std::string& name = std::get<std::string>(g.where);
        const auto place = env_.place(name);
        if (!place) continue;  // the runner checked every name; nothing to add for a stale one
        stop.place = name;
        stop.point = place->point;
      }
      route_->stops.push_back(std::move(stop));
    }
  }

  void add_agent_goals(const crowd::RunnerAgent& a) {
    if (a.kind != crowd::AgentKind::kSpotlight || route_->entry >= program_.agents.size()) return;
    const crowd::ProgramAgent& entry = program_.agents[route_->entry];
    add_goals(entry.goals, entry.goal_radius);
    route_->cyclic = entry.cyclic_goals;
  }

  void place_stop(RouteStop::Kind kind, const std::string& name, std::optional<double> duration) {
    const auto place = env_.place(name);
    if (!place) return;
    RouteStop stop;
    stop.kind = kind;
    stop.place = name;
    stop.point = place->point;
    stop.radius = region_radius(*place);
    stop.duration = std::max(0.0, duration.value_or(0.0));
    route_->stops.push_back(std::move(stop));
  }

  void goto_stop(const BtNodeSpec& spec, const crowd::RunnerAgent& a) {
    if (const auto name = literal_text(spec, "goal"); name && !name->empty()) {
      place_stop(RouteStop::Kind::kWalk, *name, std::nullopt);
      return;
    }
    const auto index = literal_number(spec, "goal_id");
    if (!index || *index < 0 || a.kind != crowd::AgentKind::kSpotlight ||
        route_->entry >= program_.agents.size())
      return;
    const auto& goals = program_.agents[route_->entry].goals;
    const auto k = static_cast<std::size_t>(*index);
    if (k < goals.size()) add_goals({goals[k]}, program_.agents[route_->entry].goal_radius);
  }

  void queue_stop(const BtNodeSpec& spec, std::optional<double> duration) {
    const auto name = literal_text(spec, "queue");
    if (!name) return;
    // ServeAtCounter / AdvanceQueue after JoinQueue on the same queue: one stop.
    if (!route_->stops.empty() && route_->stops.back().kind == RouteStop::Kind::kQueue &&
        route_->stops.back().place == *name) {
      if (duration) route_->stops.back().duration = std::max(0.0, *duration);
      return;
    }
    crowd::BtEnvironment::Queue* q = env_.queue(*name);
    if (q == nullptr) return;
    RouteStop stop;
    stop.kind = RouteStop::Kind::kQueue;
    stop.place = *name;
    stop.point = q->head;
    stop.radius = 0.3;
    stop.duration = std::max(0.0, duration.value_or(0.0));
    route_->stops.push_back(std::move(stop));
  }

  void linger(const std::optional<std::string>& name, std::optional<double> duration) {
    if (name && !name->empty()) place_stop(RouteStop::Kind::kLinger, *name, duration);
  }

  void exit_stop(const BtNodeSpec& spec, crowd::Vec2 from) {
    const auto name = literal_text(spec, "exit");
    std::optional<std::size_t> e = name && !name->empty() ? env_.exit_index(*name) : env_.nearest_exit(from);
    if (!e) return;
    const crowd::BtEnvironment::Exit& exit = env_.exits()[*e];
    RouteStop stop;
    stop.place = exit.name;
    stop.point = exit.beyond.value_or(exit.point);
    stop.radius = 0.5;
    route_->stops.push_back(std::move(stop));
  }

  void field_stop(const BtNodeSpec& spec) {
    const auto name = literal_text(spec, "field");
    if (!name) return;
    const crowd::BtEnvironment::FieldEntry* f = env_.velocity_field(*name);
    if (f == nullptr || f->goals.empty()) return;
    RouteStop stop;
    const geometry::Polygon& goal = f->goals.front();
    const world::Point c = geometry::centroid(goal.outer);
    stop.point = {c.x, c.y};
    stop.radius = std::max(0.3, std::sqrt(std::abs(geometry::area(goal)) / 3.141592653589793) * 0.8);
    // The goal region's name, when the group named it.
    for (const crowd::AmbientGroup& g : program_.ambient_groups) {
      if (g.name != *name || g.goal.empty()) continue;
      if (const auto* n = std::get_if<std::string>(&g.goal.front().where)) {
        stop.place = *n;
        if (const auto place = env_.place(*n)) stop.point = place->point;
      }
    }
    route_->stops.push_back(std::move(stop));
  }

  crowd::ScenarioRunner& runner_;
  crowd::BtEnvironment& env_;
  const crowd::Program& program_;
  AgentRoute* route_ = nullptr;
};

}  // namespace

std::vector<AgentRoute> agent_routes(crowd::ScenarioRunner& runner, const crowd::Program& program) {
  RouteReader reader(runner, program);
  std::vector<AgentRoute> out;
  out.reserve(runner.agents().size());
  for (const crowd::RunnerAgent& a : runner.agents()) out.push_back(reader.read(a));
  return out;
}

Result<std::vector<AgentRoute>> program_routes(const world::World& world, const crowd::Program& program,
                                               std::uint64_t seed) {
  crowd::RunnerOptions options;
  options.seed = seed;
  options.record_metrics = false;
  auto runner = crowd::ScenarioRunner::create(&world, program, options);
  if (!runner) return tl::unexpected(runner.error());
  return agent_routes(**runner, program);
}

}  // namespace socsim::interop
