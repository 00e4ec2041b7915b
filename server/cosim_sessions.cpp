#include "server/cosim_sessions.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "core/common/ids.hpp"
#include "core/crowd/episode_metrics.hpp"
#include "core/world/world_document.hpp"

namespace socsim::server {
namespace {

using crowd::Outcome;
using crowd::RobotInput;

// Strict reading of one object: unknown keys and wrong types become field errors.
class Reader {
 public:
  Reader(const Json& j, std::string pointer, std::vector<FieldError>& errors)
      : j_(j), pointer_(std::move(pointer)), errors_(errors) {
    if (!j_.is_object()) errors_.push_back({pointer_, "must be an object"});
  }
  [[nodiscard]] bool ok() const { return j_.is_object(); }
  void only(std::initializer_list<std::string_view> keys) {
    if (!ok()) return;
    for (const auto& [key, v] : j_.items())
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        std::string known;
        for (std::string_view k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
        errors_.push_back({at(key), "unknown field (expected " + known + ")"});
      }
  }
  [[nodiscard]] bool has(const char* key) const { return ok() && j_.contains(key) && !j_[key].is_null(); }
  std::optional<double> number(const char* key, bool required = false) {
    if (!has(key)) {
      if (required) errors_.push_back({at(key), "is required"});
      return std::nullopt;
    }
    const Json& v = j_[key];
    if (!v.is_number() || !std::isfinite(v.get<double>())) {
      errors_.push_back({at(key), "must be a finite number"});
      return std::nullopt;
    }
    return v.get<double>();
  }
  [[nodiscard]] std::string at(std::string_view key) const {
    return pointer_ + "/" + json_pointer_token(key);
  }
  [[nodiscard]] const Json& operator[](const char* key) const { return j_[key]; }

