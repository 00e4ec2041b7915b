#pragma once
// Runs a scenario program in a world: builds the CrowdSimulation (walls, agents, ambient groups
// with their velocity fields, robot), loads every behaviour tree before the first step, ticks the
// trees at the decision rate, steps at dt and hands PedestrianState frames to a callback.
// Same world, program, seed and thread count → bit-identical frames. No I/O threads.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/crowd/bt_document.hpp"
#include "core/crowd/bt_environment.hpp"
#include "core/crowd/metrics.hpp"
#include "core/crowd/program.hpp"
#include "core/crowd/robot.hpp"

namespace socsim::crowd {

struct RunnerOptions {
  std::uint64_t seed = 0;
  unsigned threads = 1;
  std::filesystem::path base_dir;  // where behaviour-tree files of the program are found
  bool record_metrics = true;      // metrics frames at every decision step
  EnvironmentOptions environment;
  // Robots driven from outside (co-simulation): added after every person as driven agents of role
  // "robot", in this order; the program's own (scripted) robot is then left out. The behaviour
  // nodes that look at or avoid "the robot" see the first visible one.
  std::vector<RobotSpec> robots;
};

enum class AgentKind : std::uint8_t { kSpotlight, kAmbient, kRobot };

struct RunnerAgent {
  AgentId id;
  AgentKind kind = AgentKind::kSpotlight;
  std::string name;     // program name ("" when none), "<group>#k" for ambient agents, "robot"
  std::string pointer;  // program entry it comes from
};

using FrameCallback = std::function<void(double time, std::span<const PedestrianState> states)>;

class ScenarioRunner {
 public:
  // The world may be null for programs that give positions and polygons only; it must outlive
  // the runner. Errors carry JSON pointers into the program (and XML lines for trees).
  static Result<std::unique_ptr<ScenarioRunner>> create(const world::World* world, const Program& program,
                                                        const RunnerOptions& options);
  ScenarioRunner(const ScenarioRunner&) = delete;
  ScenarioRunner& operator=(const ScenarioRunner&) = delete;
  ~ScenarioRunner();

  // One simulation step (behaviour trees are ticked first when a decision step is due).
  void step();
  // Steps until `seconds` have passed; calls `frame` with the initial state and then after every
  // `frame_every` steps.
  void run(double seconds, const FrameCallback& frame = {}, unsigned frame_every = 1);

  [[nodiscard]] double time() const { return sim_->time(); }
  [[nodiscard]] CrowdSimulation& sim() { return *sim_; }
  [[nodiscard]] BtEnvironment& environment() { return *env_; }
  [[nodiscard]] const std::vector<RunnerAgent>& agents() const { return agents_; }
  // The agents of RunnerOptions::robots, in their order.
  [[nodiscard]] const std::vector<AgentId>& driven_robots() const { return driven_robots_; }
  [[nodiscard]] std::vector<PedestrianState> states() const;
  // The tree of an agent (nullptr for the robot).
  [[nodiscard]] BtTree* tree(AgentId id);
  // Run-time problems the trees reported (first few per agent).
  [[nodiscard]] std::vector<std::string> errors() const;
  [[nodiscard]] RunMetrics metrics() const;
  [[nodiscard]] double decision_period() const {
    return static_cast<double>(decision_every_) * sim_->config().dt;
  }

 private:
  ScenarioRunner() = default;
  void decide();

  const world::World* world_ = nullptr;
  std::unique_ptr<CrowdSimulation> sim_;
  std::unique_ptr<BtEnvironment> env_;
  std::unique_ptr<BtRegistry> registry_;
  std::vector<BtDocument> documents_;
  std::vector<RunnerAgent> agents_;
  std::vector<std::optional<BtTree>> trees_;
  // When each agent leaves the simulation (activity "exited").
  enum class Leaving : std::uint8_t {
    kNever,
    kWhenTreeSucceeds,  // ambient groups with on_arrival "exit": at the goal region
    kAtLastGoal,        // spotlight agents: the tree succeeds with the goal list done
  };
  std::vector<Leaving> leaving_;
  std::vector<AgentId> driven_robots_;
  std::vector<Goal> robot_goals_;
  std::size_t robot_goal_ = 0;
  bool robot_cyclic_ = false;
  std::uint64_t steps_ = 0;
  std::uint64_t decision_every_ = 1;
  std::unique_ptr<MetricsRecorder> metrics_;
};

}  // namespace socsim::crowd
