#pragma once
// Bearer API keys for writes. Secrets are compared as SHA-256 digests in constant time (no
// early exit, no length leak) and never logged.
#include <optional>
#include <string>
#include <vector>

#include "server/config.hpp"

namespace socsim::server {

class KeyRing {
 public:
  explicit KeyRing(const std::vector<ApiKey>& keys);
  [[nodiscard]] bool enabled() const { return !entries_.empty(); }
  // The key's name for an "Authorization: Bearer <secret>" header value, or nullopt.
  [[nodiscard]] std::optional<std::string> authenticate(const std::string& authorization_header) const;

 private:
  struct Entry {
    std::string name;
    std::string digest;
  };
  std::vector<Entry> entries_;
};

bool constant_time_equal(const std::string& a, const std::string& b);

// The one authorisation rule for writes to an existing resource (REST and WebSocket alike): on a
// server with keys only its owner may act on it; a key-less server has no owners to protect.
inline bool may_act_for(const KeyRing& keys, const std::string& requester, const std::string& owner) {
  return !keys.enabled() || requester == owner;
}

}  // namespace socsim::server