 private:
  const Json& j_;
  std::string pointer_;
  std::vector<FieldError>& errors_;
};

std::optional<crowd::Pose2> read_pose(const Json& j, const std::string& pointer,
                                      std::vector<FieldError>& errors, bool yaw_required) {
  Reader r(j, pointer, errors);
  r.only({"x", "y", "yaw"});
  const auto x = r.number("x", true);
  const auto y = r.number("y", true);
  const auto yaw = r.number("yaw", yaw_required);
  if (!x || !y || (yaw_required && !yaw)) return std::nullopt;
  return crowd::Pose2{*x, *y, yaw.value_or(0.0)};
}

std::optional<crowd::RobotSpec> read_robot(const Json& j, const std::string& pointer, std::size_t k,
                                           std::vector<FieldError>& errors) {
  const std::size_t before = errors.size();
  Reader r(j, pointer, errors);
  if (!r.ok()) return std::nullopt;
  r.only({"name", "start", "goal", "radius", "visible", "limits"});
  crowd::RobotSpec spec;
  spec.name = "robot_" + std::to_string(k);
  if (r.has("name")) {
    if (!r["name"].is_string() || r["name"].get<std::string>().empty() ||
        r["name"].get<std::string>().size() > 64)
      errors.push_back({r.at("name"), "must be a string of 1 to 64 characters"});
    else
      spec.name = r["name"].get<std::string>();
  }
  if (!r.has("start"))
    errors.push_back({r.at("start"), "is required ({x, y, yaw})"});
  else if (auto p = read_pose(r["start"], r.at("start"), errors, false))
    spec.start = *p;
  if (r.has("goal")) {
    Reader g(r["goal"], r.at("goal"), errors);
    g.only({"x", "y", "radius"});
    const auto x = g.number("x", true);
    const auto y = g.number("y", true);
    const auto radius = g.number("radius");
    if (radius && !(*radius > 0.0 && *radius <= 100.0))
      errors.push_back({g.at("radius"), "must be in (0, 100] m"});
    if (x && y) spec.goal = crowd::Goal{{*x, *y}, radius.value_or(0.0)};  // 0: the episode's success radius
  }
  if (const auto radius = r.number("radius")) {
    if (!(*radius >= 0.05 && *radius <= 1.5))
      errors.push_back({r.at("radius"), "must be in [0.05, 1.5] m"});
    else
      spec.radius = *radius;
  }
  if (r.has("visible")) {
    if (!r["visible"].is_boolean())
      errors.push_back({r.at("visible"), "must be true (people avoid the robot) or false (invisible)"});
    else
      spec.presence = r["visible"].get<bool>() ? crowd::Presence::kVisible : crowd::Presence::kInvisible;
  }
  if (r.has("limits")) {
    Reader l(r["limits"], r.at("limits"), errors);
    l.only({"max_speed", "max_acceleration", "max_turn_rate"});
    if (auto v = l.number("max_speed")) spec.limits.max_speed = *v;
    if (auto v = l.number("max_acceleration")) spec.limits.max_acceleration = *v;
    if (auto v = l.number("max_turn_rate")) spec.limits.max_turn_rate = *v;
    if (auto ok = crowd::validate(spec.limits, r.at("limits")); !ok)
      for (const FieldError& f : ok.error().errors) errors.push_back(f);
  }
  if (errors.size() != before) return std::nullopt;
  return spec;
}

Json pose_json(const crowd::Pose2& p) {
  return Json{{"x", p.x}, {"y", p.y}, {"yaw", p.yaw}};
}

Json robot_json(const crowd::RobotSpec& r) {
  Json goal = nullptr;
  if (r.goal) goal = Json{{"x", r.goal->position.x}, {"y", r.goal->position.y}, {"radius", r.goal->radius}};
  return Json{{"name", r.name},
              {"start", pose_json(r.start)},
              {"goal", goal},
              {"radius", r.radius},
              {"visible", r.presence == crowd::Presence::kVisible},
              {"limits",
               {{"max_speed", r.limits.max_speed},
                {"max_acceleration", r.limits.max_acceleration},
                {"max_turn_rate", r.limits.max_turn_rate}}}};
}

std::string dump(const Json& j) {
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// One robot's entry of a "step" message: {"cmd": {v, omega}} or {"pose": {x, y, yaw}, "twist": {vx, vy,
// omega}}.
std::optional<RobotInput> read_input(const Json& j, const std::string& pointer,
                                     std::vector<FieldError>& errors) {
  const std::size_t before = errors.size();
  Reader r(j, pointer, errors);
  if (!r.ok()) return std::nullopt;
  r.only({"cmd", "pose", "twist"});
  RobotInput in;
  if (r.has("cmd") == r.has("pose")) {
    errors.push_back({pointer, "give either 'cmd' {v, omega} or 'pose' {x, y, yaw} with 'twist'"});
    return std::nullopt;
  }
  if (r.has("cmd")) {
    if (r.has("twist")) errors.push_back({r.at("twist"), "goes with 'pose', not with 'cmd'"});
    Reader c(r["cmd"], r.at("cmd"), errors);
    c.only({"v", "omega"});
    const auto v = c.number("v", true);
    const auto omega = c.number("omega", true);
    in.kind = RobotInput::Kind::kCommand;
    in.command = {v.value_or(0.0), omega.value_or(0.0)};
  } else {
    in.kind = RobotInput::Kind::kState;
    if (auto p = read_pose(r["pose"], r.at("pose"), errors, true)) in.pose = *p;
    if (!r.has("twist")) {
      errors.push_back({r.at("twist"), "is required with 'pose'"});
    } else {
      Reader t(r["twist"], r.at("twist"), errors);
      t.only({"vx", "vy", "omega"});
      in.twist = {t.number("vx", true).value_or(0.0), t.number("vy", true).value_or(0.0),
                  t.number("omega", true).value_or(0.0)};
    }
  }
  if (errors.size() != before) return std::nullopt;
  return in;
}

}  // namespace

Result<CosimSettings> cosim_settings_from_json(const Json& body, const CosimLimits& limits) {
  std::vector<FieldError> errors;
  CosimSettings s;
  if (!body.is_object())
    return fail(ErrorCode::kValidation, "the body must be a JSON object", {{"", "must be an object"}});
  Reader r(body, "", errors);
  if (r.has("seed")) {
    if (!body["seed"].is_number_unsigned())
      errors.push_back({"/seed", "must be a whole number ≥ 0"});
    else
      s.seed = body["seed"].get<std::uint64_t>();
  }
  if (r.has("mode")) {
    const Json& m = body["mode"];
    if (m == "lockstep")
      s.mode = CosimMode::kLockStep;
    else if (m == "realtime")
      s.mode = CosimMode::kRealTime;
    else
      errors.push_back({"/mode", "must be 'lockstep' or 'realtime'"});
  }
  if (auto hz = r.number("rate_hz")) {
    if (!(*hz >= 1.0 && *hz <= limits.max_rate_hz))
      errors.push_back({"/rate_hz", "must be in [1, " + Json(limits.max_rate_hz).dump() + "] Hz"});
    else
      s.rate_hz = *hz;
  }
  if (auto v = r.number("time_limit")) s.episode.time_limit = *v;
  if (auto v = r.number("success_radius")) s.episode.success_radius = *v;
  if (auto v = r.number("stuck_time")) s.episode.stuck_time = *v;
  s.episode.max_robots = limits.max_robots;
  if (auto ok = crowd::validate(s.episode); !ok)
    for (const FieldError& f : ok.error().errors) errors.push_back(f);
  if (r.has("robot") && r.has("robots")) errors.push_back({"/robot", "give 'robot' or 'robots', not both"});
  if (r.has("robot")) {
    if (auto spec = read_robot(body["robot"], "/robot", 0, errors)) s.robots.push_back(*spec);
  } else if (r.has("robots")) {
    const Json& list = body["robots"];
    if (!list.is_array() || list.empty()) {
      errors.push_back({"/robots", "must be a non-empty array of robots"});
    } else if (list.size() > limits.max_robots) {
      errors.push_back({"/robots", "too many robots: " + std::to_string(list.size()) + " (at most " +
                                       std::to_string(limits.max_robots) + " per session)"});
    } else {
      for (std::size_t k = 0; k < list.size(); ++k)
        if (auto spec = read_robot(list[k], "/robots/" + std::to_string(k), k, errors))
          s.robots.push_back(*spec);
    }
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "bad co-simulation request", std::move(errors));
  return s;
}

CosimSession::CosimSession(std::string id, CosimRequest request, std::unique_ptr<crowd::Episode> episode,
                           const CosimLimits& limits)
    : id_(std::move(id)),
      author_(std::move(request.author)),
      card_id_(std::move(request.card_id)),
      settings_(std::move(request.settings)),
      limits_(limits),
      world_(std::move(request.world)),
      episode_(std::move(episode)) {
  held_.resize(episode_->robots().size());
}

bool CosimSession::ended() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return end_reason_.has_value();
}

Json CosimSession::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  Json robots = Json::array();
  for (std::size_t k = 0; k < episode_->robots().size(); ++k) {
    Json r = robot_json(episode_->robots()[k]);
    r["outcome"] = std::string(crowd::outcome_name(episode_->results()[k].outcome));
    robots.push_back(std::move(r));
  }
  Json j{{"id", id_},
         {"mode", settings_.mode == CosimMode::kLockStep ? "lockstep" : "realtime"},
         {"status", end_reason_ ? "ended" : (claimed_ ? "running" : "waiting")},
         {"end_reason", end_reason_ ? Json(*end_reason_) : Json(nullptr)},
         {"step", episode_->steps()},
         {"t", episode_->time()},
         {"dt", episode_->log().dt},
         {"seed", settings_.seed},
         {"time_limit", settings_.episode.time_limit},
         {"card_id", card_id_ ? Json(*card_id_) : Json(nullptr)},
         {"robots", std::move(robots)},
         {"ws_url", "/ws/cosim/" + id_},
         {"subprotocol", std::string(kCosimProtocol)},
         {"idle_s", limits_.idle_s},
         {"late_ticks", late_ticks_}};
  if (settings_.mode == CosimMode::kRealTime) j["rate_hz"] = settings_.rate_hz;
  if (!report_.is_null()) j["report"] = report_;
  return j;
}

