// Robots driven from outside: the unicycle model against hand-integrated poses, its limits, and a
// driven agent in the crowd — not moved by the forces, avoided by a person when visible, walked
// through when invisible, seen by the behaviour nodes only when visible; runs are bit-identical.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/crowd/robot.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

namespace socsim::crowd {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(RobotUnicycle, StraightLineRampsUpWithTheAccelerationLimit) {
  const RobotLimits limits{1.0, 1.0, 1.5};
  UnicycleState s;
  s = integrate_unicycle(s, {1.0, 0.0}, limits, 0.1);
  EXPECT_DOUBLE_EQ(s.v, 0.1);
  EXPECT_DOUBLE_EQ(s.pose.x, 0.01);
  EXPECT_DOUBLE_EQ(s.pose.y, 0.0);
  for (int k = 0; k < 9; ++k) s = integrate_unicycle(s, {5.0, 0.0}, limits, 0.1);
  // v = 0.1, 0.2, …, 1.0: x = 0.1·(0.1 + … + 1.0) = 0.55.
  EXPECT_NEAR(s.v, 1.0, 1e-12);
  EXPECT_NEAR(s.pose.x, 0.55, 1e-12);
  s = integrate_unicycle(s, {5.0, 0.0}, limits, 0.1);
  EXPECT_NEAR(s.v, 1.0, 1e-12) << "clamped to max_speed";
}

TEST(RobotUnicycle, QuarterCircleAtConstantSpeedAndTurnRate) {
  const RobotLimits limits{2.0, 10.0, 2.0};
  UnicycleState s;
  s.v = 1.0;
  for (int k = 0; k < 10; ++k) s = integrate_unicycle(s, {1.0, kPi / 2.0}, limits, 0.1);
  // Radius v/ω = 2/π; after 1 s a quarter turn: (2/π, 2/π), heading π/2.
  EXPECT_NEAR(s.pose.x, 2.0 / kPi, 1e-12);
  EXPECT_NEAR(s.pose.y, 2.0 / kPi, 1e-12);
  EXPECT_NEAR(s.pose.yaw, kPi / 2.0, 1e-12);
  const Twist2 t = twist_of(s);
  EXPECT_NEAR(t.vx, 0.0, 1e-12);
  EXPECT_NEAR(t.vy, 1.0, 1e-12);
}

TEST(RobotUnicycle, TurnRateAndReverseSpeedAreClamped) {
  const RobotLimits limits{0.5, 100.0, 1.0};
  const UnicycleState s = integrate_unicycle({}, {-3.0, -9.0}, limits, 0.1);
  EXPECT_DOUBLE_EQ(s.v, -0.5);
  EXPECT_DOUBLE_EQ(s.omega, -1.0);
}

TEST(RobotUnicycle, LimitsAreValidated) {
  EXPECT_TRUE(validate(RobotLimits{}));
  auto bad = validate(RobotLimits{std::nan(""), 0.0, 50.0});
  ASSERT_FALSE(bad);
  ASSERT_EQ(bad.error().errors.size(), 3u);
  EXPECT_EQ(bad.error().errors[0].pointer, "/limits/max_speed");
  EXPECT_EQ(bad.error().errors[1].pointer, "/limits/max_acceleration");
  EXPECT_EQ(bad.error().errors[2].pointer, "/limits/max_turn_rate");
}

// A person walks along y = 0 from x = 0 to x = 10; a robot stands at (5, 0.1).
// Returns the closest approach of the bodies (centre distance less both radii).
double closest_approach(Presence presence, std::vector<double>* trace = nullptr) {
  CrowdSimulation sim = fixtures::make();
  AgentSpec person;
  person.position = {0.0, 0.0};
  person.desired_speed = 1.2;
  const AgentId p = *sim.add_agent(person);
  EXPECT_TRUE(sim.set_goal(p, Goal{{10.0, 0.0}, 0.3}));
  AgentSpec robot;
  robot.position = {5.0, 0.1};
  robot.role = "adult";
  robot.radius = 0.35;
  const AgentId r = *sim.add_agent(robot);
  EXPECT_TRUE(sim.set_driven(r, presence));
  EXPECT_TRUE(sim.set_driven_state(r, {5.0, 0.1, kPi}, {}));
  double closest = 1e9;
  for (int k = 0; k < 400; ++k) {
    sim.step();
    const Vec2 a = sim.position(p);
    const Vec2 b = sim.position(r);
    closest = std::min(closest, std::hypot(a.x - b.x, a.y - b.y) - sim.radius(p) - sim.radius(r));
    EXPECT_EQ(b, (Vec2{5.0, 0.1})) << "a driven agent is not moved by the forces";
    if (trace != nullptr) {
      trace->push_back(a.x);
      trace->push_back(a.y);
    }
  }
  EXPECT_GT(sim.position(p).x, 9.0) << "the person still gets past";
  return closest;
}

TEST(RobotDriven, PeopleAvoidAVisibleRobotAndWalkThroughAnInvisibleOne) {
  const double visible = closest_approach(Presence::kVisible);
  const double invisible = closest_approach(Presence::kInvisible);
  EXPECT_GT(visible, -0.01) << "bodies touch at most (the crowd's 1 cm contact tolerance)";
  EXPECT_LT(invisible, -0.4) << "walks through it";
}

TEST(RobotDriven, RunsAreBitIdentical) {
  std::vector<double> a, b;
  closest_approach(Presence::kVisible, &a);
  closest_approach(Presence::kVisible, &b);
  EXPECT_EQ(a, b);
}

TEST(RobotDriven, BadDrivenStatesAreRejected) {
  CrowdSimulation sim = fixtures::make();
  const AgentId a = *sim.add_agent(AgentSpec{});
  auto not_driven = sim.set_driven_state(a, {}, {});
  ASSERT_FALSE(not_driven);
  EXPECT_EQ(not_driven.error().errors[0].pointer, "/agent_id");
  ASSERT_TRUE(sim.set_driven(a, Presence::kVisible));
  EXPECT_FALSE(sim.set_driven_state(a, {std::nan(""), 0.0, 0.0}, {}));
  EXPECT_FALSE(sim.set_driven_state(a, {0.0, 0.0, INFINITY}, {}));
  EXPECT_FALSE(sim.set_driven_state(a, {}, {9.0, 0.0, 0.0}));
  EXPECT_FALSE(sim.set_driven_state(a, {}, {0.0, 0.0, 30.0}));
  EXPECT_FALSE(sim.set_driven(AgentId(7), Presence::kVisible));
  EXPECT_TRUE(sim.set_driven_state(a, {1.0, 2.0, 0.5}, {0.5, 0.0, 0.1}));
  EXPECT_EQ(sim.position(a), (Vec2{1.0, 2.0}));
  EXPECT_DOUBLE_EQ(sim.yaw(a), 0.5);
}

TEST(RobotDriven, BehaviourNodesSeeTheFirstVisibleRobot) {
  const Program p = fixtures::program(R"({"name": "t", "agents": [{"name": "a", "position": [0, 0]}]})");
  RunnerOptions o = fixtures::options(1);
  o.robots.push_back(RobotSpec{"ghost", {2.0, 0.0, 0.0}, std::nullopt, 0.35, Presence::kInvisible, {}});
  o.robots.push_back(RobotSpec{"seen", {3.0, 0.0, 0.0}, std::nullopt, 0.35, Presence::kVisible, {}});
  auto run = ScenarioRunner::create(nullptr, p, o);
  ASSERT_TRUE(run) << run.error().message();
  ASSERT_EQ((*run)->driven_robots().size(), 2u);
  EXPECT_EQ((*run)->environment().robot(), (*run)->driven_robots()[1]);
  EXPECT_EQ((*run)->agents().back().name, "seen");
  EXPECT_EQ((*run)->agents().back().kind, AgentKind::kRobot);

  RunnerOptions hidden = fixtures::options(1);
  hidden.robots.push_back(RobotSpec{"ghost", {2.0, 0.0, 0.0}, std::nullopt, 0.35, Presence::kInvisible, {}});
  auto run2 = ScenarioRunner::create(nullptr, p, hidden);
  ASSERT_TRUE(run2);
  EXPECT_FALSE((*run2)->environment().robot());
}

}  // namespace
}  // namespace socsim::crowd
