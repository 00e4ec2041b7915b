#include "server/simulation_sessions.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "core/common/ids.hpp"
#include "core/crowd/scenario_runner.hpp"

namespace socsim::server {

using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------------------------------------
// Encodings

namespace {

void put_float(std::string& out, float v) {
  if (!std::isfinite(v)) v = 0.0f;  // JSON has no NaN; the engine keeps states finite anyway
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

void put_double(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0.0;
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

template <class Int>
void put_int(std::string& out, Int v) {
  char buf[24];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

const std::vector<std::string>& quoted_states() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> q;
    for (std::string_view n : crowd::activity_names()) q.push_back(Json(std::string(n)).dump());
    return q;
  }();
  return names;
}

// Simulated times on the wire: microseconds are plenty and keep 0.15000000000000002 readable.
double wire_time(double t) {
  return std::round(t * 1e6) / 1e6;
}

}  // namespace

std::string encode_frame_json(std::uint32_t seq, double t, std::span<const FrameAgent> agents,
                              const std::vector<std::string>& roles,
                              const std::vector<std::string>& targets) {
  std::vector<std::string> quoted_roles;
  quoted_roles.reserve(roles.size());
  for (const auto& r : roles)
    quoted_roles.push_back(Json(r).dump(-1, ' ', false, Json::error_handler_t::replace));
  std::vector<std::string> quoted_targets;
  quoted_targets.reserve(targets.size());
  for (const auto& s : targets)
    quoted_targets.push_back(s.empty() ? "null"
                                       : Json(s).dump(-1, ' ', false, Json::error_handler_t::replace));
  const auto& states = quoted_states();

  std::string out;
  out.reserve(64 + agents.size() * 150);
  out += R"({"type":"frame","seq":)";
  put_int(out, seq);
  out += R"(,"t":)";
  put_double(out, t);
  out += R"(,"agents":[)";
  bool first = true;
  for (const FrameAgent& a : agents) {
    if (!first) out += ',';
    first = false;
    out += R"({"id":)";
    put_int(out, a.id);
    out += R"(,"x":)";
    put_float(out, a.x);
    out += R"(,"y":)";
    put_float(out, a.y);
    out += R"(,"yaw":)";
    put_float(out, a.yaw);
    out += R"(,"vx":)";
    put_float(out, a.vx);
    out += R"(,"vy":)";
    put_float(out, a.vy);
    out += R"(,"state":)";
    out += a.state < states.size() ? states[a.state] : std::string("null");
    out += R"(,"role":)";
    out += a.role < quoted_roles.size() ? quoted_roles[a.role] : std::string("null");
    out += R"(,"group_id":)";
    put_int(out, a.group_id);
    out += R"(,"target":)";
    out += a.target < quoted_targets.size() ? quoted_targets[a.target] : std::string("null");
    out += '}';
  }
  out += "]}";
  return out;
}

// ---------------------------------------------------------------------------------------------
// What a session plays

// Names of places agents head for, numbered as they first appear (0 = none).
struct TargetTable {
  std::unordered_map<std::string, std::uint16_t> index;
  std::vector<std::string> names{""};
  bool grew = false;
  std::uint16_t of(const std::string& name) {
    if (name.empty()) return 0;
    if (auto it = index.find(name); it != index.end()) return it->second;
    if (names.size() > std::numeric_limits<std::uint16_t>::max()) return 0;
    const auto i = static_cast<std::uint16_t>(names.size());
    names.push_back(name);
    index.emplace(name, i);
    grew = true;
    return i;
  }
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  [[nodiscard]] virtual double time() const = 0;
  [[nodiscard]] virtual double interval() const = 0;  // simulated seconds per advance
  [[nodiscard]] virtual double start_time() const = 0;
  [[nodiscard]] virtual double end_time() const = 0;
  [[nodiscard]] virtual std::vector<std::string> roles() const = 0;
  [[nodiscard]] virtual bool seekable() const { return false; }
  [[nodiscard]] virtual std::size_t agent_count() const = 0;
  virtual bool advance() = 0;  // false: nothing follows
  virtual void seek(double /*t*/) {}
  virtual void snapshot(std::vector<FrameAgent>& out, TargetTable& targets) = 0;
};

namespace {

std::int32_t clamp_group(std::int64_t g) {
  return static_cast<std::int32_t>(std::clamp<std::int64_t>(g, -1, std::numeric_limits<std::int32_t>::max()));
}

class RunnerSource final : public FrameSource {
 public:
  RunnerSource(std::shared_ptr<const world::World> world, std::unique_ptr<crowd::ScenarioRunner> runner,
               double duration)
      : world_(std::move(world)), runner_(std::move(runner)), duration_(duration) {
    roles_ = runner_->sim().roles().names();
    for (std::size_t i = 0; i < roles_.size(); ++i)
      role_index_.emplace(roles_[i], static_cast<std::uint8_t>(std::min<std::size_t>(i, 255)));
  }
  [[nodiscard]] double time() const override { return runner_->time(); }
  [[nodiscard]] double interval() const override { return runner_->sim().config().dt; }
  [[nodiscard]] double start_time() const override { return 0.0; }
  [[nodiscard]] double end_time() const override { return duration_; }
  [[nodiscard]] std::vector<std::string> roles() const override { return roles_; }
  [[nodiscard]] std::size_t agent_count() const override { return runner_->agents().size(); }
  bool advance() override {
    runner_->step();
    return true;
  }
  void snapshot(std::vector<FrameAgent>& out, TargetTable& targets) override {
    const std::vector<crowd::PedestrianState> states = runner_->states();
    out.clear();
    out.reserve(states.size());
    for (const crowd::PedestrianState& s : states) {
      if (s.activity == crowd::Activity::kExited) continue;  // gone: absent from the frame
      FrameAgent a;
      a.id = s.id.value();
      a.x = static_cast<float>(s.pose.x);
      a.y = static_cast<float>(s.pose.y);
      a.yaw = static_cast<float>(s.pose.yaw);
      a.vx = static_cast<float>(s.twist.vx);
      a.vy = static_cast<float>(s.twist.vy);
      a.group_id = clamp_group(s.group_id);
      a.state = static_cast<std::uint8_t>(s.activity);
      auto r = role_index_.find(s.role);
      a.role = r == role_index_.end() ? 255 : r->second;
      a.target = targets.of(s.intent.target);
      out.push_back(a);
    }
  }

