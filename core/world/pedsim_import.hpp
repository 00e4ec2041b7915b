#pragma once
// pedsim_ros scenario XML → a World (obstacles as walls, waypoints/queues/attractions as ROIs)
// plus the scenario parts that are not world (agent clusters and
// their routes) as plain data for the scenario layer. Problems name the element's line.
#include <string>
#include <string_view>
#include <vector>

#include "core/world/world_builder.hpp"

namespace socsim::world {

struct PedsimWaypoint {
  std::string id;
  Point position;
  double radius = 0.0;
  int behaviour = 0;  // pedsim "b": 0 = normal, 1 = source, 2 = sink
  int line = 0;
};

struct PedsimQueue {
  std::string id;
  Point position;        // where the first agent stands
  double direction_deg;  // direction in which the queue grows
  int line = 0;
};

struct PedsimAttraction {
  std::string id;
  Point center;
  double width = 0.0;
  double height = 0.0;
  double strength = 0.0;
  int line = 0;
};

struct PedsimRouteStep {
  enum class Kind { kWaypoint, kQueue };
  Kind kind = Kind::kWaypoint;
  std::string id;
};

// An <agent> (or <source>) element: n agents scattered within ±dx, ±dy of the position.
struct PedsimAgentCluster {
  Point position;
  int count = 1;
  double dx = 0.0;
  double dy = 0.0;
  int type = 0;  // 0 adult, 1 child, 2 robot, 3 elder
  bool source = false;
  std::vector<PedsimRouteStep> route;
  int line = 0;
};

struct PedsimScenario {
  World world;
  // True when the obstacles close a perimeter around the whole scene; then every waypoint,
  // queue and agent must lie inside it. Otherwise the walkable area is the scene's bounding box.
  bool enclosed = false;
  std::vector<PedsimWaypoint> waypoints;
  std::vector<PedsimQueue> queues;
  std::vector<PedsimAttraction> attractions;
  std::vector<PedsimAgentCluster> agents;
};

struct PedsimImportOptions {
  BuildOptions build;
  double queue_length = 4.0;  // m; length of the queue_lane ROI made from a <queue>
  double queue_width = 1.0;   // m
  double margin = 1.0;        // m; around the scene's bounding box when it is not enclosed
  std::string name = "pedsim_scenario";
};

// Errors: kBadRequest for malformed XML; kValidation with one FieldError per problem, its
// pointer naming the element (/waypoints/3, /obstacles/0, /agents/2/route/1) and its line.
Result<PedsimScenario> import_pedsim(std::string_view xml, const PedsimImportOptions& options = {});

}  // namespace socsim::world
