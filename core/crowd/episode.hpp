#pragma once
// A robot episode in a scenario (co-simulation, issue 19): robots driven from outside — by their
// state or by velocity commands through the unicycle model — step with the crowd; each robot ends
// in success, collision (person or wall), timeout or stuck. Every step is logged (the robots and
// the people within 10 m of one) and the metrics come from that log (episode_metrics.hpp).
// No I/O; same world, program, seed and inputs → the same log, bit for bit.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/crowd/robot.hpp"
#include "core/crowd/scenario_runner.hpp"

namespace socsim::crowd {

enum class Outcome : std::uint8_t { kRunning, kSuccess, kCollisionPerson, kCollisionWall, kTimeout, kStuck };
std::string_view outcome_name(Outcome o);  // "running", "success", "collision_person", …

struct EpisodeOptions {
  double time_limit = 60.0;     // s; robots still running then time out
  double success_radius = 0.5;  // m, for goals that do not give their own radius
  double stuck_time = 10.0;     // s: a robot that has not moved stuck_distance for this long is stuck
  double stuck_distance = 0.1;  // m
  std::size_t max_robots = 8;
};
Status validate(const EpisodeOptions& options);

// What a client gives for one robot in one step: its new state, or a command to integrate.
struct RobotInput {
  enum class Kind : std::uint8_t { kState, kCommand };
  Kind kind = Kind::kCommand;
  VelocityCommand command;  // kCommand
  Pose2 pose;               // kState
  Twist2 twist;             // kState
};

// A body in a logged frame.
struct LoggedBody {
  std::uint32_t id = 0;  // agent id
  Vec2 position;
  Vec2 velocity;
  double yaw = 0.0;
  double omega = 0.0;
  double radius = 0.0;
  std::int64_t group = -1;  // the person's group_id (-1 alone; robots -1)
  friend bool operator==(const LoggedBody&, const LoggedBody&) = default;
};

struct EpisodeFrame {
  double time = 0.0;
  std::vector<LoggedBody> robots;  // in RobotSpec order
  std::vector<LoggedBody> people;  // active people within kEpisodeLogRange of a robot, by id
  friend bool operator==(const EpisodeFrame&, const EpisodeFrame&) = default;
};

inline constexpr double kEpisodeLogRange = 10.0;  // m, HuNavSim's search range for the closest person

struct RobotResult {
  Outcome outcome = Outcome::kRunning;
  std::optional<double> end_time;    // s, when the outcome was decided
  std::optional<std::uint32_t> hit;  // the person's agent id for a person collision
};

struct EpisodeLog {
  double dt = 0.05;
  std::vector<RobotSpec> robots;  // with the goals in force (radius = success radius)
  std::vector<WallSegment> walls;
  std::vector<EpisodeFrame> frames;  // frame 0: the start, then one per step
  std::vector<RobotResult> results;
};

class Episode {
 public:
  // The robots are options.robots, or else the program's robot (its start and its last goal).
  // kValidation with pointers (/robots/k/…) for bad robots, no robot or too many.
  static Result<std::unique_ptr<Episode>> create(const world::World* world, const Program& program,
                                                 RunnerOptions options, const EpisodeOptions& episode);
  Episode(const Episode&) = delete;
  Episode& operator=(const Episode&) = delete;
  ~Episode();

  // One step: inputs[k] for robot k (one per robot). Robots that have ended hold still and their
  // inputs are ignored. kValidation (pointer /robots/k/…) for a wrong count or a bad value — the
  // step is then not taken; kConflict once the episode has ended.
  Status step(std::span<const RobotInput> inputs);

  [[nodiscard]] bool ended() const;
  [[nodiscard]] std::uint64_t steps() const { return steps_; }
  [[nodiscard]] double time() const { return runner_->time(); }
  [[nodiscard]] const EpisodeLog& log() const { return log_; }
  [[nodiscard]] const std::vector<RobotSpec>& robots() const { return log_.robots; }
  [[nodiscard]] const std::vector<RobotResult>& results() const { return log_.results; }
  // The people now (robots left out), as socsim_people_msgs states.
  [[nodiscard]] std::vector<PedestrianState> people() const;
  // A robot's current state.
  [[nodiscard]] UnicycleState robot_state(std::size_t k) const { return robot_states_.at(k); }
  [[nodiscard]] ScenarioRunner& runner() { return *runner_; }
  [[nodiscard]] const EpisodeOptions& options() const { return options_; }

 private:
  Episode() = default;
  void record();
  void judge();

  std::unique_ptr<ScenarioRunner> runner_;
  EpisodeOptions options_;
  EpisodeLog log_;
  std::vector<UnicycleState> robot_states_;
  std::vector<Vec2> anchor_;  // where each robot was when it last moved stuck_distance
  std::vector<double> anchor_time_;
  std::uint64_t steps_ = 0;
};

}  // namespace socsim::crowd