bool CosimSession::expire_if_unclaimed(std::chrono::steady_clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (claimed_ || end_reason_) return false;
  if (std::chrono::duration<double>(now - created_).count() < limits_.idle_s) return false;
  end_reason_ = "no_client";
  ended_cv_.notify_all();
  return true;
}

Status CosimSession::claim(CosimEncoding encoding) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (end_reason_)
    return fail(ErrorCode::kConflict, "co-simulation '" + id_ + "' has ended (" + *end_reason_ + ")");
  if (claimed_) return fail(ErrorCode::kConflict, "co-simulation '" + id_ + "' already has its client");
  claimed_ = true;
  encoding_ = encoding;
  if (encoding_ == CosimEncoding::kBinary) {
    const crowd::CrowdSimulation& sim = episode_->runner().sim();
    for (const crowd::PedestrianState& p : episode_->runner().states())
      if (!sim.driven(p.id)) roles_.push_back(p.role);
    std::sort(roles_.begin(), roles_.end());
    roles_.erase(std::unique(roles_.begin(), roles_.end()), roles_.end());
    if (roles_.size() > 255) roles_.resize(255);
  }
  return {};
}

void CosimSession::push_observation_locked(CosimReply& out) const {
  if (encoding_ == CosimEncoding::kJson) return out.messages.push_back(observation_locked());
  out.binary.resize(out.messages.size(), false);
  out.messages.push_back(binary_observation_locked());
  out.binary.push_back(true);
}

