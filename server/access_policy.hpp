#pragma once
// Who may talk to the daemon from where: the Host names it answers (against DNS rebinding), the
// origins whose pages may write or open WebSockets (against cross-site requests), and the media
// types a write may carry. One policy for REST and WebSocket.
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "server/config.hpp"

namespace socsim::server {

class AccessPolicy {
 public:
  explicit AccessPolicy(const ServerConfig& config);
  // A refusal for a Host header this server does not answer, or nullopt.
  [[nodiscard]] std::optional<Error> check_host(const std::string& host_header) const;
  // A refusal for a cross-site Origin (absent Origin: a non-browser client, allowed). Same-origin
  // means the Origin's host is the Host header's and its port is `page_port` (the WebSocket port
  // serves pages of the HTTP port), or the Host header's port when `page_port` is 0.
  [[nodiscard]] std::optional<Error> check_origin(const std::string& origin, const std::string& host_header,
                                                  int page_port = 0) const;
  // Whether CORS headers should name this origin (a listed origin other than the server's own).
  [[nodiscard]] bool cors_origin(const std::string& origin, const std::string& host_header) const;

 private:
  [[nodiscard]] static bool same_origin(const std::string& origin, const std::string& host_header,
                                        int page_port);
  [[nodiscard]] bool listed_origin(const std::string& origin) const;
  std::vector<std::string> hosts_;  // lower-case names without port; empty = any
  std::vector<std::string> origins_;
  bool any_origin_ = false;
};

// A write's body type: application/json, application/<x>+json or YAML (world.yaml uploads); the
// only parameter allowed is charset=utf-8. Browsers send none of these cross-site without a
// preflight. A refusal, or nullopt.
std::optional<Error> check_media_type(const std::string& content_type);

// "Bearer <secret>", the scheme in any case (RFC 7235); nullopt when the header is not Bearer.
std::optional<std::string> bearer_token(const std::string& authorization_header);

}  // namespace socsim::server
