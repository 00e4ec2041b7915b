#include <sstream>

#include "core/geometry/planar.hpp"
#include "core/world/export_format.hpp"
#include "core/world/occupancy_grid.hpp"
#include "core/world/world_export.hpp"

namespace socsim::world {

RosMap export_ros_map(const World& world, const RosMapOptions& options) {
  const auto grid = OccupancyGrid::rasterise(world, GridOptions{options.resolution, 0.0});
  RosMap map;
  std::ostringstream header;
  header << "P5\n# socsim world " << (world.name().empty() ? "unnamed" : world.name()) << "\n"
         << grid.width() << " " << grid.height() << "\n255\n";
  map.pgm = header.str();
  map.pgm.reserve(map.pgm.size() +
                  static_cast<std::size_t>(grid.width()) * static_cast<std::size_t>(grid.height()));
  // PGM rows run top to bottom; grid row 0 is the lowest.
  for (int y = grid.height() - 1; y >= 0; --y) {
    for (int x = 0; x < grid.width(); ++x) map.pgm += static_cast<char>(grid.blocked({x, y}) ? 0 : 254);
  }
  const Point lower_left = geometry::to_parent(world.origin(), grid.origin());
  std::ostringstream y;
  y << "image: " << options.image_file << "\n"
    << "resolution: " << shortest(grid.resolution()) << "\n"
    << "origin: [" << micro(lower_left.x) << ", " << micro(lower_left.y) << ", " << micro(world.origin().yaw)
    << "]\n"
    << "negate: 0\n"
    << "occupied_thresh: " << shortest(options.occupied_thresh) << "\n"
    << "free_thresh: " << shortest(options.free_thresh) << "\n"
    << "mode: trinary\n";
  map.yaml = y.str();
  return map;
}

}  // namespace socsim::world
