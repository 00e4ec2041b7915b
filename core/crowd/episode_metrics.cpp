#include "core/crowd/episode_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "core/crowd/metrics.hpp"

namespace socsim::crowd {

namespace {

constexpr double kGroupCentreAhead =
    1.5;  // m: HuNavSim's interaction centre lies this far ahead of each member

// Distance from the robot (centre, less its radius) to the nearest group's interaction centre: the
// mean of the members' points kGroupCentreAhead ahead of them. Infinity when no group is logged.
double closest_group_centre(const std::vector<LoggedBody>& people, const LoggedBody& robot) {
  std::vector<std::pair<std::int64_t, std::size_t>> members;  // (group, index), sorted by group
  for (std::size_t i = 0; i < people.size(); ++i)
    if (people[i].group >= 0) members.emplace_back(people[i].group, i);
  std::sort(members.begin(), members.end());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < members.size();) {
    std::size_t b = a;
    Vec2 centre{};
    for (; b < members.size() && members[b].first == members[a].first; ++b) {
      const LoggedBody& p = people[members[b].second];
      centre.x += p.position.x + kGroupCentreAhead * std::cos(p.yaw);
      centre.y += p.position.y + kGroupCentreAhead * std::sin(p.yaw);
    }
    const double n = static_cast<double>(b - a);
    best = std::min(best,
                    norm({centre.x / n - robot.position.x, centre.y / n - robot.position.y}) - robot.radius);
    a = b;
  }
  return best;
}

RobotEpisodeMetrics evaluate_robot(const EpisodeLog& log, std::size_t k) {
  RobotEpisodeMetrics m;
  const RobotSpec& spec = log.robots[k];
  const RobotResult& result = log.results.at(k);
  m.name = spec.name;
  m.outcome = result.outcome;
  m.success = result.outcome == Outcome::kSuccess;
  if (m.success) m.time_to_reach_goal = result.end_time;
  // The robot's frames: up to and including the one that decided its outcome.
  std::size_t last = log.frames.size();
  if (result.end_time)
    for (std::size_t f = 0; f < log.frames.size(); ++f)
      if (log.frames[f].time >= *result.end_time - 1e-9) {
        last = f + 1;
        break;
      }
  double closest_sum = 0.0;
  std::uint64_t closest_frames = 0, intimate = 0, personal = 0, social = 0, still = 0;
  std::uint64_t group_intimate = 0, group_personal = 0, group_social = 0;
  double min_people = kEpisodeLogRange;
  double speed_sum = 0.0, acc_sum = 0.0, jerk_sum = 0.0;
  std::uint64_t acc_samples = 0, jerk_samples = 0;
  double last_acc = 0.0;
  for (std::size_t f = 0; f < last; ++f) {
    const EpisodeFrame& frame = log.frames[f];
    const LoggedBody& r = frame.robots[k];
    const double speed = norm(r.velocity);
    speed_sum += speed;
    if (f > 0) {
      const LoggedBody& before = log.frames[f - 1].robots[k];
      m.path_length += norm({r.position.x - before.position.x, r.position.y - before.position.y});
      m.cumulative_heading_changes += std::abs(angle_in_pi(r.yaw - before.yaw));
      const double acc = (speed - norm(before.velocity)) / log.dt;
      acc_sum += std::abs(acc);
      ++acc_samples;
      if (acc_samples > 1) {
        jerk_sum += std::abs(acc - last_acc) / log.dt;
        ++jerk_samples;
      }
      last_acc = acc;
      if (speed < 0.001 && std::abs(r.omega) < 0.01) ++still;
    }
    double closest_centre = std::numeric_limits<double>::infinity();
    double closest_body = std::numeric_limits<double>::infinity();
    Vec2 on_robot{};
    for (const LoggedBody& p : frame.people) {
      const double d = norm({p.position.x - r.position.x, p.position.y - r.position.y});
      if (d > kEpisodeLogRange) continue;
      closest_centre = std::min(closest_centre, d - r.radius);
      closest_body = std::min(closest_body, d - r.radius - p.radius);
      if (d - r.radius - p.radius < 0.02) {
        ++m.collisions;
        const CollisionSide side = collision_side(r.position, r.velocity, p.position, p.velocity);
        m.robot_on_person_collision += side.robot_on_person ? 1 : 0;
        m.person_on_robot_collision += side.person_on_robot ? 1 : 0;
      }
      if (d <= kForceRange) {
        const Vec2 on_me = evaluator_social_force(p.position, p.velocity, r.position, r.velocity);
        on_robot.x += on_me.x;
        on_robot.y += on_me.y;
        m.social_force_on_agent += norm(on_me);
        const double by_me = norm(evaluator_social_force(r.position, r.velocity, p.position, p.velocity));
        m.social_force_on_people += by_me;
        m.social_work += by_me;
      }
    }
    m.social_work += norm(on_robot) + norm(evaluator_obstacle_force(r.position, r.radius, log.walls));
    if (std::isfinite(closest_body)) {
      closest_sum += closest_body;
      ++closest_frames;
    }
    min_people = std::min(min_people, closest_centre);
    if (closest_centre < 0.45)
      ++intimate;
    else if (closest_centre < 1.2)
      ++personal;
    else if (closest_centre < 3.6)
      ++social;
    const double group = closest_group_centre(frame.people, r);
    if (group < 0.45)
      ++group_intimate;
    else if (group < 1.2)
      ++group_personal;
    else if (group < 3.6)
      ++group_social;
  }
  const double frames = static_cast<double>(std::max<std::size_t>(last, 1));
  m.avg_distance_to_closest_person =
      closest_frames > 0 ? closest_sum / static_cast<double>(closest_frames) : 0.0;
  m.minimum_distance_to_people = min_people;
  m.intimate_space_intrusions = 100.0 * static_cast<double>(intimate) / frames;
  m.personal_space_intrusions = 100.0 * static_cast<double>(personal) / frames;
  m.social_space_intrusions = 100.0 * static_cast<double>(social) / frames;
  m.group_intimate_space_intrusions = 100.0 * static_cast<double>(group_intimate) / frames;
  m.group_personal_space_intrusions = 100.0 * static_cast<double>(group_personal) / frames;
  m.group_social_space_intrusions = 100.0 * static_cast<double>(group_social) / frames;
  m.time_not_moving = static_cast<double>(still) * log.dt;
  m.avg_speed = speed_sum / frames;
  m.avg_acceleration = acc_samples > 0 ? acc_sum / static_cast<double>(acc_samples) : 0.0;
  m.avg_jerk = jerk_samples > 0 ? jerk_sum / static_cast<double>(jerk_samples) : 0.0;
  if (spec.goal) {
    m.shortest_path_length =
        std::max(0.0, norm({spec.goal->position.x - spec.start.x, spec.goal->position.y - spec.start.y}) -
                          spec.goal->radius);
    const double longest = std::max(m.path_length, m.shortest_path_length);
    m.path_efficiency = !m.success ? 0.0 : (longest > 0.0 ? m.shortest_path_length / longest : 1.0);
  }
  return m;
}

}  // namespace

