#pragma once
// Robots driven from outside the crowd: the unicycle model that turns a velocity command into a
// pose under speed, acceleration and turn-rate limits, and the description of a robot in a run.
#include <optional>
#include <string>

#include "core/common/error.hpp"
#include "core/crowd/crowd_simulation.hpp"
#include "core/crowd/pedestrian_state.hpp"

namespace socsim::crowd {

struct RobotLimits {
  double max_speed = 1.0;         // m/s, forwards and backwards
  double max_acceleration = 1.0;  // m/s², change of the forward speed
  double max_turn_rate = 1.5;     // rad/s
};
// Every limit finite and positive, speed ≤ 8 m/s (pointer: where the limits were given).
Status validate(const RobotLimits& limits, const std::string& pointer = "/limits");

// Forward speed and turn rate asked for by a planner.
struct VelocityCommand {
  double v = 0.0;      // m/s
  double omega = 0.0;  // rad/s
  friend bool operator==(const VelocityCommand&, const VelocityCommand&) = default;
};

struct UnicycleState {
  Pose2 pose;
  double v = 0.0;      // m/s along the heading
  double omega = 0.0;  // rad/s
  friend bool operator==(const UnicycleState&, const UnicycleState&) = default;
};

// One step of dt: the speed moves towards the command by at most max_acceleration·dt and is
// clamped to ±max_speed, the turn rate is clamped to ±max_turn_rate; the pose then advances along
// the arc at the new speed and turn rate (exact for constant v and ω).
UnicycleState integrate_unicycle(const UnicycleState& s, VelocityCommand command, const RobotLimits& limits,
                                 double dt);
// The planar twist of a unicycle state (vx, vy in the world frame).
Twist2 twist_of(const UnicycleState& s);

// A robot of a run: where it starts, where it should go, how large it is, whether people see it.
struct RobotSpec {
  std::string name = "robot";
  Pose2 start;
  std::optional<Goal> goal;  // a goal radius of 0 stands for the episode's success radius
  double radius = 0.35;      // m
  Presence presence = Presence::kVisible;
  RobotLimits limits;
};

}  // namespace socsim::crowd
