#pragma once
// A card's trajectory in Gazebo: the world's SDF (world::export_sdf: ground, walls) plus one <actor>
// per logged person whose <script><trajectory> has a <waypoint> per logged frame, so people walk in
// Gazebo without any plugin (issue 20). What is lost: see docs/interop.md.
#include <string>

#include "core/scenario/trajectory_log.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

struct GazeboActorOptions {
  std::string world_name;         // default: the world's name
  std::size_t frame_stride = 1;   // every n-th logged frame becomes a waypoint (the last always does)
  std::string skin = "walk.dae";  // Gazebo's walking person mesh, also the animation
};

std::string export_gazebo_actors(const scenario::TrajectoryLog& log, const world::World& world,
                                 const GazeboActorOptions& options = {});

}  // namespace socsim::interop
