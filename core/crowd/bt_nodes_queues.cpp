// Queue nodes: join, advance, serve at a counter.
#include "core/crowd/bt_library.hpp"

namespace socsim::crowd::nodes {
namespace {

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

}  // namespace

std::vector<BtNodeType> queue_nodes(BtEnvironment& env) {
  using K = BtNodeKind;
  return {
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
  };
}

}  // namespace socsim::crowd::nodes
