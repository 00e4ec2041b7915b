#pragma once
// The WebSocket endpoint (Boost.Beast, its own port). /ws/catalogue streams catalogue events
// (card.created, card.deleted), /ws/jobs job events (queued, running, progress, finished), as JSON
// text frames; /ws/simulations/{id} streams a live simulation's frames (JSON, or binary with the
// subprotocol socsim.binary.v1 or ?format=binary) and takes control commands; /ws/cosim/{id}
// (subprotocol socsim.cosim.v1) is a robot co-simulation's client. A slow client loses its oldest
// queued frames; it never slows the publisher.
#include <chrono>
#include <memory>
#include <string>

#include "core/common/error.hpp"
#include "server/event_hub.hpp"

namespace socsim::server {

class AccessPolicy;
class CosimSessions;
class KeyRing;
class SimulationSessions;
struct Services;

struct WsOptions {
  std::string host = "127.0.0.1";
  int port = 8081;
  std::size_t max_clients = 4096;
  std::size_t max_queued_frames = 64;
  std::size_t max_queued_simulation_frames = 8;        // per simulation viewer
  std::chrono::milliseconds handshake_timeout{10000};  // connect to upgraded
  std::size_t max_clients_per_address = 64;
  // From the daemon's configuration (the Services constructor sets them): Host/Origin checks
  // (pages of `http_port` are same-origin) and the keys that decide who may control a simulation.
  // Null: any origin, and control is open to every viewer.
  std::shared_ptr<const AccessPolicy> policy{};
  std::shared_ptr<const KeyRing> keys{};
  int http_port = 0;
  // Robot co-simulations driven at /ws/cosim/{id} (docs/cosim.md); null: that path answers 404.
  CosimSessions* cosim = nullptr;
};

struct WsStats {
  std::size_t sessions = 0;
  std::size_t refused = 0;  // connections over a limit, closed at once
  std::size_t simulation_viewers = 0;
  std::size_t frames_dropped = 0;  // oldest frames dropped for clients that did not keep up
  std::size_t frames_queued = 0;
};

class WsServer {
 public:
  // `simulations` may be null: /ws/simulations/{id} then answers 404.
  WsServer(WsOptions options, EventHub& events, SimulationSessions* simulations = nullptr);
  // Events and simulations of a daemon; the viewer queue length, cross-site policy and keys from
  // its configuration; pages served on `http_port` may open sockets.
  WsServer(WsOptions options, Services& services, int http_port = 0);
  ~WsServer();
  WsServer(const WsServer&) = delete;
  WsServer& operator=(const WsServer&) = delete;
  Result<int> bind();  // port 0 picks a free one
  void start();        // serves on a background I/O thread
  void stop();         // closes every connection and joins the thread
  [[nodiscard]] int port() const { return port_; }
  // Counters read on the I/O thread (the server must be started).
  WsStats stats();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int port_ = 0;
};

}  // namespace socsim::server
