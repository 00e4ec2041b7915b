#pragma once
// The REST daemon: cpp-httplib with limits, structured request logs, problem+json errors,
// API-key auth for writes, per-client rate limits, and the /api/v1 routes.
#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include "core/cards/catalogue.hpp"
#include "core/store/store.hpp"
#include "server/config.hpp"
#include "server/event_hub.hpp"

namespace httplib {
class Server;
}

namespace socsim::server {

class ApiServer {
 public:
  ApiServer(ServerConfig config, store::Store& store, EventHub& events);
  ~ApiServer();
  ApiServer(const ApiServer&) = delete;
  ApiServer& operator=(const ApiServer&) = delete;

  // Binds the listening socket; port 0 picks a free port. Returns the port or an error.
  Result<int> bind();
  // Serves until stop(); in-flight requests finish before it returns.
  void run();
  void stop();
  [[nodiscard]] int port() const { return port_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int port_ = 0;
};

}  // namespace socsim::server
