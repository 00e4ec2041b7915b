#pragma once
// A scenario (world + program) for Isaac Sim's Replicator Agent (IRA): the world as a USD stage,
// an IRA 1.x configuration naming it (seed, duration, one character group per program entry with
// wander/idle routines whose speeds, walking distances and idle times come from the entry's routes)
// and the exact routes as omni.anim.people commands (GoTo / Idle per character, as IRA 0.x and the
// omni.anim.people extension read them). What each loses: docs/interop.md.
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/crowd/program.hpp"
#include "core/interop/export_hunav.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

struct IsaacExportOptions {
  std::uint64_t seed = 0;            // the IRA seed, and where people start (as the runner spawns them)
  double duration_s = 60.0;          // IRA simulation_duration
  std::string stage = "world.usda";  // the stage file name, as the configuration names it
  std::string ira_version = "1.6.0";
};

// world.usda, ira_config.yaml, people_commands.txt. Fails when the program does not run in the world.
Result<std::vector<ExportFile>> export_isaac(const world::World& world, const crowd::Program& program,
                                             const IsaacExportOptions& options = {});

}  // namespace socsim::interop
