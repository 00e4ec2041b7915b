#pragma once
// The REST transport: HTTP/1.1 on Boost.Beast. A connection costs a socket and a buffer, not a
// thread, so idle and slow clients cannot hold the workers. A request must arrive whole within
// deadlines (its header, then its body at a minimum rate); the gate judges the header before the
// body is read, and a refused request's connection is closed after the reply, so an unread body
// is never taken for the next request. Complete requests run on a worker pool.
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::server {

struct CaseInsensitiveLess {
  bool operator()(const std::string& a, const std::string& b) const;
};
using Headers = std::multimap<std::string, std::string, CaseInsensitiveLess>;

struct Request {
  std::string method;
  std::string target;  // as sent: path and query
  std::string path;    // percent-decoded, without the query
  Headers headers;
  std::multimap<std::string, std::string> params;  // decoded query parameters
  std::string body;
  std::string remote_addr;  // the client: the peer, or what a trusted proxy forwarded
  std::string peer_addr;    // the socket's peer
  std::smatch matches;      // the route pattern's groups over `path`

  [[nodiscard]] bool has_header(const std::string& name) const;
  [[nodiscard]] std::string get_header_value(const std::string& name) const;  // "" when absent
  [[nodiscard]] bool has_param(const std::string& name) const;
  [[nodiscard]] std::string get_param_value(const std::string& name) const;
};

struct Response {
  int status = 200;
  Headers headers;
  std::string body;
  void set_header(const std::string& name, const std::string& value);  // replaces
  void set_content(std::string content, const std::string& content_type);
  [[nodiscard]] std::string get_header_value(const std::string& name) const;
};

using Handler = std::function<void(const Request&, Response&)>;

// Routes by method and a regular expression over the whole path; the first registered match wins.
class Router {
 public:
  struct Route {
    std::string method;
    std::regex pattern;
    std::size_t max_body = 0;  // bytes the route reads; a larger body is refused with 413
    Handler handler;
  };
  void Get(const std::string& pattern, Handler handler);
  void Delete(const std::string& pattern, Handler handler);
  void Post(const std::string& pattern, std::size_t max_body, Handler handler);
  void Put(const std::string& pattern, std::size_t max_body, Handler handler);
  void Options(const std::string& pattern, Handler handler);

  // The route for a request. Without one, `allow` lists the methods the path has (empty: none).
  [[nodiscard]] const Route* find(const std::string& method, const std::string& path, std::smatch& matches,
                                  std::string& allow) const;

 private:
  void add(std::string method, const std::string& pattern, std::size_t max_body, Handler handler);
  std::vector<Route> routes_;
};

// Addresses whose X-Forwarded-For is believed: "127.0.0.1", "10.0.0.0/8", "::1", "fd00::/8".
class TrustedProxies {
 public:
  static Result<TrustedProxies> parse(const std::vector<std::string>& specs);
  [[nodiscard]] bool contains(const std::string& address) const;
  [[nodiscard]] bool empty() const { return nets_.empty(); }
  // The client behind trusted proxies: the rightmost X-Forwarded-For entry that is not a trusted
  // proxy itself; the peer when the peer is not trusted or the header is absent or malformed.
  [[nodiscard]] std::string client(const std::string& peer, const std::string& forwarded_for) const;

 private:
  struct Net {
    std::vector<unsigned char> bytes;  // 4 or 16
    int prefix = 0;
  };
  std::vector<Net> nets_;
};

struct HttpOptions {
  std::string host = "127.0.0.1";
  int port = 0;
  int io_threads = 2;
  int workers = 8;
  std::chrono::milliseconds header_timeout{10000};  // idle wait plus the whole header
  std::size_t min_body_rate = 64 * 1024;            // bytes/s: a body's deadline grows with its size
  std::chrono::milliseconds write_timeout{10000};   // the whole response
  std::size_t max_header_bytes = 16 * 1024;
  std::size_t max_connections = 4096;
  std::size_t max_connections_per_client = 64;  // by address; trusted proxies are exempt
  int keep_alive_max = 1000;                    // requests per connection
  std::string web_root;                         // static files for GET paths no route takes
  TrustedProxies trusted_proxies;
};

struct HttpStats {
  std::size_t connections = 0;
  std::size_t refused_connections = 0;
  std::size_t timeouts = 0;
};

class HttpServer {
 public:
  // Judges a request from its header alone (the body is not read yet). Returning an error refuses
  // it (the connection closes after the reply); `res` may gain headers for every reply (CORS).
  using Gate = std::function<std::optional<Error>(const Request&, Response&)>;
  // Sees every answered request (for the log), with its time from header to reply.
  using Observer = std::function<void(const Request&, const Response&, double duration_ms)>;

  HttpServer(HttpOptions options, const Router& router, Gate gate, Observer observer);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  Result<int> bind();  // port 0 picks a free one
  void run();          // serves until stop(); requests being handled finish first
  void stop();         // from any thread
  [[nodiscard]] HttpStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace socsim::server
