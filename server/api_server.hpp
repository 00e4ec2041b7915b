#pragma once
// The REST daemon: the /api/v1 routes on the Beast HTTP transport (server/http_server.hpp), with
// structured request logs, problem+json errors, API-key auth for writes, per-client rate limits
// and the cross-site policy (server/access_policy.hpp).
#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include "core/common/error.hpp"
#include "server/services.hpp"

namespace socsim::server {

class ApiServer {
 public:
  explicit ApiServer(Services& services);
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
