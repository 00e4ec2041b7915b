#pragma once
// Co-simulation sessions (issue 19, docs/cosim.md): a robot episode (crowd::Episode) that one
// client drives over /ws/cosim/{id} with the subprotocol socsim.cosim.v1. The protocol lives here
// without transport: the WebSocket session hands each client message to handle() and sends what it
// returns. Lock-step: the crowd advances one step per client "step" message, at any speed.
// Real time: tick() advances one step per period with each robot's last command held.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/crowd/episode.hpp"
#include "core/crowd/episode_metrics.hpp"
#include "core/world/world.hpp"

namespace socsim::server {

inline constexpr std::string_view kCosimProtocol = "socsim.cosim.v1";
// The same protocol with compact binary observations (docs/cosim.md, "Binary observations"); a
// client that offers it gets it.
inline constexpr std::string_view kCosimBinaryProtocol = "socsim.cosim.v1.binary";
enum class CosimEncoding : std::uint8_t { kJson, kBinary };
inline constexpr std::size_t kCosimBinaryHeaderBytes = 32;
inline constexpr std::size_t kCosimBinaryRobotBytes = 28;
inline constexpr std::size_t kCosimBinaryPersonBytes = 32;

struct CosimLimits {
  std::size_t max_sessions = 4;    // not yet ended, at once
  std::size_t max_robots = 4;      // per session
  std::size_t max_agents = 10000;  // people per session
  double idle_s = 30.0;            // a client silent this long (or never connecting) ends the session
  double max_rate_hz = 50.0;       // real-time mode
  std::size_t ended_kept = 32;     // ended sessions still answering GET
};

enum class CosimMode : std::uint8_t { kLockStep, kRealTime };

// What POST /api/v1/cosim asks for, read and checked (cosim_request_from_json) apart from the
// card or program, which the route resolves.
struct CosimSettings {
  std::uint64_t seed = 0;
  CosimMode mode = CosimMode::kLockStep;
  double rate_hz = 20.0;                 // real time only
  std::vector<crowd::RobotSpec> robots;  // empty: the program's robot
  crowd::EpisodeOptions episode;
};
// Strict: unknown keys and bad values → kValidation with pointers. Keys of the body other than
// robot, robots, seed, mode, rate_hz, time_limit, success_radius, stuck_time are not read here.
Result<CosimSettings> cosim_settings_from_json(const Json& body, const CosimLimits& limits);

struct CosimRequest {
  std::shared_ptr<const world::World> world;  // may be null
  crowd::Program program;
  CosimSettings settings;
  std::string author;
  std::optional<std::string> card_id;
};

// What handle()/hello()/tick()/expire() give the transport to send, in order.
struct CosimReply {
  std::vector<std::string> messages;  // JSON text messages (or binary observations)
  bool close = false;                 // close the connection after sending them
  bool protocol_error = false;        // …with close code 1008 (policy violation)
  bool droppable = false;             // real-time observations: a slow client may lose old ones
  std::vector<bool> binary;           // parallel to messages when one is binary; empty: all text
};

class CosimSession {
 public:
  CosimSession(std::string id, CosimRequest request, std::unique_ptr<crowd::Episode> episode,
               const CosimLimits& limits);
  CosimSession(const CosimSession&) = delete;
  CosimSession& operator=(const CosimSession&) = delete;

  [[nodiscard]] const std::string& id() const { return id_; }
  [[nodiscard]] const std::string& author() const { return author_; }
  [[nodiscard]] CosimMode mode() const { return settings_.mode; }
  [[nodiscard]] double rate_hz() const { return settings_.rate_hz; }
  [[nodiscard]] double idle_s() const { return limits_.idle_s; }
  // {id, mode, status, end_reason, step, t, dt, robots, ws_url, subprotocol, late_ticks, report?}
  [[nodiscard]] Json status() const;
  [[nodiscard]] bool ended() const;
  // Whether a client that never connected has let the session go idle (then it ends).
  bool expire_if_unclaimed(std::chrono::steady_clock::time_point now);

