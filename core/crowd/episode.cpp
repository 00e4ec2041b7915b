#include "core/crowd/episode.hpp"

#include <algorithm>
#include <cmath>

namespace socsim::crowd {

namespace {

constexpr double kMaxCommandSpeed = kMaxAgentSpeed;  // m/s: a larger command is absurd, not clamped
constexpr double kMaxCommandTurn = 20.0;             // rad/s
// m of body overlap that is not yet a collision: the crowd's hard contact leaves touching bodies up
// to 1 cm inside each other (docs/crowd.md, "Body contact"), so brushing past is not a collision.
constexpr double kContactTolerance = 0.01;

Status input_error(std::size_t k, const std::string& field, const std::string& message) {
  const std::string pointer = "/robots/" + std::to_string(k) + field;
  return fail(ErrorCode::kValidation, pointer + ": " + message, {FieldError{pointer, message}});
}

}  // namespace

std::string_view outcome_name(Outcome o) {
  switch (o) {
    case Outcome::kRunning:
      return "running";
    case Outcome::kSuccess:
      return "success";
    case Outcome::kCollisionPerson:
      return "collision_person";
    case Outcome::kCollisionWall:
      return "collision_wall";
    case Outcome::kTimeout:
      return "timeout";
    case Outcome::kStuck:
      return "stuck";
  }
  return "running";
}

Status validate(const EpisodeOptions& o) {
  std::vector<FieldError> errors;
  if (!(std::isfinite(o.time_limit) && o.time_limit > 0.0 && o.time_limit <= 3600.0))
    errors.push_back({"/time_limit", "must be in (0, 3600] s"});
  if (!(std::isfinite(o.success_radius) && o.success_radius > 0.0 && o.success_radius <= 100.0))
    errors.push_back({"/success_radius", "must be in (0, 100] m"});
  if (!(std::isfinite(o.stuck_time) && o.stuck_time > 0.0))
    errors.push_back({"/stuck_time", "must be positive"});
  if (!(std::isfinite(o.stuck_distance) && o.stuck_distance >= 0.0))
    errors.push_back({"/stuck_distance", "must be non-negative"});
  if (o.max_robots == 0) errors.push_back({"/max_robots", "must be at least 1"});
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid episode options", std::move(errors));
  return {};
}

Episode::~Episode() = default;

Result<std::unique_ptr<Episode>> Episode::create(const world::World* world, const Program& program,
                                                 RunnerOptions options, const EpisodeOptions& episode) {
  if (auto ok = validate(episode); !ok) return tl::unexpected(ok.error());
  std::optional<ProgramPoint> program_goal;
  if (options.robots.empty() && program.robot) {
    const ProgramRobot& r = *program.robot;
    RobotSpec spec;
    spec.start = {r.position.x, r.position.y, r.yaw.value_or(0.0)};
    spec.radius = r.radius;
    spec.limits.max_speed = std::max(r.speed, 0.1);
    options.robots.push_back(spec);
    if (!r.goals.empty()) program_goal = r.goals.back();
  }
  if (options.robots.empty())
    return fail(ErrorCode::kValidation, "no robot: give robots or a program with a robot section",
                {FieldError{"/robots", "needs at least one robot (the program has no robot section)"}});
  if (options.robots.size() > episode.max_robots)
    return fail(ErrorCode::kValidation,
                "too many robots: " + std::to_string(options.robots.size()) + " (at most " +
                    std::to_string(episode.max_robots) + ")",
                {FieldError{"/robots", "at most " + std::to_string(episode.max_robots) + " robots"}});
  for (RobotSpec& r : options.robots)
    if (r.goal && r.goal->radius == 0.0) r.goal->radius = episode.success_radius;
  std::vector<FieldError> errors;
  for (std::size_t k = 0; k < options.robots.size(); ++k) {
    const RobotSpec& r = options.robots[k];
    const std::string at = "/robots/" + std::to_string(k);
    if (auto ok = validate(r.limits, at + "/limits"); !ok)
      for (const FieldError& f : ok.error().errors) errors.push_back(f);
    if (!(std::isfinite(r.start.x) && std::isfinite(r.start.y) && std::isfinite(r.start.yaw)))
      errors.push_back({at + "/start", "must be finite"});
    if (r.goal && !(std::isfinite(r.goal->position.x) && std::isfinite(r.goal->position.y) &&
                    std::isfinite(r.goal->radius) && r.goal->radius > 0.0))
      errors.push_back({at + "/goal", "must be finite with a positive radius"});
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid robots", std::move(errors));

  auto runner = ScenarioRunner::create(world, program, options);
  if (!runner) return tl::unexpected(runner.error());
  std::unique_ptr<Episode> e(new Episode());
  e->runner_ = std::move(*runner);
  e->options_ = episode;
  e->log_.dt = e->runner_->sim().config().dt;
  e->log_.robots = options.robots;
  e->log_.walls = e->runner_->sim().walls();
  if (program_goal) {
    std::optional<Vec2> at;
    if (const auto* v = std::get_if<Vec2>(&program_goal->where)) {
      at = *v;
    } else {
      const std::string& name = std::get<std::string>(program_goal->where);
      if (auto problem = e->runner_->environment().check_place(name, "place"))
        return fail(ErrorCode::kValidation, *problem, {FieldError{program_goal->pointer, *problem}});
      at = e->runner_->environment().place(name)->point;
    }
    e->log_.robots[0].goal = Goal{*at, program_goal->radius.value_or(episode.success_radius)};
  }
  e->log_.results.resize(e->log_.robots.size());
  for (std::size_t k = 0; k < e->log_.robots.size(); ++k) {
    UnicycleState s;
    s.pose = e->log_.robots[k].start;
    e->robot_states_.push_back(s);
    e->anchor_.push_back({s.pose.x, s.pose.y});
    e->anchor_time_.push_back(0.0);
    (void)e->runner_->sim().set_driven_state(e->runner_->driven_robots()[k], s.pose, twist_of(s));
  }
  e->record();
  e->judge();
  return e;
}

bool Episode::ended() const {
  return std::none_of(log_.results.begin(), log_.results.end(),
                      [](const RobotResult& r) { return r.outcome == Outcome::kRunning; });
}

Status Episode::step(std::span<const RobotInput> inputs) {
  if (ended()) return fail(ErrorCode::kConflict, "the episode has ended");
  const std::size_t n = log_.robots.size();
  if (inputs.size() != n)
    return fail(ErrorCode::kValidation,
                "expected " + std::to_string(n) + " robot input(s), got " + std::to_string(inputs.size()),
                {FieldError{"/robots", "needs one entry per robot (" + std::to_string(n) + ")"}});
  // Check everything before changing anything: a rejected step leaves the episode as it was.
  std::vector<UnicycleState> next = robot_states_;
  for (std::size_t k = 0; k < n; ++k) {
    if (log_.results[k].outcome != Outcome::kRunning) {
      next[k].v = 0.0;
      next[k].omega = 0.0;
      continue;
    }
    const RobotInput& in = inputs[k];
    if (in.kind == RobotInput::Kind::kCommand) {
      const VelocityCommand& c = in.command;
      if (!std::isfinite(c.v) || std::abs(c.v) > kMaxCommandSpeed)
        return input_error(k, "/cmd/v", "must be finite and within ±8 m/s");
      if (!std::isfinite(c.omega) || std::abs(c.omega) > kMaxCommandTurn)
        return input_error(k, "/cmd/omega", "must be finite and within ±20 rad/s");
      next[k] = integrate_unicycle(robot_states_[k], c, log_.robots[k].limits, log_.dt);
    } else {
      const Pose2& p = in.pose;
      if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.yaw)))
        return input_error(k, "/pose", "must be finite");
      const double speed = std::hypot(in.twist.vx, in.twist.vy);
      if (!std::isfinite(speed) || speed > kMaxCommandSpeed)
        return input_error(k, "/twist", "speed must be finite and at most 8 m/s");
      if (!std::isfinite(in.twist.omega) || std::abs(in.twist.omega) > kMaxCommandTurn)
        return input_error(k, "/twist/omega", "must be finite and within ±20 rad/s");
      // A pose may not jump: at most twice the speed limit (and 0.1 m) over one step.
      const double jump = distance({p.x, p.y}, {robot_states_[k].pose.x, robot_states_[k].pose.y});
      const double allowed = 2.0 * log_.robots[k].limits.max_speed * log_.dt + 0.1;
      if (jump > allowed)
        return input_error(
            k, "/pose",
            "moves " + std::to_string(jump) + " m in one step (at most " + std::to_string(allowed) + " m)");
      UnicycleState s;
      s.pose = p;
      s.v = std::cos(p.yaw) * in.twist.vx + std::sin(p.yaw) * in.twist.vy;
      s.omega = in.twist.omega;
      robot_states_[k] = s;
      next[k] = s;
      // People react to the state the client reports from this step on.
      (void)runner_->sim().set_driven_state(runner_->driven_robots()[k], p, in.twist);
    }
  }
  for (std::size_t k = 0; k < n; ++k)  // ended robots hold still from this step on
    if (log_.results[k].outcome != Outcome::kRunning)
      (void)runner_->sim().set_driven_state(runner_->driven_robots()[k], robot_states_[k].pose, {});
  // The crowd steps on the frozen current state (robots where they are), then commanded robots
  // take their integrated pose.
  runner_->step();
  ++steps_;
  for (std::size_t k = 0; k < n; ++k) {
    robot_states_[k] = next[k];
    (void)runner_->sim().set_driven_state(runner_->driven_robots()[k], next[k].pose, twist_of(next[k]));
  }
  record();
  judge();
  return {};
}

