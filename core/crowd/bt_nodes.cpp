#include "core/crowd/bt_nodes.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

#include "core/geometry/planar.hpp"

namespace socsim::crowd {

namespace {

using S = BtStatus;
constexpr double kPi = std::numbers::pi;

double dist(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}
Vec2 unit(Vec2 v) {
  const double l = std::hypot(v.x, v.y);
  return l > 1e-12 ? Vec2{v.x / l, v.y / l} : Vec2{};
}
double wrap(double a) {
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

// --- conditions --------------------------------------------------------------------------------

class IsGoalReached final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    if (!id) return S::kFailure;
    const auto g = env_.current_goal(*id);
    if (!g) return S::kFailure;
    return dist(pos(*id), g->position) <= g->radius ? S::kSuccess : S::kFailure;
  }
};

class IsRobotVisible final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto d = get<double>("distance");
    const auto r = robot();
    if (!id || !d || !r) return S::kFailure;
    const Vec2 a = pos(*id);
    const Vec2 b = pos(*r);
    return dist(a, b) <= *d && env_.line_of_sight(a, b) ? S::kSuccess : S::kFailure;
  }
};

class IsRobotClose final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto t = get<double>("threshold");
    const auto r = robot();
    if (!id || !t || !r) return S::kFailure;
    return dist(pos(*id), pos(*r)) < *t ? S::kSuccess : S::kFailure;
  }
};

// The robot faces the agent when its heading is within 0.5 rad of the direction to the agent.
class IsRobotFacingAgent final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto r = robot();
    if (!id || !r) return S::kFailure;
    const Vec2 to = {pos(*id).x - pos(*r).x, pos(*id).y - pos(*r).y};
    if (std::hypot(to.x, to.y) < 1e-9) return S::kFailure;
    return std::abs(wrap(std::atan2(to.y, to.x) - env_.heading(*r))) <= 0.5 ? S::kSuccess : S::kFailure;
  }
};

class IsAgentVisible final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto obs = agent("observer_id");
    const auto other = agent("agent_id");
    const auto d = get<double>("distance");
    const auto fov = get<double>("field_of_view");
    if (!obs || !other || !d || !fov || !env_.sim().active(*other)) return S::kFailure;
    const Vec2 a = pos(*obs);
    const Vec2 b = pos(*other);
    if (dist(a, b) > *d || !env_.line_of_sight(a, b)) return S::kFailure;
    const double bearing = std::atan2(b.y - a.y, b.x - a.x);
    return std::abs(wrap(bearing - env_.heading(*obs))) <= *fov / 2.0 ? S::kSuccess : S::kFailure;
  }
};

class IsAgentClose final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto obs = agent("observer_id");
    const auto other = agent("target_agent_id");
    const auto t = get<double>("threshold");
    if (!obs || !other || !t || !env_.sim().active(*other)) return S::kFailure;
    return dist(pos(*obs), pos(*other)) < *t ? S::kSuccess : S::kFailure;
  }
};

class IsAtPosition final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto x = get<double>("target_x");
    const auto y = get<double>("target_y");
    const auto tol = get<double>("tolerance");
    if (!id || !x || !y || !tol) return S::kFailure;
    return dist(pos(*id), {*x, *y}) <= *tol ? S::kSuccess : S::kFailure;
  }
};

class RandomChance final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto p = get<double>("probability");
    if (!id || !p) return S::kFailure;
    return env_.rng(*id).chance(*p) ? S::kSuccess : S::kFailure;
  }
};

class TimeExpired final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto seconds = get<double>("seconds");
    const auto ts = get<double>("ts");
    const auto once = get<bool>("only_once");
    if (!seconds || !ts || !once) return S::kFailure;
    if (expired_ && *once) return S::kSuccess;
    elapsed_ += *ts;
    if (elapsed_ < *seconds) return S::kFailure;
    expired_ = true;
    if (!*once) elapsed_ = 0.0;
    return S::kSuccess;
  }

 private:
  double elapsed_ = 0.0;
  bool expired_ = false;
};

// Speech: an agent counts as speaking for `duration` seconds after SaySomething.
class IsAnyoneSpeaking final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto d = get<double>("distance_threshold");
    const auto window = get<double>("duration");
    if (!id || !d || !window) return S::kFailure;
    const Vec2 p = pos(*id);
    for (std::size_t k = 0; k < env_.sim().size(); ++k) {
      const AgentId other(static_cast<std::uint32_t>(k));
      if (other == *id || !env_.sim().active(other)) continue;
      const auto spoke = env_.last_spoke(other);
      if (!spoke || env_.now() - *spoke > *window || dist(p, pos(other)) > *d) continue;
      (void)output("speaker_id", BtValue{static_cast<std::int64_t>(k)});
      return S::kSuccess;
    }
    return S::kFailure;
  }
};

class IsSpeaking final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto target = agent("target_id");
    const auto d = get<double>("distance_threshold");
    const auto window = get<double>("duration");
    if (!id || !target || !d || !window) return S::kFailure;
    const auto spoke = env_.last_spoke(*target);
    return spoke && env_.now() - *spoke <= *window && dist(pos(*id), pos(*target)) <= *d ? S::kSuccess
                                                                                         : S::kFailure;
  }
};

// Gaze: `observer` looks at `id` when the bearing from observer to id is within the angle of
// its heading. The conditions remember the last time a look was seen for `duration` seconds.
bool looks_at(const BtEnvironment& env, AgentId observer, AgentId id, double max_dist, double angle) {
  const Vec2 a = env.sim().position(observer);
  const Vec2 b = env.sim().position(id);
  const double d = dist(a, b);
  if (d > max_dist || d < 1e-9) return false;
  return std::abs(wrap(std::atan2(b.y - a.y, b.x - a.x) - env.heading(observer))) <= angle;
}

class IsAnyoneLookingAtMe final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto d = get<double>("distance_threshold");
    const auto angle = get<double>("angle_threshold");
    const auto window = get<double>("duration");
    if (!id || !d || !angle || !window) return S::kFailure;
    for (std::size_t k = 0; k < env_.sim().size(); ++k) {
      const AgentId other(static_cast<std::uint32_t>(k));
      if (other == *id || !env_.sim().active(other)) continue;
      if (!looks_at(env_, other, *id, *d, *angle)) continue;
      seen_ = now();
      observer_ = static_cast<std::int64_t>(k);
      break;
    }
    if (seen_ && now() - *seen_ <= *window) {
      (void)output("observer_id", BtValue{observer_});
      return S::kSuccess;
    }
    return S::kFailure;
  }

 private:
  std::optional<double> seen_;
  std::int64_t observer_ = -1;
};

