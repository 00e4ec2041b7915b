// GET /api/v1/health, /api/v1/info, /api/v1/openapi.yaml, /api/v1/schemas/{name}.
#include "server/http_util.hpp"
#include "server/routes.hpp"
#include "socsim/buildinfo.hpp"

namespace socsim::server {

RouteContext::RouteContext(Services& s)
    : services(s),
      config(s.config),
      store(s.store),
      events(s.events),
      jobs(*s.jobs),
      knowledge(*s.knowledge),
      llm(s.llm.get()),
      catalogue(s.store,
                [&] {
                  cards::CardLimits limits;
                  limits.max_prompt_bytes = s.config.max_prompt_bytes;
                  return limits;
                }()),
      keys(s.config.api_keys) {}

std::string RouteContext::author(const Request& req) const {
  if (!keys.enabled()) return "anonymous";
  return keys.authenticate(req.get_header_value("Authorization")).value_or("anonymous");
}

std::string RouteContext::client(const Request& req) const {
  if (keys.enabled()) return author(req);
  return "address:" + req.remote_addr;
}

Status RouteContext::check_model(const std::optional<std::string>& model) const {
  if (!model || !llm) return {};
  auto resolved = llm->config().resolve_model(model);
  if (!resolved) return tl::unexpected(resolved.error());
  return {};
}

Status RouteContext::llm_available() const {
  if (llm) return {};
  return fail(
      ErrorCode::kValidation,
      "no LLM endpoint is configured (set SOCSIM_LLM_URL), so only the offline generator is available",
      {FieldError{"/generator", "must be offline on this server"}});
}

Result<PageParams> RouteContext::page(const Request& req) const {
  return parse_page(query(req, "page_size"), query(req, "cursor"), config.default_page_size,
                    config.max_page_size);
}

void RouteContext::reply_job_accepted(Response& res, const Result<std::string>& job_id,
                                      const std::string& instance) const {
  if (!job_id) return reply_problem(res, job_id.error(), instance);
  auto job = jobs.get(*job_id);
  if (!job) return reply_problem(res, job.error(), instance);
  res.set_header("Location", "/api/v1/jobs/" + *job_id);
  reply_json(res, 202, *job);
}

std::string RouteContext::public_host(const Request& req) const {
  if (!config.public_host.empty()) return config.public_host;
  std::string host = req.get_header_value("Host");
  if (!host.empty() && host.front() == '[') {  // [::1]:8080
    return host.substr(0, host.find(']') + 1);
  }
  if (auto colon = host.find(':'); colon != std::string::npos) host = host.substr(0, colon);
  if (host.empty()) host = config.host == "0.0.0.0" ? "localhost" : config.host;
  return host;
}

namespace {
void system_routes(Router& http, RouteContext& ctx) {
  http.Get("/api/v1/health", [&ctx](const Request& req, Response& res) {
    auto count = ctx.catalogue.count();
    const double uptime =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - ctx.services.started).count();
    if (!count) {
      reply_problem(res, Error(ErrorCode::kStore, "the database is not answering: " + count.error().detail),
                    req.path);
      return;
    }
    reply_json(
        res, 200,
        {{"status", "ok"},
         {"database", {{"status", "ok"}, {"schema_version", ctx.store.schema_version()}, {"cards", *count}}},
         {"uptime_s", std::round(uptime * 10.0) / 10.0}});
  });

  http.Get("/api/v1/info", [&ctx](const Request& req, Response& res) {
    const auto& c = ctx.config;
    Json generators = Json::array();
    generators.push_back({{"name", "offline"}, {"available", true}, {"default", true}});
    generators.push_back(
        {{"name", "llm"},
         {"available", ctx.llm != nullptr},
         {"default", false},
         {"model", c.llm.model.empty() ? Json(nullptr) : Json(c.llm.model)},
         {"embedding_model", c.llm.embedding_model.empty() ? Json(nullptr) : Json(c.llm.embedding_model)}});
    reply_json(
        res, 200,
        {{"name", "socsim"},
         {"version", build::kVersion},
         {"build", {{"git_sha", build::kGitSha}, {"flavor", build::kFlavor}, {"compiler", build::kCompiler}}},
         {"api", "/api/v1"},
         {"openapi", "/api/v1/openapi.yaml"},
         {"generators", generators},
         {"websocket_url", "ws://" + ctx.public_host(req) + ":" + std::to_string(c.ws_port) + "/ws"},
         {"auth", {{"writes_require_key", ctx.keys.enabled()}, {"scheme", "Bearer"}}},
         {"limits",
          {{"max_body_bytes", c.max_body_bytes},
           {"max_prompt_bytes", c.max_prompt_bytes},
           {"max_page_size", c.max_page_size},
           {"rate_limit_rps", c.rate_limit_rps},
           {"rate_limit_burst", c.rate_limit_burst}}},
         {"schema_version", ctx.store.schema_version()}});
  });

  http.Get("/api/v1/openapi.yaml", [](const Request& req, Response& res) {
    const auto& files = embedded_schemas();
    auto it = files.find("openapi.yaml");
    if (it == files.end()) {
      reply_problem(res, Error(ErrorCode::kNotFound, "this build carries no openapi.yaml"), req.path);
      return;
    }
    res.set_content(it->second, "application/yaml");
  });

  http.Get(R"(/api/v1/schemas/([A-Za-z0-9_.\-/]+))", [](const Request& req, Response& res) {
    const auto& files = embedded_schemas();
    auto it = files.find(req.matches[1].str());
    if (it == files.end() || it->first.find("..") != std::string::npos) {
      reply_problem(res, Error(ErrorCode::kNotFound, "no schema named '" + req.matches[1].str() + "'"),
                    req.path);
      return;
    }
    const bool yaml = it->first.size() > 5 && it->first.substr(it->first.size() - 5) == ".yaml";
    res.set_content(it->second, yaml ? "application/yaml" : "application/schema+json");
  });
}

}  // namespace

SOCSIM_ROUTES("system", system_routes);

}  // namespace socsim::server
