#pragma once
// One HTTP POST of JSON over libcurl, hardened for talking to a configured LLM endpoint: http and
// https only, redirects only within the same origin, timeouts, a response size cap, cancellation.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/llm/cancel_token.hpp"

namespace socsim::llm {

struct HttpUrl {
  std::string scheme;  // "http" | "https"
  std::string host;
  int port = 0;                              // explicit or the scheme's default
  std::string path;                          // "" or starting with "/"
  [[nodiscard]] std::string origin() const;  // scheme://host[:port] (port only when not default)
};

// Accepts absolute http/https URLs with a host and no credentials, query or fragment.
Result<HttpUrl> parse_http_url(std::string_view url);

struct HttpLimits {
  int connect_timeout_ms = 5000;
  int timeout_ms = 300000;  // whole exchange
  int stall_timeout_ms = 120000;
  std::size_t max_response_bytes = 8u << 20;
  int max_redirects = 3;  // same-origin only
};

struct HttpResponse {
  long status = 0;
  std::string body;
  std::optional<int> retry_after_s;  // from Retry-After (seconds or HTTP date)
  std::string effective_url;
};

enum class TransportFailure {
  kConnect,   // refused, unreachable, DNS, TLS handshake
  kTimeout,   // connect or total or stall timeout
  kBroken,    // connection dropped mid-answer, empty reply
  kTooLarge,  // response over max_response_bytes
  kRedirect,  // redirect to another origin, or too many
  kCancelled,
  kOther,
};

struct TransportError {
  TransportFailure kind = TransportFailure::kOther;
  std::string
      message;  // libcurl's explanation, e.g. "Failed to connect to 127.0.0.1 port 9: Connection refused"
};

// POSTs `body` as application/json. HTTP error statuses are responses, not transport errors.
tl::expected<HttpResponse, TransportError> http_post_json(const std::string& url, const std::string& body,
                                                          const std::vector<std::string>& headers,
                                                          const HttpLimits& limits,
                                                          const CancelToken& cancel);

}  // namespace socsim::llm
