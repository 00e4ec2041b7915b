#pragma once
// A trajectory log as CSV, one row per agent per frame: t,id,x,y,vx,vy,state,role,group_id (the
// columns `socsim simulate` writes). Numbers in the shortest text that reads back to the logged value.
#include <string>

#include "core/scenario/trajectory_log.hpp"

namespace socsim::interop {

std::string trajectories_csv(const scenario::TrajectoryLog& log);

}  // namespace socsim::interop
