// world.yaml: Fig. 3 of paper 001 loads as transcribed and exactly as printed (zone region
// inferred, with warnings), the writer's output reads back to the same world (golden file),
// and broken files each name line, column and field.
#include "core/world/world_yaml.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/geometry/planar.hpp"
#include "tests/core/world/golden.hpp"
#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using testing::example;
using ::testing::HasSubstr;

TEST(WorldYaml, PaperFigure3LoadsAsWritten) {
  auto w = world_from_yaml(example("world_fig3.yaml"));
  ASSERT_TRUE(w) << w.error().message();
  EXPECT_EQ(w->zones().size(), 1u);
  EXPECT_EQ(w->zone(ZoneId(0)).name, "canteen_hall");
  EXPECT_EQ(w->walls().size(), 5u);
  EXPECT_EQ(w->walls()[0].style, "white_paint");
  EXPECT_DOUBLE_EQ(w->walls()[0].height, 3.0);
  EXPECT_EQ(w->floor().material, "polished_concrete");
  const Door& door = w->door(w->find_door("entrance_east").value());
  EXPECT_FALSE(door.other.has_value());  // the entrance leads outside
  EXPECT_DOUBLE_EQ(door.opening.a.x, 10.0);
  EXPECT_DOUBLE_EQ(door.pose.x, 9.8);  // kept as written
  EXPECT_EQ(w->roi(w->find_roi("queue_lane").value()).kind, "queue_lane");
  EXPECT_EQ(w->roi(w->find_roi("seating_area").value()).kind, "seating_area");
  const Entity& counter = w->entity(w->find_entity("food_counter").value());
  EXPECT_EQ(counter.type, "counter");
  EXPECT_EQ(counter.pose.position(), (Point{8.5, 1.5}));
}

// tests/fixtures/paper001_fig3_as_printed.yaml is the listing of Fig. 3 exactly as the paper
// prints it: the zone named only, one wall, and '↳' where the listing wraps its long lines.
TEST(WorldYaml, PaperFigure3AsPrintedLoadsWithWarnings) {
  auto r = read_world_yaml(
      testing::read_text(std::string(SOCSIM_SOURCE_DIR) + "/tests/fixtures/paper001_fig3_as_printed.yaml"));
  ASSERT_TRUE(r) << r.error().message();
  const World& w = r->world;
  ASSERT_EQ(w.zones().size(), 1u);
  // The one wall closes nothing, so the hall spans the wall, the door, the areas and entities.
  EXPECT_EQ(w.zone(ZoneId(0)).polygon.outer, (std::vector<Point>{{0, 0}, {10, 0}, {10, 8}, {0, 8}}));
  EXPECT_EQ(w.zone(ZoneId(0)).type, "room");
  const Door& door = w.door(w.find_door("entrance_east").value());
  EXPECT_FALSE(door.other.has_value());
  EXPECT_EQ(door.opening, (Segment{{10, 1.4}, {10, 2.6}}));
  // The written wall, then the rest of the hall's boundary in its style, the entrance open.
  ASSERT_EQ(w.walls().size(), 5u);
  EXPECT_EQ(w.walls()[0].segment, (Segment{{0, 0}, {10, 0}}));
  double length = 0;
  for (const Wall& wall : w.walls()) {
    EXPECT_EQ(wall.style, "white_paint");
    EXPECT_DOUBLE_EQ(wall.height, 3.0);
    length += geometry::length(wall.segment);
  }
  EXPECT_NEAR(length, 36.0 - 1.2, 1e-9);
  EXPECT_EQ(w.floor().material, "polished_concrete");
  EXPECT_EQ(w.roi(w.find_roi("queue_lane").value()).kind, "queue_lane");
  EXPECT_EQ(w.roi(w.find_roi("seating_area").value()).kind, "seating_area");
  EXPECT_EQ(w.entity(w.find_entity("t_01").value()).pose.position(), (Point{3, 5}));

  ASSERT_EQ(r->warnings.size(), 3u);
  EXPECT_EQ(r->warnings[0].line, 6);
  EXPECT_THAT(r->warnings[0].message, HasSubstr("lines 6, 9, 13, 15, 18, 20 begin with '↳'"));
  EXPECT_EQ(r->warnings[1].pointer, "/zones/0/polygon");
  EXPECT_EQ(r->warnings[1].line, 3);
  EXPECT_EQ(
      r->warnings[1].message,
      "zone 'canteen_hall' has no polygon and its walls enclose no region: it takes the rectangle x 0 .. "
      "10, y 0 .. 8 (80 m²) spanned by the walls, doors, segmentation areas and entities");
  EXPECT_EQ(r->warnings[2].pointer, "/walls");
  EXPECT_THAT(r->warnings[2].message, HasSubstr("4 walls (24.8 m) added"));

  // Written out, it is an ordinary world.yaml that reads back the same, without warnings.
  auto again = read_world_yaml(world_to_yaml(w));
  ASSERT_TRUE(again) << again.error().message();
  EXPECT_EQ(again->world, w);
  EXPECT_TRUE(again->warnings.empty());
}