 private:
  std::shared_ptr<const world::World> world_;  // the runner refers to it
  std::unique_ptr<crowd::ScenarioRunner> runner_;
  double duration_;
  std::vector<std::string> roles_;
  std::unordered_map<std::string, std::uint8_t> role_index_;
};

class RecordingSource final : public FrameSource {
 public:
  explicit RecordingSource(scenario::TrajectoryLog log) : log_(std::move(log)) {}
  [[nodiscard]] double time() const override { return log_.frame_time(frame_); }
  [[nodiscard]] double interval() const override { return log_.frame_interval(); }
  [[nodiscard]] double start_time() const override { return log_.frame_time(0); }
  [[nodiscard]] double end_time() const override { return log_.frame_time(log_.frame_count() - 1); }
  [[nodiscard]] std::vector<std::string> roles() const override { return log_.roles(); }
  [[nodiscard]] bool seekable() const override { return true; }
  [[nodiscard]] std::size_t agent_count() const override { return log_.agent_count(); }
  bool advance() override {
    if (frame_ + 1 >= log_.frame_count()) return false;
    ++frame_;
    return true;
  }
  // The last frame at or before t.
  void seek(double t) override {
    std::size_t lo = 0, hi = log_.frame_count() - 1;
    while (lo < hi) {
      const std::size_t mid = (lo + hi + 1) / 2;
      if (log_.frame_time(mid) <= t + 1e-9)
        lo = mid;
      else
        hi = mid - 1;
    }
    frame_ = lo;
  }
  void snapshot(std::vector<FrameAgent>& out, TargetTable&) override {
    const auto agents = log_.frame(frame_);
    out.clear();
    out.reserve(agents.size());
    for (const scenario::LoggedAgent& l : agents) {
      FrameAgent a;
      a.id = l.id;
      a.x = l.x;
      a.y = l.y;
      a.yaw = l.yaw;
      a.vx = l.vx;
      a.vy = l.vy;
      a.group_id = l.group_id;
      a.state = static_cast<std::uint8_t>(l.activity);
      a.role = static_cast<std::uint8_t>(std::min<std::uint16_t>(l.role, 255));
      out.push_back(a);
    }
  }

