#include "server/ws_server.hpp"

#include <algorithm>
#include <atomic>
#include <deque>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include "core/common/json_io.hpp"
#include "server/access_policy.hpp"
#include "server/auth.hpp"
#include "server/cosim_sessions.hpp"
#include "server/foxglove_bridge.hpp"
#include "server/services.hpp"
#include "server/simulation_sessions.hpp"
#include "socsim/buildinfo.hpp"

namespace socsim::server {
namespace {
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

class Session;

// Hands work to the I/O thread until the server stops. Simulation threads post through it, so
// nothing is posted into a context that is being destroyed. On the I/O thread itself the work
// runs at once: asio keeps posts made from inside a handler in a thread-private queue until the
// handler returns, so a post from there could land after a later post from a simulation thread
// (a "status" after the frame it precedes).
struct IoGate {
  std::mutex mutex;
  asio::io_context* io = nullptr;
  template <class F>
  void post(F&& f) {
    std::lock_guard<std::mutex> lock(mutex);
    if (io) asio::dispatch(*io, std::forward<F>(f));
  }
  void close() {
    std::lock_guard<std::mutex> lock(mutex);
    io = nullptr;
  }
};

struct Shared {
  // Co-simulation steps and messages run here, off the I/O thread (one strand per session), so
  // that a large crowd's step does not delay the port's other clients. Joined before `io` goes,
  // and declared before it: the sessions that destroying `io` releases still hold strands of it.
  asio::thread_pool cosim_workers{2};
  // Declared before the I/O context: sessions its destruction releases still count themselves out.
  std::map<std::string, std::size_t> per_address;  // open connections by peer address (I/O thread)
  std::size_t refused = 0;
  asio::io_context io{1};
  WsOptions options;
  EventHub& events;
  SimulationSessions* simulations;
  std::shared_ptr<IoGate> gate = std::make_shared<IoGate>();
  std::set<std::shared_ptr<Session>> sessions;  // touched only on the I/O thread
  Shared(WsOptions o, EventHub& e, SimulationSessions* sims)
      : options(std::move(o)), events(e), simulations(sims) {
    gate->io = &io;
  }
};

constexpr std::string_view kSimulationPath = "/ws/simulations/";
constexpr std::string_view kCosimPath = "/ws/cosim/";
constexpr std::string_view kBinaryProtocol = "socsim.binary.v1";
constexpr std::string_view kJsonProtocol = "socsim.json.v1";

// The subprotocols a client offers (Sec-WebSocket-Protocol: a, b).
std::vector<std::string> offered_protocols(std::string_view header) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= header.size()) {
    std::size_t comma = header.find(',', start);
    if (comma == std::string_view::npos) comma = header.size();
    std::string_view item = header.substr(start, comma - start);
    while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) item.remove_prefix(1);
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) item.remove_suffix(1);
    if (!item.empty()) out.emplace_back(item);
    start = comma + 1;
  }
  return out;
}

std::optional<std::string> query_value(std::string_view target, std::string_view name) {
  const auto q = target.find('?');
  if (q == std::string_view::npos) return std::nullopt;
  std::string_view rest = target.substr(q + 1);
  while (!rest.empty()) {
    const auto amp = rest.find('&');
    const std::string_view pair = rest.substr(0, amp);
    const auto eq = pair.find('=');
    if (pair.substr(0, eq) == name)
      return std::string(eq == std::string_view::npos ? "" : pair.substr(eq + 1));
    if (amp == std::string_view::npos) break;
    rest = rest.substr(amp + 1);
  }
  return std::nullopt;
}

