// Robot episodes: outcomes (success, person and wall collisions, stuck, timeout) in small worlds,
// strict step inputs, bit-identical logs; and the episode metrics on hand-made logs whose values
// are worked out by hand in the comments.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/crowd/episode.hpp"
#include "core/crowd/episode_metrics.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

namespace socsim::crowd {
namespace {

// A corridor 20 m × 3 m: walls along y = 0 and y = 3.
world::World corridor() {
  auto w = world::world_from_yaml(R"(zones:
  - {name: corridor, polygon: [[0, 0], [20, 0], [20, 3], [0, 3]]}
)");
  EXPECT_TRUE(w) << w.error().message();
  return *w;
}

RobotSpec robot_at(Pose2 start, std::optional<Goal> goal, Presence presence = Presence::kVisible) {
  RobotSpec r;
  r.start = start;
  r.goal = goal;
  r.presence = presence;
  return r;
}

std::unique_ptr<Episode> episode(const world::World& w, const Program& p, std::vector<RobotSpec> robots,
                                 EpisodeOptions eo = {}) {
  RunnerOptions o = fixtures::options(3);
  o.robots = std::move(robots);
  auto e = Episode::create(&w, p, o, eo);
  EXPECT_TRUE(e) << e.error().message();
  return std::move(*e);
}

void drive(Episode& e, VelocityCommand c, int steps) {
  const RobotInput in{RobotInput::Kind::kCommand, c, {}, {}};
  for (int k = 0; k < steps && !e.ended(); ++k) ASSERT_TRUE(e.step(std::span(&in, 1)));
}

const char* kEmpty = R"({"name": "empty", "agents": []})";

TEST(Episode, StraightToTheGoalSucceeds) {
  const world::World w = corridor();
  auto e = episode(w, fixtures::program(kEmpty), {robot_at({2, 1.5, 0}, Goal{{8, 1.5}, 0.5})});
  drive(*e, {1.0, 0.0}, 400);
  ASSERT_TRUE(e->ended());
  EXPECT_EQ(e->results()[0].outcome, Outcome::kSuccess);
  // Ramp 0 → 1 m/s in 1 s (0.5 m), then 5 m at 1 m/s (the goal radius is 0.5 m): ≈ 6.0 s.
  EXPECT_NEAR(*e->results()[0].end_time, 6.0, 0.06);
  const EpisodeMetrics m = evaluate_episode(e->log());
  EXPECT_NEAR(m.robots[0].path_length, 5.5, 0.05);
  EXPECT_NEAR(m.robots[0].path_efficiency, 1.0, 0.01);
  EXPECT_EQ(m.robots[0].collisions, 0u);
  EXPECT_DOUBLE_EQ(m.robots[0].minimum_distance_to_people, kEpisodeLogRange) << "nobody around";
}

TEST(Episode, DrivingIntoTheWallIsAWallCollision) {
  const world::World w = corridor();
  auto e =
      episode(w, fixtures::program(kEmpty), {robot_at({5, 1.5, std::numbers::pi / 2}, Goal{{15, 1.5}, 0.5})});
  drive(*e, {1.0, 0.0}, 400);
  EXPECT_EQ(e->results()[0].outcome, Outcome::kCollisionWall);
}

TEST(Episode, StandingStillIsStuckAndCirclingTimesOut) {
  const world::World w = corridor();
  EpisodeOptions eo;
  eo.stuck_time = 2.0;
  eo.time_limit = 5.0;
  auto still = episode(w, fixtures::program(kEmpty), {robot_at({5, 1.5, 0}, Goal{{15, 1.5}, 0.5})}, eo);
  drive(*still, {0.0, 0.0}, 400);
  EXPECT_EQ(still->results()[0].outcome, Outcome::kStuck);
  EXPECT_NEAR(*still->results()[0].end_time, 2.0, 1e-9);
  auto circling = episode(w, fixtures::program(kEmpty), {robot_at({5, 1.5, 0}, Goal{{15, 1.5}, 0.5})}, eo);
  drive(*circling, {0.5, 1.0}, 400);
  EXPECT_EQ(circling->results()[0].outcome, Outcome::kTimeout);
  EXPECT_NEAR(*circling->results()[0].end_time, 5.0, 1e-9);
  EXPECT_EQ(evaluate_episode(circling->log()).robots[0].path_efficiency, 0.0);
  EXPECT_EQ(circling->steps(), 100u);
  const RobotInput in{};
  EXPECT_EQ(circling->step(std::span(&in, 1)).error().code, ErrorCode::kConflict);
}

const char* kWalker = R"({"name": "encounter", "agents": [
  {"name": "walker", "position": [14, 1.5], "speed": 1.2, "goals": [[1, 1.5]], "cyclic_goals": false}]})";

