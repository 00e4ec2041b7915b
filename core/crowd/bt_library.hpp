#pragma once
// What the behaviour-node groups share (bt_nodes_*.cpp): the library node base classes, target
// resolution, small vector helpers and the port-spec helpers of the registration tables. Internal
// to core/crowd; users include bt_nodes.hpp.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/crowd/bt_nodes.hpp"
#include "core/geometry/planar.hpp"

namespace socsim::crowd::nodes {

using S = BtStatus;
constexpr double kPi = std::numbers::pi;

inline double dist(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}
inline Vec2 unit(Vec2 v) {
  const double l = std::hypot(v.x, v.y);
  return l > 1e-12 ? Vec2{v.x / l, v.y / l} : Vec2{};
}
inline double wrap(double a) {
  while (a > kPi) a -= 2.0 * kPi;
  while (a <= -kPi) a += 2.0 * kPi;
  return a;
}

// --- base classes ------------------------------------------------------------------------------

class LibraryNode : public BtNode {
 public:
  LibraryNode(const BtNodeInit& init, BtEnvironment& env)
      : BtNode(init.spec, init.tree, init.blackboard), env_(env) {}

 protected:
  // The agent named by an id port; reports and returns nullopt when it does not exist.
  std::optional<AgentId> agent(std::string_view port = "agent_id") const {
    auto id = input<std::int64_t>(port);
    if (!id) return std::nullopt;
    if (!env_.valid(*id)) {
      (void)failure("port '" + std::string(port) + "': no agent with id " + std::to_string(*id));
      return std::nullopt;
    }
    return AgentId(static_cast<std::uint32_t>(*id));
  }
  template <class T>
  std::optional<T> get(std::string_view port) const {
    auto v = input<T>(port);
    if (!v) return std::nullopt;
    return *v;
  }
  [[nodiscard]] Vec2 pos(AgentId id) const { return env_.sim().position(id); }
  [[nodiscard]] double speed_of(AgentId id) const {
    const Vec2 v = env_.sim().velocity(id);
    return std::hypot(v.x, v.y);
  }
  // Unit heading vector of an agent (its reported heading).
  [[nodiscard]] Vec2 heading_vec(AgentId id) const {
    const double h = env_.heading(id);
    return {std::cos(h), std::sin(h)};
  }
  [[nodiscard]] std::optional<AgentId> robot() const {
    auto r = env_.robot();
    if (r && !env_.sim().active(*r)) return std::nullopt;
    return r;
  }

  BtEnvironment& env_;
};

// A target resolved from goal/goal_id ports (or the agent's current goal).
struct Target {
  Vec2 point;
  const geometry::Polygon* region = nullptr;
  std::string name;
};

class TargetNode : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  std::optional<Target> resolve(AgentId id, const std::string& name_port,
                                const std::string& index_port) const {
    const auto name = get<std::string>(name_port);
    const auto index = get<std::int64_t>(index_port);
    if (!name || !index) return std::nullopt;
    if (!name->empty()) {
      const auto p = env_.place(*name);
      if (!p) {
        (void)failure("port '" + name_port + "': no place named '" + *name + "'");
        return std::nullopt;
      }
      return Target{p->point, p->region, p->name};
    }
    if (*index >= 0) {
      const auto& goals = env_.goal_list(id).goals;
      if (static_cast<std::uint64_t>(*index) >= goals.size()) {
        (void)failure("port '" + index_port + "': goal " + std::to_string(*index) + " out of range (agent " +
                      std::to_string(id.value()) + " has " + std::to_string(goals.size()) + " goals)");
        return std::nullopt;
      }
      return Target{goals[static_cast<std::size_t>(*index)].position, nullptr,
                    "goal " + std::to_string(*index)};
    }
    if (auto g = env_.current_goal(id)) return Target{g->position, nullptr, "current goal"};
    (void)failure("no goal: set '" + name_port + "' or '" + index_port + "', or give the agent goals");
    return std::nullopt;
  }
  [[nodiscard]] bool arrived(const Target& t, Vec2 p, double tolerance) const {
    if (t.region != nullptr && geometry::contains(*t.region, {p.x, p.y})) return true;
    return dist(p, t.point) <= tolerance;
  }
};

// --- registration helpers ---------------------------------------------------------------------

constexpr BtPortType I = BtPortType::kInt;
constexpr BtPortType D = BtPortType::kDouble;
constexpr BtPortType B = BtPortType::kBool;
constexpr BtPortType T = BtPortType::kString;

inline BtPortSpec in(std::string name, BtPortType type, std::optional<std::string> def = std::nullopt) {
  return BtPortSpec{std::move(name), BtPortDirection::kIn, type, std::move(def)};
}
inline BtPortSpec out(std::string name, BtPortType type) {
  return BtPortSpec{std::move(name), BtPortDirection::kOut, type, std::nullopt};
}
inline BtPortSpec agent_port() {
  return in("agent_id", I, "{id}");
}
inline BtPortSpec step_port() {
  return in("time_step", D, "{dt}");
}

template <class Node, class... Args>
inline BtFactory bind(BtEnvironment& env, Args... args) {
  return [&env, args...](const BtNodeInit& init) -> std::unique_ptr<BtNode> {
    return std::make_unique<Node>(init, env, args...);
  };
}

// The node types of each group, with their ports, in the order the library lists them.
std::vector<BtNodeType> condition_nodes(BtEnvironment& env);
std::vector<BtNodeType> navigation_nodes(BtEnvironment& env);
std::vector<BtNodeType> queue_nodes(BtEnvironment& env);
std::vector<BtNodeType> place_nodes(BtEnvironment& env);

}  // namespace socsim::crowd::nodes
