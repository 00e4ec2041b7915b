#pragma once
// A scenario (world + program) as an Arena-Rosnav scenario file (arena_bringup/configs/scenarios/
// *.json, task mode "scenario"): the people as dynamic obstacles (pedsim agents with a start pose,
// a type, a model and waypoints followed in order), the world's entities as static obstacles, the
// robot's start and goal, the map name and the number of resets. Poses are in the frame of the
// exported maps (the world's origin applied), as the ROS map export. What it loses: docs/interop.md.
#include <cstdint>
#include <string>

#include "core/common/error.hpp"
#include "core/crowd/program.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

struct ArenaExportOptions {
  std::uint64_t seed = 0;  // where people start: as the runner spawns them with this seed
  std::string map;         // default: the world's name
  int resets = 10;         // episodes Arena runs from this scenario
  std::string model = "actor1";
};

// Fails when the program does not run in the world (errors as ScenarioRunner::create's).
Result<std::string> export_arena_scenario(const world::World& world, const crowd::Program& program,
                                          const ArenaExportOptions& options = {});

}  // namespace socsim::interop
