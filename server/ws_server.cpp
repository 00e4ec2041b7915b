#include "server/ws_server.hpp"

#include <atomic>
#include <deque>
#include <future>
#include <set>
#include <thread>

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include "socsim/buildinfo.hpp"

namespace socsim::server {
namespace {
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

class Session;

struct Shared {
  asio::io_context io{1};
  WsOptions options;
  EventHub& events;
  std::set<std::shared_ptr<Session>> sessions;  // touched only on the I/O thread
  Shared(WsOptions o, EventHub& e) : options(std::move(o)), events(e) {}
};

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, Shared& shared) : ws_(std::move(socket)), shared_(shared) {}

  void start() {
    http::async_read(ws_.next_layer(), buffer_, request_,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_request(ec); });
  }

  [[nodiscard]] const std::string& topic() const { return topic_; }

  // Called on the I/O thread. Frames published before the handshake has finished are not for
  // this client yet (and writing then would race the handshake's own write).
  void send(std::string frame) {
    if (closed_ || !open_) return;
    if (queue_.size() >= shared_.options.max_queued_frames) {
      queue_.pop_front();  // drop the oldest for a slow reader
      ++dropped_;
    }
    queue_.push_back(std::move(frame));
    if (!writing_) write_next();
  }


 private:
  void on_request(beast::error_code ec) {
    if (ec) return finish();
    const std::string target(request_.target());
    const std::string path = target.substr(0, target.find('?'));
    if (path == "/ws" || path == "/ws/catalogue") topic_ = "cards";
    else if (path == "/ws/jobs") topic_ = "jobs";
    if (!websocket::is_upgrade(request_) || topic_.empty()) {
      auto res = std::make_shared<http::response<http::string_body>>(http::status::not_found, request_.version());
      res->set(http::field::content_type, "application/problem+json");
      res->body() = R"({"type":"https://socsim.dev/problems/not-found","title":"Not found","status":404,)"
                    R"("detail":"WebSocket endpoints: /ws/catalogue, /ws/jobs","errors":[]})";
      res->prepare_payload();
      http::async_write(ws_.next_layer(), *res, [self = shared_from_this(), res](beast::error_code, std::size_t) {
        self->finish();
      });
      return;
    }
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.async_accept(request_, [self = shared_from_this()](beast::error_code e) { self->on_accept(e); });
  }

  void on_accept(beast::error_code ec) {
    if (ec) return finish();
    ws_.text(true);
    open_ = true;
    send(nlohmann::json{{"type", "hello"}, {"server", "socsim"}, {"version", build::kVersion}, {"topic", topic_}}.dump());
    read_loop();
  }

  // Reads (and ignores) client frames so pings/close are handled; ends the session on error.
  void read_loop() {
    ws_.async_read(in_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->finish();
      self->in_.consume(self->in_.size());
      self->read_loop();
    });
  }

  void write_next() {
    if (queue_.empty() || closed_) {
      writing_ = false;
      return;
    }
    writing_ = true;
    current_ = std::move(queue_.front());
    queue_.pop_front();
    ws_.async_write(asio::buffer(current_), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->finish();
      self->write_next();
    });
  }

  // Forgets the session. The socket is not closed under a pending operation (Beast's stream
  // asserts when a read's failure path and a write complete out of order); it closes when the
  // last handler holding the session has run and the session is destroyed.
  void finish() {
    closed_ = true;
    queue_.clear();
    shared_.sessions.erase(shared_from_this());
  }

  websocket::stream<tcp::socket> ws_;
  Shared& shared_;
  beast::flat_buffer buffer_;
  beast::flat_buffer in_;
  http::request<http::string_body> request_;
  std::deque<std::string> queue_;
  std::string current_;
  std::string topic_;  // "cards" or "jobs", from the path
  bool writing_ = false;
  bool open_ = false;  // handshake done
  bool closed_ = false;
  std::size_t dropped_ = 0;

 public:
  [[nodiscard]] std::size_t dropped() const { return dropped_; }
  [[nodiscard]] std::size_t queued() const { return queue_.size(); }
};

}  // namespace

struct WsServer::Impl {
  Impl(WsOptions o, EventHub& e) : shared(std::move(o), e), acceptor(shared.io) {}
  Shared shared;
  tcp::acceptor acceptor;
  std::thread thread;
  int subscription = 0;

  void accept() {
    acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
      if (ec) {
        if (ec == asio::error::operation_aborted) return;
      } else if (shared.sessions.size() < shared.options.max_clients) {
        auto s = std::make_shared<Session>(std::move(socket), shared);
        shared.sessions.insert(s);
        s->start();
      }
      accept();
    });
  }
};

WsServer::WsServer(WsOptions options, EventHub& events) : impl_(std::make_unique<Impl>(std::move(options), events)) {}

WsServer::~WsServer() { stop(); }

Result<int> WsServer::bind() {
  beast::error_code ec;
  const auto address = asio::ip::make_address(impl_->shared.options.host, ec);
  if (ec) return fail(ErrorCode::kInternal, "bad WebSocket host '" + impl_->shared.options.host + "'");
  tcp::endpoint ep(address, static_cast<unsigned short>(impl_->shared.options.port));
  auto& a = impl_->acceptor;
  a.open(ep.protocol(), ec);
  if (!ec) a.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) a.bind(ep, ec);
  if (!ec) a.listen(asio::socket_base::max_listen_connections, ec);
  if (ec)
    return fail(ErrorCode::kInternal, "cannot listen for WebSocket on " + impl_->shared.options.host + ":" +
                                          std::to_string(impl_->shared.options.port) + ": " + ec.message());
  port_ = a.local_endpoint().port();
  return port_;
}

WsStats WsServer::stats() {
  std::promise<WsStats> p;
  auto f = p.get_future();
  asio::post(impl_->shared.io, [this, &p] {
    WsStats st;
    st.sessions = impl_->shared.sessions.size();
    for (const auto& s : impl_->shared.sessions) {
      st.frames_dropped += s->dropped();
      st.frames_queued += s->queued();
    }
    p.set_value(st);
  });
  return f.get();
}

void WsServer::start() {
  Impl* impl = impl_.get();
  impl->subscription = impl->shared.events.subscribe([impl](const std::string& topic, const std::string& payload) {
    asio::post(impl->shared.io, [impl, topic, payload] {
      for (const auto& s : impl->shared.sessions)
        if (s->topic() == topic) s->send(payload);
    });
  });
  impl->accept();
  impl->thread = std::thread([impl] { impl->shared.io.run(); });
}

void WsServer::stop() {
  if (!impl_ || !impl_->thread.joinable()) return;
  impl_->shared.events.unsubscribe(impl_->subscription);
  // Stopping the I/O context abandons every pending operation; destroying their handlers with
  // the context releases the sessions, whose destructors close the sockets.
  asio::post(impl_->shared.io, [impl = impl_.get()] {
    beast::error_code ec;
    impl->acceptor.close(ec);
    impl->shared.io.stop();
  });
  impl_->thread.join();
  impl_->shared.sessions.clear();
}

}  // namespace socsim::server
