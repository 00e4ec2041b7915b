#include "core/crowd/robot_planners.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/crowd/metrics.hpp"

namespace socsim::crowd {

namespace {

constexpr double kSeeRange = 5.0;   // m: people and walls farther away are ignored
constexpr double kClearance = 0.1;  // m kept beyond touching
constexpr double kEps = 1e-9;

double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
double det(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
double len(Vec2 a) {
  return std::hypot(a.x, a.y);
}
Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.y + b.y};
}
Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
Vec2 operator*(double k, Vec2 a) {
  return {k * a.x, k * a.y};
}

// The velocity towards the goal: full speed, slowing down inside the last metre.
Vec2 preferred_velocity(const PlannerInput& in) {
  if (!in.goal) return {};
  const Vec2 to{in.goal->position.x - in.robot.pose.x, in.goal->position.y - in.robot.pose.y};
  const double d = len(to);
  if (d < kEps) return {};
  const double speed = std::min(in.limits.max_speed, d);
  return (speed / d) * to;
}

Vec2 position(const PlannerInput& in) {
  return {in.robot.pose.x, in.robot.pose.y};
}

class StraightLine final : public RobotPlanner {
 public:
  [[nodiscard]] VelocityCommand plan(const PlannerInput& in) const override {
    return steer_towards(in.robot, preferred_velocity(in), in.limits);
  }
};

// The robot as a LightSFM pedestrian: relaxation towards the preferred velocity (τ = 0.5 s), the
// social forces of the people on it and the obstacle force of the walls (the evaluator's
// parameters), integrated over one step.
class SocialForce final : public RobotPlanner {
 public:
  [[nodiscard]] VelocityCommand plan(const PlannerInput& in) const override {
    constexpr double kRelaxation = 0.5;
    constexpr double kSocialWeight =
        3.0;  // the evaluator's A = 2.1 is a pedestrian's; a robot keeps more room
    const Vec2 p = position(in);
    const Twist2 t = twist_of(in.robot);
    const Vec2 v{t.vx, t.vy};
    const Vec2 pref = preferred_velocity(in);
    Vec2 social{};
    for (const LoggedBody& o : in.people)
      if (len(o.position - p) <= kSeeRange)
        social = social + evaluator_social_force(o.position, o.velocity, p, v);
    // Head-on the social force only brakes (its sideways term vanishes on the axis) and a robot
    // would stop nose to nose: the part of it that opposes the walk also pushes to the right
    // (keep right, as people do where traffic keeps right).
    const double pl = len(pref);
    if (pl > kEps) {
      const Vec2 e = (1.0 / pl) * pref;
      const double against = -dot(social, e);
      if (against > 0.0) social = social + against * Vec2{e.y, -e.x};
    }
    Vec2 force = (1.0 / kRelaxation) * (pref - v) + kSocialWeight * social;
    const std::vector<WallSegment> walls(in.walls.begin(), in.walls.end());
    force = force + evaluator_obstacle_force(p, in.radius, walls);
    // Look ahead half a second: a unicycle turns slower than a pedestrian.
    Vec2 wanted = v + 0.5 * force;
    const double s = len(wanted);
    if (s > in.limits.max_speed) wanted = (in.limits.max_speed / s) * wanted;
    return steer_towards(in.robot, wanted, in.limits);
  }
};

class Orca final : public RobotPlanner {
 public:
  [[nodiscard]] VelocityCommand plan(const PlannerInput& in) const override {
    return steer_towards(in.robot, orca_velocity(in, preferred_velocity(in)), in.limits);
  }
};

// A half-plane of permitted velocities: those v with det(direction, v − point) ≥ 0 (to the left).
struct Line {
  Vec2 point;
  Vec2 direction;
};

// The velocity obstacle of a disc at relative position `rel` (combined radius r) moving with
// relative velocity `vel` = v_robot − v_other, truncated at `horizon`: u is the smallest change of
// the relative velocity that leaves it, and the half-plane starts at own + u (the robot takes the
// whole correction).
Line orca_line(Vec2 rel, Vec2 vel, Vec2 own, double r, double horizon, double dt) {
  const double dist2 = dot(rel, rel);
  const double r2 = r * r;
  Vec2 u;
  Vec2 direction;
  if (dist2 > r2) {
    const Vec2 w = vel - (1.0 / horizon) * rel;  // from the cut-off centre to the velocity
    const double w_len2 = dot(w, w);
    const double proj = dot(w, rel);
    if (proj < 0.0 && proj * proj > r2 * w_len2) {
      // Closest to the cut-off circle.
      const double w_len = std::sqrt(w_len2);
      const Vec2 unit = w_len > kEps ? (1.0 / w_len) * w : Vec2{1.0, 0.0};
      direction = {unit.y, -unit.x};
      u = (r / horizon - w_len) * unit;
    } else {
      // Closest to a leg of the cone.
      const double leg = std::sqrt(dist2 - r2);
      if (det(rel, w) > 0.0) {
        direction = (1.0 / dist2) * Vec2{rel.x * leg - rel.y * r, rel.x * r + rel.y * leg};
      } else {
        direction = (-1.0 / dist2) * Vec2{rel.x * leg + rel.y * r, -rel.x * r + rel.y * leg};
      }
      u = dot(vel, direction) * direction - vel;
    }
  } else {
    // Already overlapping: get out within one step.
    const Vec2 w = vel - (1.0 / dt) * rel;
    const double w_len = len(w);
    const Vec2 unit = w_len > kEps ? (1.0 / w_len) * w : Vec2{1.0, 0.0};
    direction = {unit.y, -unit.x};
    u = (r / dt - w_len) * unit;
  }
  return Line{own + u, direction};
}

// Linear program on one line: the point of line i within the speed circle and the earlier lines
// closest to `preferred` (or farthest along it when `direction_opt`). False when infeasible.
bool lp1(const std::vector<Line>& lines, std::size_t i, double radius, Vec2 preferred, bool direction_opt,
         Vec2& result) {
  const Line& l = lines[i];
  const double dp = dot(l.point, l.direction);
  const double disc = dp * dp + radius * radius - dot(l.point, l.point);
  if (disc < 0.0) return false;
  const double sq = std::sqrt(disc);
  double t_left = -dp - sq;
  double t_right = -dp + sq;
  for (std::size_t j = 0; j < i; ++j) {
    const double denom = det(l.direction, lines[j].direction);
    const double numer = det(lines[j].direction, l.point - lines[j].point);
    if (std::abs(denom) <= kEps) {
      if (numer < 0.0) return false;
      continue;
    }
    const double t = numer / denom;
    if (denom >= 0.0)
      t_right = std::min(t_right, t);
    else
      t_left = std::max(t_left, t);
    if (t_left > t_right) return false;
  }
  double t;
  if (direction_opt) {
    t = dot(preferred, l.direction) > 0.0 ? t_right : t_left;
  } else {
    t = std::clamp(dot(l.direction, preferred - l.point), t_left, t_right);
  }
  result = l.point + t * l.direction;
  return true;
}

// Returns the number of lines satisfied before the first failure (lines.size() on success).
std::size_t lp2(const std::vector<Line>& lines, double radius, Vec2 preferred, bool direction_opt,
                Vec2& result) {
  if (direction_opt) {
    result = radius * preferred;
  } else if (dot(preferred, preferred) > radius * radius) {
    result = (radius / len(preferred)) * preferred;
  } else {
    result = preferred;
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (det(lines[i].direction, lines[i].point - result) > 0.0) {
      const Vec2 before = result;
      if (!lp1(lines, i, radius, preferred, direction_opt, result)) {
        result = before;
        return i;
      }
    }
  }
  return lines.size();
}

// No velocity satisfies every line: the one that minimises the largest violation.
void lp3(const std::vector<Line>& lines, std::size_t begin, double radius, Vec2& result) {
  double distance = 0.0;
  for (std::size_t i = begin; i < lines.size(); ++i) {
    if (det(lines[i].direction, lines[i].point - result) <= distance) continue;
    std::vector<Line> projected;
    for (std::size_t j = 0; j < i; ++j) {
      Line line;
      const double d = det(lines[i].direction, lines[j].direction);
      if (std::abs(d) <= kEps) {
        if (dot(lines[i].direction, lines[j].direction) > 0.0) continue;  // same direction
        line.point = 0.5 * (lines[i].point + lines[j].point);
      } else {
        line.point = lines[i].point +
                     (det(lines[j].direction, lines[i].point - lines[j].point) / d) * lines[i].direction;
      }
      line.direction = lines[j].direction - lines[i].direction;
      const double dl = len(line.direction);
      if (dl <= kEps) continue;
      line.direction = (1.0 / dl) * line.direction;
      projected.push_back(line);
    }
    const Vec2 before = result;
    if (lp2(projected, radius, {-lines[i].direction.y, lines[i].direction.x}, true, result) <
        projected.size())
      result = before;  // cannot happen in exact arithmetic
    distance = det(lines[i].direction, lines[i].point - result);
  }
}

}  // namespace