class IsLookingAtMe final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto target = agent("target_id");
    const auto d = get<double>("distance_threshold");
    const auto angle = get<double>("angle_threshold");
    const auto window = get<double>("duration");
    if (!id || !target || !d || !angle || !window) return S::kFailure;
    if (env_.sim().active(*target) && looks_at(env_, *target, *id, *d, *angle)) seen_ = now();
    return seen_ && now() - *seen_ <= *window ? S::kSuccess : S::kFailure;
  }

 private:
  std::optional<double> seen_;
};

class IsAtQueueHead final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto name = get<std::string>("queue");
    if (!id || !name) return S::kFailure;
    BtEnvironment::Queue* q = env_.queue(*name);
    if (q == nullptr) return failure("no queue_lane ROI named '" + *name + "'");
    const auto i = env_.queue_index(*q, *id);
    return i && *i == 0 ? S::kSuccess : S::kFailure;
  }
};

class IsInRegion final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto name = get<std::string>("region");
    if (!id || !name) return S::kFailure;
    const auto p = env_.place(*name);
    if (!p || p->region == nullptr) return failure("no ROI or zone named '" + *name + "'");
    return env_.inside(*p, pos(*id)) ? S::kSuccess : S::kFailure;
  }
};

// --- navigation and goals ----------------------------------------------------------------------

// One step of walking towards the current goal: RUNNING while walking, SUCCESS once the goal is
// reached (HuNavSim's RegularNav walks one step per tick; a Sequence re-checks its conditions).
class RegularNav final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    if (!id) return S::kFailure;
    const auto g = env_.current_goal(*id);
    if (!g) {
      env_.hold(*id, Activity::kStanding);
      return S::kRunning;
    }
    if (dist(pos(*id), g->position) <= g->radius) return S::kSuccess;
    env_.move_to(*id, g->position, g->radius, env_.base_speed(*id), Activity::kWalking);
    return S::kRunning;
  }
};

class UpdateGoal final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    if (!id) return S::kFailure;
    env_.advance_goal(*id);
    return S::kSuccess;
  }
};

class SetGoal final : public TargetNode {
 public:
  using TargetNode::TargetNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto name = get<std::string>("goal");
    const auto index = get<std::int64_t>("goal_id");
    if (!id || !name || !index) return S::kFailure;
    auto& list = env_.goal_list(*id);
    if (!name->empty()) {
      const auto p = env_.place(*name);
      if (!p) return failure("no place named '" + *name + "'");
      list.named = Goal{p->point, 0.3};
      return S::kSuccess;
    }
    if (*index < 0 || static_cast<std::uint64_t>(*index) >= list.goals.size())
      return failure("goal_id " + std::to_string(*index) + " out of range (agent " +
                     std::to_string(id->value()) + " has " + std::to_string(list.goals.size()) + " goals)");
    list.named.reset();
    list.index = static_cast<std::size_t>(*index);
    return S::kSuccess;
  }
};

class GoTo final : public TargetNode {
 public:
  using TargetNode::TargetNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto tol = get<double>("tolerance");
    if (!id || !tol) return S::kFailure;
    if (status() != S::kRunning) {
      target_ = resolve(*id, "goal", "goal_id");
      if (!target_) return S::kFailure;
    }
    if (arrived(*target_, pos(*id), *tol)) {
      env_.hold(*id, Activity::kStanding);
      return S::kSuccess;
    }
    env_.move_to(*id, target_->point, std::max(*tol, 0.05), env_.base_speed(*id), Activity::kWalking);
    return S::kRunning;
  }

 private:
  std::optional<Target> target_;
};

class StopAndWait final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto wait = get<double>("wait_duration");
    if (!id || !wait) return S::kFailure;
    if (status() != S::kRunning) start_ = now();
    if (now() - start_ >= *wait) return S::kSuccess;
    env_.hold(*id, Activity::kStanding);
    return S::kRunning;
  }

 private:
  double start_ = 0.0;
};

class StopMovement final : public LibraryNode {
 public:
  StopMovement(const BtNodeInit& init, BtEnvironment& env, bool stop) : LibraryNode(init, env), stop_(stop) {}

 protected:
  S on_tick() override {
    const auto id = agent();
    if (!id) return S::kFailure;
    env_.set_stopped(*id, stop_);
    if (stop_) env_.hold(*id, Activity::kStanding);
    return S::kSuccess;
  }

 private:
  bool stop_;
};

// Common frame of HuNavSim's robot reactions: RUNNING for beh_duration seconds, then SUCCESS;
// with only_once the reaction is shown once and later ticks fail (the tree falls back).
class RobotReaction : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() final {
    const auto id = agent();
    const auto duration = get<double>("beh_duration");
    const auto once = get<bool>("only_once");
    const auto r = robot();
    if (!id || !duration || !once || !r) return S::kFailure;
    if (status() != S::kRunning) {
      if (*once && shown_) return S::kFailure;
      start_ = now();
    }
    if (now() - start_ >= *duration) {
      shown_ = true;
      env_.face(*id, std::nullopt);
      return S::kSuccess;
    }
    if (!react(*id, *r)) return S::kFailure;
    return S::kRunning;
  }
  virtual bool react(AgentId id, AgentId robot) = 0;

 private:
  double start_ = 0.0;
  bool shown_ = false;
};

class SurprisedNav final : public RobotReaction {
 public:
  using RobotReaction::RobotReaction;

 protected:
  bool react(AgentId id, AgentId r) override {
    env_.hold(id, Activity::kStanding);
    env_.face(id, pos(r));
    return true;
  }
};

class CuriousNav final : public RobotReaction {
 public:
  using RobotReaction::RobotReaction;

 protected:
  bool react(AgentId id, AgentId r) override {
    const auto vel = get<double>("agent_vel");
    const auto stop = get<double>("stop_distance");
    if (!vel || !stop) return false;
    env_.face(id, pos(r));
    if (dist(pos(id), pos(r)) <= *stop + env_.sim().radius(r)) {
      env_.hold(id, Activity::kStanding);
    } else {
      env_.move_to(id, pos(r), *stop + env_.sim().radius(r), *vel, Activity::kWalking, Routing::kDirect);
    }
    return true;
  }
};

// Runs away: the desired direction is the unit sum of the direction to the current goal and
// 2·scary_force_factor times the direction away from the robot, at runaway_vel.
class ScaredNav final : public RobotReaction {
 public:
  using RobotReaction::RobotReaction;

 protected:
  bool react(AgentId id, AgentId r) override {
    const auto vel = get<double>("runaway_vel");
    const auto factor = get<double>("scary_force_factor");
    if (!vel || !factor) return false;
    const Vec2 p = pos(id);
    Vec2 away = unit({p.x - pos(r).x, p.y - pos(r).y});
    Vec2 to_goal{};
    if (auto g = env_.current_goal(id)) to_goal = unit({g->position.x - p.x, g->position.y - p.y});
    Vec2 dir = unit({to_goal.x + 2.0 * *factor * away.x, to_goal.y + 2.0 * *factor * away.y});
    if (dir == Vec2{}) dir = away == Vec2{} ? Vec2{1.0, 0.0} : away;
    env_.move_to(id, {p.x + 2.0 * dir.x, p.y + 2.0 * dir.y}, 0.05, *vel, Activity::kRunning,
                 Routing::kDirect);
    return true;
  }
};