void Episode::record() {
  const CrowdSimulation& sim = runner_->sim();
  EpisodeFrame f;
  f.time = sim.time();
  const std::vector<AgentId>& robots = runner_->driven_robots();
  for (const AgentId id : robots) {
    const PedestrianState s = sim.state(id);
    f.robots.push_back(LoggedBody{id.value(),
                                  {s.pose.x, s.pose.y},
                                  {s.twist.vx, s.twist.vy},
                                  s.pose.yaw,
                                  s.twist.omega,
                                  sim.radius(id)});
  }
  for (std::uint32_t i = 0; i < sim.size(); ++i) {
    const AgentId id(i);
    if (!sim.active(id) || sim.driven(id)) continue;
    const Vec2 p = sim.position(id);
    const bool near = std::any_of(f.robots.begin(), f.robots.end(), [&](const LoggedBody& r) {
      return distance(p, r.position) <= kEpisodeLogRange;
    });
    if (!near) continue;
    const PedestrianState s = sim.state(id);
    f.people.push_back(
        LoggedBody{i, p, {s.twist.vx, s.twist.vy}, s.pose.yaw, s.twist.omega, sim.radius(id), s.group_id});
  }
  log_.frames.push_back(std::move(f));
}

void Episode::judge() {
  const EpisodeFrame& f = log_.frames.back();
  for (std::size_t k = 0; k < log_.robots.size(); ++k) {
    RobotResult& result = log_.results[k];
    if (result.outcome != Outcome::kRunning) continue;
    const LoggedBody& r = f.robots[k];
    const RobotSpec& spec = log_.robots[k];
    auto decide = [&](Outcome o) {
      result.outcome = o;
      result.end_time = f.time;
    };
    if (spec.goal && distance(r.position, spec.goal->position) <= spec.goal->radius) {
      decide(Outcome::kSuccess);
      continue;
    }
    for (const LoggedBody& p : f.people) {
      if (distance(r.position, p.position) < r.radius + p.radius - kContactTolerance) {
        decide(Outcome::kCollisionPerson);
        result.hit = p.id;
        break;
      }
    }
    if (result.outcome != Outcome::kRunning) continue;
    for (const WallSegment& w : log_.walls) {
      if (point_segment_distance(r.position, w.a, w.b) < r.radius) {
        decide(Outcome::kCollisionWall);
        break;
      }
    }
    if (result.outcome != Outcome::kRunning) continue;
    if (distance(r.position, anchor_[k]) > options_.stuck_distance) {
      anchor_[k] = r.position;
      anchor_time_[k] = f.time;
    } else if (f.time - anchor_time_[k] >= options_.stuck_time - 1e-9) {
      decide(Outcome::kStuck);
      continue;
    }
    if (f.time >= options_.time_limit - 1e-9) decide(Outcome::kTimeout);
  }
}

std::vector<PedestrianState> Episode::people() const {
  std::vector<PedestrianState> out;
  const CrowdSimulation& sim = runner_->sim();
  for (const PedestrianState& s : runner_->states())
    if (!sim.driven(s.id) && sim.active(s.id)) out.push_back(s);
  return out;
}

}  // namespace socsim::crowd
