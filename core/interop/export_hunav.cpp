#include "core/interop/export_hunav.hpp"

#include <cctype>
#include <cmath>
#include <map>
#include <sstream>

#include "core/crowd/scenario_runner.hpp"
#include "core/interop/agent_routes.hpp"
#include "core/world/export_format.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::interop {

namespace {

using world::micro;

// A double-quoted YAML scalar.
std::string yaml_quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// Integer goal ids in order of first use; points closer than a millimetre share an id.
class GoalTable {
 public:
  int id(crowd::Vec2 p) {
    const auto key = std::make_pair(std::llround(p.x * 1000.0), std::llround(p.y * 1000.0));
    auto [it, inserted] = ids_.emplace(key, static_cast<int>(points_.size()) + 1);
    if (inserted) points_.push_back(p);
    return it->second;
  }
  [[nodiscard]] const std::vector<crowd::Vec2>& points() const { return points_; }

 private:
  std::map<std::pair<long long, long long>, int> ids_;
  std::vector<crowd::Vec2> points_;
};

struct HunavAgent {
  int id = 0;
  const AgentRoute* route = nullptr;
  std::vector<int> goals;  // one per stop (the start when there is none)
};

// HuNavSim's node models for the nodes the exported trees use (BT.CPP v4 TreeNodesModel).
constexpr const char* kNodeModels = R"(  <TreeNodesModel>
    <Action ID="GoTo">
      <input_port name="agent_id" type="int">identifier of the agent</input_port>
      <input_port name="time_step" type="double">time step in seconds</input_port>
      <input_port name="goal_id" type="int">global goal to walk to</input_port>
      <input_port name="tolerance" type="double" default="0.1">distance at which the goal counts as reached</input_port>
    </Action>
    <Action ID="StopAndWaitTimerAction">
      <input_port name="agent_id" type="int">identifier of the agent</input_port>
      <input_port name="wait_duration" type="double">seconds to stand still</input_port>
    </Action>
    <Condition ID="RandomChanceCondition">
      <input_port name="agent_id" type="int">identifier of the agent</input_port>
      <input_port name="probability" type="double" default="0.3">chance of success per tick</input_port>
    </Condition>
  </TreeNodesModel>
)";

std::string stop_nodes(const RouteStop& s, int goal, const std::string& indent) {
  std::string x = indent + "<GoTo agent_id=\"{id}\" time_step=\"{dt}\" goal_id=\"" + std::to_string(goal) +
                  "\" tolerance=\"" + micro(s.radius) + "\"/>\n";
  if (s.duration > 0.0)
    x += indent + "<StopAndWaitTimerAction agent_id=\"{id}\" wait_duration=\"" + micro(s.duration) + "\"/>\n";
  return x;
}

std::string kind_text(const RouteStop& s) {
  switch (s.kind) {
    case RouteStop::Kind::kQueue:
      return "queue";
    case RouteStop::Kind::kLinger:
      return "stay";
    case RouteStop::Kind::kWalk:
      break;
  }
  return "walk";
}

std::string agent_tree(const HunavAgent& a, const std::string& base) {
  const AgentRoute& r = *a.route;
  const std::string tree_id = "Agent" + std::to_string(a.id) + "Route";
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o << "<!-- exported by socsim for HuNavSim: " << world::xml_escape(base) << " agent " << a.id << " ("
    << world::xml_escape(r.name.empty() ? r.pointer : r.name) << ", role " << world::xml_escape(r.role)
    << ")\n";
  for (std::size_t k = 0; k < r.stops.size(); ++k) {
    const RouteStop& s = r.stops[k];
    o << "     stop " << k + 1 << ": " << kind_text(s) << " "
      << world::xml_escape(s.place.empty() ? "point" : s.place) << " = goal " << a.goals[k];
    if (s.duration > 0) o << ", " << micro(s.duration) << " s";
    if (s.probability < 1) o << ", chance " << micro(s.probability);
    o << "\n";
  }
  o << "-->\n";
  o << "<root BTCPP_format=\"4\" main_tree_to_execute=\"" << tree_id << "\">\n" << kNodeModels;
  o << "  <BehaviorTree ID=\"" << tree_id << "\">\n";
  std::string indent = "    ";
  if (!r.cyclic) {
    o << indent << "<RunOnce then_skip=\"true\">\n";
    indent += "  ";
  }
  o << indent << "<Sequence name=\"route\">\n";
  const std::string in = indent + "  ";
  if (r.stops.empty()) {
    o << in << "<GoTo agent_id=\"{id}\" time_step=\"{dt}\" goal_id=\"" << a.goals.front()
      << "\" tolerance=\"0.3\"/>\n";
    o << in << "<StopAndWaitTimerAction agent_id=\"{id}\" wait_duration=\"60\"/>\n";
  }
  for (std::size_t k = 0; k < r.stops.size(); ++k) {
    const RouteStop& s = r.stops[k];
    if (s.probability >= 1.0) {
      o << stop_nodes(s, a.goals[k], in);
      continue;
    }
    o << in << "<Fallback>\n" << in << "  <Sequence>\n";
    o << in << "    <RandomChanceCondition agent_id=\"{id}\" probability=\"" << micro(s.probability)
      << "\"/>\n";
    o << stop_nodes(s, a.goals[k], in + "    ");
    o << in << "  </Sequence>\n" << in << "  <AlwaysSuccess/>\n" << in << "</Fallback>\n";
  }
  o << indent << "</Sequence>\n";
  if (!r.cyclic) o << "    </RunOnce>\n";
  o << "  </BehaviorTree>\n</root>\n";
  return o.str();
}

}  // namespace