class ThreateningNav final : public RobotReaction {
 public:
  using RobotReaction::RobotReaction;

 protected:
  bool react(AgentId id, AgentId r) override {
    const auto ahead = get<double>("goal_dist");
    if (!ahead) return false;
    const Vec2 h = heading_vec(r);
    const Vec2 spot{pos(r).x + h.x * *ahead, pos(r).y + h.y * *ahead};
    env_.face(id, pos(r));
    env_.move_to(id, spot, 0.2, env_.base_speed(id), Activity::kWalking, Routing::kDirect);
    return true;
  }
};

class FindNearestAgent final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    if (!id) return S::kFailure;
    const Vec2 p = pos(*id);
    std::optional<std::size_t> best;
    double best_d = 0.0;
    for (std::size_t k = 0; k < env_.sim().size(); ++k) {
      const AgentId other(static_cast<std::uint32_t>(k));
      if (other == *id || !env_.sim().active(other) || other == env_.robot()) continue;
      const double d = dist(p, pos(other));
      if (!best || d < best_d) {
        best = k;
        best_d = d;
      }
    }
    if (!best) return S::kFailure;
    (void)output("target_agent_id", BtValue{static_cast<std::int64_t>(*best)});
    return S::kSuccess;
  }
};

class SaySomething final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto msg = get<std::string>("message");
    if (!id || !msg) return S::kFailure;
    env_.speak(*id, *msg);
    return S::kSuccess;
  }
};

class SetGroupId final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto g = get<std::int64_t>("group_id");
    if (!id || !g) return S::kFailure;
    if (*g < -1) return failure("group_id must be -1 or a non-negative id");
    env_.set_group(*id, *g);
    return S::kSuccess;
  }
};

// Leader-driven nodes: the leader's tree commands the members (overriding their own trees while
// the node runs).
class LeaderNode : public TargetNode {
 public:
  using TargetNode::TargetNode;

 protected:
  std::optional<std::vector<AgentId>> members(AgentId leader) const {
    const auto text = get<std::string>("non_main_agent_ids");
    if (!text) return std::nullopt;
    auto ids = parse_agent_ids(*text);
    if (!ids) {
      (void)failure("non_main_agent_ids: " + ids.error().detail);
      return std::nullopt;
    }
    std::vector<AgentId> out;
    for (std::int64_t i : *ids) {
      if (!env_.valid(i)) {
        (void)failure("non_main_agent_ids: no agent with id " + std::to_string(i));
        return std::nullopt;
      }
      if (i != static_cast<std::int64_t>(leader.value())) out.emplace_back(static_cast<std::uint32_t>(i));
    }
    return out;
  }
};

class SetGroupWalk final : public LeaderNode {
 public:
  using LeaderNode::LeaderNode;

 protected:
  S on_tick() override {
    const auto lead = agent("main_agent_id");
    const auto duration = get<double>("duration");
    if (!lead || !duration) return S::kFailure;
    const auto others = members(*lead);
    if (!others) return S::kFailure;
    if (status() != S::kRunning) {
      start_ = now();
      group_ = 1'000'000 + static_cast<std::int64_t>(lead->value());
      env_.set_group(*lead, group_);
      for (AgentId m : *others) env_.set_group(m, group_);
    }
    if (now() - start_ >= *duration) return S::kSuccess;
    // The leader walks on to its current goal; members keep formation beside and behind it.
    const Vec2 p = pos(*lead);
    if (auto g = env_.current_goal(*lead); g && dist(p, g->position) > g->radius) {
      env_.move_to(*lead, g->position, g->radius, env_.base_speed(*lead), Activity::kWalking);
    } else {
      env_.hold(*lead, Activity::kStanding);
    }
    const Vec2 h = heading_vec(*lead);
    const Vec2 side{-h.y, h.x};
    for (std::size_t k = 0; k < others->size(); ++k) {
      const double lateral = (k % 2 == 0 ? 1.0 : -1.0) * 0.75 * static_cast<double>(k / 2 + 1);
      const double back = 0.3 * static_cast<double>(k / 2);
      const Vec2 slot{p.x + side.x * lateral - h.x * back, p.y + side.y * lateral - h.y * back};
      const AgentId m = (*others)[k];
      env_.move_to(m, slot, 0.2, std::max(env_.base_speed(m), env_.base_speed(*lead)) * 1.15,
                   Activity::kWalking, Routing::kPath, BtEnvironment::Priority::kLeader);
    }
    return S::kRunning;
  }

 private:
  double start_ = 0.0;
  std::int64_t group_ = -1;
};

class ConversationFormation final : public LeaderNode {
 public:
  using LeaderNode::LeaderNode;

 protected:
  S on_tick() override {
    const auto lead = agent("main_agent_id");
    const auto duration = get<double>("conversation_duration");
    if (!lead || !duration) return S::kFailure;
    const auto others = members(*lead);
    if (!others) return S::kFailure;
    if (status() != S::kRunning) {
      const auto name = get<std::string>("goal");
      const auto index = get<std::int64_t>("goal_id");
      if (!name || !index) return S::kFailure;
      if (name->empty() && *index < 0) {
        centre_ = pos(*lead);  // talk where the leader stands
      } else {
        auto t = resolve(*lead, "goal", "goal_id");
        if (!t) return S::kFailure;
        centre_ = t->point;
      }
      talking_since_.reset();
    }
    std::vector<AgentId> all{*lead};
    all.insert(all.end(), others->begin(), others->end());
    // An F-formation: participants evenly on a circle with ~0.9 m between neighbours.
    const double n = static_cast<double>(all.size());
    const double radius = std::max(0.55, 0.9 * n / (2.0 * kPi));
    bool everyone = true;
    for (std::size_t k = 0; k < all.size(); ++k) {
      const double a = 2.0 * kPi * static_cast<double>(k) / n;
      const Vec2 slot{centre_.x + radius * std::cos(a), centre_.y + radius * std::sin(a)};
      const AgentId m = all[k];
      const auto priority = k == 0 ? BtEnvironment::Priority::kOwn : BtEnvironment::Priority::kLeader;
      if (dist(pos(m), slot) <= 0.35) {
        env_.hold_at(m, slot, Activity::kInteracting, priority);
      } else {
        everyone = false;
        env_.move_to(m, slot, 0.25, env_.base_speed(m), Activity::kWalking, Routing::kPath, priority);
      }
      env_.face(m, centre_);
    }
    if (everyone && !talking_since_) talking_since_ = now();
    if (talking_since_ && now() - *talking_since_ >= *duration) {
      for (AgentId m : all) env_.face(m, std::nullopt);
      return S::kSuccess;
    }
    return S::kRunning;
  }

