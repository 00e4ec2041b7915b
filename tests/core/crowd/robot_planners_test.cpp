// The built-in robot planners: steering towards a wanted velocity, ORCA's velocity against a
// person in the way (collision-free over its horizon), and the three planners driving through a
// corridor towards a walker who does not see the robot: straight line hits the walker, ORCA and
// the social-force robot get past.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/crowd/episode_metrics.hpp"
#include "core/crowd/robot_planners.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

namespace socsim::crowd {
namespace {

TEST(RobotPlanners, SteerTowardsTurnsOnTheSpotWhenFacingAway) {
  const RobotLimits limits{1.0, 1.0, 1.5};
  UnicycleState s;
  EXPECT_EQ(steer_towards(s, {0.8, 0.0}, limits), (VelocityCommand{0.8, 0.0}));
  const VelocityCommand back = steer_towards(s, {-1.0, 0.0}, limits);
  EXPECT_DOUBLE_EQ(back.v, 0.0);
  EXPECT_DOUBLE_EQ(std::abs(back.omega), 1.5);
  const VelocityCommand left = steer_towards(s, {1.0, 1.0}, limits);  // 45° off: v·cos, ω = 2·π/4
  EXPECT_NEAR(left.v, 1.0 * std::cos(std::numbers::pi / 4), 1e-12);
  EXPECT_NEAR(left.omega, 1.5, 1e-12);
  EXPECT_EQ(steer_towards(s, {}, limits), (VelocityCommand{}));
}

TEST(RobotPlanners, OrcaKeepsThePreferredVelocityWhenNobodyIsNear) {
  PlannerInput in;
  const Vec2 v = orca_velocity(in, {0.7, 0.2});
  EXPECT_NEAR(v.x, 0.7, 1e-12);
  EXPECT_NEAR(v.y, 0.2, 1e-12);
}

TEST(RobotPlanners, OrcaAvoidsAStandingPersonForItsHorizon) {
  PlannerInput in;
  in.robot.v = 1.0;
  in.limits.max_speed = 1.0;
  const std::vector<LoggedBody> people{LoggedBody{0, {2.0, 0.05}, {}, 0.0, 0.0, 0.3}};
  in.people = people;
  const Vec2 v = orca_velocity(in, {1.0, 0.0});
  EXPECT_LE(std::hypot(v.x, v.y), 1.0 + 1e-9);
  // Closest approach of the straight motion at v within 3 s stays ≥ 0.35 + 0.3 + 0.1.
  double closest = 1e9;
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.01 * k;
    closest = std::min(closest, std::hypot(2.0 - v.x * t, 0.05 - v.y * t));
  }
  EXPECT_GE(closest, 0.75 - 1e-6);
  EXPECT_GT(v.x, 0.3) << "goes round, does not stop";
}

TEST(RobotPlanners, NamesAndUnknownNames) {
  for (std::string_view name : planner_names()) EXPECT_NE(make_planner(name), nullptr) << name;
  EXPECT_EQ(make_planner("teleport"), nullptr);
}

// A corridor 20 m × 4 m; the walker comes from the far end along the robot's line and does not
// see the (invisible) robot, so only the planner can avoid the collision.
RobotEpisodeMetrics drive(std::string_view planner_name) {
  auto w = world::world_from_yaml(R"(zones:
  - {name: corridor, polygon: [[0, 0], [20, 0], [20, 4], [0, 4]]}
)");
  EXPECT_TRUE(w);
  auto p = program_from_text(R"({"name": "encounter", "agents": [
    {"name": "walker", "position": [16, 2], "speed": 1.0, "goals": [[1, 2]], "cyclic_goals": false}]})");
  EXPECT_TRUE(p);
  RunnerOptions o = fixtures::options(5);
  RobotSpec r;
  r.start = {2, 2, 0};
  r.goal = Goal{{18, 2}, 0.5};
  r.presence = Presence::kInvisible;
  o.robots = {r};
  EpisodeOptions eo;
  eo.time_limit = 40.0;
  auto e = Episode::create(&*w, *p, o, eo);
  EXPECT_TRUE(e) << e.error().message();
  const auto planner = make_planner(planner_name);
  while (!(*e)->ended()) {
    const RobotInput in{RobotInput::Kind::kCommand, planner->plan(planner_input(**e, 0)), {}, {}};
    EXPECT_TRUE((*e)->step(std::span(&in, 1)));
  }
  return evaluate_episode((*e)->log()).robots[0];
}

TEST(RobotPlanners, StraightLineHitsTheWalkerOrcaAndSocialForceGetPast) {
  EXPECT_EQ(drive("straight_line").outcome, Outcome::kCollisionPerson);
  const RobotEpisodeMetrics orca = drive("orca");
  EXPECT_EQ(orca.outcome, Outcome::kSuccess);
  EXPECT_EQ(orca.collisions, 0u);
  EXPECT_GT(orca.path_efficiency, 0.8);
  const RobotEpisodeMetrics sf = drive("social_force");
  EXPECT_EQ(sf.outcome, Outcome::kSuccess);
  EXPECT_EQ(sf.collisions, 0u);
}

}  // namespace
}  // namespace socsim::crowd