VelocityCommand steer_towards(const UnicycleState& robot, Vec2 wanted, const RobotLimits& limits) {
  const double speed = len(wanted);
  if (speed < 1e-6) return {0.0, 0.0};
  double error = std::atan2(wanted.y, wanted.x) - robot.pose.yaw;
  error = std::remainder(error, 2.0 * std::numbers::pi);
  const double omega = std::clamp(2.0 * error, -limits.max_turn_rate, limits.max_turn_rate);
  const double v = std::min(speed, limits.max_speed) * std::max(0.0, std::cos(error));
  return {v, omega};
}

Vec2 orca_velocity(const PlannerInput& in, Vec2 preferred, double horizon) {
  const Vec2 p = position(in);
  const Twist2 t = twist_of(in.robot);
  const Vec2 v{t.vx, t.vy};
  std::vector<Line> lines;
  // Walls first (they are hard): their nearest points as standing obstacles, horizon 1 s.
  for (const WallSegment& w : in.walls) {
    const Vec2 ab = w.b - w.a;
    const double l2 = dot(ab, ab);
    const double s = l2 > 0.0 ? std::clamp(dot(p - w.a, ab) / l2, 0.0, 1.0) : 0.0;
    const Vec2 q = w.a + s * ab;
    if (len(q - p) > std::min(kSeeRange, in.limits.max_speed * 1.0 + in.radius + kClearance)) continue;
    lines.push_back(orca_line(q - p, v, v, in.radius + kClearance, 1.0, in.dt));
  }
  for (const LoggedBody& o : in.people) {
    const Vec2 rel = o.position - p;
    if (len(rel) > kSeeRange) continue;
    lines.push_back(orca_line(rel, v - o.velocity, v, in.radius + o.radius + kClearance, horizon, in.dt));
  }
  Vec2 result;
  const std::size_t ok = lp2(lines, in.limits.max_speed, preferred, false, result);
  if (ok < lines.size()) lp3(lines, ok, in.limits.max_speed, result);
  return result;
}

std::unique_ptr<RobotPlanner> make_planner(std::string_view name) {
  if (name == "straight_line") return std::make_unique<StraightLine>();
  if (name == "social_force") return std::make_unique<SocialForce>();
  if (name == "orca") return std::make_unique<Orca>();
  return nullptr;
}

const std::vector<std::string_view>& planner_names() {
  static const std::vector<std::string_view> names{"straight_line", "social_force", "orca"};
  return names;
}

PlannerInput planner_input(const Episode& episode, std::size_t k) {
  PlannerInput in;
  const RobotSpec& spec = episode.robots().at(k);
  in.robot = episode.robot_state(k);
  in.radius = spec.radius;
  in.goal = spec.goal;
  in.limits = spec.limits;
  in.dt = episode.log().dt;
  in.people = episode.log().frames.back().people;
  in.walls = episode.log().walls;
  return in;
}

}  // namespace socsim::crowd
