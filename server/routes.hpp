#pragma once
// What the route handlers share. Route groups live in routes_*.cpp and register themselves with
// SOCSIM_ROUTES (server/registry.hpp).
#include <chrono>
#include <map>
#include <optional>
#include <string>

#include "core/cards/catalogue.hpp"
#include "server/auth.hpp"
#include "server/http_util.hpp"
#include "server/pagination.hpp"
#include "server/registry.hpp"
#include "server/services.hpp"

namespace socsim::server {

struct RouteContext {
  Services& services;
  const ServerConfig& config;
  store::Store& store;
  EventHub& events;
  JobRunner& jobs;
  knowledge::KnowledgeBase& knowledge;
  llm::LlmClient* llm;  // null when no endpoint is configured
  cards::CardCatalogue catalogue;
  KeyRing keys;
  int http_port = 0;

  explicit RouteContext(Services& s);
  // The author recorded for a write: the key's name, or "anonymous" on an open server.
  [[nodiscard]] std::string author(const Request& req) const;
  // Host name for URLs handed to clients: --public-host, else the request's Host header.
  [[nodiscard]] std::string public_host(const Request& req) const;
  // Whether a write may touch another author's resource (open servers have no authors to protect).
  [[nodiscard]] bool any_author() const { return !keys.enabled(); }
  // Who a per-client quota counts against: the key's name, or the client address on an open server.
  [[nodiscard]] std::string client(const Request& req) const;
  // A model a request names must be one this server allows (llm::LlmConfig::resolve_model): 422 at
  // /model before any job is queued. Nothing to check without a model or an LLM endpoint.
  [[nodiscard]] Status check_model(const std::optional<std::string>& model) const;
  // The answer to a request that queued a job: 202 with the job and Location: /api/v1/jobs/{id},
  // or the problem that kept it from being queued (429 over the client's quota, 503 queue full).
  void reply_job_accepted(Response& res, const Result<std::string>& job_id,
                          const std::string& instance) const;
  // A request for the LLM generator on a server without an LLM endpoint: 422 at /generator.
  [[nodiscard]] Status llm_available() const;
  // ?page_size= and ?cursor= of a list request, with this server's default and maximum page size.
  [[nodiscard]] Result<PageParams> page(const Request& req) const;
};

// Embedded copies of schemas/ (openapi.yaml and the JSON Schemas), keyed by file name.
const std::map<std::string, std::string>& embedded_schemas();

}  // namespace socsim::server
