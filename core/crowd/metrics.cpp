#include "core/crowd/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

namespace socsim::crowd {

namespace {

constexpr double kCloseRange = 10.0;  // m searched for the closest person
constexpr double kCell = 2.0;         // m, neighbour grid
constexpr double kPi = std::numbers::pi;

double wrap(double a) {
  while (a > kPi) a -= 2.0 * kPi;
  while (a <= -kPi) a += 2.0 * kPi;
  return a;
}

}  // namespace

// LightSFM's social force that `a` (position pa, velocity va) exerts on `b` (HuNavSim evaluator,
// default parameters: A = 2.1, λ = 2, γ = 0.35, n = 2, n' = 3).
Vec2 evaluator_social_force(Vec2 pa, Vec2 va, Vec2 pb, Vec2 vb) {
  constexpr double A = 2.1, lambda = 2.0, gamma = 0.35, n = 2.0, n_prime = 3.0;
  const double dx = pa.x - pb.x;
  const double dy = pa.y - pb.y;
  const double d = std::hypot(dx, dy);
  if (d < 1e-9) return {};
  const Vec2 e{dx / d, dy / d};
  const Vec2 t{lambda * (vb.x - va.x) + e.x, lambda * (vb.y - va.y) + e.y};
  const double tl = std::hypot(t.x, t.y);
  if (tl < 1e-12) return {};
  const Vec2 th{t.x / tl, t.y / tl};
  const double theta = wrap(std::atan2(th.y, th.x) - std::atan2(e.y, e.x));
  const double B = gamma * tl;
  const double fv = -std::exp(-d / B - (n_prime * B * theta) * (n_prime * B * theta));
  const double sign = theta > 0.0 ? 1.0 : (theta < 0.0 ? -1.0 : 0.0);
  const double fa = sign * std::exp(-d / B - (n * B * theta) * (n * B * theta));
  const Vec2 left{-th.y, th.x};
  return {A * (fv * th.x + fa * left.x), A * (fv * th.y + fa * left.y)};
}

// LightSFM obstacle force averaged over the nearest points of the walls within 2 m (HuNavSim
// averages over the agent's closest obstacles).
Vec2 evaluator_obstacle_force(Vec2 p, double radius, const std::vector<WallSegment>& walls) {
  Vec2 sum{};
  int count = 0;
  for (const WallSegment& w : walls) {
    const double ux = w.b.x - w.a.x;
    const double uy = w.b.y - w.a.y;
    const double len2 = ux * ux + uy * uy;
    const double t =
        len2 > 0.0 ? std::clamp(((p.x - w.a.x) * ux + (p.y - w.a.y) * uy) / len2, 0.0, 1.0) : 0.0;
    const double dx = p.x - (w.a.x + t * ux);
    const double dy = p.y - (w.a.y + t * uy);
    const double d = std::hypot(dx, dy);
    if (d > 2.0 || d < 1e-9) continue;
    const double m = 10.0 * std::exp(-(d - radius) / 0.2);
    sum.x += m * dx / d;
    sum.y += m * dy / d;
    ++count;
  }
  if (count > 0) sum = {sum.x / count, sum.y / count};
  return sum;
}

CollisionSide collision_side(Vec2 robot, Vec2 robot_velocity, Vec2 person, Vec2 person_velocity) {
  const double d = norm({person.x - robot.x, person.y - robot.y});
  if (d <= 1e-9) return {};
  // Who moved into whom: the one with the larger speed towards the other. (HuNavSim compares
  // bearings with a swapped atan2; this is the rule it describes.)
  const double robot_in =
      (robot_velocity.x * (person.x - robot.x) + robot_velocity.y * (person.y - robot.y)) / d;
  const double person_in =
      (person_velocity.x * (robot.x - person.x) + person_velocity.y * (robot.y - person.y)) / d;
  return {robot_in >= person_in, person_in >= robot_in};
}

struct MetricsRecorder::Track {
  bool seen = false;
  Vec2 last_pos;
  double last_yaw = 0.0;
  double last_speed = 0.0;
  double last_time = 0.0;
  AgentMetrics m;
  double closest_sum = 0.0;
  std::uint64_t closest_frames = 0;
  double min_people = std::numeric_limits<double>::infinity();
  std::uint64_t intimate = 0, personal = 0, social = 0, not_moving = 0;
  double speed_sum = 0.0, angular_sum = 0.0, acc_sum = 0.0, jerk_sum = 0.0;
  std::uint64_t acc_samples = 0;
  double min_goal = std::numeric_limits<double>::infinity();
  double last_goal = 0.0;
};

MetricsRecorder::MetricsRecorder(std::vector<std::vector<Goal>> goals, std::optional<AgentId> robot)
    : goals_(std::move(goals)), robot_(robot) {}
MetricsRecorder::MetricsRecorder(MetricsRecorder&&) noexcept = default;
MetricsRecorder& MetricsRecorder::operator=(MetricsRecorder&&) noexcept = default;
MetricsRecorder::~MetricsRecorder() = default;

void MetricsRecorder::observe(double time, const std::vector<PedestrianState>& states,
                              const std::vector<double>& radii, const std::vector<std::uint8_t>& active,
                              const std::vector<WallSegment>& walls) {
  const std::size_t n = states.size();
  if (tracks_.size() < n) tracks_.resize(n);
  if (frames_ == 0) first_time_ = time;
  last_time_ = time;
  ++frames_;

  // Neighbour grid over active agents.
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
  auto cell_key = [](std::int64_t gx, std::int64_t gy) {
    return (static_cast<std::uint64_t>(gx) << 32) ^ (static_cast<std::uint64_t>(gy) & 0xffffffffu);
  };
  auto key = [&](double x, double y) {
    return cell_key(static_cast<std::int64_t>(std::floor(x / kCell)),
                    static_cast<std::int64_t>(std::floor(y / kCell)));
  };
  for (std::uint32_t i = 0; i < n; ++i)
    if (active[i]) cells[key(states[i].pose.x, states[i].pose.y)].push_back(i);

  for (std::uint32_t i = 0; i < n; ++i) {
    Track& tr = tracks_[i];
    const PedestrianState& s = states[i];
    tr.m.id = i;
    tr.m.role = s.role;
    const Vec2 p{s.pose.x, s.pose.y};
    const Vec2 v{s.twist.vx, s.twist.vy};
    const double speed = norm(v);
    const bool exited = s.activity == Activity::kExited;
    if (exited && !tr.m.goal_reached) {
      tr.m.goal_reached = true;
      tr.m.time_to_reach_goal = time - first_time_;
    }
    if (!active[i]) continue;
    const bool is_robot = robot_ && robot_->value() == i;
    if (!is_robot) {
      pedestrian_speed_sum_ += speed;
      ++pedestrian_samples_;
    }
    ++tr.m.frames;
    if (tr.seen) {
      const double dt = time - tr.last_time;
      tr.m.path_length += norm({p.x - tr.last_pos.x, p.y - tr.last_pos.y});
      tr.m.cumulative_heading_changes += std::abs(wrap(tr.last_yaw - s.pose.yaw));
      if (dt > 0.0) {
        const double acc = (speed - tr.last_speed) / dt;
        tr.acc_sum += acc;
        tr.jerk_sum += acc / dt;
        ++tr.acc_samples;
      }
    }
    tr.speed_sum += speed;
    tr.angular_sum += s.twist.omega;
    if (speed < 0.001 && std::abs(s.twist.omega) < 0.01) ++tr.not_moving;

    // Goals.
    if (i < goals_.size() && !goals_[i].empty()) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Goal& g : goals_[i])
        nearest = std::min(nearest, norm({p.x - g.position.x, p.y - g.position.y}));
      tr.min_goal = std::min(tr.min_goal, nearest);
      tr.last_goal = nearest;
      const Goal& last = goals_[i].back();
      if (!tr.m.goal_reached && norm({p.x - last.position.x, p.y - last.position.y}) <= last.radius) {
        tr.m.goal_reached = true;
        tr.m.time_to_reach_goal = time - first_time_;
      }
    }