TEST(Episode, DrivingIntoAPersonIsAPersonCollision) {
  const world::World w = corridor();
  auto e = episode(w, fixtures::program(kWalker),
                   {robot_at({2, 1.5, 0}, Goal{{18, 1.5}, 0.5}, Presence::kInvisible)});
  drive(*e, {1.0, 0.0}, 400);
  EXPECT_EQ(e->results()[0].outcome, Outcome::kCollisionPerson);
  EXPECT_EQ(e->results()[0].hit, 0u);
}

RobotEpisodeMetrics parked(Presence presence) {
  // The robot parks in the walker's way (10 cm off its line); a visible one is walked round.
  const world::World w = corridor();
  EpisodeOptions eo;
  eo.stuck_time = 100.0;
  eo.time_limit = 14.0;
  auto e =
      episode(w, fixtures::program(kWalker), {robot_at({7, 1.4, 0}, Goal{{18, 1.5}, 0.5}, presence)}, eo);
  drive(*e, {0.0, 0.0}, 1000);
  return evaluate_episode(e->log()).robots[0];
}

TEST(Episode, PeopleKeepAwayFromAVisibleRobotOnly) {
  const RobotEpisodeMetrics visible = parked(Presence::kVisible);
  const RobotEpisodeMetrics invisible = parked(Presence::kInvisible);
  EXPECT_EQ(visible.outcome, Outcome::kTimeout) << "walked round, never hit";
  EXPECT_GE(visible.minimum_distance_to_people, 0.23 - 0.01) << "the person's radius: at most touching";
  EXPECT_EQ(invisible.outcome, Outcome::kCollisionPerson);
  EXPECT_GE(invisible.person_on_robot_collision, 1u);
  EXPECT_LT(invisible.minimum_distance_to_people, visible.minimum_distance_to_people);
}

TEST(Episode, LogsAreBitIdenticalForTheSameInputs) {
  const world::World w = corridor();
  auto run = [&] {
    auto e = episode(w, fixtures::program(kWalker), {robot_at({2, 1.0, 0}, Goal{{18, 1.0}, 0.5})});
    drive(*e, {0.6, 0.05}, 150);
    return e->log().frames;
  };
  EXPECT_EQ(run(), run());
}

TEST(Episode, BadInputsAreRejectedWithoutTakingTheStep) {
  const world::World w = corridor();
  auto e = episode(w, fixtures::program(kEmpty), {robot_at({5, 1.5, 0}, Goal{{15, 1.5}, 0.5})});
  auto expect_error = [&](RobotInput in, const std::string& pointer) {
    auto s = e->step(std::span(&in, 1));
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().code, ErrorCode::kValidation);
    ASSERT_FALSE(s.error().errors.empty());
    EXPECT_EQ(s.error().errors[0].pointer, pointer);
  };
  expect_error({RobotInput::Kind::kCommand, {std::nan(""), 0.0}, {}, {}}, "/robots/0/cmd/v");
  expect_error({RobotInput::Kind::kCommand, {100.0, 0.0}, {}, {}}, "/robots/0/cmd/v");
  expect_error({RobotInput::Kind::kCommand, {0.0, INFINITY}, {}, {}}, "/robots/0/cmd/omega");
  expect_error({RobotInput::Kind::kState, {}, {std::nan(""), 1.5, 0.0}, {}}, "/robots/0/pose");
  expect_error({RobotInput::Kind::kState, {}, {9.0, 1.5, 0.0}, {}}, "/robots/0/pose");
  expect_error({RobotInput::Kind::kState, {}, {5.0, 1.5, 0.0}, {50.0, 0.0, 0.0}}, "/robots/0/twist");
  auto two = std::vector<RobotInput>(2);
  EXPECT_FALSE(e->step(two));
  EXPECT_EQ(e->steps(), 0u);
  const RobotInput ok{RobotInput::Kind::kState, {}, {5.02, 1.5, 0.0}, {0.4, 0.0, 0.0}};
  ASSERT_TRUE(e->step(std::span(&ok, 1)));
  EXPECT_EQ(e->log().frames.back().robots[0].position, (Vec2{5.02, 1.5}));
}

