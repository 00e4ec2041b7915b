#pragma once
// The WebSocket endpoint (Boost.Beast, its own port). /ws/catalogue streams catalogue events
// (card.created, card.deleted), /ws/jobs job events (queued, running, progress, finished), as JSON
// text frames; /ws/simulations/{id} streams a live simulation's frames (JSON, or binary with the
// subprotocol socsim.binary.v1 or ?format=binary) and takes control commands. A slow client loses
// its oldest queued frames; it never slows the publisher.
#include <memory>
#include <string>

#include "core/common/error.hpp"
#include "server/event_hub.hpp"

namespace socsim::server {

class SimulationSessions;
struct Services;

struct WsOptions {
  std::string host = "127.0.0.1";
  int port = 8081;
  std::size_t max_clients = 256;
  std::size_t max_queued_frames = 64;
  std::size_t max_queued_simulation_frames = 8;  // per simulation viewer
};

struct WsStats {
  std::size_t sessions = 0;
  std::size_t simulation_viewers = 0;
  std::size_t frames_dropped = 0;  // oldest frames dropped for clients that did not keep up
  std::size_t frames_queued = 0;
};

class WsServer {
 public:
  // `simulations` may be null: /ws/simulations/{id} then answers 404.
  WsServer(WsOptions options, EventHub& events, SimulationSessions* simulations = nullptr);
  // Events and simulations of a daemon; the viewer queue length from its configuration.
  WsServer(WsOptions options, Services& services);
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