    // People around: the closest one, intrusions, collisions and social forces.
    const double ri = i < radii.size() ? radii[i] : 0.3;
    double closest_body = std::numeric_limits<double>::infinity();
    double closest_centre = std::numeric_limits<double>::infinity();
    Vec2 force_on_me{};
    const auto cx = static_cast<std::int64_t>(std::floor(p.x / kCell));
    const auto cy = static_cast<std::int64_t>(std::floor(p.y / kCell));
    const int rings = static_cast<int>(std::ceil(kCloseRange / kCell));
    for (int r = 0; r <= rings; ++r) {
      if (closest_centre < (r - 1) * kCell) break;  // nothing farther can be closer
      for (std::int64_t gy = cy - r; gy <= cy + r; ++gy) {
        for (std::int64_t gx = cx - r; gx <= cx + r; ++gx) {
          if (std::max(std::abs(gx - cx), std::abs(gy - cy)) != r) continue;
          auto it = cells.find(cell_key(gx, gy));
          if (it == cells.end()) continue;
          for (std::uint32_t j : it->second) {
            if (j == i) continue;
            const PedestrianState& o = states[j];
            const Vec2 q{o.pose.x, o.pose.y};
            const double d = norm({q.x - p.x, q.y - p.y});
            if (d > kCloseRange) continue;
            const double rj = j < radii.size() ? radii[j] : 0.3;
            closest_centre = std::min(closest_centre, d - ri);
            closest_body = std::min(closest_body, d - ri - rj);
            if (d - ri - rj < 0.02) {
              ++tr.m.collisions;
              if (is_robot) {
                const CollisionSide side = collision_side(p, v, q, {o.twist.vx, o.twist.vy});
                robot_on_person_ += side.robot_on_person ? 1 : 0;
                person_on_robot_ += side.person_on_robot ? 1 : 0;
              }
            }
            if (d <= kForceRange) {
              const Vec2 vj{o.twist.vx, o.twist.vy};
              const Vec2 on_me = evaluator_social_force(q, vj, p, v);
              force_on_me.x += on_me.x;
              force_on_me.y += on_me.y;
              tr.m.social_force_on_agent += norm(on_me);
              const double by_me = norm(evaluator_social_force(p, v, q, vj));
              tr.m.social_force_on_people += by_me;
              tr.m.social_work += by_me;
            }
          }
        }
      }
    }
    if (std::isfinite(closest_body)) {
      tr.closest_sum += closest_body;
      ++tr.closest_frames;
    }
    tr.min_people = std::min(tr.min_people, closest_centre);
    if (closest_centre < 0.45)
      ++tr.intimate;
    else if (closest_centre < 1.2)
      ++tr.personal;
    else if (closest_centre < 3.6)
      ++tr.social;
    tr.m.social_work += norm(force_on_me) + norm(evaluator_obstacle_force(p, ri, walls));

