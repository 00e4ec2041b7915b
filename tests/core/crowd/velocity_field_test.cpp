// Velocity fields (paper 001 Algorithm 1): the grid lookup and the look-ahead rule exactly as
// written, geodesic fields that lead round walls to the goal, seeded variation, external
// 64×64×2 fields, and errors naming the bad region.
#include <cmath>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/crowd/velocity_field.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

namespace socsim::crowd {
namespace {
using fixtures::options;

using ::testing::HasSubstr;

world::World clinic() {
  std::ifstream in(std::filesystem::path(SOCSIM_SOURCE_DIR) / "schemas/examples/world_clinic.yaml");
  std::ostringstream s;
  s << in.rdbuf();
  auto w = world::world_from_yaml(s.str());
  EXPECT_TRUE(w) << w.error().message();
  return *w;
}

geometry::Polygon rect(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

TEST(VelocityField, Algorithm1IndexAndLookAhead) {
  // V[i][j] = (i, j) / 100 over a 32 × 16 m world whose corner is at (-2, 4).
  std::vector<Vec2> values;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) values.push_back({i / 100.0, j / 100.0});
  auto f = VelocityField::from_values({{-2, 4}, {30, 20}}, 64, 64, values);
  ASSERT_TRUE(f) << f.error().message();
  // index = ⌊(pos − min) / size × 64⌋: x = 5.9 → ⌊7.9 / 32 × 64⌋ = 15, y = 11.1 → ⌊7.1 / 16 × 64⌋ = 28.
  EXPECT_EQ(f->sample({5.9, 11.1}), (Vec2{0.15, 0.28}));
  EXPECT_EQ(f->sample({-50, 100}), (Vec2{0.0, 0.63}));  // clamped to the grid

  // goal = pos + vel·dt; with ‖vel·dt‖ < 2·tol it is pushed out to 2·tol along vel.
  const Vec2 p{5.9, 11.1};
  const Vec2 g = velocity_field_goal(*f, p, 0.1, 0.5);
  const double len = std::hypot(0.15, 0.28);
  EXPECT_NEAR(g.x, p.x + 0.15 / len * 1.0, 1e-12);
  EXPECT_NEAR(g.y, p.y + 0.28 / len * 1.0, 1e-12);
  // A long step stays as it is.
  const Vec2 far = velocity_field_goal(*f, p, 20.0, 0.5);
  EXPECT_NEAR(far.x, p.x + 0.15 * 20.0, 1e-12);
  EXPECT_NEAR(far.y, p.y + 0.28 * 20.0, 1e-12);
  // Zero velocity: no look-ahead, the goal is the position itself (LightSFM then brakes).
  EXPECT_EQ(velocity_field_goal(*f, {-1.9, 4.1}, 0.1, 0.5), (Vec2{-1.9, 4.1}));
}

TEST(VelocityField, GeodesicFieldLeadsRoundTheWallsToTheGoal) {
  const world::World w = clinic();
  const world::OccupancyGrid grid = world::OccupancyGrid::rasterise(w, {0.1, 0.15, 4'000'000});
  VelocityField::GeodesicSpec spec;
  spec.start = {rect(1, 7, 9, 11)};  // waiting room
  spec.goal = {rect(14, 1, 19, 5)};  // patient room 1, reached through the corridor
  spec.speed = 1.2;
  auto f = VelocityField::from_geodesic(grid, w.bounds(), spec);
  ASSERT_TRUE(f) << f.error().message();
  // Integrate the field from the waiting room: the walk ends in the goal room without crossing a wall.
  Vec2 p{3.0, 10.0};
  bool arrived = false;
  for (int k = 0; k < 2000 && !arrived; ++k) {
    const Vec2 v = f->sample(p);
    const double s = std::hypot(v.x, v.y);
    if (s == 0.0) break;
    EXPECT_NEAR(s, 1.2, 1e-9);
    const Vec2 q{p.x + v.x / s * 0.05, p.y + v.y / s * 0.05};
    for (const world::Wall& wall : w.walls())
      ASSERT_FALSE(
          move_blocked(p, q, {wall.segment.a.x, wall.segment.a.y}, {wall.segment.b.x, wall.segment.b.y}))
          << "crossed a wall at (" << p.x << ", " << p.y << ")";
    p = q;
    arrived = geometry::contains(spec.goal[0], {p.x, p.y});
  }
  EXPECT_TRUE(arrived) << "stopped at (" << p.x << ", " << p.y << ")";
}

TEST(VelocityField, VariationIsSeededAndBounded) {
  const world::World w = clinic();
  const world::OccupancyGrid grid = world::OccupancyGrid::rasterise(w, {0.1, 0.4, 4'000'000});
  VelocityField::GeodesicSpec spec;
  spec.start = {rect(1, 1, 4, 5)};
  spec.goal = {rect(1, 7, 9, 11)};
  auto plain = VelocityField::from_geodesic(grid, w.bounds(), spec);
  spec.variation = 0.3;
  spec.seed = 11;
  auto a = VelocityField::from_geodesic(grid, w.bounds(), spec);
  auto b = VelocityField::from_geodesic(grid, w.bounds(), spec);
  spec.seed = 12;
  auto c = VelocityField::from_geodesic(grid, w.bounds(), spec);
  ASSERT_TRUE(plain && a && b && c);
  EXPECT_TRUE(std::equal(a->values().begin(), a->values().end(), b->values().begin()));
  EXPECT_FALSE(std::equal(a->values().begin(), a->values().end(), c->values().begin()));
  double max_turn = 0.0;
  for (std::size_t k = 0; k < a->values().size(); ++k) {
    const Vec2 u = plain->values()[k];
    const Vec2 v = a->values()[k];
    if (u == Vec2{}) continue;
    max_turn = std::max(max_turn, std::abs(std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y)));
  }
  EXPECT_GT(max_turn, 0.1);
  EXPECT_LE(max_turn, 0.3 + 1e-9);
}

TEST(VelocityField, BadRegionsAndValuesAreNamed) {
  const world::World w = clinic();
  const world::OccupancyGrid grid = world::OccupancyGrid::rasterise(w, {0.1, 0.4, 4'000'000});
  VelocityField::GeodesicSpec spec;
  spec.start = {rect(30, 30, 32, 32)};  // outside the building
  spec.goal = {rect(1, 7, 9, 11), rect(-9, -9, -8, -8)};
  auto f = VelocityField::from_geodesic(grid, w.bounds(), spec);
  ASSERT_FALSE(f);
  EXPECT_EQ(f.error().errors.at(0).pointer, "/goal/1");
  spec.goal.pop_back();
  f = VelocityField::from_geodesic(grid, w.bounds(), spec);
  ASSERT_FALSE(f);
  EXPECT_EQ(f.error().errors.at(0).pointer, "/start/0");
  EXPECT_THAT(f.error().errors.at(0).message, HasSubstr("no walkable cell"));

  auto bad = VelocityField::from_values({{0, 0}, {1, 1}}, 2, 2, {{0, 0}, {0, NAN}, {0, 0}, {0, 0}});
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().errors.at(0).pointer, "/values/0/1");
  EXPECT_FALSE(VelocityField::from_values({{0, 0}, {1, 1}}, 2, 2, {{0, 0}}));
}