 private:
  scenario::TrajectoryLog log_;
  std::size_t frame_ = 0;
};

std::size_t program_agent_count(const crowd::Program& p) {
  std::size_t n = p.robot ? 1 : 0;
  for (const auto& a : p.agents) n += a.count;
  for (const auto& g : p.ambient_groups) n += g.size;
  return n;
}

}  // namespace

Status check_speed(double speed, const SimulationLimits& limits, const std::string& pointer) {
  if (std::isfinite(speed) && speed >= limits.min_speed && speed <= limits.max_speed) return {};
  std::ostringstream range;
  range << "must be a speed factor between " << limits.min_speed << " and " << limits.max_speed;
  return fail(ErrorCode::kValidation, "speed out of range", {FieldError{pointer, range.str()}});
}

// ---------------------------------------------------------------------------------------------
// Viewer lease

ViewerLease::ViewerLease(std::shared_ptr<SimulationSession> session, std::uint64_t viewer)
    : session_(std::move(session)), viewer_(viewer) {}

ViewerLease::~ViewerLease() {
  session_->detach(viewer_);
}

// ---------------------------------------------------------------------------------------------
// Session

SimulationSession::SimulationSession(std::string id, SessionInfo info, std::unique_ptr<FrameSource> source,
                                     const SimulationLimits& limits, double speed)
    : id_(std::move(id)), info_(std::move(info)), limits_(limits), source_(std::move(source)), speed_(speed) {
  roles_ = source_->roles();
  targets_ = {""};
  targets_table_ = std::make_unique<TargetTable>();
  time_ = source_->time();
  start_time_ = source_->start_time();
  agents_now_ = source_->agent_count();
  idle_since_ = Clock::now();
  created_at_ = utc_now_rfc3339();
}

SimulationSession::~SimulationSession() {
  stop("shutdown");
  if (thread_.joinable()) thread_.join();
}

void SimulationSession::start() {
  thread_ = std::thread([this] {
    try {
      run();
    } catch (const std::exception& e) {
      finish(std::string("error: ") + e.what());
    }
  });
}

bool SimulationSession::ended() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return end_reason_.has_value();
}

double SimulationSession::frame_hz_locked() const {
  const double dt = source_->interval();
  const double every = std::max(1.0, std::ceil(speed_ / (limits_.stream_hz * dt) - 1e-9));
  return speed_ / (every * dt);
}

void SimulationSession::anchor_locked() {
  anchor_wall_ = Clock::now();
  anchor_sim_ = time_;
}

Json SimulationSession::status_locked() const {
  std::uint64_t dropped = dropped_by_gone_;
  for (const auto& [vid, v] : viewers_) dropped += v.counters ? v.counters->dropped.load() : 0;
  const char* state = end_reason_ ? "ended" : paused_ ? "paused" : "running";
  return Json{{"id", id_},
              {"kind", info_.kind},
              {"status", state},
              {"end_reason", end_reason_ ? Json(*end_reason_) : Json(nullptr)},
              {"t", wire_time(time_)},
              {"start_t", wire_time(start_time_)},
              {"duration_s", info_.duration_s},
              {"speed", speed_},
              {"paused", paused_},
              {"seekable", source_->seekable()},
              {"viewers", viewers_.size()},
              {"viewers_total", viewers_total_},
              {"frames_sent", frames_sent_},
              {"frames_dropped", dropped},
              {"frame_hz", frame_hz_locked()},
              {"agents", agents_now_},
              {"world_id", info_.world_id ? Json(*info_.world_id) : Json(nullptr)},
              {"card_id", info_.card_id ? Json(*info_.card_id) : Json(nullptr)},
              {"seed", info_.seed ? Json(*info_.seed) : Json(nullptr)},
              {"created_at", created_at_},
              {"ws_url", "/ws/simulations/" + id_}};
}

Json SimulationSession::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_locked();
}

WirePtr SimulationSession::text_locked(const Json& message) const {
  auto m = std::make_shared<WireMessage>();
  m->bytes = message.dump(-1, ' ', false, Json::error_handler_t::replace);
  return m;
}

void SimulationSession::broadcast_locked(const WirePtr& message, std::optional<WireFormat> only) {
  for (auto& [vid, v] : viewers_)
    if (!only || v.format == *only) v.sink(message);
}