    tr.seen = true;
    tr.last_pos = p;
    tr.last_yaw = s.pose.yaw;
    tr.last_speed = speed;
    tr.last_time = time;
  }
}

RunMetrics MetricsRecorder::finish() const {
  RunMetrics out;
  out.frames = frames_;
  out.duration = last_time_ - first_time_;
  out.frame_period = frames_ > 1 ? out.duration / static_cast<double>(frames_ - 1) : 0.0;
  out.avg_pedestrian_velocity =
      pedestrian_samples_ > 0 ? pedestrian_speed_sum_ / static_cast<double>(pedestrian_samples_) : 0.0;
  out.robot_on_person_collisions = robot_on_person_;
  out.person_on_robot_collisions = person_on_robot_;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const Track& tr = tracks_[i];
    AgentMetrics m = tr.m;
    const double frames = static_cast<double>(std::max<std::uint64_t>(m.frames, 1));
    m.avg_distance_to_closest_person =
        tr.closest_frames > 0 ? tr.closest_sum / static_cast<double>(tr.closest_frames) : 0.0;
    m.minimum_distance_to_people = std::isfinite(tr.min_people) ? tr.min_people : 0.0;
    m.intimate_space_intrusions = 100.0 * static_cast<double>(tr.intimate) / frames;
    m.personal_space_intrusions = 100.0 * static_cast<double>(tr.personal) / frames;
    m.social_space_intrusions = 100.0 * static_cast<double>(tr.social) / frames;
    m.time_not_moving = static_cast<double>(tr.not_moving) * out.frame_period;
    m.avg_linear_speed = tr.speed_sum / frames;
    m.avg_angular_speed = tr.angular_sum / frames;
    m.avg_acceleration = tr.acc_samples > 0 ? tr.acc_sum / static_cast<double>(tr.acc_samples) : 0.0;
    m.avg_overacceleration = tr.acc_samples > 0 ? tr.jerk_sum / static_cast<double>(tr.acc_samples) : 0.0;
    m.final_goal_distance = std::isfinite(tr.min_goal) ? tr.last_goal : 0.0;
    m.minimum_goal_distance = std::isfinite(tr.min_goal) ? tr.min_goal : 0.0;
    if (robot_ && robot_->value() == i)
      out.robot = m;
    else
      out.agents.push_back(std::move(m));
  }
  return out;
}

Json to_json(const AgentMetrics& m) {
  Json j = {{"id", m.id},
            {"role", m.role},
            {"goal_reached", m.goal_reached},
            {"avg_linear_speed", m.avg_linear_speed},
            {"avg_angular_speed", m.avg_angular_speed},
            {"avg_acceleration", m.avg_acceleration},
            {"avg_overacceleration", m.avg_overacceleration},
            {"final_goal_distance", m.final_goal_distance},
            {"minimum_goal_distance", m.minimum_goal_distance},
            {"frames", m.frames}};
  put_hunav_figures(j, m);
  return j;
}

Json to_json(const RunMetrics& m) {
  Json agents = Json::array();
  for (const AgentMetrics& a : m.agents) agents.push_back(to_json(a));
  Json j = {{"duration", m.duration},
            {"frames", m.frames},
            {"frame_period", m.frame_period},
            {"avg_pedestrian_velocity", m.avg_pedestrian_velocity},
            {"agents", std::move(agents)}};
  if (m.robot) {
    Json r = to_json(*m.robot);
    r["robot_on_person_collision"] = m.robot_on_person_collisions;
    r["person_on_robot_collision"] = m.person_on_robot_collisions;
    j["robot"] = std::move(r);
  } else {
    j["robot"] = nullptr;
  }
  return j;
}

}  // namespace socsim::crowd
