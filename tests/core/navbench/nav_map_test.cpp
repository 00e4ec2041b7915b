// The grid of reachable points and the action model: free cells lie inside rooms, clear of walls
// and furniture; rooms connect only through doors; sight stops at walls; seeing needs range and
// field of view; breadth-first step counts agree with the closed form in an open room and with an
// independent relaxation in a house with walls.
#include "core/navbench/nav_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/core/navbench/navbench_fixture.hpp"

namespace socsim::navbench {
namespace {

using household::RoomType;
using testing::cell_near;
using testing::hand_built_house;
using testing::map_of;

//  z=3 +----------------+----------------+
//      |    kitchen     |  living room   |
//      |     [table]   door              |
//      |                |                |
//  z=0 +----------------+----------------+
//     x=0              x=4              x=8
household::House two_rooms(bool with_door = true) {
  std::vector<testing::DoorAt> doors;
  if (with_door) doors.push_back({0, 1, 4.0, 1.5});
  return hand_built_house({{RoomType::kKitchen, 0, 0, 4, 3}, {RoomType::kLivingRoom, 4, 0, 8, 3}}, doors,
                          {{"DiningTable", 0, 2.0, 1.5, 1.0, 1.0}, {"Sofa", 1, 6.0, 2.6, 1.6, 0.6}});
}

TEST(NavMap, FreeCellsAreInsideRoomsClearOfWallsAndFurniture) {
  const auto house = two_rooms();
  const NavMap map = map_of(house);
  EXPECT_EQ(map.width(), 32);
  EXPECT_EQ(map.depth(), 12);
  EXPECT_TRUE(map.free(cell_near(map, 0.1, 0.1)));   // 0.125 m from both walls
  EXPECT_FALSE(map.free(cell_near(map, 2.1, 1.6)));  // under the table
  EXPECT_FALSE(map.free(cell_near(map, 6.0, 2.6)));  // under the sofa
  EXPECT_TRUE(map.free(cell_near(map, 2.1, 0.3)));
  NavConfig wide;
  wide.wall_clearance = 0.2;
  EXPECT_FALSE(map_of(house, wide).free(cell_near(map, 0.1, 0.1)));
  // 192 cells per room minus footprints (cells whose centre is under the table: 4×4, the sofa: 6×3).
  EXPECT_EQ(map.free_cells(), 2 * 192 - 16 - 18);
}

TEST(NavMap, RoomsConnectOnlyThroughTheDoor) {
  const auto house = two_rooms();
  const NavMap map = map_of(house);
  const int start = pose_of(cell_near(map, 0.6, 0.6), 0);
  const StepField field = map.steps_from(start);
  const int living = cell_near(map, 7.5, 0.5);
  ASSERT_GE(field.distance[static_cast<std::size_t>(pose_of(living, 0))], 0);
  // Every move of the path that crosses x = 4 passes through the opening (z in 1.05 … 1.95).
  const auto path = field.path_to(pose_of(living, 0));
  int previous = start;
  for (int p : path) {
    const auto a = map.center(cell_of(previous)), b = map.center(cell_of(p));
    if ((a.x - 4.0) * (b.x - 4.0) < 0) {
      EXPECT_GT(a.z, 1.05);
      EXPECT_LT(a.z, 1.95);
    }
    previous = p;
  }
  const NavMap closed = map_of(two_rooms(false));
  EXPECT_EQ(closed.steps_from(start).distance[static_cast<std::size_t>(pose_of(living, 0))], -1);
}

TEST(NavMap, SightStopsAtWallsAndPassesTheDoor) {
  const NavMap map = map_of(two_rooms());
  EXPECT_FALSE(map.line_of_sight({3.5, 0.5}, {4.5, 0.5}));
  EXPECT_TRUE(map.line_of_sight({3.5, 1.5}, {4.5, 1.5}));
  EXPECT_TRUE(map.line_of_sight({0.5, 0.5}, {3.5, 2.5}));
}

TEST(NavMap, SeeingNeedsRangeFieldOfViewAndLineOfSight) {
  const NavMap map = map_of(two_rooms());
  const int cell = cell_near(map, 2.1, 0.1);  // centre (2.125, 0.125), 1.375 m below the table's centre
  EXPECT_TRUE(map.sees(pose_of(cell, 1), {2.0, 1.5}));   // facing +z
  EXPECT_FALSE(map.sees(pose_of(cell, 3), {2.0, 1.5}));  // facing away
  EXPECT_FALSE(map.sees(pose_of(cell, 0), {2.0, 1.5}));  // 95° to the side: outside a 90° view
  EXPECT_FALSE(map.sees(pose_of(cell_near(map, 0.1, 0.1), 0), {2.0, 1.5}));  // 2.4 m away
  EXPECT_FALSE(map.sees(pose_of(cell_near(map, 3.6, 2.6), 0), {4.5, 2.6}));  // 0.9 m, but through the wall
  // The table is on the map with the poses that see it; the one above is among them when the
  // distance is taken on the floor, not when it is taken from a camera 1.5 m up to the table's
  // top at 0.85 m (1.35 m on the floor at most).
  NavConfig flat;
  flat.view_distance_from_camera = false;
  const NavMap flat_map = map_of(two_rooms(), flat);
  const auto& table = flat_map.receptacles()[0];
  EXPECT_EQ(table.type, "DiningTable");
  EXPECT_TRUE(std::binary_search(table.views.begin(), table.views.end(), pose_of(cell, 1)));
  for (int v : table.views) EXPECT_TRUE(map.sees(v, {table.x, table.z}));
  const auto& views = map.receptacles()[0].views;
  EXPECT_FALSE(std::binary_search(views.begin(), views.end(), pose_of(cell, 1)));
  for (int v : views) {
    const auto c = map.center(cell_of(v));
    EXPECT_LE(std::hypot(c.x - table.x, c.z - table.z), std::sqrt(1.5 * 1.5 - 0.65 * 0.65) + 1e-9);
  }
}

int turns(int from, int to) {
  const int d = ((to - from) % 4 + 4) % 4;
  return d == 3 ? 1 : d;
}

TEST(NavMap, StepsInAnOpenRoomAreManhattanPlusTurns) {
  const NavMap map = map_of(hand_built_house({{RoomType::kBedroom, 0, 0, 3, 2}}, {}, {}));
  ASSERT_EQ(map.free_cells(), 96);
  for (int a = 0; a < map.cells(); a += 7)
    for (int h = 0; h < kHeadings; ++h) {
      const StepField field = map.steps_from(pose_of(a, h));
      for (int b = 0; b < map.cells(); ++b) {
        const int dx = b % map.width() - a % map.width(), dz = b / map.width() - a / map.width();
        int expected = std::abs(dx) + std::abs(dz);
        if (dx != 0 && dz != 0)
          expected += 1 + std::min(turns(h, dx > 0 ? 0 : 2), turns(h, dz > 0 ? 1 : 3));
        else if (dx != 0)
          expected += turns(h, dx > 0 ? 0 : 2);
        else if (dz != 0)
          expected += turns(h, dz > 0 ? 1 : 3);
        const int poses[] = {pose_of(b, 0), pose_of(b, 1), pose_of(b, 2), pose_of(b, 3)};
        const int nearest = field.nearest(poses);
        ASSERT_EQ(field.distance[static_cast<std::size_t>(nearest)], expected)
            << "from cell " << a << " heading " << h << " to " << b;
        ASSERT_EQ(static_cast<int>(field.path_to(nearest).size()), expected);
      }
    }
}

TEST(NavMap, BreadthFirstStepsAgreeWithRelaxationAroundWalls) {
  const NavMap map = map_of(two_rooms());
  const int start = pose_of(cell_near(map, 0.6, 2.6), 3);
  const StepField field = map.steps_from(start);
  // Bellman–Ford over the same three actions, written independently of the queue.
  std::vector<int> d(static_cast<std::size_t>(map.poses()), 1 << 28);
  d[static_cast<std::size_t>(start)] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int p = 0; p < map.poses(); ++p) {
      if (d[static_cast<std::size_t>(p)] >= (1 << 28)) continue;
      for (int action = 0; action < 3; ++action) {
        const int q = map.act(p, action);
        if (d[static_cast<std::size_t>(p)] + 1 < d[static_cast<std::size_t>(q)])
          d[static_cast<std::size_t>(q)] = d[static_cast<std::size_t>(p)] + 1, changed = true;
      }
    }
  }
  int reachable = 0;
  for (int p = 0; p < map.poses(); ++p) {
    const int expected = d[static_cast<std::size_t>(p)] >= (1 << 28) ? -1 : d[static_cast<std::size_t>(p)];
    ASSERT_EQ(field.distance[static_cast<std::size_t>(p)], expected) << "pose " << p;
    reachable += expected >= 0;
  }
  EXPECT_EQ(reachable, map.free_cells() * kHeadings);
}

