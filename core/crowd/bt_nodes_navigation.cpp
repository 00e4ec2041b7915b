// Navigation and social nodes: walking to goals, stopping, HuNavSim's robot reactions, nearest agents,
// speech, groups (walk, conversation), approach, block, avoid, follow, look at.
#include "core/crowd/bt_library.hpp"

namespace socsim::crowd::nodes {
namespace {

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

}  // namespace

std::vector<BtNodeType> navigation_nodes(BtEnvironment& env) {
  using K = BtNodeKind;
  return {
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
  };
}

}  // namespace socsim::crowd::nodes