WirePtr SimulationSession::encoded_last_locked(WireFormat format) {
  if (!has_last_) return nullptr;
  WirePtr& cached = format == WireFormat::kJson ? last_json_ : last_binary_;
  if (!cached) {
    auto m = std::make_shared<WireMessage>();
    m->frame = true;
    m->binary = format == WireFormat::kBinary;
    m->bytes = m->binary ? encode_frame_binary(last_seq_, last_t_, last_agents_)
                         : encode_frame_json(last_seq_, last_t_, last_agents_, roles_, targets_);
    cached = std::move(m);
  }
  return cached;
}

Result<std::unique_ptr<ViewerLease>> SimulationSession::attach(std::shared_ptr<SimulationSession> self,
                                                               WireFormat format, ViewerSink sink,
                                                               std::shared_ptr<ViewerCounters> counters) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (end_reason_ || stop_reason_)
    return fail(ErrorCode::kConflict,
                "simulation '" + id_ + "' has ended (" + end_reason_.value_or("stopping") + ")");
  if (viewers_.size() >= limits_.max_viewers) {
    Error e(ErrorCode::kRateLimited, "simulation '" + id_ + "' already has " +
                                         std::to_string(viewers_.size()) +
                                         " viewers, the most this server allows (--max-viewers)");
    e.retry_after_s = 5;
    return tl::unexpected(e);
  }
  Json roles = roles_;
  Json states = Json::array();
  for (std::string_view n : crowd::activity_names()) states.push_back(std::string(n));
  Json hello = {
      {"type", "hello"},
      {"session", id_},
      {"kind", info_.kind},
      {"format", format == WireFormat::kBinary ? "binary" : "json"},
      {"world_id", info_.world_id ? Json(*info_.world_id) : Json(nullptr)},
      {"card_id", info_.card_id ? Json(*info_.card_id) : Json(nullptr)},
      {"roles", roles},
      {"states", states},
      {"targets", targets_},
      {"frame_hz", frame_hz_locked()},
      {"speed", speed_},
      {"paused", paused_},
      {"seekable", source_->seekable()},
      {"t", wire_time(time_)},
      {"start_t", wire_time(start_time_)},
      {"duration_s", info_.duration_s},
      {"binary_layout",
       {{"magic", "SSF1"}, {"header_bytes", kBinaryHeaderBytes}, {"agent_bytes", kBinaryAgentBytes}}}};
  sink(text_locked(hello));
  if (WirePtr last = encoded_last_locked(format)) sink(last);
  const std::uint64_t vid = next_viewer_++;
  viewers_.emplace(vid, Viewer{format, std::move(sink), std::move(counters)});
  ++viewers_total_;
  wake_.notify_all();
  return std::make_unique<ViewerLease>(std::move(self), vid);
}

void SimulationSession::detach(std::uint64_t viewer) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = viewers_.find(viewer);
  if (it == viewers_.end()) return;
  if (it->second.counters) dropped_by_gone_ += it->second.counters->dropped.load();
  viewers_.erase(it);
  if (viewers_.empty()) idle_since_ = Clock::now();
  wake_.notify_all();
}

