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

}  // namespace socsim::server