// docs/cosim.md, "Binary observations": little-endian; a 32-byte header, 28 bytes per robot,
// 32 per person; positions and velocities as float32.
std::string CosimSession::binary_observation_locked() const {
  static_assert(std::endian::native == std::endian::little, "the binary observation is written as in memory");
  crowd::Episode& e = *episode_;  // runner() is not const; nothing here changes it
  const crowd::CrowdSimulation& sim = e.runner().sim();
  const std::vector<crowd::PedestrianState> states = e.runner().states();
  std::uint32_t people = 0;
  for (const crowd::PedestrianState& p : states) people += !sim.driven(p.id) && sim.active(p.id) ? 1 : 0;
  const std::size_t robots = e.robots().size();
  std::string out(
      kCosimBinaryHeaderBytes + robots * kCosimBinaryRobotBytes + people * kCosimBinaryPersonBytes, '\0');
  char* at = out.data();
  const auto put = [&at](const auto& v) {
    std::memcpy(at, &v, sizeof v);
    at += sizeof v;
  };
  std::memcpy(at, "SCB1", 4);
  at += 4;
  put(static_cast<std::uint8_t>(e.ended() ? 1 : 0));
  put(static_cast<std::uint8_t>(robots));
  put(std::uint16_t{0});
  put(static_cast<std::uint64_t>(e.steps()));
  put(e.time());
  put(people);
  put(std::uint32_t{0});
  for (std::size_t k = 0; k < robots; ++k) {
    const crowd::UnicycleState s = e.robot_state(k);
    const crowd::Twist2 t = crowd::twist_of(s);
    for (double v : {s.pose.x, s.pose.y, s.pose.yaw, t.vx, t.vy, t.omega}) put(static_cast<float>(v));
    put(static_cast<std::uint8_t>(e.results()[k].outcome));
    put(std::uint8_t{0});
    put(std::uint16_t{0});
  }
  for (const crowd::PedestrianState& p : states) {
    if (sim.driven(p.id) || !sim.active(p.id)) continue;
    put(static_cast<std::uint32_t>(p.id.value()));
    for (double v : {p.pose.x, p.pose.y, p.pose.yaw, p.twist.vx, p.twist.vy}) put(static_cast<float>(v));
    put(static_cast<std::int32_t>(p.group_id));
    put(static_cast<std::uint8_t>(p.activity));
    const auto role = std::lower_bound(roles_.begin(), roles_.end(), p.role);
    put(static_cast<std::uint8_t>(role != roles_.end() && *role == p.role ? role - roles_.begin() : 255));
    put(std::uint16_t{0});
  }
  return out;
}

std::string CosimSession::observation_locked() const {
  const crowd::Episode& e = *episode_;
  Json robots = Json::array();
  for (std::size_t k = 0; k < e.robots().size(); ++k) {
    const crowd::RobotSpec& spec = e.robots()[k];
    const crowd::UnicycleState s = e.robot_state(k);
    const crowd::Twist2 t = crowd::twist_of(s);
    Json goal = nullptr;
    if (spec.goal)
      goal = Json{{"x", spec.goal->position.x}, {"y", spec.goal->position.y}, {"radius", spec.goal->radius}};
    robots.push_back(Json{{"name", spec.name},
                          {"pose", pose_json(s.pose)},
                          {"twist", {{"vx", t.vx}, {"vy", t.vy}, {"omega", t.omega}}},
                          {"goal", goal},
                          {"outcome", std::string(crowd::outcome_name(e.results()[k].outcome))}});
  }
  Json people = Json::array();
  for (const crowd::PedestrianState& p : e.people()) people.push_back(crowd::to_json(p));
  return dump(Json{{"type", "observation"},
                   {"step", e.steps()},
                   {"t", e.time()},
                   {"status", e.ended() ? "ended" : "running"},
                   {"robots", std::move(robots)},
                   {"people", std::move(people)}});
}

