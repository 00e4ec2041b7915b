#pragma once
// The scenario program (schemas/program.schema.json): spotlight agents with spawn, goals and a
// behaviour tree, groups, ambient velocity-field groups, per-role parameters and an optional
// robot. Parsing checks structure and types with JSON pointers; names of places and trees are
// checked against a world when a ScenarioRunner is built.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/crowd/wall_grid.hpp"

namespace socsim::crowd {

// A point given directly or by the name of a place of the world (ROI, POI, door, zone).
struct ProgramPoint {
  std::variant<Vec2, std::string> where;
  std::optional<double> radius;  // goal radius; default from the agent
  std::string pointer;           // JSON pointer, for errors found later
};

// A region: a place name or an explicit polygon.
struct ProgramRegion {
  std::variant<std::string, std::vector<Vec2>> where;
  std::string pointer;
};

// Behaviour tree source: inline XML, a file (relative to the program) or a named entry of
// behavior_trees; `tree` picks a BehaviorTree ID other than the main one.
struct ProgramTree {
  std::string xml;
  std::string file;
  std::string ref;
  std::string tree;
  std::string pointer;
};

struct ProgramAgent {
  std::string name;
  std::string role = "adult";
  std::optional<Vec2> position;
  std::optional<ProgramRegion> spawn;  // ROI to spawn in (random point) when no position
  std::size_t count = 1;               // agents made from this entry (spawned in `spawn`)
  std::optional<double> yaw;
  std::optional<double> speed;   // desired speed; default sampled from the role
  std::optional<double> radius;  // default from the role
  std::int64_t group_id = -1;
  std::vector<ProgramPoint> goals;
  bool cyclic_goals = true;
  double goal_radius = 0.3;
  // At the last goal (non-cyclic goals): true = leave the simulation there (activity "exited"),
  // false = stay. Unset: leave when the last goal is a place of type "exit", else stay.
  std::optional<bool> exit_at_goal;
  std::optional<ProgramTree> behavior;  // none: walk the goals (HuNavSim's regular navigation)
  std::vector<std::string> tags;
  std::string pointer;
};

// An external velocity field: values[i][j] = [vx, vy] for column i (x) and row j (y) over the
// world's bounding box (Algorithm 1's V ∈ R^{64×64×2}).
struct ProgramField {
  int width = 0;
  int height = 0;
  std::vector<Vec2> values;  // i * height + j
};

struct AmbientGroup {
  std::string name;
  std::string description;  // canonical description ("visitors walking to the exit"), paper 001 §III-G
  std::vector<ProgramRegion> start;
  std::vector<ProgramRegion> goal;
  std::size_t size = 0;
  double speed = 1.34;  // m/s, field magnitude and mean desired speed
  std::string role = "adult";
  int resolution = 64;                  // cells per axis of the generated field
  double variation = 0.0;               // rad, seeded heading variation of the generated field
  double tolerance = 0.5;               // Algorithm 1's tol
  bool exit_at_goal = true;             // agents leave the simulation in the goal region
  std::optional<ProgramField> field;    // supplied from outside (e.g. a diffusion model)
  std::optional<ProgramTree> behavior;  // default: FollowVelocityField
  std::string pointer;
};

struct ProgramRobot {
  Vec2 position;
  std::optional<double> yaw;
  double speed = 0.8;
  double radius = 0.35;
  std::vector<ProgramPoint> goals;
  bool cyclic_goals = false;
  double goal_radius = 0.3;
  std::string pointer = "/robot";
};

struct ProgramGroup {
  std::int64_t id = 0;
  std::vector<std::size_t> agents;  // indices into the expanded agent list
  std::string pointer;
};

struct Program {
  std::string name;
  double dt = 0.05;              // s, simulation step
  double decision_period = 0.1;  // s, between behaviour-tree ticks (a multiple of dt)
  Json roles = Json::object();   // RoleTable::apply_json overrides
  std::vector<std::pair<std::string, ProgramTree>> behavior_trees;
  std::vector<ProgramAgent> agents;
  std::vector<ProgramGroup> groups;
  std::vector<AmbientGroup> ambient_groups;
  std::optional<ProgramRobot> robot;
  Json body_stiffness;  // optional number overriding SimulationConfig::body_stiffness
};

// Strict parsing: unknown keys, wrong types and out-of-range numbers are kValidation errors
// with JSON pointers (all at once).
Result<Program> program_from_json(const Json& j);
// Parses text first (kBadRequest with line and column for syntax errors).
Result<Program> program_from_text(std::string_view text);

}  // namespace socsim::crowd
