#pragma once
// A daemon with its WebSocket endpoint on free ports, as `socsim serve` wires them, and a blocking
// Beast WebSocket client: shared by the live-simulation and co-simulation tests.
#include <gtest/gtest.h>

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "server/ws_server.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using namespace std::chrono_literals;

inline server::ServerConfig quick_config() {
  server::ServerConfig c;
  c.rate_limit_rps = 0;
  c.sim_idle_s = 5;
  return c;
}

// A daemon with its WebSocket endpoint, as `socsim serve` wires them.
struct Daemon {
  testing::TestServer http;
  std::unique_ptr<WsServer> ws;
  int ws_port = 0;
  explicit Daemon(server::ServerConfig config = quick_config()) : http(std::move(config)) {
    ws = std::make_unique<WsServer>(WsOptions{"127.0.0.1", 0, 64, 64, 8}, http.services());
    ws_port = ws->bind().value();
    http.services().config.ws_port = ws_port;
    ws->start();
  }
  ~Daemon() { ws->stop(); }

  Json post(const std::string& path, const Json& body, int expect) {
    auto r = http.client().Post(path.c_str(), body.dump(), "application/json");
    EXPECT_TRUE(r) << path;
    if (!r) return {};
    EXPECT_EQ(r->status, expect) << path << ": " << r->body;
    return Json::parse(r->body);
  }
  Json get(const std::string& path) {
    auto r = http.client().Get(path.c_str());
    EXPECT_TRUE(r && r->status == 200) << path;
    return r ? Json::parse(r->body) : Json();
  }
  std::string start(const Json& body) { return post("/api/v1/simulations", body, 201).value("id", ""); }
};

struct Message {
  bool binary = false;
  std::string bytes;
  [[nodiscard]] Json json() const { return Json::parse(bytes); }
  [[nodiscard]] std::string type() const { return binary ? "binary" : json().value("type", ""); }
};

struct Viewer {
  asio::io_context io;
  websocket::stream<tcp::socket> ws{io};
  std::string protocol;  // what the server selected
  websocket::response_type response;

  Viewer(int port, const std::string& path, const std::string& offer = "", int receive_buffer = 0) {
    tcp::resolver resolver(io);
    ws.next_layer().open(tcp::v4());
    if (receive_buffer > 0)
      ws.next_layer().set_option(asio::socket_base::receive_buffer_size(receive_buffer));
    ws.next_layer().connect(*resolver.resolve("127.0.0.1", std::to_string(port)).begin());
    if (!offer.empty())
      ws.set_option(websocket::stream_base::decorator(
          [offer](websocket::request_type& req) { req.set(http::field::sec_websocket_protocol, offer); }));
    ws.handshake(response, "127.0.0.1", path);
    protocol = std::string(response[http::field::sec_websocket_protocol]);
  }

  // The next message, or nothing within `timeout` (the stream is unusable after a timeout).
  std::optional<Message> read(std::chrono::milliseconds timeout = 5000ms) {
    beast::flat_buffer buf;
    bool done = false;
    beast::error_code ec;
    ws.async_read(buf, [&](beast::error_code e, std::size_t) {
      done = true;
      ec = e;
    });
    io.restart();
    io.run_for(timeout);
    if (!done) {
      beast::error_code ignored;
      ws.next_layer().cancel(ignored);
      io.restart();
      io.run();
      return std::nullopt;
    }
    if (ec) return std::nullopt;
    return Message{ws.got_binary(), beast::buffers_to_string(buf.data())};
  }
  // Skips messages until one of `type` ("frame", "binary", "status", "end", …).
  std::optional<Message> next(const std::string& type, std::chrono::milliseconds timeout = 5000ms) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      auto m = read(
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()));
      if (!m) return std::nullopt;
      if (m->type() == type) return m;
    }
    return std::nullopt;
  }
  void command(const Json& c) {
    ws.text(true);
    ws.write(asio::buffer(c.dump()));
  }
};

}  // namespace socsim::server