CosimReply CosimSession::hello() {
  std::lock_guard<std::mutex> lock(mutex_);
  Json robots = Json::array();
  for (const crowd::RobotSpec& r : episode_->robots()) robots.push_back(robot_json(r));
  CosimReply out;
  out.messages.push_back(dump(Json{{"type", "hello"},
                                   {"protocol", std::string(kCosimProtocol)},
                                   {"session", id_},
                                   {"mode", settings_.mode == CosimMode::kLockStep ? "lockstep" : "realtime"},
                                   {"dt", episode_->log().dt},
                                   {"time_limit", settings_.episode.time_limit},
                                   {"idle_s", limits_.idle_s},
                                   {"encoding", encoding_ == CosimEncoding::kBinary ? "binary" : "json"},
                                   {"roles", roles_},
                                   {"robots", std::move(robots)}}));
  push_observation_locked(out);
  return out;
}

CosimReply CosimSession::fail_locked(const Error& error, const std::string& code) {
  Json problem = error.to_problem("/ws/cosim/" + id_);
  problem["type"] = "error";
  problem["code"] = code;
  CosimReply out;
  out.messages.push_back(dump(problem));
  out.close = true;
  out.protocol_error = true;
  if (!end_reason_) end_reason_ = code;
  ended_cv_.notify_all();
  return out;
}

CosimReply CosimSession::end_locked(const std::string& reason) {
  CosimReply out;
  if (!end_reason_) end_reason_ = reason;
  ended_cv_.notify_all();
  const crowd::EpisodeMetrics m = crowd::evaluate_episode(episode_->log());
  report_ = Json{{"seed", settings_.seed}, {"steps", episode_->steps()}, {"metrics", crowd::to_json(m)}};
  Json message{{"type", "report"}, {"end_reason", *end_reason_}, {"late_ticks", late_ticks_}};
  message.update(report_);
  out.messages.push_back(dump(message));
  out.close = true;
  return out;
}

CosimReply CosimSession::step_locked(const std::vector<RobotInput>& inputs) {
  if (auto ok = episode_->step(inputs); !ok) return fail_locked(ok.error(), "protocol_error");
  CosimReply out;
  push_observation_locked(out);
  if (episode_->ended()) {
    CosimReply end = end_locked("episode_ended");
    out.messages.insert(out.messages.end(), end.messages.begin(), end.messages.end());
    out.close = true;
  }
  return out;
}

CosimReply CosimSession::handle(std::string_view text) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (end_reason_) return CosimReply{{}, true, false, false, {}};
  auto parsed = parse_json_untrusted(text);
  if (!parsed) return fail_locked(parsed.error(), "protocol_error");
  const Json& m = *parsed;
  std::vector<FieldError> errors;
  Reader r(m, "", errors);
  if (!r.ok())
    return fail_locked(Error(ErrorCode::kBadRequest, "a message is a JSON object", errors), "protocol_error");
  const Json type = m.value("type", Json(nullptr));
  if (type == "stop") {
    r.only({"type"});
    if (!errors.empty())
      return fail_locked(Error(ErrorCode::kValidation, "bad stop message", errors), "protocol_error");
    return end_locked("stopped_by_client");
  }
  if (type != "step")
    return fail_locked(Error(ErrorCode::kValidation, "unknown message type (expected 'step' or 'stop')",
                             {{"/type", "must be 'step' or 'stop'"}}),
                       "protocol_error");
  r.only({"type", "step", "robots"});
  // Lock-step: the number of the step to take; real time: the client's own message count.
  const std::uint64_t expected =
      (settings_.mode == CosimMode::kRealTime ? client_messages_ : episode_->steps()) + 1;
  if (!m.contains("step") || !m["step"].is_number_unsigned()) {
    errors.push_back({"/step", "is required: the number of the step to take, " + std::to_string(expected)});
  } else if (m["step"].get<std::uint64_t>() != expected) {
    return fail_locked(Error(ErrorCode::kConflict,
                             "out-of-order step: expected " + std::to_string(expected) + ", got " +
                                 std::to_string(m["step"].get<std::uint64_t>()),
                             {{"/step", "must be " + std::to_string(expected)}}),
                       "out_of_order");
  }
  std::vector<RobotInput> inputs;
  const std::size_t n = episode_->robots().size();
  if (!m.contains("robots") || !m["robots"].is_array()) {
    errors.push_back({"/robots", "is required: one entry per robot"});
  } else if (m["robots"].size() != n) {
    errors.push_back({"/robots", (m["robots"].size() > n ? "too many robots: " : "too few robots: ") +
                                     std::to_string(m["robots"].size()) + " given, the session has " +
                                     std::to_string(n)});
  } else {
    for (std::size_t k = 0; k < n; ++k)
      if (auto in = read_input(m["robots"][k], "/robots/" + std::to_string(k), errors)) inputs.push_back(*in);
  }
  if (!errors.empty()) {
    Error e(ErrorCode::kValidation, errors.front().pointer + ": " + errors.front().message, errors);
    return fail_locked(e, "protocol_error");
  }
  if (settings_.mode == CosimMode::kRealTime) {
    // Held until the next tick; a pose replaces the held state at once.
    held_ = inputs;
    fresh_ = true;
    ++client_messages_;
    return {};
  }
  return step_locked(inputs);
}

