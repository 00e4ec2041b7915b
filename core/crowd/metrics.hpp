#pragma once
// Social-navigation metrics over a run, with HuNavSim's names and definitions
// (hunav_evaluator): path length, distances to people, Hall's space intrusions, collisions,
// time not moving, speeds, accelerations, social forces and social work — for every agent
// (the others count as people) and for the optional robot agent.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/crowd/crowd_simulation.hpp"

namespace socsim::crowd {

// m: social forces beyond are below 1e-4 of the contact value (the metrics ignore them).
inline constexpr double kForceRange = 3.6;

struct AgentMetrics {
  std::uint32_t id = 0;
  std::string role;
  bool goal_reached = false;
  std::optional<double> time_to_reach_goal;     // s from the start; none when never reached
  double path_length = 0.0;                     // m
  double cumulative_heading_changes = 0.0;      // rad
  double avg_distance_to_closest_person = 0.0;  // m, body to body, frames with someone within 10 m
  double minimum_distance_to_people = 0.0;      // m, centre distance minus own radius
  double intimate_space_intrusions = 0.0;       // % of frames, closest person < 0.45 m
  double personal_space_intrusions = 0.0;       // % of frames, 0.45 .. 1.2 m
  double social_space_intrusions = 0.0;         // % of frames, 1.2 .. 3.6 m
  std::uint64_t collisions = 0;                 // frame × person pairs with bodies < 0.02 m apart
  double time_not_moving = 0.0;                 // s with speed < 0.001 m/s and |ω| < 0.01 rad/s
  double avg_linear_speed = 0.0;                // m/s
  double avg_angular_speed = 0.0;               // rad/s
  double avg_acceleration = 0.0;                // m/s², mean of dv/dt
  double avg_overacceleration = 0.0;            // m/s³, mean of (dv/dt)/dt (HuNavSim's jerk)
  double final_goal_distance = 0.0;             // m to the nearest goal at the end (0 without goals)
  double minimum_goal_distance = 0.0;           // m over the run
  double social_force_on_agent = 0.0;           // Σ frames Σ people |F_social(person → agent)|
  double social_force_on_people = 0.0;          // Σ frames Σ people |F_social(agent → person)|
  double social_work = 0.0;  // Σ frames |Σ F_social on agent| + |F_obstacle| + Σ |F(agent → person)|
  std::uint64_t frames = 0;
};

struct RunMetrics {
  double duration = 0.0;  // s
  std::uint64_t frames = 0;
  double frame_period = 0.0;             // s between recorded frames
  double avg_pedestrian_velocity = 0.0;  // m/s over every pedestrian and frame (robot excluded)
  std::vector<AgentMetrics> agents;      // pedestrians
  std::optional<AgentMetrics> robot;
  // Robot only (HuNavSim's SEAN 2.0 split of collisions): robot on person when the robot's speed
  // towards the person is the larger, person on robot when the person's is (both when equal).
  std::uint64_t robot_on_person_collisions = 0;
  std::uint64_t person_on_robot_collisions = 0;
};

// HuNavSim evaluator's force terms (LightSFM, default parameters), shared with the episode metrics:
// the social force that a body at pa moving with va exerts on one at pb moving with vb, and the
// obstacle force on a body of `radius` at p, averaged over the nearest points of walls within 2 m.
Vec2 evaluator_social_force(Vec2 pa, Vec2 va, Vec2 pb, Vec2 vb);
Vec2 evaluator_obstacle_force(Vec2 p, double radius, const std::vector<WallSegment>& walls);
// SEAN 2.0's split of a robot–person collision: robot on person when the robot's speed towards the
// person is the larger, person on robot when the person's is (both when equal).
struct CollisionSide {
  bool robot_on_person = false;
  bool person_on_robot = false;
};
CollisionSide collision_side(Vec2 robot, Vec2 robot_velocity, Vec2 person, Vec2 person_velocity);

// The HuNavSim figures that AgentMetrics and the robot episode metrics (episode_metrics.hpp) both
// carry under the same names, written into j.
template <class Figures>
void put_hunav_figures(Json& j, const Figures& m) {
  j["time_to_reach_goal"] = m.time_to_reach_goal ? Json(*m.time_to_reach_goal) : Json(nullptr);
  j["path_length"] = m.path_length;
  j["cumulative_heading_changes"] = m.cumulative_heading_changes;
  j["avg_distance_to_closest_person"] = m.avg_distance_to_closest_person;
  j["minimum_distance_to_people"] = m.minimum_distance_to_people;
  j["intimate_space_intrusions"] = m.intimate_space_intrusions;
  j["personal_space_intrusions"] = m.personal_space_intrusions;
  j["social_space_intrusions"] = m.social_space_intrusions;
  j["collisions"] = m.collisions;
  j["time_not_moving"] = m.time_not_moving;
  j["social_force_on_agent"] = m.social_force_on_agent;
  j["social_force_on_people"] = m.social_force_on_people;
  j["social_work"] = m.social_work;
}

Json to_json(const AgentMetrics& m);
Json to_json(const RunMetrics& m);

// Records frames of a simulation and computes the metrics. People within 10 m are considered
// for distances (farther people cannot be the closest in an intrusion band); social forces use
// LightSFM's default parameters as HuNavSim's evaluator does.
class MetricsRecorder {
 public:
  // goals[i]: the goals of agent i (the last one decides goal_reached); robot: its id if any.
  MetricsRecorder(std::vector<std::vector<Goal>> goals, std::optional<AgentId> robot);
  MetricsRecorder(MetricsRecorder&&) noexcept;
  MetricsRecorder& operator=(MetricsRecorder&&) noexcept;
  ~MetricsRecorder();
  // One frame; `states` holds every agent's state (index = id), inactive ones flagged by `active`.
  void observe(double time, const std::vector<PedestrianState>& states, const std::vector<double>& radii,
               const std::vector<std::uint8_t>& active, const std::vector<WallSegment>& walls);
  [[nodiscard]] RunMetrics finish() const;

 private:
  struct Track;
  std::vector<std::vector<Goal>> goals_;
  std::optional<AgentId> robot_;
  std::vector<Track> tracks_;
  std::uint64_t frames_ = 0;
  double first_time_ = 0.0;
  double last_time_ = 0.0;
  double pedestrian_speed_sum_ = 0.0;
  std::uint64_t pedestrian_samples_ = 0;
  std::uint64_t robot_on_person_ = 0;
  std::uint64_t person_on_robot_ = 0;
};

}  // namespace socsim::crowd
