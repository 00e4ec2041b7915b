#pragma once
// An in-process daemon (REST and WebSocket on free loopback ports, a scratch database) and the
// counter-flow lanes program, shared by the benchmarks that talk to the server over sockets.
#include <httplib.h>

#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>

#include "server/api_server.hpp"
#include "server/ws_server.hpp"

namespace socsim::bench {

// Lanes 1 m apart, alternate lanes walking in opposite directions between their two ends:
// counter-flow with neighbours in reach, but no pile-up at a shared goal.
inline nlohmann::json lanes_program(int agents) {
  const int per_lane = 40;
  const double length = 60.0;
  nlohmann::json list = nlohmann::json::array();
  for (int i = 0; i < agents; ++i) {
    const int lane = i / per_lane;
    const double y = 1.0 * lane;
    const double x = (i % per_lane) * (length / per_lane) + (lane % 2 ? 0.7 : 0.0);
    const double to = lane % 2 ? 0.0 : length;
    list.push_back({{"position", {x, y}}, {"goals", {{to, y}, {length - to, y}}}});
  }
  return {{"name", "bench lanes"}, {"dt", 0.05}, {"decision_period", 0.1}, {"agents", list}};
}

class InProcessDaemon {
 public:
  // `tune` adjusts the configuration (limits) before the services are made.
  static std::unique_ptr<InProcessDaemon> start(const std::string& name,
                                                const std::function<void(server::ServerConfig&)>& tune) {
    std::unique_ptr<InProcessDaemon> d(new InProcessDaemon());
    d->dir_ =
        std::filesystem::temp_directory_path() / ("socsim-bench-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(d->dir_);
    std::filesystem::create_directories(d->dir_);
    server::ServerConfig cfg;
    cfg.host = "127.0.0.1";
    cfg.port = 0;
    cfg.db = (d->dir_ / "bench.db").string();
    cfg.web_root = d->dir_.string();
    cfg.rate_limit_rps = 0;
    cfg.max_body_bytes = 16u << 20;
    tune(cfg);
    auto store = store::Store::open(cfg.db);
    if (!store) {
      std::cerr << store.error().message() << "\n";
      return nullptr;
    }
    d->store_ = std::move(*store);
    auto services = server::Services::create(cfg, *d->store_);
    if (!services) {
      std::cerr << services.error().message() << "\n";
      return nullptr;
    }
    d->services_ = std::move(*services);
    d->api_ = std::make_unique<server::ApiServer>(*d->services_);
    d->port_ = d->api_->bind().value();
    d->thread_ = std::thread([api = d->api_.get()] { api->run(); });
    d->ws_ = std::make_unique<server::WsServer>(server::WsOptions{"127.0.0.1", 0, 1024, 64, cfg.viewer_queue},
                                                *d->services_);
    d->ws_port_ = d->ws_->bind().value();
    d->services_->config.ws_port = d->ws_port_;
    d->ws_->start();
    return d;
  }
  InProcessDaemon(const InProcessDaemon&) = delete;
  InProcessDaemon& operator=(const InProcessDaemon&) = delete;
  ~InProcessDaemon() {
    ws_->stop();
    api_->stop();
    thread_.join();
    services_->shutdown();
    store_->close();
    std::filesystem::remove_all(dir_);
  }
  [[nodiscard]] int port() const { return port_; }
  [[nodiscard]] int ws_port() const { return ws_port_; }

 private:
  InProcessDaemon() = default;
  std::filesystem::path dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<server::Services> services_;
  std::unique_ptr<server::ApiServer> api_;
  std::unique_ptr<server::WsServer> ws_;
  std::thread thread_;
  int port_ = 0;
  int ws_port_ = 0;
};

}  // namespace socsim::bench
