#pragma once
// Social-navigation metrics of a robot episode, computed from its log (docs/metrics.md): HuNavSim's
// evaluator set, SocNavBench's motion figures and SPL-style path efficiency. Pure functions.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/crowd/episode.hpp"

namespace socsim::crowd {

struct RobotEpisodeMetrics {
  std::string name;
  Outcome outcome = Outcome::kRunning;
  bool success = false;
  std::optional<double> time_to_reach_goal;     // s
  double path_length = 0.0;                     // m
  double cumulative_heading_changes = 0.0;      // rad
  double avg_distance_to_closest_person = 0.0;  // m, body to body, frames with someone within 10 m
  double minimum_distance_to_people = 0.0;      // m, centre distance − robot radius (10 m when nobody)
  double intimate_space_intrusions = 0.0;       // % of frames, closest person < 0.45 m
  double personal_space_intrusions = 0.0;       // % of frames, 0.45 .. 1.2 m
  double social_space_intrusions = 0.0;         // % of frames, 1.2 .. 3.6 m
  // The same classes for the closest group's interaction centre (HuNavSim: the mean of its members'
  // points 1.5 m ahead of them); 0 when no group is within range.
  double group_intimate_space_intrusions = 0.0;
  double group_personal_space_intrusions = 0.0;
  double group_social_space_intrusions = 0.0;
  std::uint64_t collisions = 0;  // frame × person pairs, bodies < 0.02 m apart
  std::uint64_t robot_on_person_collision = 0;
  std::uint64_t person_on_robot_collision = 0;
  double time_not_moving = 0.0;         // s, speed < 0.001 m/s and |ω| < 0.01 rad/s
  double social_force_on_agent = 0.0;   // Σ frames Σ people |F(person → robot)|
  double social_force_on_people = 0.0;  // Σ frames Σ people |F(robot → person)|
  double social_work = 0.0;             // Σ frames |Σ F on robot| + |F_obstacle| + Σ |F(robot → person)|
  double avg_speed = 0.0;               // m/s (SocNavBench)
  double avg_acceleration = 0.0;        // m/s², mean |Δv|/dt of the speed
  double avg_jerk = 0.0;                // m/s³, mean |Δa|/dt
  double path_efficiency = 0.0;         // SPL: success · l / max(path_length, l)
  double shortest_path_length = 0.0;    // m, l: straight start → goal less the goal radius
};

struct EpisodeMetrics {
  double duration = 0.0;  // s
  std::uint64_t steps = 0;
  std::vector<RobotEpisodeMetrics> robots;
};

EpisodeMetrics evaluate_episode(const EpisodeLog& log);
Json to_json(const RobotEpisodeMetrics& m);
Json to_json(const EpisodeMetrics& m);

}  // namespace socsim::crowd
