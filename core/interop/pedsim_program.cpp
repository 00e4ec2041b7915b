#include "core/interop/pedsim_program.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/crowd/scenario_runner.hpp"
#include "core/geometry/geos.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/export_format.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::interop {

namespace {

using world::PedsimAgentCluster;
using world::PedsimRouteStep;

double round_micro(double v) {
  return std::round(v * 1e6) / 1e6;
}

Json point_json(double x, double y) {
  return Json::array({round_micro(x), round_micro(y)});
}

// pedsim agent types (libpedsim ped_agent.h): 0 adult, 1 child, 2 robot, 3 elder.
std::string role_of(int type) {
  if (type == 1) return "child";
  if (type == 3) return "elderly";
  return "adult";
}

// The walkable part of the cluster's scatter box: box ∩ zones, the part holding the cluster's
// centre (else the largest part). Empty when nothing of the box is walkable.
std::vector<world::Point> spawn_region(const geometry::Geos& geos, const world::World& w, world::Point c,
                                       double dx, double dy) {
  const world::Polygon box{
      {{c.x - dx, c.y - dy}, {c.x + dx, c.y - dy}, {c.x + dx, c.y + dy}, {c.x - dx, c.y + dy}}, {}};
  geometry::MultiPolygon zones;
  for (const auto& z : w.zones()) zones.push_back(z.polygon);
  const geometry::MultiPolygon parts = geos.intersection(geometry::MultiPolygon{box}, zones);
  const world::Polygon* best = nullptr;
  for (const auto& p : parts) {
    if (geometry::contains(p, c)) {
      best = &p;
      break;
    }
    if (best == nullptr || geometry::area(p) > geometry::area(*best)) best = &p;
  }
  if (best == nullptr || geometry::area(*best) < 0.01) return {};
  return best->outer;
}

struct Attraction {
  const world::PedsimAttraction* source;
  double probability;
};

class Converter {
 public:
  Converter(const world::PedsimScenario& s, const PedsimProgramOptions& o) : s_(s), o_(o) {
    for (const auto& w : s.waypoints) waypoints_[w.id] = &w;
    for (const auto& a : s.attractions) {
      const double p = std::min(0.9, a.strength / std::max(o.attraction_scale, 1e-9));
      if (p > 0.0 && s.world.find_roi(a.id)) attractions_.push_back({&a, p});
    }
  }

  Result<PedsimProgram> run() {
    Json program = {{"version", 1}, {"name", o_.name.empty() ? s_.world.name() : o_.name}};
    Json agents = Json::array();
    Json trees = Json::object();
    bool children = false;
    for (std::size_t i = 0; i < s_.agents.size(); ++i) {
      const PedsimAgentCluster& c = s_.agents[i];
      const std::string ptr = "/agents/" + std::to_string(i);
      check_route(c, ptr);
      if (c.type == 2) {
        robot(c, ptr, program);
        continue;
      }
      if (c.count == 0) continue;
      children = children || c.type == 1;
      const std::string name = "cluster" + std::to_string(i);
      Json a = {{"name", name}, {"role", role_of(c.type)}};
      const bool scattered = c.count > 1 || c.dx > 0 || c.dy > 0;
      if (!scattered) {
        a["position"] = point_json(c.position.x, c.position.y);
      } else {
        const double dx = std::max(c.dx, c.count > 1 ? o_.min_spread : 0.0);
        const double dy = std::max(c.dy, c.count > 1 ? o_.min_spread : 0.0);
        const auto ring = spawn_region(geos_, s_.world, c.position, dx, dy);
        if (ring.empty()) {
          error(ptr, c.line,
                "the cluster's area (±" + world::shortest(dx) + ", ±" + world::shortest(dy) +
                    " m) has no walkable part inside the walls");
          continue;
        }
        Json poly = Json::array();
        for (const auto& p : ring) poly.push_back(point_json(p.x, p.y));
        a["spawn"] = poly;
        if (c.count > 1) a["count"] = c.count;
      }
      const std::string entry = "/agents/" + std::to_string(agents.size());
      sources_.push_back({entry, ptr, c.line});
      if (auto tree = route_tree(c)) {
        const std::string tree_name = "route_" + std::to_string(i);
        trees[tree_name] = {{"xml", *tree}};
        a["behavior"] = tree_name;
        sources_.push_back({"/behavior_trees/" + tree_name, ptr, c.line});
      } else if (!c.route.empty()) {
        Json goals = Json::array();
        for (const auto& step : c.route) goals.push_back(goal(step));
        a["goals"] = goals;
        a["cyclic_goals"] = true;
      }
      agents.push_back(std::move(a));
    }
    if (!errors_.empty())
      return fail(ErrorCode::kValidation, "the pedsim scenario cannot become a program", errors_);
    if (children) {
      // Assumed: children (pedsim type 1) walk slower than adults and are smaller.
      program["roles"] = {
          {"child", {{"speed", {{"mean", 1.1}, {"sd", 0.2}, {"min", 0.5}, {"max", 1.8}}}, {"radius", 0.22}}}};
    }
    if (!trees.empty()) program["behavior_trees"] = trees;
    program["agents"] = agents;
    return PedsimProgram{std::move(program), std::move(sources_)};
  }

