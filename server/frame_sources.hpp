#pragma once
// What a live session plays (server/simulation_sessions.hpp): a scenario runner stepped live, or a
// card's recorded trajectory log played back, both giving frames of FrameAgent.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/crowd/program.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/world/world.hpp"
#include "server/frame_codec.hpp"

namespace socsim::server {

// Names of places agents head for, numbered as they first appear (0 = none).
struct TargetTable {
  std::unordered_map<std::string, std::uint16_t> index;
  std::vector<std::string> names{""};
  bool grew = false;
  std::uint16_t of(const std::string& name) {
    if (name.empty()) return 0;
    if (auto it = index.find(name); it != index.end()) return it->second;
    if (names.size() > std::numeric_limits<std::uint16_t>::max()) return 0;
    const auto i = static_cast<std::uint16_t>(names.size());
    names.push_back(name);
    index.emplace(name, i);
    grew = true;
    return i;
  }
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  [[nodiscard]] virtual double time() const = 0;
  [[nodiscard]] virtual double interval() const = 0;  // simulated seconds per advance
  [[nodiscard]] virtual double start_time() const = 0;
  [[nodiscard]] virtual double end_time() const = 0;
  [[nodiscard]] virtual std::vector<std::string> roles() const = 0;
  [[nodiscard]] virtual bool seekable() const { return false; }
  [[nodiscard]] virtual std::size_t agent_count() const = 0;
  virtual bool advance() = 0;  // false: nothing follows
  virtual void seek(double /*t*/) {}
  virtual void snapshot(std::vector<FrameAgent>& out, TargetTable& targets) = 0;
};

// A live run of `runner` for `duration` simulated seconds (the runner refers to `world`).
std::unique_ptr<FrameSource> runner_source(std::shared_ptr<const world::World> world,
                                           std::unique_ptr<crowd::ScenarioRunner> runner, double duration);
// A recorded log played back (seekable).
std::unique_ptr<FrameSource> recording_source(scenario::TrajectoryLog log);
// People a program starts with (spotlight counts, ambient group sizes, the robot).
std::size_t program_agent_count(const crowd::Program& p);

}  // namespace socsim::server
