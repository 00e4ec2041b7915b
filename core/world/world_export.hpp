#pragma once
// Simulator and map formats produced from one World: SVG drawing, Gazebo SDF world, ROS
// map_server occupancy map (PGM + YAML) and pedsim_ros scenario XML. Every export except
// SVG places the world at its origin pose (world.origin()).
#include <string>

#include "core/world/pedsim_import.hpp"
#include "core/world/world.hpp"

namespace socsim::world {

struct SvgOptions {
  double pixels_per_metre = 40.0;
  bool labels = true;
};
// Zones filled by type, walls, doors, ROIs (dashed) and entities, labelled; y up.
std::string export_svg(const World& world, const SvgOptions& options = {});

struct SdfOptions {
  double wall_thickness = 0.15;  // m; box depth of each wall
  std::string world_name;        // default: the world's name, else "socsim_world"
};
// SDF 1.7: a ground plane and one static model with one link per wall (box of the wall's
// length × thickness × height, pose at its centre). Walls that meet are extended by half
// the thickness so corners close; door jambs are not.
std::string export_sdf(const World& world, const SdfOptions& options = {});

struct UsdOptions {
  double wall_thickness = 0.15;  // m, as the SDF export
};
// USD ASCII (usda 1.0, Z up, metres): /World at the world's origin pose with Scopes Zones (one
// flat Mesh per zone, named after it), Walls (scaled unit Cubes; door openings are the gaps),
// Doors and Entities (Xforms with socsim:* attributes) and Regions (guide Meshes of the ROIs).
std::string export_usda(const World& world, const UsdOptions& options = {});

struct RosMapOptions {
  double resolution = 0.05;  // m per pixel
  std::string image_file = "map.pgm";
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
};
struct RosMap {
  std::string pgm;   // binary P5, 254 = free, 0 = occupied (walls, outside the zones)
  std::string yaml;  // map_server metadata naming image_file
};
RosMap export_ros_map(const World& world, const RosMapOptions& options = {});

// pedsim_ros scenario: <obstacle> per wall, <waypoint> per ROI that is not a queue or an
// attraction (centroid, radius of the equal-area circle) and per entity (r = 1), <queue> per queue_lane ROI
// (head at the end nearest an entity within a lane length, else nearest the polygon's first vertex; direction
// along the lane), <attraction> per seating_area or waiting_zone ROI (bounding box, strength 1). No agents:
// those belong to the scenario.
std::string export_pedsim(const World& world);

// The walls and queues of export_pedsim as values in the parent frame (a queue as the importer
// reads it: pedsim_import.hpp), so the scenario export
// (core/interop/export_pedsim_scenario.cpp) writes them without reading its own output back.
struct PedsimObstacle {
  Point a;
  Point b;
};
std::vector<PedsimObstacle> pedsim_obstacles(const World& world);
std::vector<PedsimQueue> pedsim_queues(const World& world);
// One element as export_pedsim writes it (two spaces of indent, a newline after).
std::string pedsim_element(const PedsimObstacle& o);
std::string pedsim_element(const PedsimQueue& q);

}  // namespace socsim::world
