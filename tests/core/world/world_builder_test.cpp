// WorldBuilder: validation once (polygons, overlaps, doors on shared boundaries, walls that
// block doors, ROIs/entities inside zones, reachability for an agent radius) and the walls
// it derives as zone boundaries minus door openings.
#include "core/world/world_builder.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/geometry/planar.hpp"
#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using ::testing::HasSubstr;
using testing::kTwoRooms;
using testing::load;

static_assert(!std::is_default_constructible_v<World>, "only the builder makes worlds");
static_assert(std::is_copy_constructible_v<World>);

double wall_length(const World& w) {
  double l = 0;
  for (const auto& wall : w.walls()) l += geometry::length(wall.segment);
  return l;
}

// The first field error at `pointer`, or a failure listing what was reported.
const FieldError* error_at(const Error& e, const std::string& pointer) {
  for (const auto& fe : e.errors) {
    if (fe.pointer == pointer) return &fe;
  }
  std::string all;
  for (const auto& fe : e.errors) all += "\n  " + fe.pointer + ": " + fe.message;
  ADD_FAILURE() << "no error at " << pointer << "; got:" << all;
  return nullptr;
}

TEST(WorldBuilder, DerivedWallsAreZoneBoundariesMinusTheDoorOpening) {
  const World w = load(kTwoRooms);
  // Outline 24 m + shared wall 4 m − door 1 m.
  EXPECT_NEAR(wall_length(w), 27.0, 1e-9);
  for (const auto& wall : w.walls()) {
    EXPECT_GT(geometry::distance(wall.segment, Point{4, 2}), 0.49) << "a wall covers the door";
    EXPECT_DOUBLE_EQ(wall.height, 3.0);
  }
  const Door& d = w.door(DoorId(0));
  EXPECT_EQ(w.zone(d.zone).name, "a");
  ASSERT_TRUE(d.other.has_value());
  EXPECT_EQ(w.zone(*d.other).name, "b");
  EXPECT_NEAR(geometry::length(d.opening), 1.0, 1e-12);
}

// Issue 14 #11: a vertex at 1e200 m passed and made GEOS fail on overflowing arithmetic.
TEST(WorldBuilder, CoordinatesAreBoundedToAHundredKilometres) {
  for (double far : {1e200, -1e308, kMaxCoordinate * 1.01}) {
    WorldBuilder b;
    b.add_zone(Zone{"hall", "hall", "", {{{0, 0}, {far, 0}, {far, 10}, {0, 10}}, {}}});
    b.add_door(DoorSpec{"d", Pose2{5, 1e300, 0}, 1.0, {"hall"}});
    auto w = b.build();
    ASSERT_FALSE(w);
    EXPECT_THAT(error_at(w.error(), "/zones/0/polygon/1")->message, HasSubstr("within ±100000 m"));
    EXPECT_TRUE(error_at(w.error(), "/doors/0/pose"));
  }
  WorldBuilder edge;
  edge.add_zone(Zone{"hall", "hall", "", {{{-kMaxCoordinate, 0}, {kMaxCoordinate, 0}, {0, 10}}, {}}});
  EXPECT_TRUE(edge.build()) << "±100 km itself is inside the range";
}

TEST(WorldBuilder, DerivedWallsTakeTheZoneMaterialAsStyle) {
  auto b = testing::row_of_rooms(2);
  const World w = b.build().value();
  std::set<std::string> styles;
  for (const auto& wall : w.walls()) styles.insert(wall.style);
  EXPECT_TRUE(styles.count("washable_paint"));
  EXPECT_TRUE(styles.count("painted_plaster"));
}

