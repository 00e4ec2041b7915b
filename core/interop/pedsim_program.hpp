#pragma once
// pedsim_ros scenario → socsim scenario program (schemas/program.schema.json): agent clusters
// spawn within ±dx, ±dy (clipped to the walls), walk their waypoint routes cyclically as pedsim
// agents do, queue on the queue_lane ROIs (JoinQueue + ServeAtCounter), linger at attractions
// (RandomChance + Wander); type 2 becomes the program's robot. Problems name the XML element and line.
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/crowd/program.hpp"
#include "core/world/pedsim_import.hpp"

namespace socsim::interop {

struct PedsimProgramOptions {
  std::string name;                // program name; default: the world's name
  double service_time = 8.0;       // s at the head of a queue (pedsim serves one agent at a time)
  double service_spread = 4.0;     // s, uniform ± around service_time
  double queue_spacing = 0.7;      // m between agents in line
  double min_spread = 0.5;         // m, half-extent of a cluster of n > 1 given dx or dy = 0
  double attraction_reach = 3.0;   // m; a route waypoint this close to an attraction passes it
  double attraction_time = 20.0;   // s an attracted agent wanders in the attraction
  double attraction_scale = 10.0;  // strength s attracts with probability min(0.9, s / scale)
};

// Where a program entry came from: its pointer in the program and the pedsim element.
struct PedsimSource {
  std::string program_pointer;  // "/agents/3", "/robot", "/behavior_trees/route_3"
  std::string pedsim_pointer;   // "/agents/5" (index among <agent>/<source> elements)
  int line = 0;
};

struct PedsimProgram {
  Json program;  // schemas/program.schema.json
  std::vector<PedsimSource> sources;
};

// Fails (kValidation, pedsim pointers and lines) for a second robot, a route step whose
// waypoint did not become an ROI, or a cluster with no walkable area around it.
Result<PedsimProgram> pedsim_to_program(const world::PedsimScenario& scenario,
                                        const PedsimProgramOptions& options = {});

// Rewrites field errors whose pointer lies inside a program entry of `program` to the pedsim
// element it came from (pointer and line), keeping the program pointer in the message.
Error locate_in_pedsim(Error error, const PedsimProgram& program);

struct ImportedPedsim {
  world::PedsimScenario scenario;
  PedsimProgram program;
  crowd::Program parsed;  // program_from_json(program.program)
};

// import_pedsim + pedsim_to_program + program_from_json, then a ScenarioRunner is built once
// (seed 0) so that every place, tree and spawn region is checked before anything runs.
Result<ImportedPedsim> import_pedsim_scenario(std::string_view xml,
                                              const world::PedsimImportOptions& import_options = {},
                                              const PedsimProgramOptions& options = {});

}  // namespace socsim::interop
