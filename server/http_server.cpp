#include "server/http_server.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>
#include <unordered_map>

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include "server/http_util.hpp"

namespace socsim::server {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

// ---- Request, Response, Router ----------------------------------------------------------------

bool CaseInsensitiveLess::operator()(const std::string& a, const std::string& b) const {
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) < std::tolower(static_cast<unsigned char>(y));
  });
}

bool Request::has_header(const std::string& name) const {
  return headers.find(name) != headers.end();
}
std::string Request::get_header_value(const std::string& name) const {
  auto it = headers.find(name);
  return it == headers.end() ? std::string() : it->second;
}
bool Request::has_param(const std::string& name) const {
  return params.find(name) != params.end();
}
std::string Request::get_param_value(const std::string& name) const {
  auto it = params.find(name);
  return it == params.end() ? std::string() : it->second;
}

void Response::set_header(const std::string& name, const std::string& value) {
  headers.erase(name);
  headers.emplace(name, value);
}
void Response::set_content(std::string content, const std::string& content_type) {
  body = std::move(content);
  set_header("Content-Type", content_type);
}
std::string Response::get_header_value(const std::string& name) const {
  auto it = headers.find(name);
  return it == headers.end() ? std::string() : it->second;
}

void Router::add(std::string method, const std::string& pattern, std::size_t max_body, Handler handler) {
  routes_.push_back({std::move(method), std::regex(pattern), max_body, std::move(handler)});
}
void Router::Get(const std::string& pattern, Handler handler) {
  add("GET", pattern, 0, std::move(handler));
}
void Router::Delete(const std::string& pattern, Handler handler) {
  add("DELETE", pattern, 0, std::move(handler));
}
void Router::Post(const std::string& pattern, std::size_t max_body, Handler handler) {
  add("POST", pattern, max_body, std::move(handler));
}
void Router::Put(const std::string& pattern, std::size_t max_body, Handler handler) {
  add("PUT", pattern, max_body, std::move(handler));
}
void Router::Options(const std::string& pattern, Handler handler) {
  add("OPTIONS", pattern, 0, std::move(handler));
}

const Router::Route* Router::find(const std::string& method, const std::string& path, std::smatch& matches,
                                  std::string& allow) const {
  const std::string& wanted = method == "HEAD" ? std::string("GET") : method;
  allow.clear();
  for (const Route& r : routes_) {
    std::smatch m;
    if (!std::regex_match(path, m, r.pattern)) continue;
    if (r.method == wanted) {
      matches = std::move(m);
      return &r;
    }
    if (r.method != "OPTIONS" && allow.find(r.method) == std::string::npos)
      allow += (allow.empty() ? "" : ", ") + r.method;
  }
  return nullptr;
}

// ---- Trusted proxies -------------------------------------------------------------------------

namespace {

std::optional<std::vector<unsigned char>> address_bytes(const std::string& text) {
  beast::error_code ec;
  auto a = asio::ip::make_address(text, ec);
  if (ec) return std::nullopt;
  if (a.is_v6() && a.to_v6().is_v4_mapped()) a = asio::ip::make_address_v4(asio::ip::v4_mapped, a.to_v6());
  if (a.is_v4()) {
    auto b = a.to_v4().to_bytes();
    return std::vector<unsigned char>(b.begin(), b.end());
  }
  auto b = a.to_v6().to_bytes();
  return std::vector<unsigned char>(b.begin(), b.end());
}

std::string trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

}  // namespace

Result<TrustedProxies> TrustedProxies::parse(const std::vector<std::string>& specs) {
  TrustedProxies out;
  for (const std::string& spec : specs) {
    const auto slash = spec.find('/');
    auto bytes = address_bytes(spec.substr(0, slash));
    int prefix = bytes ? static_cast<int>(bytes->size() * 8) : 0;
    bool ok = bytes.has_value();
    if (ok && slash != std::string::npos) {
      try {
        std::size_t used = 0;
        prefix = std::stoi(spec.substr(slash + 1), &used);
        ok = used == spec.size() - slash - 1 && prefix >= 0 && prefix <= static_cast<int>(bytes->size() * 8);
      } catch (const std::exception&) {
        ok = false;
      }
    }
    if (!ok)
      return fail(ErrorCode::kBadRequest, "trusted proxy '" + spec + "' is not an address or address/prefix",
                  {{"", "must be like 10.0.0.0/8, 127.0.0.1 or ::1", "--trusted-proxies", 0, 0}});
    out.nets_.push_back({std::move(*bytes), prefix});
  }
  return out;
}

