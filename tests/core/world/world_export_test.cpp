// Exports from one World: SVG, Gazebo SDF (well-formed, every link with pose and geometry,
// wall heights), ROS map_server PGM + YAML, pedsim_ros XML (only pedsim elements); golden
// files for the clinic example and the world origin applied to simulator coordinates.
#include "core/world/world_export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/world/pedsim_import.hpp"
#include "core/world/xml_reader.hpp"
#include "tests/core/world/golden.hpp"
#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using ::testing::HasSubstr;

World clinic() {
  return testing::load(testing::example("world_clinic.yaml"));
}

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> out;
  double v = 0;
  while (in >> v) out.push_back(v);
  return out;
}

TEST(WorldExport, SvgDrawsEveryElementWithIds) {
  const World w = clinic();
  auto svg = parse_xml(export_svg(w));
  ASSERT_TRUE(svg) << svg.error().message();
  EXPECT_EQ(svg->name, "svg");
  std::set<std::string> ids;
  std::function<void(const XmlElement&)> walk = [&](const XmlElement& e) {
    if (auto id = e.attribute("id")) ids.insert(*id);
    for (const auto& c : e.children) walk(c);
  };
  walk(*svg);
  for (const auto& z : w.zones()) EXPECT_TRUE(ids.count("zone-" + z.name)) << z.name;
  for (const auto& d : w.doors()) EXPECT_TRUE(ids.count("door-" + d.name)) << d.name;
  for (const auto& r : w.rois()) EXPECT_TRUE(ids.count("roi-" + r.name)) << r.name;
  for (const auto& e : w.entities()) EXPECT_TRUE(ids.count("entity-" + e.name)) << e.name;
}

TEST(WorldExport, SvgGoldenForFigure3) {
  testing::expect_golden(
      "world_fig3.svg",
      "# golden: export_svg of schemas/examples/world_fig3.yaml — zone fill by type, dashed ROIs,\n"
      "# golden: explicit walls, the east door opening, entities and labels; y flipped for SVG.\n",
      export_svg(testing::load(testing::example("world_fig3.yaml"))));
}

TEST(WorldExport, SdfIsWellFormedAndEveryLinkHasPoseAndGeometry) {
  const World w = clinic();
  auto sdf = parse_xml(export_sdf(w));
  ASSERT_TRUE(sdf) << sdf.error().message();
  EXPECT_EQ(sdf->name, "sdf");
  EXPECT_EQ(*sdf->attribute("version"), "1.7");
  const XmlElement& world = sdf->children.at(0);
  EXPECT_EQ(*world.attribute("name"), "clinic_small");
  std::size_t wall_links = 0;
  for (const XmlElement* model : world.children_named("model")) {
    ASSERT_EQ(model->children_named("pose").size(), 1u);
    for (const XmlElement* link : model->children_named("link")) {
      const auto poses = link->children_named("pose");
      ASSERT_EQ(poses.size(), 1u) << *link->attribute("name");
      EXPECT_EQ(numbers(poses[0]->text).size(), 6u);
      for (const char* part : {"collision", "visual"}) {
        const auto parts = link->children_named(part);
        ASSERT_EQ(parts.size(), 1u);
        const auto geometry = parts[0]->children_named("geometry");
        ASSERT_EQ(geometry.size(), 1u);
        const auto size = geometry[0]->children.at(0).children_named("size");
        ASSERT_EQ(size.size(), 1u);
        const auto dims = numbers(size[0]->text);
        ASSERT_EQ(dims.size(), 3u);
        for (double d : dims) EXPECT_GT(d, 0.0);
      }
      if (*model->attribute("name") == "walls") {
        ++wall_links;
        // Height of the box = the wall's height (3 m), centred at half height.
        const auto dims =
            numbers(link->children_named("collision")[0]->children[0].children[0].children[0].text);
        EXPECT_DOUBLE_EQ(dims[2], 3.0);
        EXPECT_DOUBLE_EQ(numbers(poses[0]->text)[2], 1.5);
      }
    }
  }
  EXPECT_EQ(wall_links, w.walls().size());
}

TEST(WorldExport, SdfGoldenForTheClinic) {
  testing::expect_golden(
      "world_clinic.sdf",
      "# golden: export_sdf of schemas/examples/world_clinic.yaml — floor box, one static link per\n"
      "# golden: derived wall (length x 0.15 x 3 m box at its centre, corners closed, jambs not).\n",
      export_sdf(clinic()));
}