Result<Json> SimulationSession::control(const Json& command) {
  if (!command.is_object())
    return fail(ErrorCode::kValidation, "a control command is an object {action, value?}",
                {FieldError{"", "must be an object"}});
  std::vector<FieldError> errors;
  for (const auto& [key, v] : command.items())
    if (key != "action" && key != "value")
      errors.push_back({"/" + json_pointer_token(key), "unknown field (expected action, value)"});
  static const std::vector<std::string> kActions = {"pause", "resume", "speed", "seek", "stop"};
  std::string action;
  if (!command.contains("action") || !command["action"].is_string() ||
      std::find(kActions.begin(), kActions.end(), command["action"].get<std::string>()) == kActions.end())
    errors.push_back({"/action", "must be one of pause, resume, speed, seek, stop"});
  else
    action = command["action"].get<std::string>();
  std::optional<double> value;
  if (command.contains("value")) {
    if (command["value"].is_number())
      value = command["value"].get<double>();
    else
      errors.push_back({"/value", "must be a number"});
  }
  if ((action == "speed" || action == "seek") && !value && errors.empty())
    errors.push_back(
        {"/value", action == "speed" ? "the new speed factor is needed" : "the time to seek to is needed"});
  if (!errors.empty()) return fail(ErrorCode::kValidation, "bad control command", std::move(errors));

  std::unique_lock<std::mutex> lock(mutex_);
  if (end_reason_ || stop_reason_)
    return fail(ErrorCode::kConflict,
                "simulation '" + id_ + "' has ended (" + end_reason_.value_or("stopping") + ")");
  if (action == "pause") {
    paused_ = true;
  } else if (action == "resume") {
    if (paused_) anchor_locked();
    paused_ = false;
  } else if (action == "speed") {
    if (auto s = check_speed(*value, limits_, "/value"); !s) return tl::unexpected(s.error());
    speed_ = *value;
    anchor_locked();
  } else if (action == "seek") {
    if (!source_->seekable())
      return fail(
          ErrorCode::kValidation, "seek works only in recorded (card) sessions",
          {FieldError{"/action", "this session runs a program live; only a card's recording can seek"}});
    const double end = info_.duration_s + start_time_;
    if (!std::isfinite(*value) || *value < start_time_ || *value > end) {
      std::ostringstream why;
      why << "must be a time between " << start_time_ << " and " << end << " s";
      return fail(ErrorCode::kValidation, "seek time out of range", {FieldError{"/value", why.str()}});
    }
    seek_to_ = *value;
  } else if (action == "stop") {
    lock.unlock();
    stop("stopped");
    return status();
  }
  wake_.notify_all();
  Json st = status_locked();
  Json message = {{"type", "status"}};
  for (const char* k : {"status", "t", "speed", "paused", "frame_hz"}) message[k] = st[k];
  // A viewer that does not read keeps only the latest statuses (commands cannot grow its queue).
  auto status_message = std::make_shared<WireMessage>();
  status_message->bytes = message.dump(-1, ' ', false, Json::error_handler_t::replace);
  status_message->droppable = true;
  broadcast_locked(status_message);
  return st;
}

void SimulationSession::stop(const std::string& reason) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (end_reason_) return;
  if (!stop_reason_) stop_reason_ = reason;
  wake_.notify_all();
  if (!thread_.joinable() || thread_.get_id() == std::this_thread::get_id()) return;
  wake_.wait(lock, [this] { return end_reason_.has_value(); });
}

void SimulationSession::finish(const std::string& reason) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (end_reason_) return;
  end_reason_ = reason;
  paused_ = false;
  auto end = std::make_shared<WireMessage>();
  end->bytes =
      Json{{"type", "end"}, {"reason", reason}, {"t", wire_time(time_)}, {"frames_sent", frames_sent_}}.dump(
          -1, ' ', false, Json::error_handler_t::replace);
  end->last = true;
  broadcast_locked(end);
  wake_.notify_all();
}

void SimulationSession::publish_frame() {
  // The source, the scratch frame and the target table are touched by this thread only.
  std::vector<FrameAgent>& agents = scratch_;
  source_->snapshot(agents, *targets_table_);
  const double t = wire_time(source_->time());
  std::unique_lock<std::mutex> lock(mutex_);
  if (targets_table_->grew) {
    targets_table_->grew = false;
    targets_ = targets_table_->names;
    broadcast_locked(text_locked({{"type", "targets"}, {"targets", targets_}}));
  }
  bool want_json = false, want_binary = false;
  for (const auto& [vid, v] : viewers_) (v.format == WireFormat::kJson ? want_json : want_binary) = true;
  const std::uint32_t seq = frames_sent_ + 1;
  const std::vector<std::string> targets = targets_;
  lock.unlock();

  WirePtr json, binary;
  if (want_json) {
    auto m = std::make_shared<WireMessage>();
    m->frame = true;
    m->bytes = encode_frame_json(seq, t, agents, roles_, targets);
    json = std::move(m);
  }
  if (want_binary) {
    auto m = std::make_shared<WireMessage>();
    m->frame = true;
    m->binary = true;
    m->bytes = encode_frame_binary(seq, t, agents);
    binary = std::move(m);
  }

  lock.lock();
  // A seek arrived while this frame was made: the frame after the seek is the next one viewers see.
  if (seek_to_) return;
  frames_sent_ = seq;
  last_seq_ = seq;
  last_t_ = t;
  agents_now_ = agents.size();
  has_last_ = true;
  last_agents_.swap(agents);
  last_json_ = json;
  last_binary_ = binary;
  for (auto& [vid, v] : viewers_) {
    const WirePtr& m = v.format == WireFormat::kJson ? json : binary;
    if (m) v.sink(m);
  }
}