bool TrustedProxies::contains(const std::string& address) const {
  auto bytes = address_bytes(address);
  if (!bytes) return false;
  for (const Net& n : nets_) {
    if (n.bytes.size() != bytes->size()) continue;
    bool match = true;
    for (int bit = 0; bit < n.prefix && match; bit += 8) {
      const int take = std::min(8, n.prefix - bit);
      const unsigned mask = (0xFFu << (8 - take)) & 0xFFu;
      const auto i = static_cast<std::size_t>(bit / 8);
      match = ((n.bytes[i] ^ (*bytes)[i]) & mask) == 0;
    }
    if (match) return true;
  }
  return false;
}

std::string TrustedProxies::client(const std::string& peer, const std::string& forwarded_for) const {
  if (forwarded_for.empty() || !contains(peer)) return peer;
  std::string_view rest = forwarded_for;
  std::string candidate = peer;
  while (!rest.empty()) {
    const auto comma = rest.rfind(',');
    const std::string item = trim(comma == std::string_view::npos ? rest : rest.substr(comma + 1));
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(0, comma);
    if (!address_bytes(item)) return candidate;  // malformed: believe no further
    candidate = item;
    if (!contains(item)) return item;
  }
  return candidate;
}

// ---- The server --------------------------------------------------------------------------------

namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Percent-decoding; `plus_is_space` for query strings. nullopt for a broken escape or a NUL.
std::optional<std::string> decode(std::string_view s, bool plus_is_space) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c == '%') {
      if (i + 2 >= s.size()) return std::nullopt;
      const int hi = hex_value(s[i + 1]);
      const int lo = hex_value(s[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    } else if (c == '+' && plus_is_space) {
      c = ' ';
    }
    if (c == '\0') return std::nullopt;
    out.push_back(c);
  }
  return out;
}

bool parse_target(Request& req) {
  if (req.target.empty() || req.target.front() != '/') return false;
  const auto q = req.target.find('?');
  auto path = decode(std::string_view(req.target).substr(0, q), false);
  if (!path) return false;
  req.path = std::move(*path);
  if (q == std::string::npos) return true;
  std::string_view rest = std::string_view(req.target).substr(q + 1);
  while (!rest.empty()) {
    const auto amp = rest.find('&');
    const std::string_view pair = rest.substr(0, amp);
    rest = amp == std::string_view::npos ? std::string_view() : rest.substr(amp + 1);
    if (pair.empty()) continue;
    const auto eq = pair.find('=');
    auto key = decode(pair.substr(0, eq), true);
    auto value = decode(eq == std::string_view::npos ? std::string_view() : pair.substr(eq + 1), true);
    if (!key || !value) return false;
    req.params.emplace(std::move(*key), std::move(*value));
  }
  return true;
}

std::string mime_type(const std::filesystem::path& file) {
  static const std::map<std::string, std::string> types = {{".html", "text/html; charset=utf-8"},
                                                           {".js", "text/javascript; charset=utf-8"},
                                                           {".mjs", "text/javascript; charset=utf-8"},
                                                           {".css", "text/css; charset=utf-8"},
                                                           {".json", "application/json"},
                                                           {".svg", "image/svg+xml"},
                                                           {".png", "image/png"},
                                                           {".ico", "image/x-icon"},
                                                           {".yaml", "application/yaml"},
                                                           {".txt", "text/plain; charset=utf-8"},
                                                           {".wasm", "application/wasm"}};
  auto it = types.find(file.extension().string());
  return it == types.end() ? "application/octet-stream" : it->second;
}

// A file under the web root for a GET path, or nullopt. Paths with dot segments never leave it.
std::optional<std::filesystem::path> static_file(const std::string& web_root, const std::string& path) {
  if (web_root.empty() || path.find("..") != std::string::npos || path.find('\\') != std::string::npos)
    return std::nullopt;
  std::error_code ec;
  std::filesystem::path file = std::filesystem::path(web_root) / path.substr(1);
  if (std::filesystem::is_directory(file, ec)) file /= "index.html";
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  return file;
}

}  // namespace