// USD ASCII read back by a small reader of its syntax: the header, balanced brackets outside
// strings, every prim a valid identifier unique among its siblings, finite numbers; the scopes hold
// one prim per zone, non-degenerate wall, door, region and entity.
struct UsdaPrims {
  std::map<std::string, std::vector<std::string>> children;  // scope path → prim names
  std::string error;
};
UsdaPrims read_usda(const std::string& text) {
  UsdaPrims out;
  if (text.rfind("#usda 1.0\n", 0) != 0) out.error = "no #usda 1.0 header";
  std::vector<char> open;
  std::vector<std::string> path;  // prim names of the open '{' blocks ("" for non-prim braces)
  std::string pending;            // the prim a following '{' opens
  bool in_string = false;
  for (std::size_t i = 0; i < text.size() && out.error.empty(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '#' && (i == 0 || text[i - 1] == '\n')) {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    const bool word_start = i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1]));
    if (word_start && (text.compare(i, 3, "nan") == 0 || text.compare(i, 3, "inf") == 0) &&
        (i + 3 >= text.size() || !std::isalnum(static_cast<unsigned char>(text[i + 3]))))
      out.error = "a non-finite number";
    if (c == '"') {
      in_string = true;
    } else if (c == 'd' && text.compare(i, 4, "def ") == 0 && (i == 0 || std::isspace(text[i - 1]))) {
      const std::size_t q1 = text.find('"', i), q2 = text.find('"', q1 + 1);
      const std::string name = text.substr(q1 + 1, q2 - q1 - 1);
      const bool valid = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                         std::all_of(name.begin(), name.end(), [](char ch) {
                           return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
                         });
      if (!valid) out.error = "invalid prim name '" + name + "'";
      std::string parent;
      for (const auto& p : path)
        if (!p.empty()) parent += "/" + p;
      auto& siblings = out.children[parent];
      if (std::find(siblings.begin(), siblings.end(), name) != siblings.end())
        out.error = "prim " + parent + "/" + name + " defined twice";
      siblings.push_back(name);
      pending = name;
      i = q2;
    } else if (c == '{' || c == '(' || c == '[') {
      open.push_back(c);
      if (c == '{') path.push_back(std::exchange(pending, {}));
    } else if (c == '}' || c == ')' || c == ']') {
      const char want = c == '}' ? '{' : c == ')' ? '(' : '[';
      if (open.empty() || open.back() != want)
        out.error = std::string("unbalanced '") + c + "'";
      else
        open.pop_back();
      if (c == '}' && !path.empty()) path.pop_back();
    }
  }
  if (out.error.empty() && (in_string || !open.empty())) out.error = "unclosed string or bracket";
  return out;
}

TEST(WorldExport, UsdaStageHasOnePrimPerElementAndParses) {
  for (const char* file : {"world_clinic.yaml", "world_fig3.yaml"}) {
    const World w = testing::load(testing::example(file));
    const std::string usda = export_usda(w);
    const UsdaPrims prims = read_usda(usda);
    ASSERT_TRUE(prims.error.empty()) << file << ": " << prims.error;
    EXPECT_EQ(prims.children.at(""), std::vector<std::string>{"World"});
    EXPECT_EQ(prims.children.at("/World"),
              (std::vector<std::string>{"Zones", "Walls", "Doors", "Regions", "Entities"}));
    auto count = [&](const std::string& scope) {
      const auto it = prims.children.find("/World/" + scope);
      return it == prims.children.end() ? 0u : it->second.size();
    };
    EXPECT_EQ(count("Zones"), w.zones().size()) << file;
    EXPECT_EQ(count("Walls"), w.walls().size()) << file;
    EXPECT_EQ(count("Doors"), w.doors().size()) << file;
    EXPECT_EQ(count("Regions"), w.rois().size()) << file;
    EXPECT_EQ(count("Entities"), w.entities().size()) << file;
    EXPECT_THAT(usda, HasSubstr("upAxis = \"Z\""));
  }
  // Names that are not USD identifiers are made into ones, and stay distinct.
  World odd = testing::load(R"(name: odd
zones:
  - {name: 2nd.floor, type: hall, polygon: [[0,0],[4,0],[4,4],[0,4]]}
  - {name: 2nd-floor, type: hall, polygon: [[4,0],[8,0],[8,4],[4,4]]}
doors:
  - {name: d, pose: [4, 2], width: 1.0, connects: [2nd.floor, 2nd-floor]}
)");
  const UsdaPrims prims = read_usda(export_usda(odd));
  ASSERT_TRUE(prims.error.empty()) << prims.error;
  EXPECT_EQ(prims.children.at("/World/Zones"), (std::vector<std::string>{"_2nd_floor", "_2nd_floor_2"}));
}

TEST(WorldExport, UsdaGoldenForTheClinic) {
  testing::expect_golden(
      "world_clinic.usda",
      "# golden: export_usda of schemas/examples/world_clinic.yaml — zones as flat meshes, "
      "walls as scaled cubes,\n"
      "# golden: doors, regions (guide meshes) and entities with socsim:* attributes.\n",
      export_usda(clinic()));
}

