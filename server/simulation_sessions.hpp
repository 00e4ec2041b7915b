#pragma once
// Live simulation sessions: a scenario program stepped on its own thread in real time × speed, or
// a card's recorded trajectory log played back. Each frame is encoded once per wire format and the
// one buffer is handed to every viewer; viewers only enqueue, so a slow one never slows a session.
// Wire format: schemas/simulation_frame.schema.json and schemas/simulation_binary_frame.md.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/crowd/program.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/world/world.hpp"
#include "server/frame_codec.hpp"

namespace socsim::server {

struct SimulationLimits {
  std::size_t max_sessions = 4;    // running at once
  std::size_t max_viewers = 32;    // per session
  std::size_t max_agents = 10000;  // per session
  double min_speed = 0.1;
  double max_speed = 16.0;
  double stream_hz = 20.0;         // most frames per wall-clock second
  double idle_s = 30.0;            // a session without viewers for this long ends
  double max_duration_s = 3600.0;  // simulated seconds of a program session
  std::size_t ended_kept = 32;     // ended sessions still answering GET
};

enum class WireFormat : std::uint8_t { kJson, kBinary };

// One message to viewers. Frames (and superseded messages such as "status") may be dropped for a
// slow viewer; hello, targets and end may not.
struct WireMessage {
  std::string bytes;
  bool binary = false;
  bool frame = false;
  bool droppable = false;  // implied by frame
  bool last = false;       // "end": the viewer's connection closes after it
};
using WirePtr = std::shared_ptr<const WireMessage>;

// Runs on the session's thread (and on the attaching thread for the first messages): must only
// enqueue.
using ViewerSink = std::function<void(const WirePtr&)>;

// What a viewer's transport reports back (read by status()).
struct ViewerCounters {
  std::atomic<std::uint64_t> delivered{0};
  std::atomic<std::uint64_t> dropped{0};
};

// The JSON frame (schemas/simulation_frame.schema.json; the binary one is in frame_codec.hpp).
// `roles` and `targets` are the session's tables; targets[0] is "" (none).
std::string encode_frame_json(std::uint32_t seq, double t, std::span<const FrameAgent> agents,
                              const std::vector<std::string>& roles, const std::vector<std::string>& targets);

class SimulationSession;

// A viewer's place in a session; destroying it detaches the viewer.
class ViewerLease {
 public:
  ViewerLease(std::shared_ptr<SimulationSession> session, std::uint64_t viewer);
  ~ViewerLease();
  ViewerLease(const ViewerLease&) = delete;
  ViewerLease& operator=(const ViewerLease&) = delete;
  [[nodiscard]] SimulationSession& session() { return *session_; }

 private:
  std::shared_ptr<SimulationSession> session_;
  std::uint64_t viewer_;
};

// What a session plays (server/frame_sources.hpp): a live runner or a recorded log.
class FrameSource;
struct TargetTable;

struct SessionInfo {
  std::string kind;  // "program" | "card"
  std::string author;
  std::optional<std::string> world_id;
  std::optional<std::string> card_id;
  std::optional<std::uint64_t> seed;
  double duration_s = 0;                      // simulated seconds until the session ends by itself
  std::shared_ptr<const world::World> world;  // may be null (the Foxglove bridge draws it)
};

class SimulationSession {
 public:
  SimulationSession(std::string id, SessionInfo info, std::unique_ptr<FrameSource> source,
                    const SimulationLimits& limits, double speed);
  ~SimulationSession();  // stops and joins the thread
  SimulationSession(const SimulationSession&) = delete;
  SimulationSession& operator=(const SimulationSession&) = delete;

  [[nodiscard]] const std::string& id() const { return id_; }
  [[nodiscard]] const SessionInfo& info() const { return info_; }
  [[nodiscard]] bool ended() const;
  // {id, kind, status, end_reason, t, duration_s, speed, paused, seekable, viewers, frames_sent,
  //  frames_dropped, frame_hz, agents, ws_url, …}
  [[nodiscard]] Json status() const;
  // {action: pause|resume|speed|seek|stop, value?}: 422 with pointers for bad commands, 409 once
  // ended. Returns the new status; viewers receive a "status" message.
  Result<Json> control(const Json& command);
  // Adds a viewer: it is sent "hello" and the latest frame at once. 429 past the viewer limit.
  Result<std::unique_ptr<ViewerLease>> attach(std::shared_ptr<SimulationSession> self, WireFormat format,
                                              ViewerSink sink, std::shared_ptr<ViewerCounters> counters);
  void stop(const std::string& reason);

