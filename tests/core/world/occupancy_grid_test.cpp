// OccupancyGrid: outside-of-zones cells blocked, walls rasterised with inflation, door gaps
// open or closed depending on the agent radius, zone labels, coarsening of huge worlds.
#include "core/world/occupancy_grid.hpp"

#include <gtest/gtest.h>

#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using testing::kTwoRooms;
using testing::load;

bool free_at(const OccupancyGrid& g, Point p) {
  const auto c = g.cell_of(p);
  return c && !g.blocked(*c);
}

TEST(OccupancyGrid, CoversTheWorldWithAOneCellMargin) {
  const auto g = OccupancyGrid::rasterise(load(kTwoRooms), GridOptions{0.1, 0.0});
  EXPECT_EQ(g.width(), 82);
  EXPECT_EQ(g.height(), 42);
  EXPECT_NEAR(g.origin().x, -0.1, 1e-12);
  EXPECT_NEAR(g.origin().y, -0.1, 1e-12);
  EXPECT_FALSE(free_at(g, {-0.05, 2}));  // margin, outside every zone
  EXPECT_TRUE(free_at(g, {2, 2}));
  EXPECT_EQ(g.zone_of(*g.cell_of({6, 1})), ZoneId(1));
  EXPECT_FALSE(g.zone_of(*g.cell_of({-0.05, -0.05})).has_value());
}

TEST(OccupancyGrid, WallsAreInflatedByTheAgentRadius) {
  const World w = load(kTwoRooms);
  const auto thin = OccupancyGrid::rasterise(w, GridOptions{0.05, 0.0});
  const auto fat = OccupancyGrid::rasterise(w, GridOptions{0.05, 0.3});
  EXPECT_TRUE(free_at(thin, {4.2, 0.5}));  // 0.2 m from the shared wall
  EXPECT_FALSE(free_at(fat, {4.2, 0.5}));
  EXPECT_TRUE(free_at(fat, {4.4, 0.5}));
  EXPECT_FALSE(free_at(fat, {2, 0.2}));  // near the outline too
  // The door gap (y 1.5 .. 2.5) stays open for r = 0.3: its middle is 0.5 m from the jambs.
  EXPECT_TRUE(free_at(fat, {4.0, 2.0}));
  EXPECT_FALSE(free_at(fat, {4.0, 1.6}));
  EXPECT_LT(fat.free_count(), thin.free_count());
}

TEST(OccupancyGrid, ADoorNarrowerThanTheAgentSplitsTheFreeSpace) {
  const World w = load(kTwoRooms);
  auto components_between = [&](double radius) {
    const auto g = OccupancyGrid::rasterise(w, GridOptions{0.05, radius});
    const auto label = g.components();
    return std::pair{label[g.index(*g.cell_of({2, 2}))], label[g.index(*g.cell_of({6, 2}))]};
  };
  const auto [a1, b1] = components_between(0.4);
  EXPECT_EQ(a1, b1);
  const auto [a2, b2] = components_between(0.55);
  EXPECT_NE(a2, b2);
}

TEST(OccupancyGrid, WallsWithoutInflationStillSealRooms) {
  // Zero inflation: a wall still blocks every cell it passes through, so a room closed by
  // walls is a component of its own even when the wall runs diagonally.
  const World w = load(R"(zones:
  - {name: a, polygon: [[0, 0], [6, 0], [6, 6], [0, 6]]}
walls:
  - {start: [0, 3.03], end: [6, 2.01], height: 2}
)",
                       BuildOptions{.check_reachability = false});
  const auto g = OccupancyGrid::rasterise(w, GridOptions{0.1, 0.0});
  const auto label = g.components();
  EXPECT_NE(label[g.index(*g.cell_of({1, 1}))], label[g.index(*g.cell_of({1, 5}))]);
}

TEST(OccupancyGrid, HugeWorldsAreCoarsenedToTheCellCap) {
  const World w = load(R"(zones:
  - {name: field, polygon: [[0, 0], [500, 0], [500, 400], [0, 400]]}
)");
  const auto g = OccupancyGrid::rasterise(w, GridOptions{0.05, 0.0, 100'000});
  EXPECT_LE(static_cast<std::size_t>(g.width()) * static_cast<std::size_t>(g.height()), 100'000u);
  EXPECT_GT(g.resolution(), 1.4);
  EXPECT_TRUE(free_at(g, {250, 200}));
}

}  // namespace
}  // namespace socsim::world