 private:
  Vec2 centre_;
  std::optional<double> talking_since_;
};

// ApproachAgent / ApproachRobot: walk up to closest_dist of the target; SUCCESS when there,
// FAILURE when duration passes first (duration <= 0: no limit).
class Approach final : public LibraryNode {
 public:
  Approach(const BtNodeInit& init, BtEnvironment& env, bool to_robot)
      : LibraryNode(init, env), robot_(to_robot) {}

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto target = robot_ ? robot() : agent("target_agent_id");
    const auto closest = get<double>("closest_dist");
    const auto vmax = get<double>("max_vel");
    const auto duration = get<double>("duration");
    if (!id || !target || !closest || !vmax || !duration || !env_.sim().active(*target)) return S::kFailure;
    if (status() != S::kRunning) start_ = now();
    const Vec2 t = pos(*target);
    env_.face(*id, t);
    if (dist(pos(*id), t) <= *closest + 0.05) {
      env_.hold(*id, Activity::kStanding);
      return S::kSuccess;
    }
    if (*duration > 0.0 && now() - start_ >= *duration) {
      env_.hold(*id, Activity::kStanding);
      return S::kFailure;
    }
    env_.move_to(*id, t, *closest, std::min(*vmax, kMaxAgentSpeed), Activity::kWalking);
    return S::kRunning;
  }

 private:
  bool robot_;
  double start_ = 0.0;
};

// BlockAgent / BlockRobot: stand front_dist ahead of the target, in its way, for duration.
class Block final : public LibraryNode {
 public:
  Block(const BtNodeInit& init, BtEnvironment& env, bool to_robot)
      : LibraryNode(init, env), robot_(to_robot) {}

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto target = robot_ ? robot() : agent("target_agent_id");
    const auto front = get<double>("front_dist");
    const auto duration = get<double>("duration");
    if (!id || !target || !front || !duration || !env_.sim().active(*target)) return S::kFailure;
    if (status() != S::kRunning) start_ = now();
    if (now() - start_ >= *duration) return S::kSuccess;
    const Vec2 h = heading_vec(*target);
    const Vec2 spot{pos(*target).x + h.x * *front, pos(*target).y + h.y * *front};
    env_.face(*id, pos(*target));
    env_.move_to(*id, spot, 0.15, env_.base_speed(*id) * 1.2, Activity::kWalking, Routing::kDirect);
    return S::kRunning;
  }

 private:
  bool robot_;
  double start_ = 0.0;
};

// AvoidAgent / AvoidRobot: step away while closer than safe_distance, else stand watching.
class Avoid final : public LibraryNode {
 public:
  Avoid(const BtNodeInit& init, BtEnvironment& env, bool from_robot)
      : LibraryNode(init, env), robot_(from_robot) {}

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto target = robot_ ? robot() : agent("target_agent_id");
    const auto safe = get<double>("safe_distance");
    const auto vmax = get<double>(robot_ ? "runaway_vel" : "max_vel");
    const auto duration = get<double>("duration");
    if (!id || !target || !safe || !vmax || !duration || !env_.sim().active(*target)) return S::kFailure;
    if (status() != S::kRunning) start_ = now();
    if (*duration > 0.0 && now() - start_ >= *duration) return S::kSuccess;
    const Vec2 p = pos(*id);
    const Vec2 t = pos(*target);
    env_.face(*id, t);
    if (dist(p, t) < *safe) {
      Vec2 away = unit({p.x - t.x, p.y - t.y});
      if (away == Vec2{}) away = {1.0, 0.0};
      env_.move_to(*id, {p.x + 2.0 * away.x, p.y + 2.0 * away.y}, 0.05, std::min(*vmax, kMaxAgentSpeed),
                   Activity::kWalking, Routing::kDirect);
    } else {
      env_.hold(*id, Activity::kStanding);
    }
    return S::kRunning;
  }

 private:
  bool robot_;
  double start_ = 0.0;
};

// Walks 1 m behind the target agent (following distance) for duration seconds (<= 0: until halted).
class FollowAgent final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto target = agent("target_agent_id");
    const auto duration = get<double>("duration");
    if (!id || !target || !duration || !env_.sim().active(*target)) return S::kFailure;
    if (status() != S::kRunning) start_ = now();
    if (*duration > 0.0 && now() - start_ >= *duration) return S::kSuccess;
    const Vec2 h = heading_vec(*target);
    const Vec2 t = pos(*target);
    const Vec2 spot{t.x - h.x * 1.0, t.y - h.y * 1.0};
    if (dist(pos(*id), spot) < 0.3) {
      env_.hold(*id, Activity::kStanding);
    } else {
      env_.move_to(*id, spot, 0.3, env_.base_speed(*id) * 1.2, Activity::kWalking);
    }
    return S::kRunning;
  }

 private:
  double start_ = 0.0;
};

class LookAt final : public TargetNode {
 public:
  enum class What { kAgent, kRobot, kPoint };
  LookAt(const BtNodeInit& init, BtEnvironment& env, What what) : TargetNode(init, env), what_(what) {}

 protected:
  S on_tick() override {
    const auto id = agent(what_ == What::kAgent ? "observer_id" : "agent_id");
    if (!id) return S::kFailure;
    std::optional<Vec2> at;
    if (what_ == What::kAgent) {
      if (const auto t = agent("target_id")) at = pos(*t);
    } else if (what_ == What::kRobot) {
      if (const auto r = robot()) at = pos(*r);
    } else if (const auto t = resolve(*id, "goal", "goal_id")) {
      at = t->point;
    }
    if (!at) return S::kFailure;
    env_.face(*id, at);
    return S::kSuccess;
  }

 private:
  What what_;
};

// --- queues ------------------------------------------------------------------------------------

class QueueNode : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  BtEnvironment::Queue* queue_of() const {
    const auto name = get<std::string>("queue");
    if (!name) return nullptr;
    BtEnvironment::Queue* q = env_.queue(*name);
    if (q == nullptr) (void)failure("no queue_lane ROI named '" + *name + "'");
    return q;
  }
  // Steers to the agent's place in line; returns whether it stands there.
  bool keep_place(AgentId id, const BtEnvironment::Queue& q, std::size_t index) {
    const Vec2 place = env_.queue_place(q, index);
    if (dist(pos(id), place) <= 0.3) {
      env_.hold_at(id, place, Activity::kQueuing);
      if (q.counter) env_.face(id, *q.counter);
      return true;
    }
    env_.move_to(id, place, 0.2, env_.base_speed(id), Activity::kQueuing);
    return false;
  }
  void halted_leave(AgentId id) {
    if (BtEnvironment::Queue* q = queue_of()) env_.leave_queue(*q, id);
  }
};