 private:
  void error(const std::string& ptr, int line, std::string message) {
    errors_.push_back(FieldError{ptr, std::move(message), {}, line, 1});
  }

  // Every waypoint and queue a route names must have become an ROI of the world.
  void check_route(const PedsimAgentCluster& c, const std::string& ptr) {
    for (std::size_t k = 0; k < c.route.size(); ++k) {
      if (!s_.world.find_roi(c.route[k].id))
        error(ptr + "/route/" + std::to_string(k), c.line,
              "'" + c.route[k].id + "' has no walkable area inside the walls, so the route cannot use it");
    }
  }

  Json goal(const PedsimRouteStep& step) const {
    Json g = {{"place", step.id}};
    if (auto it = waypoints_.find(step.id); it != waypoints_.end()) g["radius"] = it->second->radius;
    return g;
  }

  void robot(const PedsimAgentCluster& c, const std::string& ptr, Json& program) {
    if (robot_line_ != 0) {
      error(ptr, c.line,
            "a second robot (type 2): a program has one robot, the first is at line " +
                std::to_string(robot_line_));
      return;
    }
    if (c.count != 1) {
      error(ptr, c.line,
            "a robot cluster of n=" + std::to_string(c.count) + ": a program has exactly one robot");
      return;
    }
    robot_line_ = c.line;
    Json r = {{"position", point_json(c.position.x, c.position.y)}};
    if (!c.route.empty()) {
      Json goals = Json::array();
      for (const auto& step : c.route) goals.push_back(goal(step));
      r["goals"] = goals;
      r["cyclic_goals"] = true;  // pedsim agents loop over their waypoints
    }
    program["robot"] = r;
    sources_.push_back({"/robot", ptr, c.line});
  }

  // Attractions whose area lies within reach of waypoint w's circle.
  std::vector<const Attraction*> attractions_near(const world::PedsimWaypoint& w) const {
    std::vector<const Attraction*> out;
    for (const Attraction& a : attractions_) {
      const auto* at = a.source;
      const double ox = std::max(0.0, std::abs(w.position.x - at->center.x) - at->width / 2);
      const double oy = std::max(0.0, std::abs(w.position.y - at->center.y) - at->height / 2);
      if (std::hypot(ox, oy) <= w.radius + o_.attraction_reach) out.push_back(&a);
    }
    return out;
  }