TEST(WorldBuilder, DoorZonesAreInferredWhenConnectsIsOmitted) {
  const World w = load(R"(zones:
  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}
  - {name: b, polygon: [[4, 0], [8, 0], [8, 4], [4, 4]]}
doors:
  - {name: inner, pose: [4.1, 2], width: 1.0}
  - {name: outer, pose: [8, 2], width: 1.0}
)");
  const Door& inner = w.door(w.find_door("inner").value());
  ASSERT_TRUE(inner.other.has_value());
  EXPECT_EQ(w.zone(inner.zone).name, "a");
  EXPECT_EQ(w.zone(*inner.other).name, "b");
  EXPECT_DOUBLE_EQ(inner.opening.a.x, 4.0);  // snapped onto the shared boundary
  const Door& outer = w.door(w.find_door("outer").value());
  EXPECT_EQ(w.zone(outer.zone).name, "b");
  EXPECT_FALSE(outer.other.has_value());
}

TEST(WorldBuilder, OverlappingZonesAreNamedWithTheOverlapArea) {
  auto w = world_from_yaml(R"(zones:
  - {name: hall, polygon: [[0, 0], [6, 0], [6, 4], [0, 4]]}
  - {name: office, polygon: [[5, 0], [9, 0], [9, 4], [5, 4]]}
)");
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/zones/1/polygon");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("overlaps zone 'hall'"));
  EXPECT_THAT(fe->message, HasSubstr("4 m²"));
}

TEST(WorldBuilder, DoorAwayFromTheSharedBoundaryIsRejected) {
  auto w = world_from_yaml(R"(zones:
  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}
  - {name: b, polygon: [[4, 0], [8, 0], [8, 4], [4, 4]]}
doors:
  - {name: d, pose: [2, 2], width: 1.0, connects: [a, b]}
)");
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/doors/0/pose");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("not on the boundary shared by zones 'a' and 'b' (2 m away"));
}

TEST(WorldBuilder, DoorBetweenZonesThatDoNotTouchIsRejected) {
  auto w = world_from_yaml(R"(zones:
  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}
  - {name: b, polygon: [[4, 0], [8, 0], [8, 4], [4, 4]]}
  - {name: c, polygon: [[8, 0], [12, 0], [12, 4], [8, 4]]}
doors:
  - {name: d, pose: [4, 2], width: 1.0, connects: [a, c]}
)");
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/doors/0/connects");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("share no boundary"));
}

TEST(WorldBuilder, DoorWiderThanItsWallIsRejected) {
  auto b = testing::row_of_rooms(1);
  b.add_door(DoorSpec{"huge", {2, 7, 0}, 6.0, {"room_0"}});
  auto w = b.build();
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/doors/2/width");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("runs 1 m past its end"));
}

TEST(WorldBuilder, OverlappingDoorsAreRejected) {
  auto b = testing::row_of_rooms(1);
  b.add_door(DoorSpec{"twin", {2.3, 2, 0}, 0.9, {"corridor", "room_0"}});
  auto w = b.build();
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/doors/2/pose");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("overlaps door 'room_0_door'"));
}

TEST(WorldBuilder, ZoneWithoutDoorIsUnreachable) {
  auto w = world_from_yaml(R"(zones:
  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}
  - {name: b, polygon: [[4, 0], [8, 0], [8, 4], [4, 4]]}
  - {name: c, polygon: [[8, 0], [12, 0], [12, 4], [8, 4]]}
doors:
  - {name: d, pose: [4, 2], width: 1.0}
)");
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/zones/2");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(
      fe->message,
      HasSubstr("zone 'c' cannot be reached from zone 'a' by an agent of radius 0.25 m; it has no door"));
}

TEST(WorldBuilder, ReachabilityDependsOnTheAgentRadius) {
  BuildOptions wide;
  wide.agent_radius = 0.55;
  auto w = world_from_yaml(kTwoRooms, wide);
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/doors/0/width");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("narrower than an agent of radius 0.55 m"));
  BuildOptions slim;
  slim.agent_radius = 0.45;
  EXPECT_TRUE(world_from_yaml(kTwoRooms, slim));
}

TEST(WorldBuilder, ExplicitWallsCanCutAZoneOff) {
  // An explicit wall right across room b at x = 6 leaves its east half unreachable: the
  // east half is part of zone b, but most of b's free cells are there, so b is reported.
  auto w = world_from_yaml(std::string(kTwoRooms) + R"(walls:
  - {start: [5, 0], end: [5, 4], height: 2.5}
)");
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/zones/1");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("cannot be reached"));
}