class JoinQueue final : public QueueNode {
 public:
  using QueueNode::QueueNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto spacing = get<double>("spacing");
    BtEnvironment::Queue* q = queue_of();
    if (!id || !spacing || q == nullptr) return S::kFailure;
    id_ = *id;
    if (q->members.empty()) q->spacing = std::max(0.3, *spacing);
    auto index = env_.queue_index(*q, *id);
    if (!index) {
      // Walk to the tail; take the next free place when close to it.
      const Vec2 tail = env_.queue_place(*q, q->members.size());
      if (dist(pos(*id), tail) > 1.2) {
        env_.move_to(*id, tail, 0.3, env_.base_speed(*id), Activity::kWalking);
        return S::kRunning;
      }
      env_.join_queue(*q, *id);
      index = env_.queue_index(*q, *id);
    }
    (void)output("position", BtValue{static_cast<std::int64_t>(*index)});
    return keep_place(*id, *q, *index) ? S::kSuccess : S::kRunning;
  }
  void on_halt() override {
    if (id_) halted_leave(*id_);
  }

 private:
  std::optional<AgentId> id_;
};

class AdvanceQueue final : public QueueNode {
 public:
  using QueueNode::QueueNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto interval = get<double>("advance_interval");
    BtEnvironment::Queue* q = queue_of();
    if (!id || !interval || q == nullptr) return S::kFailure;
    id_ = *id;
    const auto index = env_.queue_index(*q, *id);
    if (!index) return failure("agent " + std::to_string(id->value()) + " is not in queue '" + q->name + "'");
    (void)output("position", BtValue{static_cast<std::int64_t>(*index)});
    const bool there = keep_place(*id, *q, *index);
    if (*index != 0 || !there) return S::kRunning;
    if (*interval <= 0.0) return S::kSuccess;
    if (now() - q->head_since < *interval) return S::kRunning;
    env_.log_service(*q, *id);
    env_.leave_queue(*q, *id);  // timed queue: the head moves on by itself
    ++q->served;
    return S::kSuccess;
  }
  void on_halt() override {
    if (id_) halted_leave(*id_);
  }

 private:
  std::optional<AgentId> id_;
};

class ServeAtCounter final : public QueueNode {
 public:
  using QueueNode::QueueNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto mean = get<double>("service_time");
    const auto spread = get<double>("service_spread");
    const auto counter_name = get<std::string>("counter");
    BtEnvironment::Queue* q = queue_of();
    if (!id || !mean || !spread || !counter_name || q == nullptr) return S::kFailure;
    id_ = *id;
    const auto index = env_.queue_index(*q, *id);
    if (!index) return failure("agent " + std::to_string(id->value()) + " is not in queue '" + q->name + "'");
    if (status() != S::kRunning) {
      served_since_.reset();
      duration_ = std::max(0.0, *mean + (*spread > 0.0 ? env_.rng(*id).uniform(-*spread, *spread) : 0.0));
    }
    if (*index != 0) {  // wait for the turn
      keep_place(*id, *q, *index);
      return S::kRunning;
    }
    const auto counter = env_.place(*counter_name);
    const Vec2 desk = counter ? counter->point : q->service;
    if (!served_since_) {
      if (dist(pos(*id), q->service) > 0.3) {
        env_.move_to(*id, q->service, 0.2, env_.base_speed(*id), Activity::kQueuing);
        return S::kRunning;
      }
      served_since_ = now();
    }
    env_.hold_at(*id, q->service, Activity::kInteracting);
    env_.face(*id, desk);
    if (now() - *served_since_ < duration_) return S::kRunning;
    env_.log_service(*q, *id);
    env_.leave_queue(*q, *id);
    ++q->served;
    env_.face(*id, std::nullopt);
    return S::kSuccess;
  }
  void on_halt() override {
    if (id_) halted_leave(*id_);
  }

 private:
  std::optional<AgentId> id_;
  std::optional<double> served_since_;
  double duration_ = 0.0;
};

// --- places ------------------------------------------------------------------------------------

class SitAt final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto name = get<std::string>("seat");
    const auto duration = get<double>("duration");
    if (!id || !name || !duration) return S::kFailure;
    id_ = *id;
    if (status() != S::kRunning) {
      const auto p = env_.place(*name);
      if (!p) return failure("no place named '" + *name + "'");
      seat_ = env_.reserve_seat(*p, *id, pos(*id));
      if (!seat_) return S::kFailure;  // no free seat
      seated_since_.reset();
    }
    if (!seated_since_) {
      if (dist(pos(*id), *seat_) > 0.25) {
        env_.move_to(*id, *seat_, 0.15, env_.base_speed(*id), Activity::kWalking);
        return S::kRunning;
      }
      seated_since_ = now();
    }
    env_.hold_at(*id, *seat_, Activity::kSitting);
    if (now() - *seated_since_ < *duration) return S::kRunning;
    env_.release_seat(*id);
    env_.hold(*id, Activity::kStanding);
    return S::kSuccess;
  }
  void on_halt() override {
    if (id_) env_.release_seat(*id_);
  }

 private:
  std::optional<AgentId> id_;
  std::optional<Vec2> seat_;
  std::optional<double> seated_since_;
};

class Wander final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto name = get<std::string>("region");
    const auto duration = get<double>("duration");
    const auto pmin = get<double>("pause_min");
    const auto pmax = get<double>("pause_max");
    if (!id || !name || !duration || !pmin || !pmax) return S::kFailure;
    const auto region = env_.place(*name);
    if (!region || region->region == nullptr) return failure("no ROI or zone named '" + *name + "'");
    if (status() != S::kRunning) {
      start_ = now();
      point_.reset();
      pause_until_.reset();
    }
    if (*duration > 0.0 && now() - start_ >= *duration) return S::kSuccess;
    if (pause_until_) {
      if (now() < *pause_until_) {
        env_.hold(*id, Activity::kStanding);
        return S::kRunning;
      }
      pause_until_.reset();
      point_.reset();
    }
    Rng& rng = env_.rng(*id);
    if (!point_) {
      const geometry::Box box = geometry::bounds(region->region->outer);
      for (int attempt = 0; attempt < 64 && !point_; ++attempt) {
        const Vec2 p{rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y)};
        if (geometry::contains(*region->region, {p.x, p.y}) && env_.walking_distance(pos(*id), p) < 1e9)
          point_ = p;
      }
      if (!point_) point_ = region->point;
    }
    if (dist(pos(*id), *point_) <= 0.4) {
      const double lo = std::min(*pmin, *pmax);
      const double hi = std::max(*pmin, *pmax);
      pause_until_ = now() + (hi > lo ? rng.uniform(lo, hi) : lo);
      env_.hold(*id, Activity::kStanding);
      return S::kRunning;
    }
    env_.move_to(*id, *point_, 0.3, env_.base_speed(*id), Activity::kWalking);
    return S::kRunning;
  }

 private:
  double start_ = 0.0;
  std::optional<Vec2> point_;
  std::optional<double> pause_until_;
};

