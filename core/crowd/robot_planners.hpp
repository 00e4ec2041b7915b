#pragma once
// Built-in reference planners for a robot episode, so that the co-simulation API is useful out of
// the box and its tests have a real client: a straight-line goal seeker, a social-force robot and
// ORCA (optimal reciprocal collision avoidance, van den Berg et al. 2011) written for the robot.
// Each turns what the robot sees into a unicycle command; deterministic, no state between calls.
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/crowd/episode.hpp"

namespace socsim::crowd {

struct PlannerInput {
  UnicycleState robot;
  double radius = 0.35;
  std::optional<Goal> goal;  // none: stand still
  RobotLimits limits;
  double dt = 0.05;
  std::span<const LoggedBody> people;  // people near the robot
  std::span<const WallSegment> walls;
};

class RobotPlanner {
 public:
  virtual ~RobotPlanner() = default;
  [[nodiscard]] virtual VelocityCommand plan(const PlannerInput& in) const = 0;
};

// "straight_line", "social_force", "orca"; null for another name.
std::unique_ptr<RobotPlanner> make_planner(std::string_view name);
const std::vector<std::string_view>& planner_names();

// What a planner sees in an episode: robot k's state and goal, the people of the latest frame.
PlannerInput planner_input(const Episode& episode, std::size_t k);

// The unicycle command that turns towards a wanted planar velocity: ω proportional to the heading
// error (gain 2/s, limited), forward speed |v|·cos(error) (0 when facing away).
VelocityCommand steer_towards(const UnicycleState& robot, Vec2 wanted, const RobotLimits& limits);

// ORCA's velocity for the robot: the velocity closest to `preferred`, within max_speed, outside
// every person's velocity obstacle for `horizon` seconds (the robot takes all the avoiding:
// people are not assumed to cooperate), and outside the walls' for 1 s. When no velocity is
// collision-free, the one that least violates the constraints.
Vec2 orca_velocity(const PlannerInput& in, Vec2 preferred, double horizon = 3.0);

}  // namespace socsim::crowd