TEST(NavMap, AHouseWithoutRoomsIsRefused) {
  household::House empty;
  auto m = build_nav_map(empty);
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().code, ErrorCode::kValidation);
  EXPECT_EQ(m.error().errors.at(0).pointer, "/rooms");
}

//  z=4 +--------------+
//      |  [side table]|   top at 0.65 m
//      |  [shelf]     |   1.8 m tall, between the table and the agent
//      |     agent ^  |
//  z=0 +--------------+
TEST(NavMap, TallFurnitureHidesWhatIsBehindIt) {
  auto house =
      hand_built_house({{RoomType::kLivingRoom, 0, 0, 4, 4}}, {},
                       {{"SideTable", 0, 2.0, 3.0, 0.5, 0.5}, {"ShelvingUnit", 0, 2.0, 2.2, 1.2, 0.4}});
  house.entities[0].position.y = 0.3;  // top at 0.6 m
  house.entities[1].position.y = 0.9;  // 1.8 m tall
  const int agent = pose_of(cell_near(map_of(house), 2.1, 1.85), 1);
  NavConfig open;
  open.furniture_occludes = false;
  const NavMap blind = map_of(house), clear = map_of(house, open);
  auto sees_table = [&](const NavMap& m) {
    const auto v = m.visible_from(agent);
    return std::find(v.begin(), v.end(), 0) != v.end();
  };
  EXPECT_TRUE(sees_table(clear));
  EXPECT_FALSE(sees_table(blind));
  // A low piece in between (a 0.45 m seat) does not hide a 0.6 m top.
  house.entities[1].position.y = 0.225;
  EXPECT_TRUE(sees_table(map_of(house)));
}