class Gather final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto name = get<std::string>("point");
    const auto radius = get<double>("radius");
    const auto group_port = get<std::int64_t>("group_id");
    const auto duration = get<double>("duration");
    if (!id || !name || !radius || !group_port || !duration) return S::kFailure;
    const auto place = env_.place(*name);
    if (!place) return failure("no place named '" + *name + "'");
    const std::int64_t group = *group_port >= 0 ? *group_port : env_.group(*id);
    if (status() != S::kRunning) together_since_.reset();
    // Members of the group in id order; this agent's slot is its rank on a circle.
    std::vector<AgentId> members;
    for (std::size_t k = 0; k < env_.sim().size(); ++k) {
      const AgentId m(static_cast<std::uint32_t>(k));
      if (m == *id || (group >= 0 && env_.group(m) == group && env_.sim().active(m))) members.push_back(m);
    }
    const auto rank = static_cast<double>(std::find(members.begin(), members.end(), *id) - members.begin());
    const double n = static_cast<double>(members.size());
    const double ring = n > 1 ? std::min(*radius * 0.7, std::max(0.45, 0.8 * n / (2.0 * kPi))) : 0.0;
    const double a = 2.0 * kPi * rank / std::max(n, 1.0);
    const Vec2 slot{place->point.x + ring * std::cos(a), place->point.y + ring * std::sin(a)};
    env_.face(*id, place->point);
    if (dist(pos(*id), slot) > 0.3) {
      env_.move_to(*id, slot, 0.25, env_.base_speed(*id), Activity::kWalking);
    } else {
      env_.hold(*id, Activity::kInteracting);
    }
    bool all_there = true;
    for (AgentId m : members) all_there = all_there && dist(pos(m), place->point) <= *radius;
    if (!all_there) {
      together_since_.reset();
      return S::kRunning;
    }
    if (!together_since_) together_since_ = now();
    if (now() - *together_since_ < *duration) return S::kRunning;
    env_.face(*id, std::nullopt);
    return S::kSuccess;
  }

 private:
  std::optional<double> together_since_;
};

class Evacuate final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto name = get<std::string>("exit");
    const auto factor = get<double>("speed_factor");
    if (!id || !name || !factor) return S::kFailure;
    const Vec2 p = pos(*id);
    if (status() != S::kRunning) {
      exit_ = name->empty() ? env_.nearest_exit(p) : env_.exit_index(*name);
      if (!exit_) return failure(name->empty() ? "no exit is reachable" : "no exit named '" + *name + "'");
    }
    const BtEnvironment::Exit& e = env_.exits()[*exit_];
    const bool out = e.region != nullptr ? geometry::contains(*e.region, {p.x, p.y}) : env_.outside(p);
    if (out) {
      (void)env_.sim().set_activity(*id, Activity::kExited);  // left the building: no longer simulated
      return S::kSuccess;
    }
    const double speed = std::min(env_.base_speed(*id) * *factor, kMaxAgentSpeed);
    if (e.beyond && dist(p, e.point) < 1.2) {
      env_.move_to(*id, *e.beyond, 0.05, speed, Activity::kEvacuating, Routing::kDirect);
    } else {
      env_.move_to(*id, e.point, 0.05, speed, Activity::kEvacuating);
    }
    return S::kRunning;
  }

 private:
  std::optional<std::size_t> exit_;
};

class WaitAt final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto location = get<std::string>("location");
    const auto duration = get<double>("duration");
    const auto face = get<std::string>("face");
    if (!id || !location || !duration || !face) return S::kFailure;
    const auto place = env_.place(*location);
    if (!place) return failure("no place named '" + *location + "'");
    if (status() != S::kRunning) waiting_since_.reset();
    if (!waiting_since_) {
      if (!env_.inside(*place, pos(*id)) && dist(pos(*id), place->point) > 0.4) {
        env_.move_to(*id, place->point, 0.3, env_.base_speed(*id), Activity::kWalking);
        return S::kRunning;
      }
      waiting_since_ = now();
    }
    env_.hold(*id, Activity::kWaiting);
    if (!face->empty())
      if (const auto f = env_.place(*face)) env_.face(*id, f->point);
    if (now() - *waiting_since_ < *duration) return S::kRunning;
    env_.face(*id, std::nullopt);
    return S::kSuccess;
  }

 private:
  std::optional<double> waiting_since_;
};

// Algorithm 1 of paper 001: the sampled velocity becomes an intermediate goal at least 2·tol
// ahead, and the simulation's LightSFM desired force pulls towards it (goal radius tol).
class FollowVelocityField final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 protected:
  S on_tick() override {
    const auto id = agent();
    const auto dt = get<double>("time_step");
    const auto name = get<std::string>("field");
    const auto tol = get<double>("tolerance");
    if (!id || !dt || !name || !tol) return S::kFailure;
    const BtEnvironment::FieldEntry* f = env_.velocity_field(*name);
    if (f == nullptr) return failure("no velocity field named '" + *name + "'");
    const Vec2 p = pos(*id);
    for (const geometry::Polygon& g : f->goals) {
      if (geometry::contains(g, {p.x, p.y})) {
        env_.hold(*id, Activity::kStanding);
        return S::kSuccess;
      }
    }
    const Vec2 goal = velocity_field_goal(f->field, p, *dt, *tol);
    if (goal == p) {
      env_.hold(*id, Activity::kStanding);  // zero velocity here: LightSFM brakes (goal reached)
    } else {
      env_.move_to(*id, goal, *tol, env_.base_speed(*id), Activity::kWalking, Routing::kDirect);
    }
    return S::kRunning;
  }
};

// --- registration ------------------------------------------------------------------------------

constexpr BtPortType I = BtPortType::kInt;
constexpr BtPortType D = BtPortType::kDouble;
constexpr BtPortType B = BtPortType::kBool;
constexpr BtPortType T = BtPortType::kString;

BtPortSpec in(std::string name, BtPortType type, std::optional<std::string> def = std::nullopt) {
  return BtPortSpec{std::move(name), BtPortDirection::kIn, type, std::move(def)};
}
BtPortSpec out(std::string name, BtPortType type) {
  return BtPortSpec{std::move(name), BtPortDirection::kOut, type, std::nullopt};
}
BtPortSpec agent_port() {
  return in("agent_id", I, "{id}");
}
BtPortSpec step_port() {
  return in("time_step", D, "{dt}");
}