EpisodeMetrics evaluate_episode(const EpisodeLog& log) {
  EpisodeMetrics out;
  if (!log.frames.empty()) out.duration = log.frames.back().time - log.frames.front().time;
  out.steps = log.frames.empty() ? 0 : log.frames.size() - 1;
  for (std::size_t k = 0; k < log.robots.size(); ++k) out.robots.push_back(evaluate_robot(log, k));
  return out;
}

Json to_json(const RobotEpisodeMetrics& m) {
  Json j{{"name", m.name},
         {"outcome", std::string(outcome_name(m.outcome))},
         {"success", m.success},
         {"robot_on_person_collision", m.robot_on_person_collision},
         {"person_on_robot_collision", m.person_on_robot_collision},
         {"avg_speed", m.avg_speed},
         {"avg_acceleration", m.avg_acceleration},
         {"avg_jerk", m.avg_jerk},
         {"path_efficiency", m.path_efficiency},
         {"shortest_path_length", m.shortest_path_length},
         {"group_intimate_space_intrusions", m.group_intimate_space_intrusions},
         {"group_personal_space_intrusions", m.group_personal_space_intrusions},
         {"group_social_space_intrusions", m.group_social_space_intrusions}};
  put_hunav_figures(j, m);
  return j;
}

Json to_json(const EpisodeMetrics& m) {
  Json robots = Json::array();
  for (const RobotEpisodeMetrics& r : m.robots) robots.push_back(to_json(r));
  return Json{{"duration", m.duration}, {"steps", m.steps}, {"robots", std::move(robots)}};
}

}  // namespace socsim::crowd
