// Exports from one World: SVG, Gazebo SDF (well-formed, every link with pose and geometry,
// wall heights), ROS map_server PGM + YAML, pedsim_ros XML (only pedsim elements); golden
// files for the clinic example and the world origin applied to simulator coordinates.
#include "core/world/world_export.hpp"

#include <cmath>
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
