// The evaluation table (crowd::evaluation_table): cell means over seeds, per-planner means over
// cards with Student-t intervals, outcome rates, the collision ranking; the t quantiles.
#include <gtest/gtest.h>

#include <cmath>

#include "core/crowd/robot_evaluation.hpp"

namespace socsim::crowd {
namespace {

EvaluationEpisode episode_of(std::size_t card, std::size_t planner, std::size_t seed, Outcome outcome,
                             double path_length) {
  EvaluationEpisode e;
  e.scenario = card;
  e.planner = planner;
  e.seed = seed;
  e.metrics.outcome = outcome;
  e.metrics.success = outcome == Outcome::kSuccess;
  if (e.metrics.success) e.metrics.time_to_reach_goal = 10.0 + static_cast<double>(card);
  e.metrics.path_length = path_length;
  return e;
}

TEST(RobotEvaluation, StudentTQuantiles) {
  EXPECT_DOUBLE_EQ(student_t_975(1), 12.706);
  EXPECT_DOUBLE_EQ(student_t_975(2), 4.303);
  EXPECT_DOUBLE_EQ(student_t_975(30), 2.042);
  EXPECT_NEAR(student_t_975(40), 2.021, 1e-3);
  EXPECT_NEAR(student_t_975(1000), 1.962, 1e-3);
  EXPECT_TRUE(std::isnan(student_t_975(0)));
}

// Two cards × two planners × two seeds: "fast" always hits someone, "careful" succeeds on card 0.
TEST(RobotEvaluation, TableOfCellsAndPlannersWithIntervalsOverCards) {
  EvaluationPlan plan;
  plan.scenarios = {{"card_a", nullptr, nullptr}, {"card_b", nullptr, nullptr}};
  plan.seeds = {1, 2};
  plan.planners = {"builtin:fast", "builtin:careful"};
  std::vector<EvaluationEpisode> episodes;
  for (std::size_t c = 0; c < 2; ++c)
    for (std::size_t s = 0; s < 2; ++s) {
      episodes.push_back(episode_of(c, 0, s, Outcome::kCollisionPerson, 2.0 + static_cast<double>(s)));
      episodes.push_back(episode_of(c, 1, s, c == 0 ? Outcome::kSuccess : Outcome::kTimeout, 10.0));
    }
  const Json t = evaluation_table(plan, episodes);
  ASSERT_EQ(t["cells"].size(), 4u);
  const Json& fast_a = t["cells"][0];
  EXPECT_EQ(fast_a["card"], "card_a");
  EXPECT_EQ(fast_a["planner"], "builtin:fast");
  EXPECT_EQ(fast_a["episodes"], 2);
  EXPECT_EQ(fast_a["outcomes"]["collision_person"], 2);
  EXPECT_DOUBLE_EQ(fast_a["mean"]["path_length"], 2.5);
  EXPECT_DOUBLE_EQ(fast_a["mean"]["collision"], 1.0);
  EXPECT_TRUE(fast_a["mean"]["time_to_reach_goal"].is_null());

  const Json& careful = t["planners"][1]["metrics"];
  EXPECT_DOUBLE_EQ(careful["success"]["mean"], 0.5);
  EXPECT_EQ(careful["success"]["n"], 2);
  // Card means 1 and 0: sd √½, half width t(1) · √½ / √2 = 12.706 / 2.
  EXPECT_DOUBLE_EQ(careful["success"]["ci95"][0], 0.5 - 6.353);
  EXPECT_DOUBLE_EQ(careful["success"]["ci95"][1], 0.5 + 6.353);
  EXPECT_DOUBLE_EQ(careful["timeout"]["mean"], 0.5);
  EXPECT_EQ(careful["time_to_reach_goal"]["n"], 1);  // successes only: card 0
  EXPECT_TRUE(careful["time_to_reach_goal"]["ci95"].is_null());
  EXPECT_EQ(t["ranking"]["collision"], Json({"builtin:careful", "builtin:fast"}));
  EXPECT_EQ(t["planners"][0]["episodes"], 4);
  EXPECT_EQ(t["summary"].size(), 2u);
}

}  // namespace
}  // namespace socsim::crowd
