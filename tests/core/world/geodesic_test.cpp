// GeodesicField: fast-marching distances match straight lines in open space, go around
// walls through doors, stay infinite where unreachable; descent points towards the goal.
#include "core/world/geodesic.hpp"

#include <chrono>
#include <cmath>

#include <gtest/gtest.h>

#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using testing::load;

TEST(GeodesicField, OpenRoomDistancesAreEuclideanWithinAFewPercent) {
  const World w = load("zones:\n  - {name: a, polygon: [[0, 0], [20, 0], [20, 20], [0, 20]]}\n");
  const auto g = OccupancyGrid::rasterise(w, GridOptions{0.1, 0.0});
  const Point src{5, 5};
  const auto f = GeodesicField::from_points(g, std::span<const Point>(&src, 1));
  ASSERT_TRUE(f.has_source());
  for (const Point p : {Point{15, 5}, Point{5, 15}, Point{15, 15}, Point{12, 8}}) {
    const double exact = std::hypot(p.x - src.x, p.y - src.y);
    const auto d = f.distance(p);
    ASSERT_TRUE(d.has_value());
    EXPECT_NEAR(*d, exact, 0.03 * exact) << p.x << "," << p.y;
  }
}

TEST(GeodesicField, PathsGoAroundWallsThroughTheDoor) {
  // Two rooms, door at (4, 2): from (2, 3.5) to (6, 3.5) one walks down to the door and back up.
  const World w = load(testing::kTwoRooms);
  const auto g = OccupancyGrid::rasterise(w, GridOptions{0.05, 0.25});
  const Point goal{6, 3.5};
  const auto f = GeodesicField::from_points(g, std::span<const Point>(&goal, 1));
  const auto d = f.distance({2, 3.5});
  ASSERT_TRUE(d.has_value());
  // Lower bound: via the door's top usable point (4, 2.25): 2 * hypot(2, 1.25) ≈ 4.72.
  EXPECT_GT(*d, 4.7);
  EXPECT_LT(*d, 5.2);
  // Descent from the west room points towards the door (east and down).
  const auto dir = f.descent({2, 3.5});
  ASSERT_TRUE(dir.has_value());
  EXPECT_GT(dir->x, 0.5);
  EXPECT_LT(dir->y, 0.0);
}

TEST(GeodesicField, UnreachableCellsAreInfinite) {
  const World w = load(testing::kTwoRooms);
  const auto g = OccupancyGrid::rasterise(w, GridOptions{0.05, 0.6});  // wider than the door
  const Point goal{6, 2};
  const auto f = GeodesicField::from_points(g, std::span<const Point>(&goal, 1));
  EXPECT_FALSE(f.distance({2, 2}).has_value());
  EXPECT_TRUE(f.distance({7, 2}).has_value());
}

TEST(GeodesicField, RegionSourcesAreZeroInside) {
  const World w = load(testing::kTwoRooms);
  const auto g = OccupancyGrid::rasterise(w, GridOptions{0.1, 0.0});
  const Polygon region{{{6, 1}, {7, 1}, {7, 3}, {6, 3}}, {}};
  const auto f = GeodesicField::from_region(g, region);
  EXPECT_NEAR(f.distance({6.5, 2}).value(), 0.0, 1e-6);
  EXPECT_NEAR(f.distance({5, 2}).value(), 1.0, 0.1);
}

TEST(GeodesicField, SourcesInWallsAreIgnored) {
  const World w = load(testing::kTwoRooms);
  const auto g = OccupancyGrid::rasterise(w, GridOptions{0.1, 0.3});
  const Point in_wall{4, 0.5};
  EXPECT_FALSE(GeodesicField::from_points(g, std::span<const Point>(&in_wall, 1)).has_source());
}

}  // namespace
}  // namespace socsim::world
