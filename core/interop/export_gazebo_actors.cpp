#include "core/interop/export_gazebo_actors.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include "core/world/export_format.hpp"
#include "core/world/world_export.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::interop {
namespace {

struct Waypoint {
  double t, x, y, yaw;
};

}  // namespace

std::string export_gazebo_actors(const scenario::TrajectoryLog& log, const world::World& world,
                                 const GazeboActorOptions& options) {
  world::SdfOptions sdf_options;
  sdf_options.world_name = options.world_name;
  std::string sdf = world::export_sdf(world, sdf_options);

  // Each person's poses in the frame of the SDF world (the world's origin pose applied).
  const geometry::Pose2& origin = world.origin();
  const double c = std::cos(origin.yaw), s = std::sin(origin.yaw);
  const std::size_t stride = std::max<std::size_t>(1, options.frame_stride);
  std::map<std::uint32_t, std::vector<Waypoint>> tracks;
  std::map<std::uint32_t, std::string> roles;
  for (std::size_t f = 0; f < log.frame_count(); ++f) {
    if (f % stride != 0 && f + 1 != log.frame_count()) continue;
    for (const scenario::LoggedAgent& a : log.frame(f)) {
      const double x = origin.x + c * a.x - s * a.y, y = origin.y + s * a.x + c * a.y;
      tracks[a.id].push_back(
          {log.frame_time(f), x, y, std::remainder(a.yaw + origin.yaw, 2 * std::numbers::pi)});
      roles.emplace(a.id, log.roles().at(a.role));
    }
  }

  std::ostringstream o;
  const std::string skin = world::xml_escape(options.skin);
  for (auto& [id, track] : tracks) {
    // A trajectory needs two waypoints; someone logged once stands there for a frame.
    if (track.size() == 1)
      track.push_back({track[0].t + log.frame_interval(), track[0].x, track[0].y, track[0].yaw});
    o << "    <actor name=\"person_" << id << "\">\n";
    o << "      <!-- role " << world::xml_escape(roles[id]) << ", " << track.size() << " waypoints -->\n";
    o << "      <skin><filename>" << skin << "</filename></skin>\n";
    o << "      <animation name=\"walking\"><filename>" << skin
      << "</filename><interpolate_x>true</interpolate_x></animation>\n";
    o << "      <script><loop>false</loop><delay_start>0</delay_start><auto_start>true</auto_start>\n";
    o << "        <trajectory id=\"" << id << "\" type=\"walking\">\n";
    // Times from the first logged frame: an actor starts its script at t = 0.
    const double t0 = log.frame_time(0);
    for (const Waypoint& w : track)
      o << "          <waypoint><time>" << world::micro(w.t - t0) << "</time><pose>" << world::micro(w.x)
        << ' ' << world::micro(w.y) << " 0 0 0 " << world::micro(w.yaw) << "</pose></waypoint>\n";
    o << "        </trajectory>\n      </script>\n    </actor>\n";
  }
  const std::string closing = "  </world>";
  const auto at = sdf.rfind(closing);
  sdf.insert(at == std::string::npos ? sdf.size() : at, o.str());
  return sdf;
}

}  // namespace socsim::interop
