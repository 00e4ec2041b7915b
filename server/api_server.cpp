#include "server/api_server.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>

#include "server/auth.hpp"
#include "server/http_util.hpp"
#include "server/rate_limit.hpp"
#include "server/routes.hpp"
#include "socsim/buildinfo.hpp"

namespace socsim::server {
namespace {

thread_local std::chrono::steady_clock::time_point t_request_start{};

bool is_write(const std::string& method) {
  return method == "POST" || method == "PUT" || method == "PATCH" || method == "DELETE";
}

bool json_content_type(const std::string& ct) {
  // YAML is accepted too: POST /api/v1/worlds/validate takes a world.yaml text.
  return ct.empty() || ct.rfind("application/json", 0) == 0 || ct.rfind("application/problem+json", 0) == 0 ||
         (ct.find("+json") != std::string::npos) || ct.rfind("application/yaml", 0) == 0 ||
         ct.rfind("text/yaml", 0) == 0;
}

std::mutex& log_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

void log_line(const Json& line) {
  const std::string text = line.dump(-1, ' ', false, Json::error_handler_t::replace);
  std::lock_guard<std::mutex> lock(log_mutex());
  std::cout << text << '\n' << std::flush;
}

struct ApiServer::Impl {
  explicit Impl(Services& s) : ctx(s), limiter(s.config.rate_limit_rps, s.config.rate_limit_burst) {}
  RouteContext ctx;
  RateLimiter limiter;
  httplib::Server http;
};

ApiServer::ApiServer(Services& services) : impl_(std::make_unique<Impl>(services)) {
  auto& http = impl_->http;
  auto& ctx = impl_->ctx;
  const ServerConfig& cfg = ctx.config;

  http.new_task_queue = [n = cfg.threads] { return new httplib::ThreadPool(static_cast<std::size_t>(n)); };
  http.set_payload_max_length(kBodyDrainFactor *
                              cfg.max_body_bytes);  // POST routes enforce max_body (http_util)
  http.set_read_timeout(cfg.read_timeout_s, 0);
  http.set_write_timeout(cfg.write_timeout_s, 0);
  http.set_tcp_nodelay(true);  // small JSON replies must not wait for delayed ACKs (Nagle)
  http.set_keep_alive_max_count(100);
  http.set_keep_alive_timeout(5);
  http.set_default_headers({{"X-Content-Type-Options", "nosniff"}});

  http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    t_request_start = std::chrono::steady_clock::now();
    if (int wait = impl_->limiter.admit(req.remote_addr); wait > 0) {
      Error e(ErrorCode::kRateLimited, "more than " + std::to_string(impl_->ctx.config.rate_limit_rps) +
                                           " requests per second from this client; retry after " +
                                           std::to_string(wait) + " s");
      e.retry_after_s = wait;
      reply_problem(res, e, req.path);
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.path.rfind("/api/", 0) == 0 && is_write(req.method)) {
      if (impl_->ctx.keys.enabled() && !impl_->ctx.keys.authenticate(req.get_header_value("Authorization"))) {
        reply_problem(res,
                      Error(ErrorCode::kUnauthorized,
                            "this server requires 'Authorization: Bearer <key>' for writes; the key is "
                            "missing or unknown"),
                      req.path);
        return httplib::Server::HandlerResponse::Handled;
      }
      // The body is not read yet: judge by the declared type.
      if (req.has_header("Content-Type") && !json_content_type(req.get_header_value("Content-Type"))) {
        reply_problem(
            res,
            Error(ErrorCode::kUnsupportedMediaType,
                  "send the body as application/json (got '" + req.get_header_value("Content-Type") + "')"),
            req.path);
        return httplib::Server::HandlerResponse::Handled;
      }
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // Every 4xx/5xx without a body (unknown route, body too large, …) becomes problem+json.
  http.set_error_handler(
      httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        std::string detail;
        switch (res.status) {
          case 404:
            detail = "no resource at " + req.method + " " + req.path;
            break;
          case 413:
            detail = "the request body is larger than this server accepts";
            break;
          default:
            detail = "the request failed with HTTP status " + std::to_string(res.status);
        }
        reply_problem(res, Error(code_for_status(res.status), detail), req.path);
        return httplib::Server::HandlerResponse::Handled;
      }));

  http.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "unknown exception";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    log_line({{"level", "error"},
              {"event", "exception"},
              {"method", req.method},
              {"path", req.path},
              {"what", what}});
    reply_problem(res, Error(ErrorCode::kInternal, "the server failed while handling this request"),
                  req.path);
  });

  http.set_logger([](const httplib::Request& req, const httplib::Response& res) {
    Json line = {{"level", "info"},
                 {"event", "request"},
                 {"method", req.method},
                 {"path", req.path},
                 {"status", res.status},
                 {"bytes_in", req.body.size()},
                 {"bytes_out", res.body.size()},
                 {"client", req.remote_addr}};
    if (t_request_start != std::chrono::steady_clock::time_point{}) {
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_request_start)
              .count();
      line["duration_ms"] = std::round(ms * 1000.0) / 1000.0;
      t_request_start = {};
    }
    log_line(line);
  });

  for (auto& [name, registrar] : route_groups()) registrar(http, ctx);

  if (std::filesystem::is_directory(cfg.web_root)) {
    http.set_mount_point("/", cfg.web_root);
  } else {
    log_line({{"level", "warn"}, {"event", "web_root_missing"}, {"web_root", cfg.web_root}});
  }
}

ApiServer::~ApiServer() = default;

Result<int> ApiServer::bind() {
  auto& http = impl_->http;
  const auto& cfg = impl_->ctx.config;
  if (cfg.port == 0) {
    port_ = http.bind_to_any_port(cfg.host.c_str());
    if (port_ <= 0) return fail(ErrorCode::kInternal, "cannot bind an HTTP port on " + cfg.host);
  } else {
    if (!http.bind_to_port(cfg.host.c_str(), cfg.port))
      return fail(ErrorCode::kInternal, "cannot listen on " + cfg.host + ":" + std::to_string(cfg.port) +
                                            " (in use, or not allowed)");
    port_ = cfg.port;
  }
  impl_->ctx.http_port = port_;
  return port_;
}

void ApiServer::run() {
  impl_->http.listen_after_bind();
}
void ApiServer::stop() {
  impl_->http.stop();
}

}  // namespace socsim::server