TEST(WorldYaml, AZoneWrittenByNameTakesTheRegionItsWallsEnclose) {
  // An L-shaped hall closed by its walls and the gap of its entrance; a kiosk with its own
  // polygon stands in a corner, and walls are added around it (its door left open).
  auto r = read_world_yaml(R"(zones:
  - name: hall
  - {name: kiosk, polygon: [[0, 0], [2, 0], [2, 2], [0, 2]]}
walls:
  - {start: [0, 0], end: [5.4, 0]}
  - {start: [6.6, 0], end: [8, 0]}
  - {start: [8, 0], end: [8, 4]}
  - {start: [8, 4], end: [4, 4]}
  - {start: [4, 4], end: [4, 8]}
  - {start: [4, 8], end: [0, 8]}
  - {start: [0, 8], end: [0, 0]}
doors:
  - {name: in, pose: [6, 0], width: 1.2}
  - {name: kiosk_door, pose: [2, 1], width: 0.9}
)");
  ASSERT_TRUE(r) << r.error().message();
  const World& w = r->world;
  EXPECT_DOUBLE_EQ(geometry::area(w.zone(ZoneId(0)).polygon), 48.0 - 4.0);
  ASSERT_EQ(r->warnings.size(), 2u);
  EXPECT_EQ(r->warnings[0].message,
            "zone 'hall' has no polygon: it takes the region its walls enclose, x 0 .. 8, y 0 .. 8 (44 m²)");
  EXPECT_EQ(r->warnings[0].line, 2);
  EXPECT_THAT(r->warnings[1].message, HasSubstr("3 walls (3.1 m) added along its boundary"));
  EXPECT_EQ(w.walls().size(), 7u + 3u);
  EXPECT_EQ(w.door(w.find_door("kiosk_door").value()).other, std::optional<ZoneId>(ZoneId(1)));
  EXPECT_FALSE(w.door(w.find_door("in").value()).other.has_value());
}

TEST(WorldYaml, AZoneNothingEnclosesIsRefusedWithItsLine) {
  struct Case {
    const char* yaml;
    int line;
    const char* message;
  };
  const Case cases[] = {
      // The figure's first lines: one wall and nothing else to span a region.
      {"zones:\n  - name: canteen_hall\nwalls:\n  - {start: [0.0, 0.0], end: [10.0, 0.0],\n    height: "
       "3.0}\n",
       2,
       "zone 'canteen_hall' has no polygon, its walls enclose no region and there are no segmentation areas "
       "to span one; give it a polygon or walls that close around it"},
      // Two rooms closed by walls: which one is the zone?
      {"zones:\n  - name: z\nwalls:\n  - {start: [0, 0], end: [2, 0]}\n  - {start: [2, 0], end: [2, 2]}\n"
       "  - {start: [2, 2], end: [0, 2]}\n  - {start: [0, 2], end: [0, 0]}\n  - {start: [5, 0], end: [7, "
       "0]}\n"
       "  - {start: [7, 0], end: [7, 2]}\n  - {start: [7, 2], end: [5, 2]}\n  - {start: [5, 2], end: [5, "
       "0]}\n",
       2,
       "zone 'z' has no polygon and the walls enclose 2 separate regions (x 0 .. 7, y 0 .. 2); give the zone "
       "a polygon"},
      // Only one zone may be written by name.
      {"zones:\n  - name: a\n  - name: b\nsegmentation:\n  - {name: q, polygon: [[0, 0], [1, 0], [1, 1]]}\n",
       3,
       "zone 'b' has no polygon; only one zone of a world may take its region from the walls (zone 'a' at "
       "/zones/0 does), so give it a polygon"},
  };
  for (const auto& c : cases) {
    auto w = world_from_yaml(c.yaml);
    ASSERT_FALSE(w) << c.yaml;
    EXPECT_EQ(w.error().code, ErrorCode::kValidation);
    ASSERT_EQ(w.error().errors.size(), 1u) << w.error().message();
    EXPECT_EQ(w.error().errors[0].pointer, c.line == 3 ? "/zones/1/polygon" : "/zones/0/polygon");
    EXPECT_EQ(w.error().errors[0].line, c.line) << c.yaml;
    EXPECT_EQ(w.error().errors[0].message, c.message);
  }
}

