#include <cmath>
#include <sstream>

#include "core/geometry/planar.hpp"
#include "core/world/export_format.hpp"
#include "core/world/world_export.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::world {

namespace {

std::string pose(double x, double y, double z, double yaw) {
  return micro(x) + " " + micro(y) + " " + micro(z) + " 0 0 " + micro(yaw);
}

void box_link(std::ostringstream& o, const std::string& name, const std::string& pose_text,
              const std::string& size) {
  o << "      <link name=\"" << name << "\">\n"
    << "        <pose>" << pose_text << "</pose>\n"
    << "        <collision name=\"collision\"><geometry><box><size>" << size
    << "</size></box></geometry></collision>\n"
    << "        <visual name=\"visual\"><geometry><box><size>" << size
    << "</size></box></geometry></visual>\n"
    << "      </link>\n";
}

}  // namespace

std::string export_sdf(const World& world, const SdfOptions& options) {
  const std::string name = !options.world_name.empty() ? options.world_name
                           : !world.name().empty()     ? world.name()
                                                       : "socsim_world";
  const Pose2& origin = world.origin();
  const std::string model_pose = pose(origin.x, origin.y, 0, origin.yaw);
  const double t = options.wall_thickness;
  const geometry::Box b = world.bounds();
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<sdf version=\"1.7\">\n";
  o << "  <world name=\"" << xml_escape(name) << "\">\n";
  o << "    <model name=\"floor\">\n      <static>true</static>\n      <pose>" << model_pose << "</pose>\n";
  const std::string floor_size = micro(b.width() + 2) + " " + micro(b.height() + 2) + " 0.01";
  box_link(o, "floor", pose((b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, -0.005, 0), floor_size);
  o << "    </model>\n";
  o << "    <model name=\"walls\">\n      <static>true</static>\n      <pose>" << model_pose << "</pose>\n";
  const auto walls = world.walls();
  // An end that meets another wall's end is extended by t/2 so that the boxes close the corner.
  auto meets = [&](std::size_t self, Point p) {
    for (std::size_t k = 0; k < walls.size(); ++k) {
      if (k == self) continue;
      if (geometry::distance(walls[k].segment.a, p) < 1e-6 ||
          geometry::distance(walls[k].segment.b, p) < 1e-6)
        return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const Segment& s = walls[i].segment;
    const double len = geometry::length(s);
    const double ux = (s.b.x - s.a.x) / len;
    const double uy = (s.b.y - s.a.y) / len;
    const double ea = meets(i, s.a) ? t / 2 : 0.0;
    const double eb = meets(i, s.b) ? t / 2 : 0.0;
    const Point a{s.a.x - ux * ea, s.a.y - uy * ea};
    const Point e{s.b.x + ux * eb, s.b.y + uy * eb};
    const double h = walls[i].height;
    box_link(o, "wall_" + std::to_string(i),
             pose((a.x + e.x) / 2, (a.y + e.y) / 2, h / 2, std::atan2(uy, ux)),
             micro(len + ea + eb) + " " + micro(t) + " " + micro(h));
  }
  o << "    </model>\n  </world>\n</sdf>\n";
  return o.str();
}

}  // namespace socsim::world
