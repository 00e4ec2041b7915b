#include "core/interop/export_isaac.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "core/geometry/planar.hpp"
#include "core/interop/agent_routes.hpp"
#include "core/world/export_format.hpp"
#include "core/world/world_export.hpp"

namespace socsim::interop {
namespace {

// What one program entry's people do, summarised for a routine.
struct GroupSummary {
  std::string name;
  std::size_t num = 0;
  double speed_lo = 1e9, speed_hi = 0;
  double walk_lo = 1e9, walk_hi = 0;  // m between consecutive stops
  double idle_lo = 1e9, idle_hi = 0;  // s at stops
};

std::string yaml_number(double v) {
  return world::micro(std::round(v * 100.0) / 100.0);
}

// omni.anim.people names the characters it spawns Character, Character_01, Character_02, …
std::string character_name(std::size_t k) {
  if (k == 0) return "Character";
  return "Character_" + std::string(k < 10 ? "0" : "") + std::to_string(k);
}

}  // namespace

Result<std::vector<ExportFile>> export_isaac(const world::World& world, const crowd::Program& program,
                                             const IsaacExportOptions& options) {
  auto program_stops = program_routes(world, program, options.seed);
  if (!program_stops) return tl::unexpected(program_stops.error());
  const std::vector<AgentRoute>& routes = *program_stops;

  // Routes in the stage's frame: /World carries the world's origin pose, so stage coordinates are
  // the world's own; omni.anim.people commands are in the stage's world frame.
  const geometry::Pose2& origin = world.origin();
  auto stage_point = [&origin](crowd::Vec2 p) {
    return geometry::to_parent(origin, geometry::Point{p.x, p.y});
  };

  std::vector<GroupSummary> groups;
  std::map<std::string, std::size_t> group_of;  // program pointer → group
  std::ostringstream commands;
  commands << "# socsim: the people's routes as omni.anim.people commands (one character per person, in\n"
           << "# the order IRA spawns them); GoTo x y z yaw ('_' = any heading), Idle seconds.\n";
  std::size_t character = 0;
  for (const AgentRoute& r : routes) {
    if (r.kind == crowd::AgentKind::kRobot) continue;
    auto [it, fresh] = group_of.emplace(r.pointer, groups.size());
    if (fresh) {
      GroupSummary g;
      // The program entry's own name (agents[k].name, ambient_groups[g].name).
      std::string entry;
      if (r.kind == crowd::AgentKind::kAmbient && r.entry < program.ambient_groups.size())
        entry = program.ambient_groups[r.entry].name;
      else if (r.kind == crowd::AgentKind::kSpotlight && r.entry < program.agents.size())
        entry = program.agents[r.entry].name;
      g.name = file_stem(entry, "group_" + std::to_string(groups.size() + 1));
      groups.push_back(g);
    }
    GroupSummary& g = groups[it->second];
    ++g.num;
    g.speed_lo = std::min(g.speed_lo, r.speed);
    g.speed_hi = std::max(g.speed_hi, r.speed);
    const std::string who = character_name(character++);
    crowd::Vec2 at = r.start;
    for (const RouteStop& s : r.stops) {
      const double leg = std::hypot(s.point.x - at.x, s.point.y - at.y);
      if (leg > 0.05) g.walk_lo = std::min(g.walk_lo, leg), g.walk_hi = std::max(g.walk_hi, leg);
      const geometry::Point p = stage_point(s.point);
      commands << who << " GoTo " << yaml_number(p.x) << " " << yaml_number(p.y) << " 0 _\n";
      if (s.duration > 0) {
        g.idle_lo = std::min(g.idle_lo, s.duration);
        g.idle_hi = std::max(g.idle_hi, s.duration);
        commands << who << " Idle " << yaml_number(s.duration) << "\n";
      }
      at = s.point;
    }
    if (r.stops.empty()) commands << who << " Idle " << yaml_number(options.duration_s) << "\n";  // stands
  }

  std::ostringstream ira;
  ira << "# socsim: Isaac Sim Replicator Agent (IRA 1.x) configuration of the scenario '"
      << (program.name.empty() ? world.name() : program.name) << "'.\n"
      << "# The stage is " << options.stage
      << " beside this file: give base_stage_asset_path as an absolute\n"
      << "# path or URL where you put it (IRA resolves other relative paths against its asset root).\n"
      << "# Routines approximate the routes (walking speeds, distances and idle times of each group);\n"
      << "# the exact routes are in people_commands.txt (omni.anim.people GoTo/Idle commands).\n"
      << "isaacsim.replicator.agent:\n"
      << "  version: " << options.ira_version << "\n"
      << "  seed: " << options.seed << "\n"
      << "  simulation_duration: " << yaml_number(options.duration_s) << "\n"
      << "  environment:\n"
      << "    base_stage_asset_path: " << options.stage << "\n";
  if (!groups.empty()) {
    ira << "  character:\n    groups:\n";
    std::map<std::string, int> used;
    for (const GroupSummary& g : groups) {
      const int k = used[g.name]++;
      const double walk_lo = g.walk_hi > 0 ? g.walk_lo : 2.0, walk_hi = g.walk_hi > 0 ? g.walk_hi : 5.0;
      const double idle_lo = g.idle_hi > 0 ? g.idle_lo : 1.0, idle_hi = g.idle_hi > 0 ? g.idle_hi : 3.0;
      ira << "      " << g.name << (k ? "_" + std::to_string(k + 1) : "") << ":\n"
          << "        num: " << g.num << "\n"
          << "        asset_path: \"Isaac/People/Characters/\"\n"
          << "        routines:\n"
          << "          - wander:\n"
          << "              weight: 1.0\n"
          << "              repeat: 1\n"
          << "              walk:\n"
          << "                speed_range: [" << yaml_number(g.speed_lo) << ", " << yaml_number(g.speed_hi)
          << "]\n"
          << "                distance_range: [" << yaml_number(walk_lo) << ", " << yaml_number(walk_hi)
          << "]\n"
          << "                navigation_areas: []\n"
          << "              idle:\n"
          << "                - animation: idle\n"
          << "                  weight: 1.0\n"
          << "                  time_range: [" << yaml_number(idle_lo) << ", " << yaml_number(idle_hi)
          << "]\n";
    }
  }
  return std::vector<ExportFile>{{options.stage, world::export_usda(world)},
                                 {"ira_config.yaml", ira.str()},
                                 {"people_commands.txt", commands.str()}};
}

}  // namespace socsim::interop