TEST(Episode, TheProgramRobotIsTheDefaultAndRobotsAreCounted) {
  const world::World w = corridor();
  const Program p = fixtures::program(R"({"name": "r", "agents": [],
    "robot": {"position": [2, 1.5], "speed": 0.8, "goals": [[10, 1.5]]}})");
  auto e = Episode::create(&w, p, fixtures::options(1), {});
  ASSERT_TRUE(e) << e.error().message();
  ASSERT_EQ((*e)->robots().size(), 1u);
  ASSERT_TRUE((*e)->robots()[0].goal);
  EXPECT_EQ((*e)->robots()[0].goal->position, (Vec2{10, 1.5}));
  EXPECT_DOUBLE_EQ((*e)->robots()[0].limits.max_speed, 0.8);

  auto none = Episode::create(&w, fixtures::program(kEmpty), fixtures::options(1), {});
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().errors[0].pointer, "/robots");
  RunnerOptions many = fixtures::options(1);
  for (int k = 0; k < 3; ++k) many.robots.push_back(robot_at({2.0 + k, 1.5, 0}, std::nullopt));
  EpisodeOptions two;
  two.max_robots = 2;
  auto too_many = Episode::create(&w, fixtures::program(kEmpty), many, two);
  ASSERT_FALSE(too_many);
  EXPECT_NE(too_many.error().message().find("too many robots"), std::string::npos);
}

// --- metrics on hand-made logs ---------------------------------------------------------------

// The robot (radius 0.35) drives along y = 0 at x = 0, 0.5, …, 2 (dt = 0.5 s) with speeds
// 0, 1, 1, 1, 1 m/s; goal (3, 0), radius 1: reached in the last frame (t = 2 s).
EpisodeLog straight_log(Vec2 person) {
  EpisodeLog log;
  log.dt = 0.5;
  RobotSpec r;
  r.start = {0, 0, 0};
  r.goal = Goal{{3, 0}, 1.0};
  log.robots = {r};
  for (int f = 0; f < 5; ++f) {
    EpisodeFrame frame;
    frame.time = 0.5 * f;
    frame.robots.push_back(LoggedBody{1, {0.5 * f, 0.0}, {f == 0 ? 0.0 : 1.0, 0.0}, 0.0, 0.0, 0.35});
    frame.people.push_back(LoggedBody{0, person, {}, 0.0, 0.0, 0.25});
    log.frames.push_back(frame);
  }
  log.results = {RobotResult{Outcome::kSuccess, 2.0, std::nullopt}};
  return log;
}

TEST(EpisodeMetrics, MotionFiguresAndPathEfficiency) {
  const RobotEpisodeMetrics m = evaluate_episode(straight_log({1.0, 1.0})).robots[0];
  EXPECT_TRUE(m.success);
  EXPECT_DOUBLE_EQ(*m.time_to_reach_goal, 2.0);
  EXPECT_DOUBLE_EQ(m.path_length, 2.0);
  EXPECT_DOUBLE_EQ(m.cumulative_heading_changes, 0.0);
  EXPECT_DOUBLE_EQ(m.avg_speed, 0.8);             // (0 + 1 + 1 + 1 + 1) / 5
  EXPECT_DOUBLE_EQ(m.avg_acceleration, 0.5);      // |a| = 2, 0, 0, 0 m/s²
  EXPECT_DOUBLE_EQ(m.avg_jerk, 4.0 / 3.0);        // |Δa|/dt = 4, 0, 0 m/s³
  EXPECT_DOUBLE_EQ(m.shortest_path_length, 2.0);  // 3 m less the goal radius
  EXPECT_DOUBLE_EQ(m.path_efficiency, 1.0);
  EXPECT_DOUBLE_EQ(m.time_not_moving, 0.0);
}