  // A client connects: 409 when one is already connected or the session has ended. Its encoding
  // is that of the subprotocol it chose.
  Status claim(CosimEncoding encoding = CosimEncoding::kJson);
  // The first messages to a new client: hello and the observation of step 0.
  CosimReply hello();
  // One client message.
  CosimReply handle(std::string_view text);
  // Real time: one step with the held commands (lateness counted when none came since the last tick).
  CosimReply tick();
  // The client was silent for idle_s: an error "idle_timeout", then close.
  CosimReply expire();
  // The client went away: the session ends (reason "client_closed") unless it had ended.
  void release();
  // The server stops.
  void stop(const std::string& reason);
  // Blocks until the episode has ended or `timeout` has passed; true when it has ended. A session
  // no client has claimed within idle_s ends here ("no_client") as in expire_if_unclaimed.
  bool wait_ended(std::chrono::milliseconds timeout);
  // Why it ended (empty while it runs), and the metrics of its log as the report has them.
  [[nodiscard]] std::optional<std::string> end_reason() const;
  [[nodiscard]] crowd::EpisodeMetrics metrics() const;
  // What a viewer draws (GET /api/v1/cosim/{id}/view): status, every person now, each robot's
  // pose, goal, outcome, path since frame `since` and the contacts with people that began since
  // then; the world document when with_world. Figures rounded to the millimetre.
  [[nodiscard]] Json view(std::size_t since, bool with_world) const;
  [[nodiscard]] std::optional<std::string> card_id() const { return card_id_; }

 private:
  CosimReply fail_locked(const Error& error, const std::string& code);
  CosimReply step_locked(const std::vector<crowd::RobotInput>& inputs);
  CosimReply end_locked(const std::string& reason);
  void push_observation_locked(CosimReply& out) const;
  [[nodiscard]] std::string observation_locked() const;
  [[nodiscard]] std::string binary_observation_locked() const;

  const std::string id_;
  const std::string author_;
  const std::optional<std::string> card_id_;
  const CosimSettings settings_;
  const CosimLimits limits_;
  std::shared_ptr<const world::World> world_;  // the episode refers to it
  mutable std::mutex mutex_;
  std::condition_variable ended_cv_;  // notified when end_reason_ is set
  std::unique_ptr<crowd::Episode> episode_;
  bool claimed_ = false;
  CosimEncoding encoding_ = CosimEncoding::kJson;
  std::vector<std::string> roles_;  // binary: the people's roles at claim time, sorted (hello's "roles")
  std::optional<std::string> end_reason_;
  Json report_;                          // set at the end
  std::vector<crowd::RobotInput> held_;  // real time: the last commands
  bool fresh_ = false;                   // real time: a step message came since the last tick
  std::uint64_t late_ticks_ = 0;
  std::uint64_t client_messages_ = 0;  // real time: step messages taken
  std::chrono::steady_clock::time_point created_ = std::chrono::steady_clock::now();
};

class CosimSessions {
 public:
  explicit CosimSessions(CosimLimits limits) : limits_(limits) {}
  [[nodiscard]] const CosimLimits& limits() const { return limits_; }
  // 429 at the session limit; 422 (pointers under /) when the episode cannot be built.
  Result<std::shared_ptr<CosimSession>> create(CosimRequest request);
  Result<std::shared_ptr<CosimSession>> find(const std::string& id);
  // The sessions kept (running, waiting and the last ended_kept ended ones), newest first.
  std::vector<std::shared_ptr<CosimSession>> list();
  void shutdown();

 private:
  void purge_locked();
  CosimLimits limits_;
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<CosimSession>> sessions_;
  std::vector<std::string> order_;  // creation order, for dropping old ended sessions
};

}  // namespace socsim::server