namespace {

class Session;

// What every connection of one server shares.
struct HttpCore {
  HttpCore(HttpOptions o, const Router& r, HttpServer::Gate g, HttpServer::Observer obs)
      : options(std::move(o)),
        router(r),
        gate(std::move(g)),
        observer(std::move(obs)),
        io(std::max(1, options.io_threads)),
        acceptor(asio::make_strand(io)),
        workers(static_cast<std::size_t>(std::max(1, options.workers))) {}

  HttpOptions options;
  const Router& router;
  HttpServer::Gate gate;
  HttpServer::Observer observer;
  std::atomic<bool> stopping{false};
  std::atomic<std::size_t> refused{0};
  std::atomic<std::size_t> timeouts{0};
  int shutdown_ticks = 0;
  // Declared before the I/O context and the workers: sessions released while those are destroyed
  // (with their pending handlers) still count themselves out here.
  std::mutex mutex;  // guards the two tables below
  std::unordered_map<std::string, std::size_t> per_client;
  std::map<Session*, std::weak_ptr<Session>> sessions;
  asio::io_context io;
  tcp::acceptor acceptor;
  asio::thread_pool workers;  // destroyed before the I/O context its handlers write to
  asio::steady_timer shutdown_timer{io};

  void accept();
  bool admit(const std::string& peer);
  void forget(Session* s, const std::string& peer, bool counted);
  void wait_for_sessions();
};

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, HttpCore& server, std::string peer, bool counted)
      : stream_(std::move(socket)), server_(server), peer_(std::move(peer)), counted_(counted) {}
  ~Session() { server_.forget(this, peer_, counted_); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  void start() { read_header(); }

  // The server is stopping: a connection waiting for a request closes now; one being served
  // closes after its reply.
  void stop_if_idle() {
    asio::dispatch(stream_.get_executor(), [self = shared_from_this()] {
      if (self->waiting_) {
        beast::error_code ec;
        self->stream_.socket().shutdown(tcp::socket::shutdown_both, ec);
        self->stream_.close();
      }
    });
  }

 private:
  void read_header() {
    if (server_.stopping) return close();
    waiting_ = true;
    header_parser_.emplace();
    header_parser_->header_limit(static_cast<std::uint32_t>(server_.options.max_header_bytes));
    // The route decides the body limit once the header is known (read_body).
    header_parser_->body_limit(std::numeric_limits<std::uint64_t>::max());
    stream_.expires_after(server_.options.header_timeout);
    http::async_read_header(
        stream_, buffer_, *header_parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
  }

  void on_header(beast::error_code ec) {
    waiting_ = false;
    started_ = std::chrono::steady_clock::now();
    if (ec == beast::error::timeout) ++server_.timeouts;
    if (ec == http::error::header_limit)
      return refuse(
          Error(ErrorCode::kBadRequest, "the request header is larger than " +
                                            std::to_string(server_.options.max_header_bytes) + " bytes"),
          431);
    if (ec) {
      // A broken request line or header gets a 400; a client that left or timed out, nothing.
      if (ec.category() == http::make_error_code(http::error::bad_target).category() &&
          ec != http::error::end_of_stream && ec != http::error::partial_message)
        return refuse(Error(ErrorCode::kBadRequest, "malformed HTTP request: " + ec.message()));
      return close();
    }
    auto& h = header_parser_->get();
    req_ = Request{};
    res_ = Response{};
    req_.method = std::string(h.method_string());
    req_.target = std::string(h.target());
    for (const auto& field : h)
      req_.headers.emplace(std::string(field.name_string()), std::string(field.value()));
    req_.peer_addr = peer_;
    req_.remote_addr =
        server_.options.trusted_proxies.client(peer_, req_.get_header_value("X-Forwarded-For"));
    keep_alive_ = h.keep_alive() && ++served_ < server_.options.keep_alive_max;
    if (!parse_target(req_)) return refuse(Error(ErrorCode::kBadRequest, "malformed request target"));
    if (h.version() == 11 && !req_.has_header("Host"))
      return refuse(Error(ErrorCode::kBadRequest, "an HTTP/1.1 request needs a Host header"));
    if (auto refusal = server_.gate(req_, res_)) return refuse(*refusal);

    std::string allow;
    route_ = server_.router.find(req_.method, req_.path, req_.matches, allow);
    std::size_t limit = route_ ? route_->max_body : 0;
    if (!route_ && !allow.empty()) {
      res_.set_header("Allow", allow);
      return refuse(Error(ErrorCode::kMethodNotAllowed,
                          req_.method + " is not allowed on " + req_.path + " (allowed: " + allow + ")"));
    }
    if (!route_ && req_.method != "GET" && req_.method != "HEAD")
      return refuse(Error(ErrorCode::kNotFound, "no resource at " + req_.method + " " + req_.path));
    const bool has_body =
        h.chunked() || (h.has_content_length() && header_parser_->content_length().value_or(0) > 0);
    if (has_body && header_parser_->content_length().value_or(0) > limit) return too_large(limit);
    if (!has_body) return dispatch();
    if (h[http::field::expect] == "100-continue") {
      auto cont = std::make_shared<http::response<http::empty_body>>(http::status::continue_, h.version());
      stream_.expires_after(server_.options.write_timeout);
      return http::async_write(stream_, *cont,
                               [self = shared_from_this(), cont, limit](beast::error_code e, std::size_t) {
                                 if (e) return self->close();
                                 self->read_body(limit);
                               });
    }
    read_body(limit);
  }

  void read_body(std::size_t limit) {
    body_parser_.emplace(std::move(*header_parser_));
    body_parser_->body_limit(limit);
    const auto declared = body_parser_->content_length().value_or(limit);
    stream_.expires_after(
        server_.options.header_timeout +
        std::chrono::milliseconds(1000 * declared / std::max<std::size_t>(1, server_.options.min_body_rate)));
    http::async_read(stream_, buffer_, *body_parser_,
                     [self = shared_from_this(), limit](beast::error_code ec, std::size_t) {
                       if (ec == http::error::body_limit) return self->too_large(limit);
                       if (ec == beast::error::timeout) ++self->server_.timeouts;
                       if (ec == beast::error::timeout)
                         return self->refuse(
                             Error(ErrorCode::kBadRequest, "the request body did not arrive in time"), 408);
                       if (ec) return self->close();
                       self->req_.body = std::move(self->body_parser_->get().body());
                       self->dispatch();
                     });
  }

  void too_large(std::size_t limit) {
    refuse(Error(ErrorCode::kPayloadTooLarge, limit == 0 ? "this resource takes no request body"
                                                         : "the request body is larger than " +
                                                               std::to_string(limit) +
                                                               " bytes, the most this server accepts"));
  }

  // Runs the handler on a worker; the reply is written back on this connection's strand.
  void dispatch() {
    asio::post(server_.workers, [self = shared_from_this()] {
      self->handle();
      asio::dispatch(self->stream_.get_executor(), [self] { self->write(); });
    });
  }

  void handle() {
    try {
      if (route_) {
        route_->handler(req_, res_);
      } else if (auto file = (req_.method == "GET" || req_.method == "HEAD")
                                 ? static_file(server_.options.web_root, req_.path)
                                 : std::nullopt) {
        std::ifstream in(*file, std::ios::binary);
        std::ostringstream content;
        content << in.rdbuf();
        res_.set_content(content.str(), mime_type(*file));
        res_.set_header("Cache-Control", "no-cache");
      } else {
        reply_problem(res_, Error(ErrorCode::kNotFound, "no resource at " + req_.method + " " + req_.path),
                      req_.path);
      }
    } catch (const std::exception& e) {
      log_exception(e.what());
    } catch (...) {
      log_exception("unknown exception");
    }
    if (res_.status >= 400 && res_.body.empty())
      reply_problem(res_,
                    Error(code_for_status(res_.status),
                          "the request failed with HTTP status " + std::to_string(res_.status)),
                    req_.path);
  }

  void log_exception(const std::string& what) {
    log_line({{"level", "error"},
              {"event", "exception"},
              {"method", req_.method},
              {"path", req_.path},
              {"what", what}});
    res_ = Response{};
    reply_problem(res_, Error(ErrorCode::kInternal, "the server failed while handling this request"),
                  req_.path);
  }

  // Answers without reading the body and closes the connection afterwards.
  void refuse(const Error& error, int status = 0) {
    keep_alive_ = false;
    drain_ = true;
    Response res = std::move(res_);  // keeps headers the gate added (CORS, Allow)
    reply_problem(res, error, req_.path.empty() ? std::string("/") : req_.path);
    if (status) res.status = status;
    res_ = std::move(res);
    write();
  }

  void write() {
    if (server_.stopping) keep_alive_ = false;
    auto msg = std::make_shared<http::response<http::string_body>>();
    msg->version(11);
    msg->result(static_cast<unsigned>(res_.status));
    msg->set(http::field::server, "socsim");
    msg->set("X-Content-Type-Options", "nosniff");
    for (const auto& [k, v] : res_.headers) msg->insert(k, v);
    const bool head = req_.method == "HEAD";
    msg->body() = head ? std::string() : res_.body;
    msg->keep_alive(keep_alive_);
    msg->prepare_payload();
    if (head) msg->content_length(res_.body.size());
    if (server_.observer && !req_.method.empty())
      server_.observer(
          req_, res_,
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_).count());
    stream_.expires_after(server_.options.write_timeout);
    if (head) {
      auto sr = std::make_shared<http::response_serializer<http::string_body>>(*msg);
      return http::async_write_header(
          stream_, *sr,
          [self = shared_from_this(), msg, sr](beast::error_code ec, std::size_t) { self->after_write(ec); });
    }
    http::async_write(stream_, *msg, [self = shared_from_this(), msg](beast::error_code ec, std::size_t) {
      self->after_write(ec);
    });
  }

  void after_write(beast::error_code ec) {
    if (ec) return close();
    if (!keep_alive_) return drain_ ? lingering_close() : close();
    body_parser_.reset();
    read_header();
  }

  // After a refusal the client may still be sending its body: stop writing, read and drop what
  // comes for a moment, then close, so the reply is not lost to a reset.
  void lingering_close() {
    beast::error_code ec;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
    stream_.expires_after(std::chrono::seconds(2));
    discard();
  }
  void discard() {
    stream_.async_read_some(asio::buffer(sink_),
                            [self = shared_from_this()](beast::error_code ec, std::size_t n) {
                              self->discarded_ += n;
                              if (ec || self->discarded_ > (8u << 20)) return self->close();
                              self->discard();
                            });
  }

  void close() {
    beast::error_code ec;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ec);
    stream_.close();
  }

  beast::tcp_stream stream_;
  HttpCore& server_;
  std::string peer_;
  bool counted_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::empty_body>> header_parser_;
  std::optional<http::request_parser<http::string_body>> body_parser_;
  Request req_;
  Response res_;
  const Router::Route* route_ = nullptr;
  std::chrono::steady_clock::time_point started_{};
  int served_ = 0;
  bool keep_alive_ = true;
  bool waiting_ = false;
  bool drain_ = false;
  std::size_t discarded_ = 0;
  std::array<char, 16384> sink_{};
};

