#pragma once
// What the route handlers share, and the functions that register each group of routes.
#include <chrono>
#include <optional>
#include <string>

#include <httplib.h>

#include "core/cards/catalogue.hpp"
#include "core/store/store.hpp"
#include "server/auth.hpp"
#include "server/config.hpp"
#include "server/event_hub.hpp"

namespace socsim::server {

struct RouteContext {
  ServerConfig config;
  store::Store& store;
  EventHub& events;
  cards::CardCatalogue catalogue;
  KeyRing keys;
  std::chrono::steady_clock::time_point started;
  int http_port = 0;

  // The author recorded for a write: the key's name, or "anonymous" on an open server.
  [[nodiscard]] std::string author(const httplib::Request& req) const;
  // Base of URLs handed to clients, from --public-host or the request's Host header.
  [[nodiscard]] std::string public_host(const httplib::Request& req) const;
};

void register_system_routes(httplib::Server& http, RouteContext& ctx);
void register_card_routes(httplib::Server& http, RouteContext& ctx);

// Embedded copies of schemas/ (openapi.yaml and the JSON Schemas), keyed by file name.
const std::map<std::string, std::string>& embedded_schemas();

// One structured log line on stdout.
void log_line(const Json& line);

}  // namespace socsim::server