CosimReply CosimSession::tick() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (end_reason_ || settings_.mode != CosimMode::kRealTime) return {};
  if (!fresh_ && episode_->steps() > 0) ++late_ticks_;
  fresh_ = false;
  // A held pose is taken once; on later ticks the robot keeps the velocity it reported.
  const std::vector<RobotInput> inputs = held_;
  for (RobotInput& in : held_)
    if (in.kind == RobotInput::Kind::kState) {
      const double v = std::cos(in.pose.yaw) * in.twist.vx + std::sin(in.pose.yaw) * in.twist.vy;
      in = RobotInput{RobotInput::Kind::kCommand, {v, in.twist.omega}, {}, {}};
    }
  CosimReply out = step_locked(inputs);
  out.droppable = !out.close;
  return out;
}

CosimReply CosimSession::expire() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (end_reason_) return {};
  return fail_locked(Error(ErrorCode::kConflict, "no message for " + std::to_string(limits_.idle_s) +
                                                     " s: the session has timed out"),
                     "idle_timeout");
}

void CosimSession::release() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!end_reason_) (void)end_locked("client_closed");
}

void CosimSession::stop(const std::string& reason) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!end_reason_) (void)end_locked(reason);
}

bool CosimSession::wait_ended(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  ended_cv_.wait_for(lock, timeout, [this] { return end_reason_.has_value(); });
  if (!end_reason_ && !claimed_ &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - created_).count() >= limits_.idle_s) {
    end_reason_ = "no_client";
    ended_cv_.notify_all();
  }
  return end_reason_.has_value();
}

std::optional<std::string> CosimSession::end_reason() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return end_reason_;
}

namespace {
double mm(double v) {
  return std::round(v * 1000.0) / 1000.0;
}
// Bodies closer than this are in contact (the metrics' collision rule, docs/metrics.md).
constexpr double kContactGap = 0.02;
bool in_contact(const crowd::LoggedBody& r, const crowd::LoggedBody& p) {
  return std::hypot(p.position.x - r.position.x, p.position.y - r.position.y) - r.radius - p.radius <
         kContactGap;
}
}  // namespace

Json CosimSession::view(std::size_t since, bool with_world) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const crowd::Episode& e = *episode_;
  const crowd::EpisodeLog& log = e.log();
  since = std::min(since, log.frames.size());
  Json robots = Json::array();
  for (std::size_t k = 0; k < e.robots().size(); ++k) {
    const crowd::RobotSpec& spec = e.robots()[k];
    const crowd::UnicycleState s = e.robot_state(k);
    Json path = Json::array(), contacts = Json::array();
    for (std::size_t f = since; f < log.frames.size(); ++f) {
      const crowd::LoggedBody& r = log.frames[f].robots[k];
      path.push_back({mm(r.position.x), mm(r.position.y)});
      for (const crowd::LoggedBody& p : log.frames[f].people) {
        if (!in_contact(r, p)) continue;
        bool before = false;  // already in contact in the previous frame: the same contact
        if (f > 0)
          for (const crowd::LoggedBody& q : log.frames[f - 1].people)
            if (q.id == p.id) before = in_contact(log.frames[f - 1].robots[k], q);
        if (!before)
          contacts.push_back({{"t", mm(log.frames[f].time)},
                              {"x", mm(0.5 * (r.position.x + p.position.x))},
                              {"y", mm(0.5 * (r.position.y + p.position.y))},
                              {"person", p.id}});
      }
    }
    Json robot = robot_json(spec);  // name, start, goal, radius, visible, limits
    robot["pose"] = {{"x", mm(s.pose.x)}, {"y", mm(s.pose.y)}, {"yaw", mm(s.pose.yaw)}};
    robot["outcome"] = std::string(crowd::outcome_name(e.results()[k].outcome));
    robot["path"] = std::move(path);
    robot["contacts"] = std::move(contacts);
    robots.push_back(std::move(robot));
  }
  Json people = Json::array();
  for (const crowd::PedestrianState& p : e.people())
    people.push_back({{"id", p.id.value()},
                      {"x", mm(p.pose.x)},
                      {"y", mm(p.pose.y)},
                      {"yaw", mm(p.pose.yaw)},
                      {"state", std::string(crowd::activity_name(p.activity))},
                      {"role", p.role},
                      {"group_id", p.group_id}});
  Json j{{"id", id_},
         {"status", end_reason_ ? "ended" : (claimed_ ? "running" : "waiting")},
         {"end_reason", end_reason_ ? Json(*end_reason_) : Json(nullptr)},
         {"step", e.steps()},
         {"t", e.time()},
         {"card_id", card_id_ ? Json(*card_id_) : Json(nullptr)},
         {"since", since},
         {"frames", log.frames.size()},
         {"robots", std::move(robots)},
         {"people", std::move(people)}};
  if (!report_.is_null()) j["report"] = report_;
  if (with_world && world_) j["world"] = world::world_to_document(*world_);
  return j;
}