  // A behaviour tree when the route queues or passes an attraction; plain goals otherwise.
  std::optional<std::string> route_tree(const PedsimAgentCluster& c) const {
    bool needs_tree = false;
    for (const auto& step : c.route) {
      if (step.kind == PedsimRouteStep::Kind::kQueue) needs_tree = true;
      if (auto it = waypoints_.find(step.id);
          it != waypoints_.end() && !attractions_near(*it->second).empty())
        needs_tree = true;
    }
    if (!needs_tree) return std::nullopt;
    using world::xml_escape;
    std::string x =
        "<root BTCPP_format=\"4\" main_tree_to_execute=\"Route\">\n  <BehaviorTree ID=\"Route\">\n"
        "    <Sequence name=\"pedsim route\">\n";
    std::set<std::string> visited;
    for (const auto& step : c.route) {
      const std::string id = xml_escape(step.id);
      if (step.kind == PedsimRouteStep::Kind::kQueue) {
        x +=
            "      <JoinQueue queue=\"" + id + "\" spacing=\"" + world::shortest(o_.queue_spacing) + "\"/>\n";
        x += "      <ServeAtCounter counter=\"" + id + "\" queue=\"" + id + "\" service_time=\"" +
             world::shortest(o_.service_time) + "\" service_spread=\"" + world::shortest(o_.service_spread) +
             "\"/>\n";
        continue;
      }
      x += "      <GoTo goal=\"" + id + "\"/>\n";
      const auto it = waypoints_.find(step.id);
      if (it == waypoints_.end()) continue;
      for (const Attraction* a : attractions_near(*it->second)) {
        const std::string aid = xml_escape(a->source->id);
        x += "      <Fallback name=\"attraction " + aid + "\">\n        <Sequence>\n";
        x += "          <RandomChance probability=\"" + world::shortest(round_micro(a->probability)) +
             "\"/>\n";
        x += "          <Wander region=\"" + aid + "\" duration=\"" + world::shortest(o_.attraction_time) +
             "\"/>\n";
        x += "        </Sequence>\n        <AlwaysSuccess/>\n      </Fallback>\n";
      }
    }
    x += "    </Sequence>\n  </BehaviorTree>\n</root>\n";
    return x;
  }

  const world::PedsimScenario& s_;
  const PedsimProgramOptions& o_;
  geometry::Geos geos_;
  std::map<std::string, const world::PedsimWaypoint*> waypoints_;
  std::vector<Attraction> attractions_;
  std::vector<PedsimSource> sources_;
  std::vector<FieldError> errors_;
  int robot_line_ = 0;
};

bool under(const std::string& pointer, const std::string& prefix) {
  return pointer.size() >= prefix.size() && pointer.compare(0, prefix.size(), prefix) == 0 &&
         (pointer.size() == prefix.size() || pointer[prefix.size()] == '/');
}

}  // namespace

Result<PedsimProgram> pedsim_to_program(const world::PedsimScenario& scenario,
                                        const PedsimProgramOptions& options) {
  return Converter(scenario, options).run();
}

Error locate_in_pedsim(Error error, const PedsimProgram& program) {
  for (FieldError& f : error.errors) {
    for (const PedsimSource& s : program.sources) {
      if (!under(f.pointer, s.program_pointer)) continue;
      // Lines inside a behaviour tree's XML belong to the generated tree, not to the pedsim file.
      f.message = "program " + f.pointer + (f.line > 0 ? " (tree line " + std::to_string(f.line) + ")" : "") +
                  ": " + f.message;
      f.pointer = s.pedsim_pointer;
      f.line = s.line;
      f.column = 1;
      break;
    }
  }
  if (!error.errors.empty()) {
    const FieldError& first = error.errors.front();
    error.detail = first.pointer + " (line " + std::to_string(first.line) + "): " + first.message;
  }
  return error;
}

Result<ImportedPedsim> import_pedsim_scenario(std::string_view xml,
                                              const world::PedsimImportOptions& import_options,
                                              const PedsimProgramOptions& options) {
  auto scenario = world::import_pedsim(xml, import_options);
  if (!scenario) return tl::unexpected(scenario.error());
  auto program = pedsim_to_program(*scenario, options);
  if (!program) return tl::unexpected(program.error());
  auto parsed = crowd::program_from_json(program->program);
  if (!parsed) return tl::unexpected(locate_in_pedsim(parsed.error(), *program));
  auto runner = crowd::ScenarioRunner::create(&scenario->world, *parsed, crowd::RunnerOptions{});
  if (!runner) return tl::unexpected(locate_in_pedsim(runner.error(), *program));
  return ImportedPedsim{std::move(*scenario), std::move(*program), std::move(*parsed)};
}

}  // namespace socsim::interop