 private:
  friend class ViewerLease;
  friend class SimulationSessions;
  struct Viewer {
    WireFormat format;
    ViewerSink sink;
    std::shared_ptr<ViewerCounters> counters;
  };
  void start();
  void detach(std::uint64_t viewer);
  void run();
  void publish_frame();
  void finish(const std::string& reason);
  void broadcast_locked(const WirePtr& message, std::optional<WireFormat> only = std::nullopt);
  [[nodiscard]] Json status_locked() const;
  [[nodiscard]] double frame_hz_locked() const;
  void anchor_locked();
  WirePtr encoded_last_locked(WireFormat format);
  WirePtr text_locked(const Json& message) const;

  const std::string id_;
  const SessionInfo info_;
  const SimulationLimits limits_;
  std::unique_ptr<FrameSource> source_;  // touched by the session thread only (after start)

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::uint64_t, Viewer> viewers_;
  std::uint64_t next_viewer_ = 1;
  std::uint64_t viewers_total_ = 0;
  std::uint64_t dropped_by_gone_ = 0;  // drops of viewers that have left
  double speed_ = 1.0;
  bool paused_ = false;
  std::optional<double> seek_to_;
  std::optional<std::string> stop_reason_;
  std::optional<std::string> end_reason_;
  double time_ = 0.0;      // simulated time of the latest state
  double start_time_ = 0;  // first frame's time (recordings need not start at 0)
  std::size_t agents_now_ = 0;
  std::uint32_t frames_sent_ = 0;
  std::chrono::steady_clock::time_point anchor_wall_;
  double anchor_sim_ = 0.0;
  std::chrono::steady_clock::time_point idle_since_;
  std::string created_at_;
  // The latest frame, for viewers that arrive later, and its encodings so far.
  std::vector<FrameAgent> last_agents_;
  std::uint32_t last_seq_ = 0;
  double last_t_ = 0;
  bool has_last_ = false;
  WirePtr last_json_, last_binary_;
  std::vector<std::string> roles_;    // fixed when the session starts
  std::vector<std::string> targets_;  // grows; [0] = ""
  // Touched by the session thread only.
  std::unique_ptr<TargetTable> targets_table_;
  std::vector<FrameAgent> scratch_;
  std::thread thread_;
};

struct ProgramSessionRequest {
  std::shared_ptr<const world::World> world;  // may be null: positions and polygons only
  std::optional<std::string> world_id;
  crowd::Program program;
  std::uint64_t seed = 0;
  double speed = 1.0;
  std::optional<double> duration_s;  // default: the limit
  std::string author;
};

struct RecordingSessionRequest {
  scenario::TrajectoryLog log;
  std::shared_ptr<const world::World> world;  // the card's world, when it has one
  std::string card_id;
  std::optional<std::string> world_id;
  double speed = 1.0;
  std::string author;
};

// Every session of the daemon.
class SimulationSessions {
 public:
  explicit SimulationSessions(SimulationLimits limits) : limits_(limits) {}
  ~SimulationSessions() { shutdown(); }
  SimulationSessions(const SimulationSessions&) = delete;
  SimulationSessions& operator=(const SimulationSessions&) = delete;

  [[nodiscard]] const SimulationLimits& limits() const { return limits_; }
  // Builds the runner (422 with pointers into the program, 429 past the session limit) and starts.
  Result<std::shared_ptr<SimulationSession>> start_program(ProgramSessionRequest request);
  Result<std::shared_ptr<SimulationSession>> start_recording(RecordingSessionRequest request);
  // 404 for unknown ids (ended sessions are kept a while).
  Result<std::shared_ptr<SimulationSession>> find(const std::string& id);
  // Newest first.
  std::vector<std::shared_ptr<SimulationSession>> list();
  // Stops the session and forgets it.
  Status remove(const std::string& id);
  // 429 when `limits.max_sessions` are running.
  Status check_capacity();
  [[nodiscard]] std::size_t running();
  void shutdown();

 private:
  Result<std::shared_ptr<SimulationSession>> add(SessionInfo info, std::unique_ptr<FrameSource> source,
                                                 double speed);
  void forget_ended_locked();
  [[nodiscard]] Status capacity_locked() const;

  const SimulationLimits limits_;
  std::mutex mutex_;
  std::vector<std::shared_ptr<SimulationSession>> sessions_;  // oldest first
  bool closed_ = false;
};

// Speed within the limits: 422 at `pointer` otherwise.
Status check_speed(double speed, const SimulationLimits& limits, const std::string& pointer);

}  // namespace socsim::server