TEST(WorldYaml, OnlyAWrapMarkThatBeginsALineIsRead) {
  // Inside a name the mark is an ordinary character, and names may not contain it.
  auto w = world_from_yaml("zones:\n  - {name: \"a↳b\", polygon: [[0, 0], [1, 0], [1, 1]]}\n");
  ASSERT_FALSE(w);
  EXPECT_EQ(w.error().errors[0].pointer, "/zones/0/name");
  auto plain = read_world_yaml(testing::kTwoRooms);
  ASSERT_TRUE(plain);
  EXPECT_TRUE(plain->warnings.empty());
}

TEST(WorldYaml, ClinicExampleLoadsWithDerivedWalls) {
  auto w = world_from_yaml(example("world_clinic.yaml"));
  ASSERT_TRUE(w) << w.error().message();
  EXPECT_EQ(w->zones().size(), 5u);
  EXPECT_EQ(w->doors().size(), 6u);
  EXPECT_FALSE(w->walls().empty());
  EXPECT_EQ(w->rois_of_kind("queue_lane").size(), 1u);
}

TEST(WorldYaml, WritingAndReadingBackGivesTheSameWorld) {
  for (const char* name : {"world_fig3.yaml", "world_clinic.yaml"}) {
    const World w = testing::load(example(name));
    const std::string text = world_to_yaml(w);
    auto again = world_from_yaml(text);
    ASSERT_TRUE(again) << name << ": " << again.error().message() << "\n" << text;
    EXPECT_EQ(*again, w) << name;
    EXPECT_EQ(world_to_yaml(*again), text) << name << ": writing is not stable";
  }
}

TEST(WorldYaml, ClinicGoldenFile) {
  testing::expect_golden(
      "world_clinic.yaml",
      "# golden: world_to_yaml of schemas/examples/world_clinic.yaml — derived walls (zone\n"
      "# golden: boundaries minus door openings, zone materials as styles), doors with connects,\n"
      "# golden: ROI kinds, entity affordances, yaw only where non-zero, shortest numbers.\n",
      world_to_yaml(testing::load(example("world_clinic.yaml"))));
}

TEST(WorldYaml, UnitsAreConvertedToMetresAndRadians) {
  const World w = testing::load(R"(units: {length: cm, angle: deg}
zones:
  - {name: a, polygon: [[0, 0], [400, 0], [400, 400], [0, 400]]}
entities:
  - {type: chair, name: c, pose: [100, 200, 90]}
)");
  EXPECT_DOUBLE_EQ(w.zone(ZoneId(0)).polygon.outer[2].x, 4.0);
  EXPECT_DOUBLE_EQ(w.entity(EntityId(0)).pose.y, 2.0);
  EXPECT_NEAR(w.entity(EntityId(0)).pose.yaw, 1.5707963267948966, 1e-15);
}

struct BrokenCase {
  const char* what;
  const char* yaml;
  const char* pointer;
  int line;
  const char* message;
};

class BrokenWorld : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(BrokenWorld, NamesLineColumnAndField) {
  const BrokenCase& c = GetParam();
  auto w = world_from_yaml(c.yaml);
  ASSERT_FALSE(w) << c.what;
  EXPECT_EQ(w.error().status(), 422) << c.what;
  const FieldError* found = nullptr;
  for (const auto& fe : w.error().errors) {
    if (fe.pointer == c.pointer) found = &fe;
  }
  ASSERT_NE(found, nullptr) << c.what << ": " << w.error().message();
  EXPECT_EQ(found->line, c.line) << c.what;
  EXPECT_GT(found->column, 0) << c.what;
  EXPECT_THAT(found->message, HasSubstr(c.message)) << c.what;
}

constexpr const char* kRoom = "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\n";

