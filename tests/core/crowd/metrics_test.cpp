// HuNavSim's social-navigation metrics on hand-made frames whose values can be worked out:
// path length, Hall's intrusion bands, collisions, time not moving, goal timing, speeds, and
// the LightSFM social force between two agents.
#include <cmath>

#include <gtest/gtest.h>

#include "core/crowd/metrics.hpp"

namespace socsim::crowd {
namespace {

PedestrianState at(std::uint32_t id, double x, double y, double vx = 0.0, double vy = 0.0) {
  PedestrianState s;
  s.id = AgentId(id);
  s.pose = {x, y, vx != 0.0 || vy != 0.0 ? std::atan2(vy, vx) : 0.0};
  s.twist = {vx, vy, 0.0};
  s.role = id == 2 ? "robot" : "adult";
  return s;
}

TEST(Metrics, WorkedExampleWithAWalkerAStanderAndARobot) {
  // Agent 0 walks +x at 1 m/s from (0, 0) for 4 s; agent 1 stands at (2, 1); the robot (2)
  // stands at (10, 0). Frames every 0.5 s; agent 0's goal is (3, 0), radius 0.3.
  MetricsRecorder rec({{Goal{{3.0, 0.0}, 0.3}}, {}, {}}, AgentId(2));
  const std::vector<double> radii = {0.3, 0.3, 0.35};
  const std::vector<std::uint8_t> active = {1, 1, 1};
  for (int k = 0; k <= 8; ++k) {
    const double t = 0.5 * k;
    rec.observe(t, {at(0, t, 0.0, 1.0, 0.0), at(1, 2.0, 1.0), at(2, 10.0, 0.0)}, radii, active, {});
  }
  const RunMetrics m = rec.finish();
  EXPECT_EQ(m.frames, 9u);
  EXPECT_DOUBLE_EQ(m.duration, 4.0);
  ASSERT_EQ(m.agents.size(), 2u);
  const AgentMetrics& walker = m.agents[0];
  EXPECT_NEAR(walker.path_length, 4.0, 1e-12);
  EXPECT_TRUE(walker.goal_reached);
  EXPECT_DOUBLE_EQ(*walker.time_to_reach_goal, 3.0);  // first frame within 0.3 m of (3, 0)
  EXPECT_NEAR(walker.avg_linear_speed, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(walker.time_not_moving, 0.0);
  EXPECT_NEAR(walker.final_goal_distance, 1.0, 1e-12);
  EXPECT_NEAR(walker.minimum_goal_distance, 0.0, 1e-12);
  // Closest person minus own radius per frame: x = 0..4 → |(x,0)−(2,1)| − 0.3, the robot is
  // farther except at x = 4 where (2,1) is 2.236 away; bands: < 0.45 intimate, < 1.2 personal, < 3.6 social.
  int intimate = 0, personal = 0, social = 0;
  double min_d = 1e9;
  for (int k = 0; k <= 8; ++k) {
    const double x = 0.5 * k;
    const double d = std::min(std::hypot(x - 2.0, 1.0), std::hypot(x - 10.0, 0.0)) - 0.3;
    min_d = std::min(min_d, d);
    if (d < 0.45)
      ++intimate;
    else if (d < 1.2)
      ++personal;
    else if (d < 3.6)
      ++social;
  }
  EXPECT_NEAR(walker.minimum_distance_to_people, min_d, 1e-12);
  EXPECT_NEAR(walker.intimate_space_intrusions, 100.0 * intimate / 9.0, 1e-9);
  EXPECT_NEAR(walker.personal_space_intrusions, 100.0 * personal / 9.0, 1e-9);
  EXPECT_NEAR(walker.social_space_intrusions, 100.0 * social / 9.0, 1e-9);
  EXPECT_EQ(walker.collisions, 0u);
  EXPECT_GT(walker.social_force_on_agent, 0.0);

  const AgentMetrics& stander = m.agents[1];
  EXPECT_DOUBLE_EQ(stander.path_length, 0.0);
  EXPECT_DOUBLE_EQ(stander.time_not_moving, 9 * 0.5);
  ASSERT_TRUE(m.robot.has_value());
  EXPECT_EQ(m.robot->role, "robot");
  EXPECT_NEAR(m.robot->minimum_distance_to_people, 6.0 - 0.35, 1e-12);  // walker at x = 4
  EXPECT_NEAR(m.avg_pedestrian_velocity, 0.5, 1e-12);                   // (1 + 0) / 2, robot excluded
}

TEST(Metrics, CollisionsAndWhoHitWhom) {
  // The robot drives into a standing person: bodies overlap in the last two frames.
  MetricsRecorder rec({{}, {}, {}}, AgentId(2));
  const std::vector<double> radii = {0.3, 0.3, 0.35};
  const std::vector<std::uint8_t> active = {1, 0, 1};  // agent 1 is gone (exited)
  for (int k = 0; k < 5; ++k)
    rec.observe(0.1 * k, {at(0, 1.0, 0.0), at(1, 50, 50), at(2, 0.1 + 0.1 * k, 0.0, 1.0, 0.0)}, radii, active,
                {});
  const RunMetrics m = rec.finish();
  EXPECT_EQ(m.robot->collisions, 2u);  // (1 − x) − 0.65 < 0.02 for the robot at x = 0.4 and 0.5
  EXPECT_EQ(m.robot_on_person_collisions, 2u);
  EXPECT_EQ(m.person_on_robot_collisions, 0u);
  EXPECT_EQ(m.agents[0].collisions, 2u);
  EXPECT_EQ(m.agents[1].frames, 0u);
  const Json j = to_json(m);
  EXPECT_EQ(j["robot"]["robot_on_person_collision"], 2);
  EXPECT_TRUE(j["agents"][1]["time_to_reach_goal"].is_null());
}

}  // namespace
}  // namespace socsim::crowd