TEST(WorldExport, RosMapMarksWallsAndOutsideOccupied) {
  const World w = clinic();
  const RosMap map = export_ros_map(w, RosMapOptions{0.1, "clinic.pgm"});
  std::istringstream in(map.pgm);
  std::string magic, comment;
  int width = 0, height = 0, maxval = 0;
  in >> magic;
  in.get();
  std::getline(in, comment);
  in >> width >> height >> maxval;
  in.get();
  EXPECT_EQ(magic, "P5");
  EXPECT_EQ(comment, "# socsim world clinic_small");
  EXPECT_EQ(width, 202);  // 20 m / 0.1 + one cell margin each side
  EXPECT_EQ(height, 122);
  EXPECT_EQ(maxval, 255);
  const std::size_t data = static_cast<std::size_t>(in.tellg());
  ASSERT_EQ(map.pgm.size() - data, static_cast<std::size_t>(width * height));
  auto pixel = [&](double x, double y) {
    // Map origin is (-0.1, -0.1); rows are stored top down.
    const int col = static_cast<int>(std::floor((x + 0.1) / 0.1));
    const int row = height - 1 - static_cast<int>(std::floor((y + 0.1) / 0.1));
    return static_cast<unsigned char>(map.pgm[data + static_cast<std::size_t>(row * width + col)]);
  };
  EXPECT_EQ(pixel(5, 3), 254);      // lobby
  EXPECT_EQ(pixel(10.01, 1), 0);    // wall between lobby and corridor
  EXPECT_EQ(pixel(10.01, 3), 254);  // ... except at the door
  EXPECT_EQ(pixel(-0.05, 3), 0);    // outside
  EXPECT_THAT(map.yaml, HasSubstr("image: clinic.pgm\n"));
  testing::expect_golden(
      "world_clinic.map.yaml",
      "# golden: export_ros_map metadata for schemas/examples/world_clinic.yaml at 0.1 m.\n", map.yaml);
}

TEST(WorldExport, PedsimUsesOnlyPedsimElements) {
  const World w = clinic();
  auto doc = parse_xml(export_pedsim(w));
  ASSERT_TRUE(doc) << doc.error().message();
  EXPECT_EQ(doc->name, "scenario");
  const std::set<std::string> known = {"obstacle", "waypoint", "queue", "attraction", "agent", "source"};
  for (const auto& e : doc->children) EXPECT_TRUE(known.count(e.name)) << e.name;
  EXPECT_EQ(doc->children_named("obstacle").size(), w.walls().size());
  EXPECT_EQ(doc->children_named("waypoint").size(), 2u + w.entities().size());
  ASSERT_EQ(doc->children_named("queue").size(), 1u);
  const XmlElement& queue = *doc->children_named("queue")[0];
  // The queue lane runs from the reception counter (y 4.8) down: head at the counter end.
  EXPECT_EQ(*queue.attribute("x"), "5");
  EXPECT_EQ(*queue.attribute("y"), "4.2");
  EXPECT_EQ(*queue.attribute("direction"), "270");
  EXPECT_EQ(doc->children_named("attraction").size(), 1u);
  // Each id once: the export reads back (the waiting seats were a waypoint and an attraction).
  auto back = import_pedsim(export_pedsim(w));
  EXPECT_TRUE(back) << back.error().message();
  testing::expect_golden(
      "world_clinic.pedsim.xml",
      "# golden: export_pedsim of schemas/examples/world_clinic.yaml — obstacles from derived walls,\n"
      "# golden: waypoints from ROIs and entities, the reception queue, the waiting-seat attraction.\n",
      export_pedsim(w));
}

TEST(WorldExport, OriginPlacesTheWorldInSimulatorCoordinates) {
  const World w = testing::load(R"(origin: [100, 50, 1.5707963267948966]
zones:
  - {name: a, polygon: [[0, 0], [4, 0], [4, 2], [0, 2]]}
walls:
  - {start: [0, 0], end: [4, 0]}
)");
  auto doc = parse_xml(export_pedsim(w));
  ASSERT_TRUE(doc);
  const XmlElement& ob = *doc->children_named("obstacle").at(0);
  EXPECT_EQ(*ob.attribute("x1"), "100");
  EXPECT_EQ(*ob.attribute("y1"), "50");
  EXPECT_EQ(*ob.attribute("x2"), "100");
  EXPECT_EQ(*ob.attribute("y2"), "54");
  EXPECT_THAT(export_sdf(w), HasSubstr("<pose>100 50 0 0 0 1.570796</pose>"));
  EXPECT_THAT(export_ros_map(w).yaml, HasSubstr("origin: [100.05, 49.95, 1.570796]"));
}

}  // namespace
}  // namespace socsim::world