bool HttpCore::admit(const std::string& peer) {
  std::lock_guard<std::mutex> lock(mutex);
  if (sessions.size() >= options.max_connections) return false;
  if (options.trusted_proxies.contains(peer)) return true;
  auto& n = per_client[peer];
  if (n >= options.max_connections_per_client) return false;
  ++n;
  return true;
}

void HttpCore::forget(Session* s, const std::string& peer, bool counted) {
  std::lock_guard<std::mutex> lock(mutex);
  sessions.erase(s);
  if (!counted) return;
  auto it = per_client.find(peer);
  if (it != per_client.end() && --it->second == 0) per_client.erase(it);
}

void HttpCore::accept() {
  acceptor.async_accept(asio::make_strand(io), [this](beast::error_code ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted || stopping) return;
    if (!ec) {
      beast::error_code e2;
      const auto endpoint = socket.remote_endpoint(e2);
      std::string peer = e2 ? std::string() : endpoint.address().to_string();
      if (!e2 && endpoint.address().is_v6() && endpoint.address().to_v6().is_v4_mapped())
        peer = asio::ip::make_address_v4(asio::ip::v4_mapped, endpoint.address().to_v6()).to_string();
      if (e2 || !admit(peer)) {
        ++refused;
        // Too many connections: a short 503 written without waiting, then the socket closes.
        static const std::string kBusy = [] {
          const std::string body =
              R"({"type":"https://socsim.dev/problems/too-many-connections","title":"Too many connections",)"
              R"("status":503,"detail":"too many open connections from this address; retry later","errors":[]})";
          return "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/problem+json\r\n"
                 "Connection: close\r\nRetry-After: 1\r\nContent-Length: " +
                 std::to_string(body.size()) + "\r\n\r\n" + body;
        }();
        socket.non_blocking(true, e2);
        socket.write_some(asio::buffer(kBusy.data(), kBusy.size()), e2);
        socket.shutdown(tcp::socket::shutdown_both, e2);
      } else {
        const bool counted = !options.trusted_proxies.contains(peer);
        auto s = std::make_shared<Session>(std::move(socket), *this, peer, counted);
        {
          std::lock_guard<std::mutex> lock(mutex);
          sessions[s.get()] = s;
        }
        s->start();
      }
    }
    accept();
  });
}

