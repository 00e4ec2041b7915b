#pragma once
// What each agent of a scenario program does, read off a built ScenarioRunner: where it starts
// and the stops it makes in order (its goals, and the places its behaviour tree names in literal
// ports: GoTo, queues, waits, seats, gatherings, wandering, exits, velocity-field goals). The
// exporters to simulators without socsim's node library (HuNavSim, pedsim_ros) are built on it.
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/crowd/program.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

struct RouteStop {
  enum class Kind : std::uint8_t {
    kWalk,    // walk to the place
    kQueue,   // join the queue `place` (a queue_lane ROI) and be served for `duration`
    kLinger,  // walk to the place and stay there for `duration` (wait, sit, gather, wander)
  };
  Kind kind = Kind::kWalk;
  std::string place;         // name of a place of the world; empty for a bare point
  crowd::Vec2 point;         // where to go (a queue's head)
  double radius = 0.3;       // m, arrival tolerance
  double duration = 0.0;     // s spent at the stop
  double probability = 1.0;  // chance of making the stop (a RandomChance guarding it)
};

struct AgentRoute {
  crowd::AgentId id{0};
  crowd::AgentKind kind = crowd::AgentKind::kSpotlight;
  std::string name;       // as the runner names it
  std::string pointer;    // program entry: /agents/k, /ambient_groups/g or /robot
  std::size_t entry = 0;  // index of that entry in its program list
  std::string role;
  crowd::Vec2 start;
  double yaw = 0.0;
  double radius = 0.3;
  double speed = 1.34;
  std::int64_t group_id = -1;
  bool cyclic = true;  // starts over after the last stop
  std::vector<RouteStop> stops;
};

// One route per runner agent, in id order. Call before the runner steps (initial states).
std::vector<AgentRoute> agent_routes(crowd::ScenarioRunner& runner, const crowd::Program& program);

// The routes of `program` in `world` with people placed as the runner spawns them with `seed`;
// fails as ScenarioRunner::create does when the program does not run in the world.
Result<std::vector<AgentRoute>> program_routes(const world::World& world, const crowd::Program& program,
                                               std::uint64_t seed);

}  // namespace socsim::interop
