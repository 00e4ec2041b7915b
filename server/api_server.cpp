#include "server/api_server.hpp"

#include <cmath>
#include <filesystem>

#include "server/access_policy.hpp"
#include "server/auth.hpp"
#include "server/http_server.hpp"
#include "server/http_util.hpp"
#include "server/rate_limit.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

bool is_write(const std::string& method) {
  return method == "POST" || method == "PUT" || method == "PATCH" || method == "DELETE";
}

bool has_body(const Request& req) {
  if (req.has_header("Transfer-Encoding")) return true;
  const std::string length = req.get_header_value("Content-Length");
  return !length.empty() && length.find_first_not_of('0') != std::string::npos;
}

HttpOptions http_options(const ServerConfig& cfg) {
  HttpOptions o;
  o.host = cfg.host;
  o.port = cfg.port;
  o.workers = cfg.threads;
  o.header_timeout = std::chrono::seconds(cfg.read_timeout_s);
  o.write_timeout = std::chrono::seconds(cfg.write_timeout_s);
  o.max_connections_per_client = cfg.max_connections_per_client;
  o.trusted_proxies = TrustedProxies::parse(cfg.trusted_proxies).value_or(TrustedProxies{});
  if (std::filesystem::is_directory(cfg.web_root)) {
    o.web_root = cfg.web_root;
  } else {
    log_line({{"level", "warn"}, {"event", "web_root_missing"}, {"web_root", cfg.web_root}});
  }
  return o;
}

}  // namespace

struct ApiServer::Impl {
  explicit Impl(Services& s)
      : ctx(s), limiter(s.config.rate_limit_rps, s.config.rate_limit_burst), policy(s.config) {}

  // Judges a request by its header: rate, Host, Origin, key, media type. Runs before the body is
  // read; a refusal closes the connection, so an unread body is never parsed as a request.
  std::optional<Error> gate(const Request& req, Response& res) {
    if (int wait = limiter.admit(req.remote_addr); wait > 0) {
      Error e(ErrorCode::kRateLimited,
              "more than " + std::to_string(ctx.config.rate_limit_rps) +
                  " requests per second from this client; retry after " + std::to_string(wait) + " s",
              {{"", "rate limit"}});
      e.retry_after_s = wait;
      return e;
    }
    const std::string host = req.get_header_value("Host");
    if (auto e = policy.check_host(host)) return e;
    const std::string origin = req.get_header_value("Origin");
    if (policy.cors_origin(origin, host)) {
      res.set_header("Access-Control-Allow-Origin", origin);
      res.set_header("Vary", "Origin");
    }
    if (req.method == "OPTIONS") return policy.check_origin(origin, host);  // CORS preflight
    if (req.path.rfind("/api/", 0) != 0 || !is_write(req.method)) return std::nullopt;
    if (auto e = policy.check_origin(origin, host)) return e;
    if (ctx.keys.enabled() && !ctx.keys.authenticate(req.get_header_value("Authorization")))
      return Error(
          ErrorCode::kUnauthorized,
          "this server requires 'Authorization: Bearer <key>' for writes; the key is missing or unknown",
          {{"", "missing or unknown key", "Authorization", 0, 0}});
    if (req.has_header("Content-Type") || has_body(req))
      if (auto e = check_media_type(req.get_header_value("Content-Type"))) return e;
    return std::nullopt;
  }

  RouteContext ctx;
  RateLimiter limiter;
  AccessPolicy policy;
  Router router;
  std::unique_ptr<HttpServer> http;
};

ApiServer::ApiServer(Services& services) : impl_(std::make_unique<Impl>(services)) {
  for (auto& [name, registrar] : route_groups()) registrar(impl_->router, impl_->ctx);
  // CORS preflight of an allowed origin (the gate refuses others).
  impl_->router.Options(".*", [](const Request&, Response& res) {
    res.status = 204;
    res.set_header("Access-Control-Allow-Methods", "GET, POST, PUT, DELETE");
    res.set_header("Access-Control-Allow-Headers", "Authorization, Content-Type, If-None-Match");
    res.set_header("Access-Control-Max-Age", "600");
  });
  auto gate = [impl = impl_.get()](const Request& req, Response& res) { return impl->gate(req, res); };
  auto observe = [](const Request& req, const Response& res, double ms) {
    log_line({{"level", "info"},
              {"event", "request"},
              {"method", req.method},
              {"path", req.path},
              {"status", res.status},
              {"bytes_in", req.body.size()},
              {"bytes_out", res.body.size()},
              {"client", req.remote_addr},
              {"duration_ms", std::round(ms * 1000.0) / 1000.0}});
  };
  impl_->http = std::make_unique<HttpServer>(http_options(services.config), impl_->router, gate, observe);
}

ApiServer::~ApiServer() = default;

Result<int> ApiServer::bind() {
  auto port = impl_->http->bind();
  if (!port) return port;
  port_ = *port;
  impl_->ctx.http_port = port_;
  return port_;
}

void ApiServer::run() {
  impl_->http->run();
}
void ApiServer::stop() {
  impl_->http->stop();
}

}  // namespace socsim::server
