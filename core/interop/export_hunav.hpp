#pragma once
// A scenario (world + program) as HuNavSim input: the agents YAML of hunav_loader (newest layout:
// global_goals with integer ids, behavior.type "Regular", goals as id lists) and one
// BehaviorTree.CPP v4 tree per agent, named as hunav_agent_manager loads them
// (behavior_trees/<yaml_base_name>__agent_<id>_bt.xml). socsim nodes HuNavSim lacks (queues,
// seats, gatherings, wandering) become GoTo + StopAndWaitTimerAction with the same stops and times.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/crowd/program.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

// One file of an export, with its path relative to the export directory.
struct ExportFile {
  std::string path;
  std::string content;
};

struct HunavOptions {
  std::string base_name;             // yaml_base_name; default: the program's (else world's) name
  std::string map;                   // default: the world's name
  std::string simulator = "Gazebo";  // hunav_loader's `simulator`
  std::uint64_t seed = 0;            // initial positions: as the runner spawns them with this seed
};

// "<base>.yaml" first, then one tree per agent. The robot is not a HuNavSim agent and is left
// out; every other agent (spotlight and ambient) is. Fails when the program does not run in the world.
Result<std::vector<ExportFile>> export_hunav(const world::World& world, const crowd::Program& program,
                                             const HunavOptions& options = {});

// A name usable as a file name and YAML key: letters, digits and '_' (others become '_').
std::string file_stem(std::string_view name, std::string_view fallback);

}  // namespace socsim::interop
