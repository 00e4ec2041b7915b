// The world as a USD ASCII stage (issue 20): what Isaac Sim (and any USD tool) opens as the
// environment of a scenario. Z up, metres; the world's origin pose on /World.
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "core/geometry/planar.hpp"
#include "core/world/export_format.hpp"
#include "core/world/world_export.hpp"

namespace socsim::world {

namespace {

// A USD identifier: letters, digits and '_', not starting with a digit; unique among siblings.
class PrimNames {
 public:
  std::string operator()(const std::string& wanted, const std::string& fallback) {
    std::string n;
    for (char c : wanted) n += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    if (n.empty()) n = fallback;
    if (std::isdigit(static_cast<unsigned char>(n[0]))) n = "_" + n;
    const int k = used_[n]++;
    return k == 0 ? n : n + "_" + std::to_string(k + 1);
  }

 private:
  std::map<std::string, int> used_;
};

// A string in USD's double-quoted form.
std::string usd_quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string degrees(double radians) {
  return micro(radians * 180.0 / std::numbers::pi);
}

void placed(std::ostringstream& o, const std::string& indent, double x, double y, double z, double yaw) {
  o << indent << "double3 xformOp:translate = (" << micro(x) << ", " << micro(y) << ", " << micro(z) << ")\n"
    << indent << "float xformOp:rotateZ = " << degrees(yaw) << "\n"
    << indent << "uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateZ\"]\n";
}

// A flat polygon at height z as a one-face mesh.
void polygon_mesh(std::ostringstream& o, const std::string& name, const Polygon& polygon, double z,
                  const std::string& extra) {
  const auto& ring = polygon.outer;
  o << "        def Mesh " << usd_quoted(name) << "\n        {\n"
    << "            int[] faceVertexCounts = [" << ring.size() << "]\n"
    << "            int[] faceVertexIndices = [";
  for (std::size_t i = 0; i < ring.size(); ++i) o << (i ? ", " : "") << i;
  o << "]\n            point3f[] points = [";
  for (std::size_t i = 0; i < ring.size(); ++i)
    o << (i ? ", " : "") << "(" << micro(ring[i].x) << ", " << micro(ring[i].y) << ", " << micro(z) << ")";
  o << "]\n            uniform token subdivisionScheme = \"none\"\n" << extra << "        }\n";
}

}  // namespace

std::string export_usda(const World& world, const UsdOptions& options) {
  std::ostringstream o;
  const std::string name = world.name().empty() ? "socsim_world" : world.name();
  o << "#usda 1.0\n(\n    defaultPrim = \"World\"\n    metersPerUnit = 1\n    upAxis = \"Z\"\n"
    << "    doc = "
    << usd_quoted("socsim world " + name +
                  ": zones (floors), walls with door openings, doors, "
                  "regions and entities")
    << "\n)\n\n";
  o << "def Xform \"World\" (\n    kind = \"assembly\"\n)\n{\n";
  placed(o, "    ", world.origin().x, world.origin().y, 0.0, world.origin().yaw);
  o << "    custom string socsim:name = " << usd_quoted(name) << "\n\n";

  PrimNames zone_names;
  o << "    def Scope \"Zones\"\n    {\n";
  for (const Zone& z : world.zones())
    polygon_mesh(o, zone_names(z.name, "zone"), z.polygon, 0.0,
                 "            custom string socsim:name = " + usd_quoted(z.name) +
                     "\n            custom string socsim:type = " + usd_quoted(z.type) + "\n");
  o << "    }\n\n";

  // Walls as boxes (a unit cube scaled), meeting ends extended by half the thickness so corners
  // close, as the SDF export does; doorways are the gaps between walls.
  const auto walls = world.walls();
  const double t = options.wall_thickness;
  auto meets = [&](std::size_t self, Point p) {
    for (std::size_t k = 0; k < walls.size(); ++k)
      if (k != self && (geometry::distance(walls[k].segment.a, p) < 1e-6 ||
                        geometry::distance(walls[k].segment.b, p) < 1e-6))
        return true;
    return false;
  };
  o << "    def Scope \"Walls\"\n    {\n";
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const Segment& s = walls[i].segment;
    const double len = geometry::length(s);
    if (len <= 1e-9) continue;
    const double ux = (s.b.x - s.a.x) / len, uy = (s.b.y - s.a.y) / len;
    const double ea = meets(i, s.a) ? t / 2 : 0.0, eb = meets(i, s.b) ? t / 2 : 0.0;
    const Point a{s.a.x - ux * ea, s.a.y - uy * ea}, e{s.b.x + ux * eb, s.b.y + uy * eb};
    const double h = walls[i].height;
    o << "        def Cube \"wall_" << i << "\"\n        {\n"
      << "            double size = 1\n"
      << "            double3 xformOp:translate = (" << micro((a.x + e.x) / 2) << ", "
      << micro((a.y + e.y) / 2) << ", " << micro(h / 2) << ")\n"
      << "            float xformOp:rotateZ = " << degrees(std::atan2(uy, ux)) << "\n"
      << "            float3 xformOp:scale = (" << micro(len + ea + eb) << ", " << micro(t) << ", "
      << micro(h) << ")\n"
      << "            uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateZ\", "
         "\"xformOp:scale\"]\n"
      << "        }\n";
  }
  o << "    }\n\n";

  PrimNames door_names;
  o << "    def Scope \"Doors\"\n    {\n";
  for (const Door& d : world.doors()) {
    o << "        def Xform " << usd_quoted(door_names(d.name, "door")) << "\n        {\n";
    placed(o, "            ", (d.opening.a.x + d.opening.b.x) / 2, (d.opening.a.y + d.opening.b.y) / 2, 0.0,
           d.pose.yaw);
    o << "            custom string socsim:name = " << usd_quoted(d.name) << "\n"
      << "            custom double socsim:width = " << micro(geometry::length(d.opening)) << "\n"
      << "            custom string socsim:zone = " << usd_quoted(world.zone(d.zone).name) << "\n";
    if (d.other)
      o << "            custom string socsim:other_zone = " << usd_quoted(world.zone(*d.other).name) << "\n";
    o << "        }\n";
  }
  o << "    }\n\n";

  PrimNames roi_names;
  o << "    def Scope \"Regions\"\n    {\n";
  for (const Roi& r : world.rois())
    polygon_mesh(o, roi_names(r.name, "region"), r.polygon, 0.01,
                 "            uniform token purpose = \"guide\"\n            custom string socsim:name = " +
                     usd_quoted(r.name) + "\n            custom string socsim:kind = " + usd_quoted(r.kind) +
                     "\n");
  o << "    }\n\n";

  PrimNames entity_names;
  o << "    def Scope \"Entities\"\n    {\n";
  for (const Entity& e : world.entities()) {
    o << "        def Xform " << usd_quoted(entity_names(e.name, "entity")) << "\n        {\n";
    placed(o, "            ", e.pose.x, e.pose.y, 0.0, e.pose.yaw);
    o << "            custom string socsim:name = " << usd_quoted(e.name) << "\n"
      << "            custom string socsim:type = " << usd_quoted(e.type) << "\n"
      << "            custom string[] socsim:affordances = [";
    for (std::size_t i = 0; i < e.affordances.size(); ++i)
      o << (i ? ", " : "") << usd_quoted(e.affordances[i]);
    o << "]\n        }\n";
  }
  o << "    }\n}\n";
  return o.str();
}

}  // namespace socsim::world
