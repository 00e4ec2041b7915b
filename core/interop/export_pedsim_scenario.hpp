#pragma once
// A scenario (world + program) as a pedsim_ros scenario XML: the world's part as
// world::export_pedsim writes it (obstacles, queues), waypoints (circles fitted back to the
// waypoint ROIs), attractions (area, seating and waiting ROIs), and one <agent> per program entry
// with its scatter box, type (0 adult, 1 child, 2 robot, 3 elder) and route of <addwaypoint>/<addqueue>.
// Only elements pedsim_ros knows; import_pedsim reads it back.
#include <cstdint>
#include <string>

#include "core/common/error.hpp"
#include "core/crowd/program.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

struct PedsimExportOptions {
  std::uint64_t seed = 0;  // for routes that depend on where agents start (nearest exit)
  // An attraction's strength is the largest chance with which routes linger in it times this
  // scale (PedsimProgramOptions::attraction_scale, so pedsim → program → pedsim keeps it);
  // areas nobody lingers in get 0, seating and waiting areas 1.
  double attraction_scale = 10.0;
};

// Fails when the program does not run in the world (errors as ScenarioRunner::create's).
Result<std::string> export_pedsim_scenario(const world::World& world, const crowd::Program& program,
                                           const PedsimExportOptions& options = {});

}  // namespace socsim::interop