// The key a client presented: "Authorization: Bearer <key>", or (browsers cannot set headers on a
// WebSocket) a subprotocol "bearer.<key>" offered beside socsim.json.v1 / socsim.binary.v1.
std::string presented_key(const http::request<http::string_body>& req) {
  if (auto t = bearer_token(std::string(req[http::field::authorization]))) return "Bearer " + *t;
  for (const std::string& p : offered_protocols(std::string(req[http::field::sec_websocket_protocol])))
    if (p.rfind("bearer.", 0) == 0) return "Bearer " + p.substr(7);
  return {};
}

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, Shared& shared, std::string peer)
      : ws_(std::move(socket)), shared_(shared), peer_(std::move(peer)) {
    ++shared_.per_address[peer_];
  }
  ~Session() {
    auto it = shared_.per_address.find(peer_);
    if (it != shared_.per_address.end() && --it->second == 0) shared_.per_address.erase(it);
  }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  void start() {
    // The whole upgrade request must arrive within the handshake deadline.
    beast::get_lowest_layer(ws_).expires_after(shared_.options.handshake_timeout);
    http::async_read(
        ws_.next_layer(), buffer_, request_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_request(ec); });
  }

  [[nodiscard]] const std::string& topic() const { return topic_; }

  // Called on the I/O thread. Frames published before the handshake has finished are not for
  // this client yet (and writing then would race the handshake's own write).
  void send(std::string frame) {
    if (!open_) return;
    auto m = std::make_shared<WireMessage>();
    m->bytes = std::move(frame);
    m->frame = true;
    enqueue(std::move(m));
  }

  // Called on the I/O thread. A simulation viewer's messages queue from the moment it is attached
  // (its hello first) and are written once the handshake is done.
  void enqueue(WirePtr message) {
    if (closed_ || close_after_) return;
    // A Foxglove client's frame is a Time record and one record per subscription.
    const std::size_t limit = simulation_ ? shared_.options.max_queued_simulation_frames *
                                                (bridge_ ? 1 + bridge_->subscriptions() : 1)
                                          : shared_.options.max_queued_frames;
    const auto droppable = [](const WirePtr& m) { return m->frame || m->droppable; };
    if (droppable(message) && queue_.size() >= limit) {
      // Drop the oldest frame (or status, error) for a slow reader; hello, targets and end are kept.
      auto oldest = std::find_if(queue_.begin(), queue_.end(), droppable);
      if (oldest != queue_.end()) {
        if ((*oldest)->frame) {
          ++dropped_;
          if (counters_) ++counters_->dropped;
        }
        queue_.erase(oldest);
      }
    }
    queue_.push_back(std::move(message));
    if (open_ && !writing_) write_next();
  }

 private:
  void refuse(const Error& error) {
    auto res = std::make_shared<http::response<http::string_body>>(static_cast<http::status>(error.status()),
                                                                   request_.version());
    res->set(http::field::content_type, "application/problem+json");
    if (error.retry_after_s > 0) res->set(http::field::retry_after, std::to_string(error.retry_after_s));
    const std::string target(request_.target());
    res->body() = error.to_problem(target.substr(0, target.find('?')))
                      .dump(-1, ' ', false, Json::error_handler_t::replace);
    res->prepare_payload();
    res->keep_alive(false);
    beast::get_lowest_layer(ws_).expires_after(shared_.options.handshake_timeout);
    http::async_write(ws_.next_layer(), *res,
                      [self = shared_from_this(), res](beast::error_code, std::size_t) { self->finish(); });
  }

  // Server-side timeouts of the upgraded socket: the handshake's own deadline, pings when idle.
  void upgrade_timeouts() {
    beast::get_lowest_layer(ws_).expires_never();
    auto timeouts = websocket::stream_base::timeout::suggested(beast::role_type::server);
    timeouts.handshake_timeout = shared_.options.handshake_timeout;
    ws_.set_option(timeouts);
  }

  void on_request(beast::error_code ec) {
    if (ec) return finish();
    if (const auto& policy = shared_.options.policy) {
      const std::string host(request_[http::field::host]);
      if (auto e = policy->check_host(host)) return refuse(*e);
      if (auto e = policy->check_origin(std::string(request_[http::field::origin]), host,
                                        shared_.options.http_port))
        return refuse(*e);
    }
    if (const auto& keys = shared_.options.keys; keys && keys->enabled())
      author_ = keys->authenticate(presented_key(request_)).value_or("anonymous");
    const std::string target(request_.target());
    const std::string path = target.substr(0, target.find('?'));
    if (path == "/ws" || path == "/ws/catalogue")
      topic_ = "cards";
    else if (path == "/ws/jobs")
      topic_ = "jobs";
    else if (path.rfind(kSimulationPath, 0) == 0 && websocket::is_upgrade(request_))
      return on_simulation_request(target, path.substr(kSimulationPath.size()));
    else if (path.rfind(kCosimPath, 0) == 0 && websocket::is_upgrade(request_))
      return on_cosim_request(path.substr(kCosimPath.size()));
    else if (path.rfind(kFoxglovePath, 0) == 0 && websocket::is_upgrade(request_))
      return on_foxglove_request(path.substr(kFoxglovePath.size()));
    if (!websocket::is_upgrade(request_) || topic_.empty())
      return refuse(
          Error(ErrorCode::kNotFound,
                "WebSocket endpoints: /ws/catalogue, /ws/jobs, /ws/simulations/{id}, /ws/cosim/{id}, "
                "/foxglove/{simulation id}"));
    upgrade_timeouts();
    ws_.async_accept(request_, [self = shared_from_this()](beast::error_code e) { self->on_accept(e); });
  }

  // /ws/simulations/{id}[?format=json|binary]: attach as a viewer before accepting, so an unknown,
  // ended or full session is refused with an HTTP problem.
  void on_simulation_request(const std::string& target, const std::string& id) {
    if (!shared_.simulations)
      return refuse(Error(ErrorCode::kNotFound, "no simulation with id '" + id + "'"));
    auto session = shared_.simulations->find(id);
    if (!session) return refuse(session.error());
    WireFormat format = WireFormat::kJson;
    std::string protocol;
    if (auto q = query_value(target, "format")) {
      if (*q == "binary")
        format = WireFormat::kBinary;
      else if (*q != "json")
        return refuse(Error(ErrorCode::kValidation, "unknown frame format",
                            {FieldError{"", "must be json or binary", "format", 0, 0}}));
    }
    for (const std::string& p :
         offered_protocols(std::string(request_[http::field::sec_websocket_protocol]))) {
      if (p == kBinaryProtocol || p == kJsonProtocol) {  // the client's first known choice wins
        protocol = p;
        format = p == kBinaryProtocol ? WireFormat::kBinary : WireFormat::kJson;
        break;
      }
    }
    watch(*session, format, protocol);
  }

  // Attaches this connection as a viewer of `session` (the session's messages come to
  // from_session() on the I/O thread), then accepts the upgrade answering with `protocol`; an
  // ended or full session is refused with its problem.
  void watch(std::shared_ptr<SimulationSession> session, WireFormat format, const std::string& protocol) {
    simulation_ = session;
    counters_ = std::make_shared<ViewerCounters>();
    std::weak_ptr<Session> weak = shared_from_this();
    std::shared_ptr<IoGate> gate = shared_.gate;
    auto lease = session->attach(
        session, format,
        [weak, gate](const WirePtr& m) {
          gate->post([weak, m] {
            if (auto self = weak.lock()) self->from_session(m);
          });
        },
        counters_);
    if (!lease) {
      simulation_.reset();
      bridge_.reset();
      queue_.clear();
      return refuse(lease.error());
    }
    lease_ = std::move(*lease);
    upgrade_timeouts();
    ws_.set_option(websocket::stream_base::decorator([protocol](websocket::response_type& res) {
      res.set(http::field::server, "socsim");
      if (!protocol.empty()) res.set(http::field::sec_websocket_protocol, protocol);
    }));
    ws_.auto_fragment(false);         // one WebSocket frame per message: fewer writes
    ws_.read_message_max(64 * 1024);  // control commands and subscriptions are small
    ws_.async_accept(request_, [self = shared_from_this()](beast::error_code e) { self->on_accept(e); });
  }

  // On the I/O thread: a message of the watched session, as it is or through the Foxglove bridge.
  void from_session(const WirePtr& m) {
    if (!bridge_) return enqueue(m);
    if (closed_) return;
    for (WirePtr& out : bridge_->on_session(*m)) enqueue(std::move(out));
  }

  // /foxglove/{id}: a Foxglove client (foxglove.websocket.v1) of a live simulation. It watches as
  // a binary viewer; the bridge turns the session's frames into the channels it subscribed to.
  void on_foxglove_request(const std::string& id) {
    if (!shared_.simulations)
      return refuse(Error(ErrorCode::kNotFound, "no simulation with id '" + id + "'"));
    auto session = shared_.simulations->find(id);
    if (!session) return refuse(session.error());
    const auto offered = offered_protocols(std::string(request_[http::field::sec_websocket_protocol]));
    if (std::find(offered.begin(), offered.end(), std::string(kFoxgloveProtocol)) == offered.end())
      return refuse(Error(ErrorCode::kBadRequest, "a Foxglove client must offer the subprotocol " +
                                                      std::string(kFoxgloveProtocol) +
                                                      " (Sec-WebSocket-Protocol)"));
    bridge_ = std::make_unique<FoxgloveBridge>((*session)->id(), (*session)->info().world);
    for (WirePtr& m : bridge_->open()) enqueue(std::move(m));
    watch(*session, WireFormat::kBinary, std::string(kFoxgloveProtocol));
  }

  // /ws/cosim/{id}: the one client of a co-simulation; it must speak socsim.cosim.v1.
  void on_cosim_request(const std::string& id) {
    if (!shared_.options.cosim)
      return refuse(Error(ErrorCode::kNotFound, "no co-simulation with id '" + id + "'"));
    auto session = shared_.options.cosim->find(id);
    if (!session) return refuse(session.error());
    const auto offered = offered_protocols(std::string(request_[http::field::sec_websocket_protocol]));
    const auto offers = [&offered](std::string_view p) {
      return std::find(offered.begin(), offered.end(), std::string(p)) != offered.end();
    };
    if (!offers(kCosimProtocol) && !offers(kCosimBinaryProtocol))
      return refuse(Error(ErrorCode::kBadRequest,
                          "a co-simulation client must offer the subprotocol " + std::string(kCosimProtocol) +
                              " or " + std::string(kCosimBinaryProtocol) + " (Sec-WebSocket-Protocol)"));
    const bool binary = offers(kCosimBinaryProtocol);
    const auto& keys = shared_.options.keys;
    if (keys && !may_act_for(*keys, author_, (*session)->author()))
      return refuse(Error(ErrorCode::kForbidden, "co-simulation '" + id + "' was started by another author"));
    if (auto ok = (*session)->claim(binary ? CosimEncoding::kBinary : CosimEncoding::kJson); !ok)
      return refuse(ok.error());
    cosim_ = *session;
    upgrade_timeouts();
    ws_.set_option(websocket::stream_base::decorator([binary](websocket::response_type& res) {
      res.set(http::field::server, "socsim");
      res.set(http::field::sec_websocket_protocol,
              std::string(binary ? kCosimBinaryProtocol : kCosimProtocol));
    }));
    ws_.auto_fragment(false);
    ws_.read_message_max(1024 * 1024);  // a step with a few robots is small; this is generous
    ws_.async_accept(request_, [self = shared_from_this()](beast::error_code e) { self->on_accept(e); });
  }

  // Sends what the co-simulation answered; closes after it when it says so.
  void cosim_send(const CosimReply& reply) {
    for (std::size_t k = 0; k < reply.messages.size(); ++k) {
      auto m = std::make_shared<WireMessage>();
      m->bytes = reply.messages[k];
      m->binary = k < reply.binary.size() && reply.binary[k];
      m->frame = reply.droppable;  // real time: a client that does not read loses old observations
      m->last = reply.close && k + 1 == reply.messages.size();
      enqueue(std::move(m));
    }
    if (reply.close) {
      close_code_ =
          reply.protocol_error ? websocket::close_code::policy_error : websocket::close_code::normal;
      stop_cosim_timers();
      if (reply.messages.empty()) {  // nothing left to say: close once any write under way is done
        close_after_ = true;
        if (!writing_) close();
      }
    }
  }

  void arm_idle() {
    idle_timer_.expires_after(
        std::chrono::milliseconds(static_cast<std::int64_t>(cosim_->idle_s() * 1000.0)));
    idle_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec || self->closed_ || !self->cosim_) return;
      self->cosim_send(self->cosim_->expire());
    });
  }

  void arm_tick(std::chrono::steady_clock::time_point at) {
    tick_timer_.expires_at(at);
    tick_timer_.async_wait([self = shared_from_this(), at](beast::error_code ec) {
      if (ec || self->closed_ || !self->cosim_) return;
      // A tick still stepping when the next is due: that one is skipped, not queued behind it.
      if (!self->tick_running_) {
        self->tick_running_ = true;
        self->run_cosim([](CosimSession& c) { return c.tick(); }, true);
      }
      const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(1.0 / self->cosim_->rate_hz()));
      // A tick that overran its period does not make the next ones pile up: the schedule restarts
      // from now (the missed ticks are not made up). The reply that ends the episode stops the timer.
      self->arm_tick(std::max(at + period, std::chrono::steady_clock::now()));
    });
  }

  // Runs co-simulation work on the session's strand of the workers and sends its reply from the
  // I/O thread, in order. Only a weak reference travels, so the session is released on the I/O
  // thread (its destructor counts connections there).
  template <class Work>
  void run_cosim(Work work, bool tick = false) {
    asio::post(cosim_strand_, [weak = weak_from_this(), cosim = cosim_, gate = shared_.gate, tick,
                               work = std::move(work)]() mutable {
      CosimReply reply = work(*cosim);
      gate->post([weak, tick, reply = std::move(reply)]() {
        auto self = weak.lock();
        if (!self) return;
        if (tick) self->tick_running_ = false;
        if (!self->closed_) self->cosim_send(reply);
      });
    });
  }

  void stop_cosim_timers() {
    idle_timer_.cancel();
    tick_timer_.cancel();
  }

  void on_accept(beast::error_code ec) {
    if (ec) return finish();
    open_ = true;
    if (cosim_) {
      ws_.text(true);
      cosim_send(cosim_->hello());
      arm_idle();
      if (cosim_->mode() == CosimMode::kRealTime) arm_tick(std::chrono::steady_clock::now());
      return read_loop();
    }
    if (simulation_) {
      if (!queue_.empty() && !writing_) write_next();
    } else {
      ws_.text(true);
      send(nlohmann::json{
          {"type", "hello"}, {"server", "socsim"}, {"version", build::kVersion}, {"topic", topic_}}
               .dump());
    }
    read_loop();
  }

  // Reads client frames so pings/close are handled (simulation viewers' frames are control
  // commands); ends the session on error.
  void read_loop() {
    ws_.async_read(in_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->finish();
      if (self->bridge_) {
        if (self->ws_.got_text())
          for (WirePtr& m : self->bridge_->on_client_text(beast::buffers_to_string(self->in_.data())))
            self->enqueue(std::move(m));
      } else if (self->simulation_) {
        self->on_command(beast::buffers_to_string(self->in_.data()));
      }
      if (self->cosim_ && !self->close_after_) {
        self->arm_idle();
        self->run_cosim(
            [text = beast::buffers_to_string(self->in_.data())](CosimSession& c) { return c.handle(text); });
      }
      self->in_.consume(self->in_.size());
      self->read_loop();
    });
  }

  // {"action": "pause"} etc.: the session tells every viewer the new status; a bad command is
  // answered to this viewer only.
  void on_command(const std::string& text) {
    auto command = parse_json_untrusted(text);
    Result<Json> done = fail(ErrorCode::kForbidden, "simulation '" + simulation_->id() +
                                                        "' was started by another author; its viewers may "
                                                        "watch but not control it");
    const auto& keys = shared_.options.keys;
    if (!command)
      done = tl::unexpected(command.error());
    else if (!keys || may_act_for(*keys, author_, simulation_->info().author))
      done = simulation_->control(*command);
    if (done) return;
    Json problem = done.error().to_problem("/ws/simulations/" + simulation_->id());
    problem["type"] = "error";
    problem["problem"] = done.error().to_problem()["type"];
    auto m = std::make_shared<WireMessage>();
    m->bytes = problem.dump(-1, ' ', false, Json::error_handler_t::replace);
    m->droppable = true;  // a client that sends bad commands and never reads cannot grow its queue
    enqueue(std::move(m));
  }

  void write_next() {
    if (closed_) return;
    if (queue_.empty()) {
      writing_ = false;
      if (close_after_) close();
      return;
    }
    writing_ = true;
    current_ = std::move(queue_.front());
    queue_.pop_front();
    if (current_->last) close_after_ = true;
    ws_.binary(current_->binary);
    ws_.async_write(asio::buffer(current_->bytes),
                    [self = shared_from_this()](beast::error_code ec, std::size_t) {
                      if (ec) return self->finish();
                      if (self->counters_ && self->current_->frame) ++self->counters_->delivered;
                      self->write_next();
                    });
  }

  // After a simulation's "end": a normal close, then forget the session.
  void close() {
    queue_.clear();
    ws_.async_close(close_code_, [self = shared_from_this()](beast::error_code) { self->finish(); });
  }

  // Forgets the session. The socket is not closed under a pending operation (Beast's stream
  // asserts when a read's failure path and a write complete out of order); it closes when the
  // last handler holding the session has run and the session is destroyed.
  void finish() {
    closed_ = true;
    queue_.clear();
    lease_.reset();  // leaves the simulation's viewers
    if (cosim_) {
      stop_cosim_timers();
      cosim_->release();  // a client gone mid-episode ends it ("client_closed")
    }
    shared_.sessions.erase(shared_from_this());
  }

  websocket::stream<beast::tcp_stream> ws_;
  Shared& shared_;
  std::string peer_;
  std::string author_ = "anonymous";  // whose key the handshake presented
  beast::flat_buffer buffer_;
  beast::flat_buffer in_;
  http::request<http::string_body> request_;
  std::deque<WirePtr> queue_;
  WirePtr current_;
  std::string topic_;                              // "cards" or "jobs", from the path
  std::shared_ptr<SimulationSession> simulation_;  // set for /ws/simulations/{id}
  std::shared_ptr<CosimSession> cosim_;            // set for /ws/cosim/{id}
  std::unique_ptr<FoxgloveBridge> bridge_;         // set for /foxglove/{id} (with simulation_)
  asio::steady_timer idle_timer_{ws_.get_executor()};
  asio::steady_timer tick_timer_{ws_.get_executor()};
  websocket::close_code close_code_ = websocket::close_code::normal;
  std::unique_ptr<ViewerLease> lease_;
  std::shared_ptr<ViewerCounters> counters_;
  bool writing_ = false;
  bool open_ = false;  // handshake done
  bool closed_ = false;
  bool close_after_ = false;   // the simulation ended: close once its "end" is written
  bool tick_running_ = false;  // real time: a tick is stepping on the co-simulation workers
  asio::strand<asio::thread_pool::executor_type> cosim_strand_{asio::make_strand(shared_.cosim_workers)};
  std::size_t dropped_ = 0;

 public:
  [[nodiscard]] std::size_t dropped() const { return dropped_; }
  [[nodiscard]] std::size_t queued() const { return queue_.size(); }
  [[nodiscard]] bool viewing() const { return lease_ != nullptr; }
  // Leaves the simulation at once (the server is stopping; the socket closes later).
  void leave() { lease_.reset(); }
};

}  // namespace