void SimulationSession::run() {
  publish_frame();  // the initial state
  std::unique_lock<std::mutex> lock(mutex_);
  anchor_locked();
  const double end_time = start_time_ + info_.duration_s;
  const auto idle =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.idle_s));
  std::size_t since_emit = 0;
  std::string reason;
  for (;;) {
    if (stop_reason_) {
      reason = *stop_reason_;
      break;
    }
    const auto now = Clock::now();
    if (viewers_.empty() && now - idle_since_ >= idle) {
      reason = "idle";
      break;
    }
    const auto idle_deadline = viewers_.empty() ? idle_since_ + idle : now + std::chrono::hours(1);
    if (seek_to_) {
      const double to = *seek_to_;
      seek_to_.reset();
      lock.unlock();
      source_->seek(to);
      const double t = source_->time();
      publish_frame();  // takes the lock itself
      lock.lock();
      time_ = t;
      since_emit = 0;
      anchor_locked();
      continue;
    }
    if (paused_) {
      wake_.wait_until(lock, idle_deadline);
      continue;
    }
    if (time_ >= end_time - 1e-9) {
      reason = "completed";
      break;
    }
    const double dt = source_->interval();
    const auto due = anchor_wall_ + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>((time_ + dt - anchor_sim_) / speed_));
    if (now < due) {
      wake_.wait_until(lock, std::min(due, idle_deadline));
      continue;
    }
    // Behind by more than a quarter second (a step costs more than real time × speed allows):
    // carry on from now rather than rushing to catch up.
    if (now - due > std::chrono::milliseconds(250)) {
      anchor_wall_ = now;
      anchor_sim_ = time_;
    }
    const auto every =
        static_cast<std::size_t>(std::max(1.0, std::ceil(speed_ / (limits_.stream_hz * dt) - 1e-9)));
    lock.unlock();
    const bool more = source_->advance();
    const double t = source_->time();
    const bool last = !more || t >= end_time - 1e-9;
    lock.lock();
    time_ = t;
    lock.unlock();
    if (++since_emit >= every || last) {
      publish_frame();
      since_emit = 0;
    }
    lock.lock();
    if (!more) {
      reason = "completed";
      break;
    }
  }
  lock.unlock();
  finish(reason);
}

// ---------------------------------------------------------------------------------------------
// All sessions

Status SimulationSessions::check_capacity() {
  std::lock_guard<std::mutex> lock(mutex_);
  return capacity_locked();
}

Status SimulationSessions::capacity_locked() const {
  if (closed_) return fail(ErrorCode::kInternal, "the server is shutting down");
  std::size_t live = 0;
  for (const auto& s : sessions_) live += s->ended() ? 0 : 1;
  if (live < limits_.max_sessions) return {};
  Error e(ErrorCode::kRateLimited,
          std::to_string(live) +
              " simulations are running, the most this server allows (--max-simulations); "
              "stop one or retry later");
  e.retry_after_s = 10;
  return tl::unexpected(e);
}

std::size_t SimulationSessions::running() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::size_t live = 0;
  for (const auto& s : sessions_) live += s->ended() ? 0 : 1;
  return live;
}

void SimulationSessions::forget_ended_locked() {
  std::size_t ended = 0;
  for (const auto& s : sessions_) ended += s->ended() ? 1 : 0;
  for (auto it = sessions_.begin(); it != sessions_.end() && ended > limits_.ended_kept;) {
    if ((*it)->ended()) {
      it = sessions_.erase(it);
      --ended;
    } else {
      ++it;
    }
  }
}

Result<std::shared_ptr<SimulationSession>> SimulationSessions::add(SessionInfo info,
                                                                   std::unique_ptr<FrameSource> source,
                                                                   double speed) {
  std::lock_guard<std::mutex> lock(mutex_);  // the check and the insertion at once
  if (auto s = capacity_locked(); !s) return tl::unexpected(s.error());
  auto session = std::make_shared<SimulationSession>(random_id("sim_"), std::move(info), std::move(source),
                                                     limits_, speed);
  forget_ended_locked();
  sessions_.push_back(session);
  session->start();
  return session;
}

