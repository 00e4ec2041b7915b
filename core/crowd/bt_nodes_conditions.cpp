// Condition nodes: goals, robot and agent visibility and distance, positions, chance, timers, speech, gaze,
// queue heads, regions.
#include "core/crowd/bt_library.hpp"

namespace socsim::crowd::nodes {
namespace {

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

}  // namespace

std::vector<BtNodeType> condition_nodes(BtEnvironment& env) {
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
      {"IsAtQueueHead", K::kCondition, {agent_port(), in("queue", T)}, bind<IsAtQueueHead>(env), {}},
      {"IsInRegion", K::kCondition, {agent_port(), in("region", T)}, bind<IsInRegion>(env), {}},
  };
}

}  // namespace socsim::crowd::nodes