template <class Node, class... Args>
BtFactory bind(BtEnvironment& env, Args... args) {
  return [&env, args...](const BtNodeInit& init) -> std::unique_ptr<BtNode> {
    return std::make_unique<Node>(init, env, args...);
  };
}

std::vector<BtNodeType> library(BtEnvironment& env) {
  using K = BtNodeKind;
  return {
      {"IsGoalReached", K::kCondition, {agent_port()}, bind<IsGoalReached>(env), {}},
      {"IsRobotVisible",
       K::kCondition,
       {agent_port(), in("distance", D, "5.0")},
       bind<IsRobotVisible>(env),
       {}},
      {"IsRobotClose", K::kCondition, {agent_port(), in("threshold", D, "1.0")}, bind<IsRobotClose>(env), {}},
      {"IsRobotFacingAgent", K::kCondition, {agent_port()}, bind<IsRobotFacingAgent>(env), {}},
      {"IsAgentVisible",
       K::kCondition,
       {in("observer_id", I, "{id}"), in("agent_id", I), in("distance", D, "5.0"),
        in("field_of_view", D, "3.14")},
       bind<IsAgentVisible>(env),
       {}},
      {"IsAgentClose",
       K::kCondition,
       {in("observer_id", I, "{id}"), in("target_agent_id", I), in("threshold", D, "1.0")},
       bind<IsAgentClose>(env),
       {}},
      {"IsAtPosition",
       K::kCondition,
       {agent_port(), in("target_x", D), in("target_y", D), in("tolerance", D, "0.1")},
       bind<IsAtPosition>(env),
       {}},
      {"RandomChance",
       K::kCondition,
       {agent_port(), in("probability", D, "0.3")},
       bind<RandomChance>(env),
       {"RandomChanceCondition"}},
      {"TimeExpired",
       K::kCondition,
       {in("seconds", D), in("ts", D, "{dt}"), in("only_once", B, "false")},
       bind<TimeExpired>(env),
       {"TimeExpiredCondition"}},
      {"IsAnyoneSpeaking",
       K::kCondition,
       {agent_port(), step_port(), in("distance_threshold", D, "5.0"), in("duration", D, "5.0"),
        out("speaker_id", I)},
       bind<IsAnyoneSpeaking>(env),
       {}},
      {"IsSpeaking",
       K::kCondition,
       {agent_port(), step_port(), in("target_id", I), in("distance_threshold", D, "5.0"),
        in("duration", D, "5.0")},
       bind<IsSpeaking>(env),
       {}},
      {"IsAnyoneLookingAtMe",
       K::kCondition,
       {agent_port(), step_port(), in("distance_threshold", D, "5.0"), in("angle_threshold", D, "0.2"),
        in("duration", D, "5.0"), out("observer_id", I)},
       bind<IsAnyoneLookingAtMe>(env),
       {}},
      {"IsLookingAtMe",
       K::kCondition,
       {agent_port(), step_port(), in("target_id", I), in("distance_threshold", D, "5.0"),
        in("angle_threshold", D, "0.2"), in("duration", D, "5.0")},
       bind<IsLookingAtMe>(env),
       {}},
      {"RegularNav", K::kAction, {agent_port(), step_port()}, bind<RegularNav>(env), {}},
      {"UpdateGoal", K::kAction, {agent_port()}, bind<UpdateGoal>(env), {}},
      {"SetGoal",
       K::kAction,
       {agent_port(), in("goal_id", I, "-1"), in("goal", T, "")},
       bind<SetGoal>(env),
       {}},
      {"GoTo",
       K::kAction,
       {agent_port(), step_port(), in("goal_id", I, "-1"), in("goal", T, ""), in("tolerance", D, "0.1")},
       bind<GoTo>(env),
       {}},
      {"StopAndWait",
       K::kAction,
       {agent_port(), in("wait_duration", D, "3.0")},
       bind<StopAndWait>(env),
       {"StopAndWaitTimerAction"}},
      {"StopMovement", K::kAction, {agent_port()}, bind<StopMovement>(env, true), {}},
      {"ResumeMovement", K::kAction, {agent_port()}, bind<StopMovement>(env, false), {}},
      {"SurprisedNav",
       K::kAction,
       {agent_port(), step_port(), in("beh_duration", D, "5.0"), in("only_once", B, "true")},
       bind<SurprisedNav>(env),
       {}},
      {"CuriousNav",
       K::kAction,
       {agent_port(), step_port(), in("beh_duration", D, "5.0"), in("only_once", B, "true"),
        in("agent_vel", D, "1.0"), in("stop_distance", D, "0.5")},
       bind<CuriousNav>(env),
       {}},
      {"ScaredNav",
       K::kAction,
       {agent_port(), step_port(), in("beh_duration", D, "5.0"), in("only_once", B, "true"),
        in("runaway_vel", D, "1.5"), in("scary_force_factor", D, "1.0")},
       bind<ScaredNav>(env),
       {}},
      {"ThreateningNav",
       K::kAction,
       {agent_port(), step_port(), in("beh_duration", D, "5.0"), in("only_once", B, "true"),
        in("goal_dist", D, "1.0")},
       bind<ThreateningNav>(env),
       {}},
      {"FindNearestAgent",
       K::kAction,
       {agent_port(), out("target_agent_id", I)},
       bind<FindNearestAgent>(env),
       {}},
      {"SaySomething", K::kAction, {agent_port(), in("message", T, "")}, bind<SaySomething>(env), {}},
      {"SetGroupId", K::kAction, {agent_port(), in("group_id", I)}, bind<SetGroupId>(env), {}},
      {"SetGroupWalk",
       K::kAction,
       {in("main_agent_id", I, "{id}"), step_port(), in("non_main_agent_ids", T), in("duration", D, "5.0")},
       bind<SetGroupWalk>(env),
       {}},
      {"ConversationFormation",
       K::kAction,
       {in("main_agent_id", I, "{id}"), in("non_main_agent_ids", T), in("goal_id", I, "-1"),
        in("goal", T, ""), in("conversation_duration", D, "10.0"), step_port()},
       bind<ConversationFormation>(env),
       {}},
      {"ApproachAgent",
       K::kAction,
       {agent_port(), step_port(), in("target_agent_id", I), in("closest_dist", D, "0.5"),
        in("max_vel", D, "1.0"), in("duration", D, "5.0")},
       bind<Approach>(env, false),
       {}},
      {"ApproachRobot",
       K::kAction,
       {agent_port(), step_port(), in("closest_dist", D, "1.5"), in("max_vel", D, "1.8"),
        in("duration", D, "5.0")},
       bind<Approach>(env, true),
       {}},
      {"BlockRobot",
       K::kAction,
       {agent_port(), step_port(), in("front_dist", D, "1.0"), in("duration", D, "5.0")},
       bind<Block>(env, true),
       {}},
      {"BlockAgent",
       K::kAction,
       {agent_port(), step_port(), in("target_agent_id", I), in("front_dist", D, "1.0"),
        in("duration", D, "5.0")},
       bind<Block>(env, false),
       {}},
      {"AvoidRobot",
       K::kAction,
       {agent_port(), step_port(), in("safe_distance", D, "1.5"), in("runaway_vel", D, "1.2"),
        in("duration", D, "0.0")},
       bind<Avoid>(env, true),
       {}},
      {"FollowAgent",
       K::kAction,
       {agent_port(), step_port(), in("target_agent_id", I), in("duration", D, "5.0")},
       bind<FollowAgent>(env),
       {}},
      {"LookAtAgent",
       K::kAction,
       {in("observer_id", I, "{id}"), in("target_id", I)},
       bind<LookAt>(env, LookAt::What::kAgent),
       {}},
      {"LookAtRobot", K::kAction, {agent_port()}, bind<LookAt>(env, LookAt::What::kRobot), {}},
      {"LookAtPoint",
       K::kAction,
       {agent_port(), in("goal_id", I, "-1"), in("goal", T, "")},
       bind<LookAt>(env, LookAt::What::kPoint),
       {}},
      {"AvoidAgent",
       K::kAction,
       {agent_port(), step_port(), in("target_agent_id", I), in("safe_distance", D, "1.5"),
        in("max_vel", D, "1.2"), in("duration", D, "0.0")},
       bind<Avoid>(env, false),
       {}},
      {"JoinQueue",
       K::kAction,
       {agent_port(), step_port(), in("queue", T), in("spacing", D, "0.7"), out("position", I)},
       bind<JoinQueue>(env),
       {}},
      {"AdvanceQueue",
       K::kAction,
       {agent_port(), step_port(), in("queue", T), in("advance_interval", D, "0.0"), out("position", I)},
       bind<AdvanceQueue>(env),
       {}},
      {"ServeAtCounter",
       K::kAction,
       {agent_port(), in("counter", T), in("queue", T), in("service_time", D, "20.0"),
        in("service_spread", D, "0.0")},
       bind<ServeAtCounter>(env),
       {}},
      {"IsAtQueueHead", K::kCondition, {agent_port(), in("queue", T)}, bind<IsAtQueueHead>(env), {}},
      {"SitAt",
       K::kAction,
       {agent_port(), step_port(), in("seat", T), in("duration", D, "300.0")},
       bind<SitAt>(env),
       {}},
      {"Wander",
       K::kAction,
       {agent_port(), step_port(), in("region", T), in("duration", D, "0.0"), in("pause_min", D, "1.0"),
        in("pause_max", D, "8.0")},
       bind<Wander>(env),
       {}},
      {"Gather",
       K::kAction,
       {agent_port(), step_port(), in("point", T), in("radius", D, "1.5"), in("group_id", I, "-1"),
        in("duration", D, "60.0")},
       bind<Gather>(env),
       {}},
      {"Evacuate",
       K::kAction,
       {agent_port(), step_port(), in("exit", T, ""), in("speed_factor", D, "1.3")},
       bind<Evacuate>(env),
       {}},
      {"WaitAt",
       K::kAction,
       {agent_port(), step_port(), in("location", T), in("duration", D, "30.0"), in("face", T, "")},
       bind<WaitAt>(env),
       {}},
      {"IsInRegion", K::kCondition, {agent_port(), in("region", T)}, bind<IsInRegion>(env), {}},
      {"FollowVelocityField",
       K::kAction,
       {agent_port(), step_port(), in("field", T), in("tolerance", D, "0.5")},
       bind<FollowVelocityField>(env),
       {}},
  };
}

}  // namespace