Result<std::shared_ptr<SimulationSession>> SimulationSessions::start_program(ProgramSessionRequest request) {
  if (auto s = check_capacity(); !s) return tl::unexpected(s.error());
  if (auto s = check_speed(request.speed, limits_, "/speed"); !s) return tl::unexpected(s.error());
  const double duration = request.duration_s.value_or(limits_.max_duration_s);
  if (!std::isfinite(duration) || duration <= 0 || duration > limits_.max_duration_s)
    return fail(ErrorCode::kValidation, "duration out of range",
                {FieldError{"/duration_s", "must be more than 0 and at most " +
                                               std::to_string(limits_.max_duration_s) + " s"}});
  const std::size_t agents = program_agent_count(request.program);
  if (agents > limits_.max_agents)
    return fail(
        ErrorCode::kValidation, "too many agents for a live simulation",
        {FieldError{"/program", "has " + std::to_string(agents) + " agents; this server simulates at most " +
                                    std::to_string(limits_.max_agents) + " live (--max-sim-agents)"}});
  crowd::RunnerOptions options;
  options.seed = request.seed;
  options.threads = 1;
  options.record_metrics = false;
  auto runner = crowd::ScenarioRunner::create(request.world.get(), request.program, options);
  if (!runner) return tl::unexpected(Error(runner.error()).under("/program"));
  SessionInfo info;
  info.kind = "program";
  info.author = request.author;
  info.world_id = request.world_id;
  info.seed = request.seed;
  info.duration_s = duration;
  auto source = std::make_unique<RunnerSource>(std::move(request.world), std::move(*runner), duration);
  return add(std::move(info), std::move(source), request.speed);
}

Result<std::shared_ptr<SimulationSession>> SimulationSessions::start_recording(
    RecordingSessionRequest request) {
  if (auto s = check_speed(request.speed, limits_, "/speed"); !s) return tl::unexpected(s.error());
  if (request.log.frame_count() == 0)
    return fail(ErrorCode::kValidation, "the card's trajectory log has no frames",
                {FieldError{"/card_id", "its recording is empty"}});
  if (request.log.agent_count() > limits_.max_agents)
    return fail(ErrorCode::kValidation, "too many agents for a live simulation",
                {FieldError{"/card_id", "the recording has " + std::to_string(request.log.agent_count()) +
                                            " agents; this server streams at most " +
                                            std::to_string(limits_.max_agents) + " (--max-sim-agents)"}});
  if (request.log.roles().size() > 255)
    return fail(ErrorCode::kValidation, "the recording names more roles than the wire format carries",
                {FieldError{"/card_id", "more than 255 roles"}});
  SessionInfo info;
  info.kind = "card";
  info.author = request.author;
  info.card_id = request.card_id;
  info.world_id = request.world_id;
  auto source = std::make_unique<RecordingSource>(std::move(request.log));
  info.duration_s = source->end_time() - source->start_time();
  return add(std::move(info), std::move(source), request.speed);
}

Result<std::shared_ptr<SimulationSession>> SimulationSessions::find(const std::string& id) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& s : sessions_)
    if (s->id() == id) return s;
  return fail(ErrorCode::kNotFound, "no simulation with id '" + id + "'");
}

std::vector<std::shared_ptr<SimulationSession>> SimulationSessions::list() {
  std::lock_guard<std::mutex> lock(mutex_);
  forget_ended_locked();
  return {sessions_.rbegin(), sessions_.rend()};
}

Status SimulationSessions::remove(const std::string& id) {
  std::shared_ptr<SimulationSession> session;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = std::find_if(sessions_.begin(), sessions_.end(), [&](const auto& s) { return s->id() == id; });
    if (it == sessions_.end()) return fail(ErrorCode::kNotFound, "no simulation with id '" + id + "'");
    session = *it;
    sessions_.erase(it);
  }
  session->stop("deleted");
  return {};
}

void SimulationSessions::shutdown() {
  std::vector<std::shared_ptr<SimulationSession>> all;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    all = sessions_;
  }
  for (const auto& s : all) s->stop("shutdown");
  for (const auto& s : all)
    if (s->thread_.joinable()) s->thread_.join();
}

}  // namespace socsim::server
