// Place nodes: sit, wander, gather, evacuate, wait at, and following a velocity field (Algorithm 1 of paper
// 001).
#include "core/crowd/bt_library.hpp"

namespace socsim::crowd::nodes {
namespace {

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

// How far past a door's wall line an evacuating agent counts as out. It walks straight out from
// where it crossed the opening; removed while still within reach of those behind (0.9 m from the
// door's centre before), it left them an empty doorway and 80 people passed a 1 m door at
// 2.6-2.8 /s (speed_factor 1.3), against about 1.9 /s measured by Seyfried et al. 2009. At 2 m the
// leader no longer caps a follower's speed (headway ~0.4 m + 0.6 s x speed) nor pushes it.
constexpr double kExitClearance = 2.0;

class Evacuate final : public LibraryNode {
 public:
  using LibraryNode::LibraryNode;

 private:
  S exited(AgentId id) {
    (void)env_.sim().set_activity(id, Activity::kExited);  // left the building: no longer simulated
    return S::kSuccess;
  }

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
    const double speed = std::min(env_.base_speed(*id) * *factor, kMaxAgentSpeed);
    if (e.region != nullptr) {
      if (geometry::contains(*e.region, {p.x, p.y})) return exited(*id);
      env_.move_to(*id, e.point, 0.05, speed, Activity::kEvacuating);
      return S::kRunning;
    }
    if (!e.beyond) {
      env_.move_to(*id, e.point, 0.05, speed, Activity::kEvacuating);
      return S::kRunning;
    }
    // Through a door to the outside: towards its centre until within 1.2 m of it and abreast of
    // the opening, then straight out from where the agent is across the opening (people leave a
    // door side by side rather than converging on one point behind it); out once kExitClearance
    // past the wall line.
    const Vec2 normal{e.beyond->x - e.point.x, e.beyond->y - e.point.y};  // unit, pointing out
    const double out = (p.x - e.point.x) * normal.x + (p.y - e.point.y) * normal.y;
    if (out >= kExitClearance && env_.outside(p)) return exited(*id);
    const double half = std::hypot(e.half_opening.x, e.half_opening.y);
    const Vec2 u = half > 1e-9 ? Vec2{e.half_opening.x / half, e.half_opening.y / half} : Vec2{0.0, 0.0};
    const double room = std::max(0.0, half - env_.sim().radius(*id) - 0.05);
    const double lateral = (p.x - e.point.x) * u.x + (p.y - e.point.y) * u.y;
    if (out <= 0.0 && (dist(p, e.point) >= 1.2 || std::abs(lateral) > room + 0.05)) {
      env_.move_to(*id, e.point, 0.05, speed, Activity::kEvacuating);
      return S::kRunning;
    }
    const double across = std::clamp(lateral, -room, room);
    const double ahead = kExitClearance + 1.0;
    env_.move_to(*id,
                 {e.point.x + u.x * across + normal.x * ahead, e.point.y + u.y * across + normal.y * ahead},
                 0.05, speed, Activity::kEvacuating, Routing::kDirect);
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

}  // namespace

std::vector<BtNodeType> place_nodes(BtEnvironment& env) {
  using K = BtNodeKind;
  return {
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
       {agent_port(), step_port(), in("exit", T, ""), in("speed_factor", D, "1.0")},
       bind<Evacuate>(env),
       {}},
      {"WaitAt",
       K::kAction,
       {agent_port(), step_port(), in("location", T), in("duration", D, "30.0"), in("face", T, "")},
       bind<WaitAt>(env),
       {}},
      {"FollowVelocityField",
       K::kAction,
       {agent_port(), step_port(), in("field", T), in("tolerance", D, "0.5")},
       bind<FollowVelocityField>(env),
       {}},
  };
}

}  // namespace socsim::crowd::nodes