// An ambient group driven by a field from outside (as a diffusion model would supply it):
// every cell points +x, so the agents cross the lobby towards its east side and leave there.
TEST(VelocityField, ExternalFieldDrivesAnAmbientGroup) {
  const world::World w = clinic();
  Json columns = Json::array();
  for (int i = 0; i < 64; ++i) {
    Json col = Json::array();
    for (int j = 0; j < 64; ++j) col.push_back({1.0, 0.0});
    columns.push_back(col);
  }
  Json program = {{"ambient_groups",
                   {{{"name", "east"},
                     {"start", {{{0.5, 0.5}, {2.5, 0.5}, {2.5, 5.5}, {0.5, 5.5}}}},
                     {"goal", {{{8, 0.5}, {9.5, 0.5}, {9.5, 5.5}, {8, 5.5}}}},
                     {"size", 8},
                     {"field", {{"values", columns}}}}}}};
  auto p = program_from_json(program);
  ASSERT_TRUE(p) << p.error().message();
  auto runner = ScenarioRunner::create(&w, *p, options(5));
  ASSERT_TRUE(runner) << runner.error().message();
  (*runner)->run(20.0);
  for (std::uint32_t i = 0; i < 8; ++i) {
    const PedestrianState s = (*runner)->sim().state(AgentId(i));
    EXPECT_EQ(s.activity, Activity::kExited) << i;
    EXPECT_GT(s.pose.x, 7.9) << i;
  }
}

}  // namespace
}  // namespace socsim::crowd