crowd::EpisodeMetrics CosimSession::metrics() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return crowd::evaluate_episode(episode_->log());
}

Result<std::shared_ptr<CosimSession>> CosimSessions::create(CosimRequest request) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    purge_locked();
    const auto open =
        std::count_if(sessions_.begin(), sessions_.end(), [](const auto& s) { return !s.second->ended(); });
    if (static_cast<std::size_t>(open) >= limits_.max_sessions) {
      Error e(ErrorCode::kRateLimited, "at most " + std::to_string(limits_.max_sessions) +
                                           " co-simulations run at once; retry when one has ended");
      e.retry_after_s = 5;
      return tl::unexpected(e);
    }
  }
  crowd::RunnerOptions options;
  options.seed = request.settings.seed;
  options.record_metrics = false;
  options.robots = request.settings.robots;
  auto episode =
      crowd::Episode::create(request.world.get(), request.program, options, request.settings.episode);
  if (!episode) return tl::unexpected(episode.error());
  if ((*episode)->runner().sim().size() > limits_.max_agents + (*episode)->robots().size())
    return fail(ErrorCode::kValidation,
                "the scenario has more than " + std::to_string(limits_.max_agents) + " people",
                {{"/program", "too many people for a co-simulation"}});
  auto session =
      std::make_shared<CosimSession>(random_id("cosim_"), std::move(request), std::move(*episode), limits_);
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_[session->id()] = session;
  order_.push_back(session->id());
  return session;
}

Result<std::shared_ptr<CosimSession>> CosimSessions::find(const std::string& id) {
  std::lock_guard<std::mutex> lock(mutex_);
  purge_locked();
  auto it = sessions_.find(id);
  if (it == sessions_.end()) return fail(ErrorCode::kNotFound, "no co-simulation with id '" + id + "'");
  return it->second;
}

void CosimSessions::purge_locked() {
  const auto now = std::chrono::steady_clock::now();
  for (auto& [id, s] : sessions_) (void)s->expire_if_unclaimed(now);
  std::size_t ended = 0;
  for (const auto& [id, s] : sessions_) ended += s->ended() ? 1 : 0;
  for (auto it = order_.begin(); it != order_.end() && ended > limits_.ended_kept;) {
    auto s = sessions_.find(*it);
    if (s != sessions_.end() && s->second->ended()) {
      sessions_.erase(s);
      it = order_.erase(it);
      --ended;
    } else {
      ++it;
    }
  }
}

std::vector<std::shared_ptr<CosimSession>> CosimSessions::list() {
  std::lock_guard<std::mutex> lock(mutex_);
  purge_locked();
  std::vector<std::shared_ptr<CosimSession>> out;
  for (auto it = order_.rbegin(); it != order_.rend(); ++it)
    if (auto s = sessions_.find(*it); s != sessions_.end()) out.push_back(s->second);
  return out;
}

void CosimSessions::shutdown() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& [id, s] : sessions_) s->stop("server_stopping");
}

}  // namespace socsim::server
