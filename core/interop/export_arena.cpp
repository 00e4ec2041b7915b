#include "core/interop/export_arena.hpp"

#include <cmath>
#include <numbers>

#include "core/common/json_io.hpp"
#include "core/geometry/planar.hpp"
#include "core/interop/agent_routes.hpp"

namespace socsim::interop {
namespace {

// Millimetres and milliradians are plenty for a scenario file, and keep it readable.
double rounded(double v) {
  return std::round(v * 1000.0) / 1000.0;
}

// Arena's pedsim agent types: adult, child, elder (others walk as adults).
std::string arena_type(const std::string& role) {
  if (role.find("child") != std::string::npos || role == "pupil" || role == "toddler") return "child";
  if (role.find("elder") != std::string::npos || role == "senior") return "elder";
  return "adult";
}

}  // namespace

Result<std::string> export_arena_scenario(const world::World& world, const crowd::Program& program,
                                          const ArenaExportOptions& options) {
  auto program_stops = program_routes(world, program, options.seed);
  if (!program_stops) return tl::unexpected(program_stops.error());
  const std::vector<AgentRoute>& routes = *program_stops;

  const geometry::Pose2& origin = world.origin();
  auto pose = [&origin](double x, double y, double yaw) {
    const geometry::Point p = geometry::to_parent(origin, geometry::Point{x, y});
    return Json::array(
        {rounded(p.x), rounded(p.y), rounded(std::remainder(yaw + origin.yaw, 2 * std::numbers::pi))});
  };

  Json dynamic = Json::array();
  const AgentRoute* robot = nullptr;
  for (const AgentRoute& r : routes) {
    if (r.kind == crowd::AgentKind::kRobot) {
      robot = &r;
      continue;
    }
    Json waypoints = Json::array();
    for (const RouteStop& s : r.stops) waypoints.push_back(pose(s.point.x, s.point.y, 0.0));
    if (waypoints.empty()) waypoints.push_back(pose(r.start.x, r.start.y, 0.0));  // stands where it starts
    dynamic.push_back({{"name", r.name.empty() ? "person_" + std::to_string(r.id.value()) : r.name},
                       {"pos", pose(r.start.x, r.start.y, r.yaw)},
                       {"type", arena_type(r.role)},
                       {"model", options.model},
                       {"waypoints", std::move(waypoints)},
                       {"waypoint_mode", 2}});
  }

  Json statics = Json::array();
  for (const world::Entity& e : world.entities())
    statics.push_back({{"name", e.name}, {"pos", pose(e.pose.x, e.pose.y, e.pose.yaw)}, {"model", e.type}});

  // The robot's start and goal: the program's robot; else the two places people go to that lie
  // farthest apart (reachable points of the world; doorways too when everyone goes to one place),
  // else the middles of the first and last zones.
  Json start, goal;
  if (robot != nullptr) {
    start = pose(robot->start.x, robot->start.y, robot->yaw);
    // Arena's robot has one goal: the program robot's stop farthest from where it starts.
    crowd::Vec2 g = robot->start;
    for (const RouteStop& s : robot->stops)
      if (std::hypot(s.point.x - robot->start.x, s.point.y - robot->start.y) >
          std::hypot(g.x - robot->start.x, g.y - robot->start.y) + 1e-9)
        g = s.point;
    goal = pose(g.x, g.y, 0.0);
  } else {
    std::vector<crowd::Vec2> places;
    for (const AgentRoute& r : routes)
      for (const RouteStop& s : r.stops) places.push_back(s.point);
    auto farthest = [&places]() {
      std::pair<std::size_t, std::size_t> pair{0, 1};
      double best = -1.0;
      for (std::size_t i = 0; i < places.size(); ++i)
        for (std::size_t j = i + 1; j < places.size(); ++j) {
          const double d = std::hypot(places[i].x - places[j].x, places[i].y - places[j].y);
          if (d > best + 1e-9) best = d, pair = {i, j};
        }
      return std::pair{pair, best};
    };
    if (places.size() < 2 || farthest().second < 1.0) {
      // Everyone goes to one place: add the doorways, 0.6 m into the room each opens from.
      for (const world::Door& d : world.doors()) {
        const double dx = d.opening.b.x - d.opening.a.x, dy = d.opening.b.y - d.opening.a.y;
        const double len = std::max(1e-9, std::hypot(dx, dy));
        const geometry::Point mid{(d.opening.a.x + d.opening.b.x) / 2, (d.opening.a.y + d.opening.b.y) / 2};
        for (const double side : {1.0, -1.0}) {
          const geometry::Point in{mid.x - side * dy / len * 0.6, mid.y + side * dx / len * 0.6};
          if (geometry::contains(world.zone(d.zone).polygon, in)) {
            places.push_back({in.x, in.y});
            break;
          }
        }
      }
    }
    if (places.size() >= 2) {
      const auto [a, b] = farthest().first;
      start = pose(places[a].x, places[a].y, 0.0);
      goal = pose(places[b].x, places[b].y, 0.0);
    } else {
      auto middle = [](const world::Zone& z) {
        double x = 0, y = 0;
        for (const auto& p : z.polygon.outer) x += p.x, y += p.y;
        const double n = std::max<double>(1.0, static_cast<double>(z.polygon.outer.size()));
        return geometry::Point{x / n, y / n};
      };
      const geometry::Point a = middle(world.zones().front()), b = middle(world.zones().back());
      start = pose(a.x, a.y, 0.0);
      goal = pose(b.x, b.y, 0.0);
    }
  }

  const Json doc = {
      {"robots", Json::array({{{"start", start}, {"goal", goal}}})},
      {"obstacles", {{"static", statics}, {"dynamic", dynamic}, {"interactive", Json::array()}}},
      {"resets", options.resets},
      {"map", options.map.empty() ? world.name() : options.map}};
  return doc.dump(2) + "\n";
}

}  // namespace socsim::interop