INSTANTIATE_TEST_SUITE_P(
    TenKindsOfMistakes, BrokenWorld,
    ::testing::Values(
        BrokenCase{"zone without polygon", "zones:\n  - name: hall\n    type: lobby\n", "/zones/0/polygon", 2,
                   "its walls enclose no region and there are no segmentation areas"},
        BrokenCase{"self-crossing polygon",
                   "zones:\n  - name: bow\n    polygon: [[0, 0], [4, 4], [4, 0], [0, 4]]\n",
                   "/zones/0/polygon", 3, "Self-intersection at (2, 2)"},
        BrokenCase{"door on no wall",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\ndoors:\n  - {name: d, "
                   "pose: [2, 2], width: 1}\n",
                   "/doors/0/pose", 4, "is on no zone boundary"},
        BrokenCase{"ROI outside every zone",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\nsegmentation:\n  - "
                   "name: far\n    kind: waiting_zone\n    polygon: [[10, 10], [12, 10], [12, 12]]\n",
                   "/segmentation/0/polygon", 6, "ROI 'far' lies outside every zone"},
        BrokenCase{"duplicate names",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\nentities:\n  - {type: "
                   "table, name: a, pose: [1, 1]}\n",
                   "/entities/0/name", 4, "duplicate name 'a'"},
        BrokenCase{"unknown key",
                   "zones:\n  - name: a\n    colour: red\n    polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]\n",
                   "/zones/0/colour", 3, "unknown field 'colour'"},
        BrokenCase{"wrong type",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\ndoors:\n  - {name: d, "
                   "pose: [4, 2], width: wide}\n",
                   "/doors/0/width", 4, "must be a number"},
        BrokenCase{"point with three coordinates",
                   "zones:\n  - name: a\n    polygon: [[0, 0], [4, 0, 1], [4, 4]]\n", "/zones/0/polygon/1", 3,
                   "must be a point [x, y]"},
        BrokenCase{"overlapping zones",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\n  - {name: b, polygon: "
                   "[[3, 0], [7, 0], [7, 4], [3, 4]]}\n",
                   "/zones/1/polygon", 3, "overlaps zone 'a'"},
        BrokenCase{"unreachable zone",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\n  - {name: b, polygon: "
                   "[[4, 0], [8, 0], [8, 4], [4, 4]]}\n",
                   "/zones/1", 3, "cannot be reached from zone 'a'"},
        BrokenCase{"door to an unknown zone",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\ndoors:\n  - name: d\n  "
                   "  pose: [4, 2]\n    width: 1\n    connects: [a, kitchen]\n",
                   "/doors/0/connects/1", 7, "unknown zone 'kitchen'"},
        BrokenCase{"entity outside every zone",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\nentities:\n\n  - "
                   "{type: bed, name: bed_1, pose: [9, 9]}\n",
                   "/entities/0/pose", 5, "is outside every zone"},
        BrokenCase{"unknown ROI kind",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\nsegmentation:\n  - "
                   "{name: r, kind: ballroom, polygon: [[1, 1], [2, 1], [2, 2]]}\n",
                   "/segmentation/0/kind", 4, "unknown ROI kind 'ballroom'"},
        BrokenCase{"zones not a list", "zones: {name: a}\n", "/zones", 1, "must be an array"},
        BrokenCase{"negative wall height",
                   "zones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\nwalls:\n  - {start: "
                   "[0, 0], end: [4, 0], height: -1}\n",
                   "/walls/0/height", 4, "positive number of metres"},
        BrokenCase{
            "unknown unit",
            "units: {length: furlong}\nzones:\n  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}\n",
            "/units/length", 1, "unknown length unit 'furlong'"}),
    [](const ::testing::TestParamInfo<BrokenCase>& param_info) {
      std::string n = param_info.param.what;
      for (char& ch : n) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      }
      return n;
    });

TEST(WorldYaml, SyntaxErrorsAndAliasesAre400WithALine) {
  auto syntax = world_from_yaml(std::string(kRoom) + "doors:\n  - {name: d, pose: [4, 2], width: 1\n");
  ASSERT_FALSE(syntax);
  EXPECT_EQ(syntax.error().status(), 400);
  EXPECT_GT(syntax.error().errors.at(0).line, 3);
  auto alias = world_from_yaml("base: &p [[0, 0], [4, 0], [4, 4]]\nzones:\n  - {name: a, polygon: *p}\n");
  ASSERT_FALSE(alias);
  EXPECT_EQ(alias.error().status(), 400);
  EXPECT_EQ(alias.error().errors.at(0).line, 1);
}

TEST(WorldYaml, EmptyFileSaysWhatIsMissing) {
  auto w = world_from_yaml("");
  ASSERT_FALSE(w);
  EXPECT_EQ(w.error().errors.at(0).pointer, "/zones");
}

}  // namespace
}  // namespace socsim::world
