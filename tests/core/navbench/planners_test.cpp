// The planners on candidates and on hand-built houses where the right visiting order is known:
// Greedy takes the nearest, CEG the best probability per step, OSG the best α-weighted trade of
// probability against distance scaled by the farthest candidate.
#include "core/navbench/planners.hpp"

#include <gtest/gtest.h>

#include "core/navbench/episode.hpp"
#include "tests/core/navbench/navbench_fixture.hpp"

namespace socsim::navbench {
namespace {

using household::RoomType;
using testing::cell_near;
using testing::hand_built_house;
using testing::map_of;

TEST(Planners, EachPicksByItsOwnRule) {
  // near & unlikely, middle & likely, far.
  const std::vector<Candidate> a = {{0, 0.10, 2}, {1, 0.60, 30}, {2, 0.30, 40}};
  EXPECT_EQ(GreedyPlanner().choose(a), 0u);
  EXPECT_EQ(CegPlanner().choose(a), 0u);     // 0.05 per step beats 0.02 and 0.0075
  EXPECT_EQ(OsgPlanner(0.5).choose(a), 0u);  // 0.5·0.1 − 0.5·2/40 = 0.025 beats −0.075 and −0.35
  const std::vector<Candidate> b = {{0, 0.05, 2}, {1, 0.60, 10}, {2, 0.35, 40}};
  EXPECT_EQ(GreedyPlanner().choose(b), 0u);
  EXPECT_EQ(CegPlanner().choose(b), 1u);  // 0.06 per step beats 0.025
  EXPECT_EQ(OsgPlanner(0.5).choose(b), 1u);
  // α = 0 is distance only, α = 1 probability only.
  EXPECT_EQ(OsgPlanner(0.0).choose(a), 0u);
  EXPECT_EQ(OsgPlanner(1.0).choose(a), 1u);
}

TEST(Planners, UniformProbabilitiesMakeEveryPlannerGreedy) {
  const std::vector<Candidate> c = {{0, 0.25, 9}, {1, 0.25, 4}, {2, 0.25, 4}, {3, 0.25, 12}};
  EXPECT_EQ(GreedyPlanner().choose(c), 1u);  // ties go to the lower receptacle index
  EXPECT_EQ(CegPlanner().choose(c), 1u);
  EXPECT_EQ(OsgPlanner(0.5).choose(c), 1u);
}

//  z=2 +--------------------------------------------------+
//      |          [0]              [1]                [2] |
//      | agent →                                          |
//  z=0 +--------------------------------------------------+
//     x=0        x=2              x=5                x=9  x=10
household::House corridor() {
  return hand_built_house(
      {{RoomType::kLivingRoom, 0, 0, 10, 2}}, {},
      {{"SideTable", 0, 2.0, 1.75}, {"SideTable", 0, 5.0, 1.75}, {"SideTable", 0, 9.0, 1.75}});
}

EpisodeResult search(const NavMap& map, const std::vector<double>& p, int target, const Planner& planner) {
  return run_episode(map, {pose_of(cell_near(map, 0.3, 0.3), 0), target, 200}, p, planner);
}

TEST(Planners, GreedyWalksTheCorridorInOrder) {
  const NavMap map = map_of(corridor());
  const auto e = search(map, {0.1, 0.2, 0.7}, 2, GreedyPlanner());
  EXPECT_TRUE(e.success);
  // Walking along the corridor the tables stand 90° to the side, out of view: each is visited.
  EXPECT_EQ(e.visited, (std::vector<int>{0, 1, 2}));
  EXPECT_GE(e.steps, e.shortest);
  EXPECT_LE(e.steps, e.shortest + 4);  // the detours are the turns to face tables 0 and 1
}

TEST(Planners, CegAndOsgGoStraightToTheLikelyFarEnd) {
  const NavMap map = map_of(corridor());
  // The target is on table 0, which Greedy looks at first; CEG and OSG believe the far end.
  const auto far_first = [&](const Planner& planner) { return search(map, {0.05, 0.05, 0.9}, 0, planner); };
  const auto greedy = far_first(GreedyPlanner()), ceg = far_first(CegPlanner()),
             osg = far_first(OsgPlanner(0.5));
  EXPECT_EQ(greedy.visited, (std::vector<int>{0}));
  EXPECT_EQ(greedy.steps, greedy.shortest);
  EXPECT_EQ(ceg.visited, (std::vector<int>{2, 1, 0}));  // back from the far end, the nearer first
  EXPECT_EQ(osg.visited, (std::vector<int>{2, 1, 0}));
  EXPECT_GT(ceg.steps, greedy.steps);
  EXPECT_LT(ceg.spl, greedy.spl);
}

//  Three rooms in a row: a receptacle in a corner behind the start (0), one in the next room (1)
//  and one two rooms away (2). CEG compares probability per step; OSG trades probability against
//  distance scaled by the farthest candidate, so a likelier but farther receptacle needs a larger
//  lead with OSG than with CEG. Where the two rules pick differently, each episode goes first to
//  its own rule's choice.
TEST(Planners, CegAndOsgDisagreeWhereTheTradeIsClose) {
  const auto house =
      hand_built_house({{RoomType::kKitchen, 0, 0, 4, 3},
                        {RoomType::kLivingRoom, 4, 0, 8, 3},
                        {RoomType::kBedroom, 8, 0, 12, 3}},
                       {{0, 1, 4.0, 1.5}, {1, 2, 8.0, 1.5}},
                       {{"CounterTop", 0, 0.4, 0.3}, {"Sofa", 1, 7.5, 2.7}, {"Bed", 2, 11.0, 2.5, 1.6, 0.8}});
  const NavMap map = map_of(house);
  const int start = pose_of(cell_near(map, 2.6, 2.6), 0);
  const double d0 = shortest_steps(map, start, 0), d1 = shortest_steps(map, start, 1),
               d2 = shortest_steps(map, start, 2);
  ASSERT_LT(d0, d1);
  ASSERT_LT(d1, d2);
  // The bed keeps 0.2. The likelier sofa: CEG takes it once p1/d1 beats p0/d0; OSG once
  // 0.5·(p1 − p0) beats 0.5·(d1 − d0)/d2. Find a split where CEG goes to the sofa, OSG to the corner.
  double p0 = -1.0;
  for (double q = 0.05; q < 0.4; q += 0.002) {
    const double q1 = 0.8 - q;
    const bool ceg_sofa = q1 / d1 > q / d0;
    const bool osg_sofa = 0.5 * q1 - 0.5 * d1 / d2 > 0.5 * q - 0.5 * d0 / d2;
    if (ceg_sofa && !osg_sofa) p0 = q;
  }
  if (p0 < 0) GTEST_SKIP() << "no close trade at these distances: " << d0 << ", " << d1 << ", " << d2;
  const std::vector<double> p = {p0, 0.8 - p0, 0.2};
  // The target is where the estimate says it most likely is: on the sofa.
  const auto ceg = run_episode(map, {start, 1, 200}, p, CegPlanner());
  const auto osg = run_episode(map, {start, 1, 200}, p, OsgPlanner(0.5));
  const auto greedy = run_episode(map, {start, 1, 200}, p, GreedyPlanner());
  EXPECT_EQ(ceg.visited, (std::vector<int>{1}));
  EXPECT_EQ(osg.visited, (std::vector<int>{0, 1}));
  EXPECT_EQ(greedy.visited, (std::vector<int>{0, 1}));
  EXPECT_EQ(ceg.steps, ceg.shortest);
  for (const auto* e : {&ceg, &osg, &greedy}) {
    EXPECT_TRUE(e->success);
    EXPECT_GE(e->steps, e->shortest);
    EXPECT_DOUBLE_EQ(e->spl, static_cast<double>(e->shortest) / e->steps);
  }
  EXPECT_LT(ceg.steps, osg.steps);
}

// One 3 m counter along a 4 m × 3 m room; the agent starts at its west end.
TEST(Planners, ALongTopIsSearchedUntilEverySpotIsSeen) {
  const NavMap map =
      map_of(hand_built_house({{RoomType::kKitchen, 0, 0, 4, 3}}, {},
                              {{"CounterTop", 0, 2.0, 2.6, 3.0, 0.6}, {"SideTable", 0, 0.4, 0.4}}));
  const auto& counter = map.receptacles()[0];
  ASSERT_GE(counter.spots.size(), 5u);  // 2.8 m inside the margins, 0.5 m spots: six along it
  // The target at the east end's spot: seen only from near that end.
  std::size_t east = 0;
  for (std::size_t j = 0; j < counter.spot_points.size(); ++j)
    if (counter.spot_points[j].x > counter.spot_points[east].x) east = j;
  EpisodeSpec spec{pose_of(cell_near(map, 0.6, 1.5), 0), 0, 200};
  spec.target_views = counter.spots[east];
  const int west_view = map.steps_from(spec.start).nearest(counter.views);
  ASSERT_GE(west_view, 0);
  // Certain it is on the counter, CEG walks along it to the east end and finds it there.
  const auto e = run_episode(map, spec, std::vector<double>{0.99, 0.01}, CegPlanner());
  EXPECT_TRUE(e.success);
  // Seen at last with the counter's last spot, at the step it is found.
  ASSERT_LE(e.visited.size(), 1u);
  if (!e.visited.empty()) {
    EXPECT_EQ(e.visited_at[0], e.steps);
  }
  EXPECT_GE(e.steps, e.shortest);
  EXPECT_FALSE(std::binary_search(counter.spots[east].begin(), counter.spots[east].end(), spec.start));
  // With the target elsewhere, the counter is crossed off only once every spot has been seen.
  EpisodeSpec other = spec;
  other.target_receptacle = 1;
  other.target_views = {};
  const auto o = run_episode(map, other, std::vector<double>{0.99, 0.01}, CegPlanner());
  EXPECT_TRUE(o.success);
  ASSERT_FALSE(o.visited.empty());
  EXPECT_EQ(o.visited[0], 0);
  EXPECT_GT(o.visited_at[0], 6);
}

}  // namespace
}  // namespace socsim::navbench