std::string file_stem(std::string_view name, std::string_view fallback) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  while (!out.empty() && out.front() == '_') out.erase(out.begin());
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty()) out = std::string(fallback);
  if (out.size() > 64) out.resize(64);
  return out;
}

Result<std::vector<ExportFile>> export_hunav(const world::World& world, const crowd::Program& program,
                                             const HunavOptions& options) {
  crowd::RunnerOptions ro;
  ro.seed = options.seed;
  ro.record_metrics = false;
  auto runner = crowd::ScenarioRunner::create(&world, program, ro);
  if (!runner) return tl::unexpected(runner.error());
  const std::vector<AgentRoute> routes = agent_routes(**runner, program);
  const crowd::RoleTable& roles = (*runner)->sim().roles();

  const std::string base =
      options.base_name.empty()
          ? file_stem(program.name.empty() ? world.name() : program.name, "socsim") + "_agents"
          : file_stem(options.base_name, "socsim_agents");
  GoalTable goals;
  std::vector<HunavAgent> agents;
  for (const AgentRoute& r : routes) {
    if (r.kind == crowd::AgentKind::kRobot) continue;
    HunavAgent a{static_cast<int>(agents.size()) + 1, &r, {}};
    for (const RouteStop& s : r.stops) a.goals.push_back(goals.id(s.point));
    if (a.goals.empty()) a.goals.push_back(goals.id(r.start));  // hunav_loader needs a goal
    agents.push_back(std::move(a));
  }

  std::ostringstream y;
  y << "# exported by socsim: world " << yaml_quoted(world.name()) << ", program "
    << yaml_quoted(program.name) << ", seed " << options.seed << "\n";
  y << "hunav_loader:\n  ros__parameters:\n";
  y << "    yaml_base_name: " << base << "\n";
  y << "    simulator: " << yaml_quoted(options.simulator) << "\n";
  y << "    map: " << yaml_quoted(options.map.empty() ? world.name() : options.map) << "\n";
  y << "    publish_people: true\n";
  y << "    global_goals:\n";
  for (std::size_t g = 0; g < goals.points().size(); ++g) {
    y << "      " << g + 1 << ":\n";
    y << "        x: " << micro(goals.points()[g].x) << "\n";
    y << "        y: " << micro(goals.points()[g].y) << "\n";
  }
  y << "    agents:\n";
  for (const HunavAgent& a : agents) y << "      - agent" << a.id << "\n";
  for (const HunavAgent& a : agents) {
    const AgentRoute& r = *a.route;
    double goal_radius = r.stops.empty() ? 0.3 : r.stops.front().radius;
    for (const RouteStop& s : r.stops) goal_radius = std::min(goal_radius, s.radius);
    const auto role = roles.index_of(r.role);
    const crowd::ForceParameters forces = role ? roles.at(*role).forces : crowd::ForceParameters{};
    y << "    agent" << a.id << ":\n";
    y << "      id: " << a.id << "\n";
    y << "      group_id: " << r.group_id << "\n";
    y << "      skin: 0\n";
    y << "      max_vel: " << micro(r.speed) << "\n";
    y << "      radius: " << micro(r.radius) << "\n";
    y << "      goal_radius: " << micro(goal_radius) << "\n";
    y << "      cyclic_goals: " << (r.cyclic ? "true" : "false") << "\n";
    y << "      init_pose:\n";
    y << "        x: " << micro(r.start.x) << "\n        y: " << micro(r.start.y) << "\n        z: 0.0\n";
    y << "        h: " << micro(r.yaw) << "\n";
    y << "      behavior:\n        type: Regular\n        configuration: 0\n";
    y << "        goal_force_factor: " << micro(forces.desired_factor) << "\n";
    y << "        obstacle_force_factor: " << micro(forces.obstacle_factor) << "\n";
    y << "        social_force_factor: " << micro(forces.social_factor) << "\n";
    y << "        other_force_factor: 20.0\n";
    y << "      goals:\n";
    for (int g : a.goals) y << "        - " << g << "\n";
  }

  std::vector<ExportFile> files;
  files.push_back({base + ".yaml", y.str()});
  for (const HunavAgent& a : agents)
    files.push_back(
        {"behavior_trees/" + base + "__agent_" + std::to_string(a.id) + "_bt.xml", agent_tree(a, base)});
  return files;
}

}  // namespace socsim::interop