struct WsServer::Impl {
  Impl(WsOptions o, EventHub& e, SimulationSessions* sims)
      : shared(std::move(o), e, sims), acceptor(shared.io) {}
  Shared shared;
  tcp::acceptor acceptor;
  std::thread thread;
  int subscription = 0;

  void accept() {
    acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
      if (ec) {
        if (ec == asio::error::operation_aborted) return;
      } else {
        beast::error_code e2;
        const auto endpoint = socket.remote_endpoint(e2);
        const std::string peer = e2 ? std::string() : endpoint.address().to_string();
        const auto it = shared.per_address.find(peer);
        const std::size_t from_peer = it == shared.per_address.end() ? 0 : it->second;
        if (!e2 && shared.sessions.size() < shared.options.max_clients &&
            from_peer < shared.options.max_clients_per_address) {
          auto s = std::make_shared<Session>(std::move(socket), shared, peer);
          shared.sessions.insert(s);
          s->start();
        } else {
          ++shared.refused;  // the socket closes here; the client may retry
        }
      }
      accept();
    });
  }
};

WsServer::WsServer(WsOptions options, EventHub& events, SimulationSessions* simulations)
    : impl_(std::make_unique<Impl>(std::move(options), events, simulations)) {}

WsServer::WsServer(WsOptions options, Services& services, int http_port)
    : WsServer(
          [&] {
            options.max_queued_simulation_frames = services.config.viewer_queue;
            options.max_clients_per_address = services.config.max_connections_per_client;
            options.policy = std::make_shared<AccessPolicy>(services.config);
            options.keys = std::make_shared<KeyRing>(services.config.api_keys);
            options.http_port = http_port > 0 ? http_port : services.config.port;
            options.cosim = services.cosim.get();
            return std::move(options);
          }(),
          services.events, services.simulations.get()) {}

WsServer::~WsServer() {
  stop();
}

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
    st.refused = impl_->shared.refused;
    for (const auto& s : impl_->shared.sessions) {
      st.frames_dropped += s->dropped();
      st.frames_queued += s->queued();
      st.simulation_viewers += s->viewing() ? 1 : 0;
    }
    p.set_value(st);
  });
  return f.get();
}

void WsServer::start() {
  Impl* impl = impl_.get();
  impl->subscription =
      impl->shared.events.subscribe([impl](const std::string& topic, const std::string& payload) {
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
  impl_->shared.gate->close();  // simulation threads stop posting here
  // Stopping the I/O context abandons every pending operation; destroying their handlers with
  // the context releases the sessions, whose destructors close the sockets.
  asio::post(impl_->shared.io, [impl = impl_.get()] {
    beast::error_code ec;
    impl->acceptor.close(ec);
    impl->shared.io.stop();
  });
  impl_->thread.join();
  impl_->shared.cosim_workers.join();  // steps under way finish; their replies find the gate closed
  for (const auto& s : impl_->shared.sessions) s->leave();
  impl_->shared.sessions.clear();
}

}  // namespace socsim::server
