#include "core/crowd/robot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/crowd/role_parameters.hpp"

namespace socsim::crowd {

namespace {}  // namespace

Status validate(const RobotLimits& limits, const std::string& pointer) {
  std::vector<FieldError> errors;
  auto positive = [&](double v, const char* name, double max) {
    if (!(std::isfinite(v) && v > 0.0 && v <= max))
      errors.push_back(FieldError{pointer + "/" + name, "must be in (0, " + std::to_string(max) + "]"});
  };
  positive(limits.max_speed, "max_speed", kMaxAgentSpeed);
  positive(limits.max_acceleration, "max_acceleration", 100.0);
  positive(limits.max_turn_rate, "max_turn_rate", 20.0);
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid robot limits", std::move(errors));
  return {};
}

UnicycleState integrate_unicycle(const UnicycleState& s, VelocityCommand command, const RobotLimits& limits,
                                 double dt) {
  const double dv = limits.max_acceleration * dt;
  const double wanted = std::clamp(command.v, -limits.max_speed, limits.max_speed);
  const double v = std::clamp(wanted, s.v - dv, s.v + dv);
  const double omega = std::clamp(command.omega, -limits.max_turn_rate, limits.max_turn_rate);
  UnicycleState next;
  next.v = v;
  next.omega = omega;
  const double yaw = s.pose.yaw;
  const double turn = omega * dt;
  if (std::abs(turn) < 1e-9) {
    next.pose.x = s.pose.x + v * dt * std::cos(yaw);
    next.pose.y = s.pose.y + v * dt * std::sin(yaw);
  } else {
    const double r = v / omega;  // radius of the arc
    next.pose.x = s.pose.x + r * (std::sin(yaw + turn) - std::sin(yaw));
    next.pose.y = s.pose.y - r * (std::cos(yaw + turn) - std::cos(yaw));
  }
  next.pose.yaw = angle_in_pi(yaw + turn);
  return next;
}

Twist2 twist_of(const UnicycleState& s) {
  return {s.v * std::cos(s.pose.yaw), s.v * std::sin(s.pose.yaw), s.omega};
}

}  // namespace socsim::crowd
