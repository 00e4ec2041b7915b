// Wall bucketing and the crossing predicate behind the "no agent crosses a wall" guarantee.
#include "core/crowd/wall_grid.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "core/common/rng.hpp"

namespace socsim::crowd {
namespace {

TEST(WallGrid, EveryWallWithinTheCutoffIsListed) {
  Rng rng(11);
  std::vector<WallSegment> walls;
  for (int i = 0; i < 200; ++i) {
    const Vec2 a{rng.uniform(-20, 20), rng.uniform(-20, 20)};
    const double len = rng.chance(0.1) ? 0.0 : rng.uniform(0.0, 6.0);
    const double ang = rng.uniform(0, 6.283);
    walls.push_back({a, {a.x + len * std::cos(ang), a.y + len * std::sin(ang)}});
  }
  const WallGrid grid(walls, 2.0, 0.5);
  for (int q = 0; q < 5000; ++q) {
    const Vec2 p{rng.uniform(-25, 25), rng.uniform(-25, 25)};
    const auto near = grid.near(p.x, p.y);
    EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
    for (std::uint32_t w = 0; w < walls.size(); ++w) {
      if (point_segment_distance(p, walls[w].a, walls[w].b) <= 2.0) {
        EXPECT_TRUE(std::binary_search(near.begin(), near.end(), w))
            << "wall " << w << " missing at " << p.x << "," << p.y;
      }
    }
  }
  EXPECT_TRUE(WallGrid({}, 2.0).near(0, 0).empty());
}

TEST(WallGrid, MoveBlockedDetectsCrossingsAndLandings) {
  const Vec2 a{0, 0};
  const Vec2 b{0, 4};
  EXPECT_TRUE(move_blocked({-1, 2}, {1, 2}, a, b));      // straight through
  EXPECT_TRUE(move_blocked({-1, 2}, {0, 2}, a, b));      // landing on the wall
  EXPECT_TRUE(move_blocked({-1, -1}, {1, 1}, a, b));     // through the end point
  EXPECT_FALSE(move_blocked({-1, 5}, {1, 5}, a, b));     // past the end
  EXPECT_FALSE(move_blocked({-1, 2}, {-0.5, 3}, a, b));  // stays on its side
  EXPECT_FALSE(move_blocked({-1, 2}, {-1, 2}, a, b));    // no move
  EXPECT_FALSE(move_blocked({0, 2}, {1, 2}, a, b));      // starting on the wall: may step off
  EXPECT_FALSE(move_blocked({0, 2}, {-1, 2}, a, b));
  EXPECT_TRUE(move_blocked({0, -1}, {0, 1}, a, b));    // sliding along the line into the wall
  EXPECT_TRUE(move_blocked({0, -1}, {0, 5}, a, b));    // ... and through it
  EXPECT_FALSE(move_blocked({0, -2}, {0, -1}, a, b));  // along the line, short of it
  EXPECT_FALSE(move_blocked({-1, 2}, {1, 2}, a, a));   // a point cannot be crossed
}

TEST(WallGrid, PointSegmentDistance) {
  EXPECT_DOUBLE_EQ(point_segment_distance({1, 1}, {0, 0}, {0, 4}), 1.0);
  EXPECT_DOUBLE_EQ(point_segment_distance({0, 7}, {0, 0}, {0, 4}), 3.0);
  EXPECT_DOUBLE_EQ(point_segment_distance({3, 4}, {0, 0}, {0, 0}), 5.0);
}

}  // namespace
}  // namespace socsim::crowd