// Once stopping: ends the I/O loop when the last connection has closed, or after 10 s.
void HttpCore::wait_for_sessions() {
  bool empty = false;
  {
    std::lock_guard<std::mutex> lock(mutex);
    empty = sessions.empty();
  }
  if (empty || ++shutdown_ticks > 100) return io.stop();
  shutdown_timer.expires_after(std::chrono::milliseconds(100));
  shutdown_timer.async_wait([this](beast::error_code) { wait_for_sessions(); });
}

}  // namespace

struct HttpServer::Impl : HttpCore {
  using HttpCore::HttpCore;
};

HttpServer::HttpServer(HttpOptions options, const Router& router, Gate gate, Observer observer)
    : impl_(std::make_unique<Impl>(std::move(options), router, std::move(gate), std::move(observer))) {}

HttpServer::~HttpServer() {
  stop();
  impl_->workers.join();
}

Result<int> HttpServer::bind() {
  // Many idle sockets are cheap here; let the process hold as many descriptors as it may.
  rlimit lim{};
  if (getrlimit(RLIMIT_NOFILE, &lim) == 0 && lim.rlim_cur < lim.rlim_max) {
    lim.rlim_cur = lim.rlim_max;
    setrlimit(RLIMIT_NOFILE, &lim);
  }
  beast::error_code ec;
  const auto address = asio::ip::make_address(impl_->options.host, ec);
  if (ec) return fail(ErrorCode::kInternal, "bad HTTP host '" + impl_->options.host + "'");
  tcp::endpoint ep(address, static_cast<unsigned short>(impl_->options.port));
  auto& a = impl_->acceptor;
  a.open(ep.protocol(), ec);
  if (!ec) a.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) a.bind(ep, ec);
  if (!ec) a.listen(asio::socket_base::max_listen_connections, ec);
  if (ec)
    return fail(ErrorCode::kInternal, "cannot listen on " + impl_->options.host + ":" +
                                          std::to_string(impl_->options.port) + " (" + ec.message() + ")");
  return static_cast<int>(a.local_endpoint().port());
}

void HttpServer::run() {
  if (impl_->stopping) return;
  impl_->accept();
  std::vector<std::thread> extra;
  for (int i = 1; i < impl_->options.io_threads; ++i) extra.emplace_back([this] { impl_->io.run(); });
  impl_->io.run();
  for (auto& t : extra) t.join();
}

void HttpServer::stop() {
  if (impl_->stopping.exchange(true)) return;
  asio::post(impl_->acceptor.get_executor(), [impl = impl_.get()] {
    beast::error_code ec;
    impl->acceptor.close(ec);
  });
  std::vector<std::shared_ptr<Session>> live;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    for (auto& [p, w] : impl_->sessions)
      if (auto s = w.lock()) live.push_back(std::move(s));
  }
  for (auto& s : live) s->stop_if_idle();
  live.clear();
  // Requests being handled finish and are answered; whatever still hangs after 10 s is cut.
  asio::post(impl_->io, [impl = impl_.get()] { impl->wait_for_sessions(); });
}

HttpStats HttpServer::stats() const {
  HttpStats s;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    s.connections = impl_->sessions.size();
  }
  s.refused_connections = impl_->refused;
  s.timeouts = impl_->timeouts;
  return s;
}

}  // namespace socsim::server