Result<std::vector<std::int64_t>> parse_agent_ids(std::string_view text) {
  std::vector<std::int64_t> ids;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ';' || text[i] == ',' || text[i] == ' ' || text[i] == '\t')) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && text[j] != ';' && text[j] != ',' && text[j] != ' ' && text[j] != '\t') ++j;
    std::int64_t v = 0;
    const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + j, v);
    if (ec != std::errc() || ptr != text.data() + j || v < 0)
      return fail(ErrorCode::kValidation, "'" + std::string(text.substr(i, j - i)) + "' is not an agent id");
    ids.push_back(v);
    i = j;
  }
  return ids;
}

BtRegistry behavior_registry(BtEnvironment& env) {
  BtRegistry r = BtRegistry::builtins();
  for (BtNodeType& t : library(env)) {
    auto ok = r.add(std::move(t));
    if (!ok) throw std::logic_error(ok.error().detail);  // a duplicate in the table above
  }
  return r;
}

BtLoadOptions behavior_load_options(const BtEnvironment& env, std::filesystem::path base_dir) {
  BtLoadOptions o;
  o.base_dir = std::move(base_dir);
  o.check_literal = [&env](const BtNodeSpec& node, const BtPortBinding& port) -> std::optional<std::string> {
    const std::string& n = port.name;
    if (port.type == BtPortType::kDouble) {
      const double v = std::get<double>(port.literal);
      if (n == "probability" && (v < 0.0 || v > 1.0)) return "must be in [0, 1]";
      const bool non_negative =
          n.find("duration") != std::string::npos || n.find("distance") != std::string::npos ||
          n.find("dist") != std::string::npos || n == "seconds" || n == "tolerance" || n == "threshold" ||
          n == "radius" || n == "spacing" || n == "service_time" || n == "service_spread" || n == "delay" ||
          n.find("vel") != std::string::npos || n == "pause_min" || n == "pause_max" || n == "speed_factor" ||
          n == "advance_interval";
      if (non_negative && v < 0.0) return "must not be negative";
      return std::nullopt;
    }
    if (port.type != BtPortType::kString) return std::nullopt;
    const std::string& v = std::get<std::string>(port.literal);
    if (n == "non_main_agent_ids") {
      auto ids = parse_agent_ids(v);
      if (!ids) return ids.error().detail;
      return std::nullopt;
    }
    if (n == "queue") return env.check_place(v, "queue");
    if (n == "region") return env.check_place(v, "region");
    if (n == "exit") return env.check_place(v, "exit");
    if (n == "field")
      return env.velocity_field(v) != nullptr
                 ? std::nullopt
                 : std::optional<std::string>("no velocity field (ambient group) named '" + v + "'");
    const bool place =
        n == "goal" || n == "counter" || n == "seat" || n == "point" || n == "location" || n == "face";
    if (place && !(v.empty() && (n == "goal" || n == "face"))) return env.check_place(v, "place");
    (void)node;
    return std::nullopt;
  };
  return o;
}

}  // namespace socsim::crowd
