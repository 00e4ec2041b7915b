#include "server/access_policy.hpp"

#include <algorithm>
#include <cctype>

namespace socsim::server {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string trim(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

struct HostPort {
  std::string host;  // lower case, IPv6 without brackets, no trailing dot
  int port = 0;      // 0 = not given
};

// "example.org:8080", "[::1]:80", "::1" (bare IPv6 as written in --host).
std::optional<HostPort> split_host(std::string text) {
  HostPort out;
  text = lower(trim(std::move(text)));
  std::string port;
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string::npos) return std::nullopt;
    out.host = text.substr(1, close - 1);
    if (close + 1 < text.size()) {
      if (text[close + 1] != ':') return std::nullopt;
      port = text.substr(close + 2);
    }
  } else if (std::count(text.begin(), text.end(), ':') == 1) {
    const auto colon = text.find(':');
    out.host = text.substr(0, colon);
    port = text.substr(colon + 1);
  } else {
    out.host = text;
  }
  if (!out.host.empty() && out.host.back() == '.') out.host.pop_back();
  if (!port.empty()) {
    if (port.size() > 5 ||
        !std::all_of(port.begin(), port.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return std::nullopt;
    out.port = std::stoi(port);
  }
  return out;
}

// "http://host:port" → host and port (default 80/443).
std::optional<HostPort> split_origin(const std::string& origin) {
  const auto sep = origin.find("://");
  if (sep == std::string::npos) return std::nullopt;
  const std::string scheme = lower(origin.substr(0, sep));
  auto hp = split_host(origin.substr(sep + 3));
  if (!hp) return std::nullopt;
  if (hp->port == 0) hp->port = scheme == "https" ? 443 : 80;
  return hp;
}

}  // namespace

AccessPolicy::AccessPolicy(const ServerConfig& config) {
  for (const std::string& o : config.allowed_origins) {
    if (o == "*") any_origin_ = true;
    std::string origin = lower(trim(o));
    while (!origin.empty() && origin.back() == '/') origin.pop_back();
    origins_.push_back(std::move(origin));
  }
  const bool any_host = std::find(config.allowed_hosts.begin(), config.allowed_hosts.end(), "*") !=
                            config.allowed_hosts.end() ||
                        (config.allowed_hosts.empty() && (config.host == "0.0.0.0" || config.host == "::"));
  if (any_host) return;
  for (std::string h : {std::string("localhost"), std::string("127.0.0.1"), std::string("::1"), config.host,
                        config.public_host})
    if (auto hp = split_host(h); hp && !hp->host.empty()) hosts_.push_back(hp->host);
  for (const std::string& h : config.allowed_hosts)
    if (auto hp = split_host(h); hp && !hp->host.empty()) hosts_.push_back(hp->host);
}

std::optional<Error> AccessPolicy::check_host(const std::string& host_header) const {
  if (hosts_.empty()) return std::nullopt;
  auto hp = split_host(host_header);
  if (hp && std::find(hosts_.begin(), hosts_.end(), hp->host) != hosts_.end()) return std::nullopt;
  return Error(
      ErrorCode::kBadRequest,
      "this server does not answer for Host '" + host_header + "' (serve other names with --allowed-hosts)",
      {{"", "unknown host", "Host", 0, 0}});
}

bool AccessPolicy::same_origin(const std::string& origin, const std::string& host_header, int page_port) {
  auto o = split_origin(origin);
  auto h = split_host(host_header);
  if (!o || !h) return false;
  const int port = page_port > 0 ? page_port : (h->port ? h->port : 80);
  return o->host == h->host && o->port == port;
}

bool AccessPolicy::listed_origin(const std::string& origin) const {
  if (any_origin_) return true;
  std::string o = lower(trim(origin));
  while (!o.empty() && o.back() == '/') o.pop_back();
  return std::find(origins_.begin(), origins_.end(), o) != origins_.end();
}

std::optional<Error> AccessPolicy::check_origin(const std::string& origin, const std::string& host_header,
                                                int page_port) const {
  if (origin.empty() || same_origin(origin, host_header, page_port) || listed_origin(origin))
    return std::nullopt;
  return Error(ErrorCode::kForbidden,
               "requests from pages of origin '" + origin + "' are refused (allow it with --allowed-origins)",
               {{"", "cross-site request", "Origin", 0, 0}});
}

bool AccessPolicy::cors_origin(const std::string& origin, const std::string& host_header) const {
  return !origin.empty() && !same_origin(origin, host_header, 0) && listed_origin(origin);
}

std::optional<Error> check_media_type(const std::string& content_type) {
  const auto semi = content_type.find(';');
  const std::string type = lower(trim(content_type.substr(0, semi)));
  bool ok = type == "application/json" || type == "application/yaml" || type == "application/x-yaml" ||
            type == "text/yaml";
  if (!ok && type.rfind("application/", 0) == 0 && type.size() > 17 && type.ends_with("+json")) {
    const std::string sub = type.substr(12, type.size() - 17);
    ok = std::all_of(sub.begin(), sub.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-';
    });
  }
  // Parameters: only charset=utf-8 (a cross-site form cannot smuggle "+json" into one).
  std::string rest = semi == std::string::npos ? std::string() : content_type.substr(semi + 1);
  while (ok && !trim(rest).empty()) {
    const auto next = rest.find(';');
    std::string param = lower(trim(rest.substr(0, next)));
    param.erase(std::remove(param.begin(), param.end(), ' '), param.end());
    ok = param == "charset=utf-8" || param == "charset=\"utf-8\"";
    rest = next == std::string::npos ? std::string() : rest.substr(next + 1);
  }
  if (ok) return std::nullopt;
  return Error(ErrorCode::kUnsupportedMediaType,
               content_type.empty() ? "a request body needs Content-Type: application/json"
                                    : "send the body as application/json (got '" + content_type + "')",
               {{"", "unsupported media type", "Content-Type", 0, 0}});
}

std::optional<std::string> bearer_token(const std::string& header) {
  const std::string h = trim(header);
  const auto space = h.find_first_of(" \t");
  if (space == std::string::npos || lower(h.substr(0, space)) != "bearer") return std::nullopt;
  std::string token = trim(h.substr(space + 1));
  if (token.empty()) return std::nullopt;
  return token;
}

}  // namespace socsim::server