TEST(WorldBuilder, ExplicitWallAcrossADoorIsRejected) {
  auto w = world_from_yaml(std::string(kTwoRooms) + R"(walls:
  - {start: [4, 0], end: [4, 4], height: 2.5, style: brick}
)");
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/walls/0");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("blocks door 'd'"));
}

TEST(WorldBuilder, RoiPartlyOutsideTheZonesReportsHowMuch) {
  auto w = world_from_yaml(std::string(kTwoRooms) + R"(segmentation:
  - {name: spill, kind: waiting_zone, polygon: [[6, 3], [10, 3], [10, 5], [6, 5]]}
)");
  ASSERT_FALSE(w);
  const FieldError* fe = error_at(w.error(), "/segmentation/0/polygon");
  ASSERT_NE(fe, nullptr);
  EXPECT_THAT(fe->message, HasSubstr("extends 6 m² (of 8 m²) outside the zones"));
}

TEST(WorldBuilder, RoiSpanningTwoZonesIsFine) {
  const World w = load(std::string(kTwoRooms) + R"(segmentation:
  - {name: walkway_1, polygon: [[1, 1.5], [7, 1.5], [7, 2.5], [1, 2.5]]}
)");
  EXPECT_EQ(w.roi(RoiId(0)).kind, "walkway");  // inferred from the name
}

TEST(WorldBuilder, EveryProblemIsReportedAtOnce) {
  auto w = world_from_yaml(R"(zones:
  - {name: a, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}
  - {name: a, polygon: [[4, 0], [8, 0], [8, 4], [4, 4]]}
entities:
  - {type: chair, name: c1, pose: [1, 1], affordances: [sit, sit]}
segmentation:
  - {name: r, kind: dance_floor, polygon: [[1, 1], [2, 1], [2, 2]]}
)");
  ASSERT_FALSE(w);
  EXPECT_EQ(w.error().code, ErrorCode::kValidation);
  EXPECT_THAT(error_at(w.error(), "/zones/1/name")->message,
              HasSubstr("duplicate name 'a' (already used at /zones/0/name)"));
  EXPECT_THAT(error_at(w.error(), "/entities/0/affordances/1")->message, HasSubstr("duplicate affordance"));
  EXPECT_THAT(error_at(w.error(), "/segmentation/0/kind")->message,
              HasSubstr("unknown ROI kind 'dance_floor'"));
}

TEST(WorldBuilder, NamesMustBeSafeIdentifiers) {
  auto b = testing::row_of_rooms(1);
  b.add_entity(EntitySpec{"table", "table <1>", {1, 1, 0}, {}});
  auto w = b.build();
  ASSERT_FALSE(w);
  EXPECT_THAT(error_at(w.error(), "/entities/0/name")->message, HasSubstr("may only contain"));
}

TEST(WorldBuilder, GeneratorStyleTenRoomPlanBuildsAndIsQueryable) {
  const World w = testing::row_of_rooms(10).build().value();
  EXPECT_EQ(w.zones().size(), 11u);
  EXPECT_EQ(w.doors().size(), 11u);
  EXPECT_NEAR(w.area(), 40 * 2 + 10 * 20, 1e-9);
  EXPECT_EQ(w.zone_at({13, 5}), w.find_zone("room_3"));
  EXPECT_EQ(w.zone_at({13, 1}), w.find_zone("corridor"));
  EXPECT_FALSE(w.zone_at({13, 9}).has_value());
  // Outline 2*(40+7) = 94, inner walls: 9 partitions of 5 m + corridor/room line 40 m;
  // minus 10 room doors (0.9) and the entrance (1.2).
  EXPECT_NEAR(wall_length(w), 94 + 45 + 40 - 9 - 1.2, 1e-9);
}

TEST(WorldBuilder, SameInputGivesTheSameWorld) {
  EXPECT_EQ(testing::row_of_rooms(4).build().value(), testing::row_of_rooms(4).build().value());
}

}  // namespace
}  // namespace socsim::world