TEST(NavMap, ATopIsInspectedSpotBySpot) {
  // The 1 m × 1 m table: 0.8 m inside the 0.1 m margins, two spots of at most 0.5 m each way; the
  // 1.6 m × 0.6 m sofa: three along its length, one across.
  const NavMap map = map_of(two_rooms());
  const auto& table = map.receptacles()[0];
  const auto& sofa = map.receptacles()[1];
  const auto table_grid = top_grid(table.footprint, MapReceptacle::kSpotSpacing);
  ASSERT_EQ(table_grid.size(), 4u);
  for (const auto& p : table_grid) {
    EXPECT_NEAR(std::abs(p.x - 2.0), 0.2, 1e-9);
    EXPECT_NEAR(std::abs(p.z - 1.5), 0.2, 1e-9);
  }
  EXPECT_EQ(top_grid(sofa.footprint, MapReceptacle::kSpotSpacing).size(), 3u);
  // Every spot kept is seen from its views, which are sorted; the spots of one top differ.
  for (const auto* r : {&table, &sofa}) {
    ASSERT_FALSE(r->spots.empty());
    ASSERT_EQ(r->spots.size(), r->spot_points.size());
    for (std::size_t j = 0; j < r->spots.size(); ++j) {
      EXPECT_TRUE(std::is_sorted(r->spots[j].begin(), r->spots[j].end()));
      for (int v : r->spots[j]) EXPECT_TRUE(map.sees(v, r->spot_points[j]));
      EXPECT_EQ(map.views_of_point(static_cast<int>(r == &table ? 0 : 1), r->spot_points[j]), r->spots[j]);
    }
  }
  EXPECT_NE(table.spots[0], table.spots[3]);
}

}  // namespace
}  // namespace socsim::navbench
