#include "server/simulation_sessions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "core/common/ids.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "server/frame_sources.hpp"

namespace socsim::server {

using Clock = std::chrono::steady_clock;

namespace {

// Simulated times on the wire: microseconds are plenty and keep 0.15000000000000002 readable.
double wire_time(double t) {
  return std::round(t * 1e6) / 1e6;
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
  info.world = request.world;
  auto source = runner_source(std::move(request.world), std::move(*runner), duration);
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
  info.world = std::move(request.world);
  auto source = recording_source(std::move(request.log));
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