TEST(EpisodeMetrics, DistancesAndIntrusionsToAStandingPerson) {
  // Person at (1, 1): centre distances √2, √1.25, 1, √1.25, √2.
  const RobotEpisodeMetrics m = evaluate_episode(straight_log({1.0, 1.0})).robots[0];
  EXPECT_DOUBLE_EQ(m.minimum_distance_to_people, 1.0 - 0.35);
  const double body = (2 * std::sqrt(2.0) + 2 * std::sqrt(1.25) + 1.0) / 5.0 - 0.6;
  EXPECT_NEAR(m.avg_distance_to_closest_person, body, 1e-12);
  EXPECT_DOUBLE_EQ(m.personal_space_intrusions, 100.0);  // 0.65 .. 1.06 m: all personal
  EXPECT_DOUBLE_EQ(m.intimate_space_intrusions, 0.0);
  EXPECT_DOUBLE_EQ(m.social_space_intrusions, 0.0);
  EXPECT_EQ(m.collisions, 0u);
  EXPECT_GT(m.social_work, 0.0);
}

TEST(EpisodeMetrics, GroupSpaceIntrusionsUseTheInteractionCentre) {
  // Two members at (1, ±1.5) facing the corridor's axis: their points 1.5 m ahead meet at (1, 0),
  // the centre the robot drives through. Robot centre − 0.35 at x = 0, 0.5, 1, 1.5, 2: 0.65, 0.15,
  // −0.35, 0.15, 0.65 → intimate in 3 frames, personal in 2.
  EpisodeLog log = straight_log({9.0, 9.0});
  for (EpisodeFrame& f : log.frames) {
    f.people.clear();
    f.people.push_back(LoggedBody{2, {1.0, 1.5}, {}, -std::numbers::pi / 2, 0.0, 0.25, 7});
    f.people.push_back(LoggedBody{3, {1.0, -1.5}, {}, std::numbers::pi / 2, 0.0, 0.25, 7});
  }
  const RobotEpisodeMetrics m = evaluate_episode(log).robots[0];
  EXPECT_DOUBLE_EQ(m.group_intimate_space_intrusions, 60.0);
  EXPECT_DOUBLE_EQ(m.group_personal_space_intrusions, 40.0);
  EXPECT_DOUBLE_EQ(m.group_social_space_intrusions, 0.0);
  // The same people walking alone are no group: no group intrusion.
  for (EpisodeFrame& f : log.frames)
    for (LoggedBody& p : f.people) p.group = -1;
  EXPECT_DOUBLE_EQ(evaluate_episode(log).robots[0].group_intimate_space_intrusions, 0.0);
}

TEST(EpisodeMetrics, CollisionsAreSplitByWhoMovedIn) {
  // Person at (1, 0.3): bodies (0.6 m) overlap at x = 0.5 (robot moving in: robot on person),
  // x = 1 (side by side, neither moves in: both) and x = 1.5 (robot moving away: person on robot).
  const RobotEpisodeMetrics m = evaluate_episode(straight_log({1.0, 0.3})).robots[0];
  EXPECT_EQ(m.collisions, 3u);
  EXPECT_EQ(m.robot_on_person_collision, 2u);
  EXPECT_EQ(m.person_on_robot_collision, 2u);
  EXPECT_DOUBLE_EQ(m.intimate_space_intrusions, 60.0);  // centre − 0.35 < 0.45 in 3 of 5 frames
}

TEST(EpisodeMetrics, FramesAfterTheOutcomeDoNotCount) {
  EpisodeLog log = straight_log({5.0, 5.0});
  log.results[0] = RobotResult{Outcome::kCollisionWall, 1.0, std::nullopt};
  const RobotEpisodeMetrics m = evaluate_episode(log).robots[0];
  EXPECT_DOUBLE_EQ(m.path_length, 1.0);  // frames 0, 1, 2
  EXPECT_FALSE(m.time_to_reach_goal);
  EXPECT_DOUBLE_EQ(m.path_efficiency, 0.0);
  EXPECT_EQ(to_json(m)["outcome"], "collision_wall");
}

}  // namespace
}  // namespace socsim::crowd
