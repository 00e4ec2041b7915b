#include "server/auth.hpp"

#include "core/common/sha256.hpp"
#include "server/access_policy.hpp"

namespace socsim::server {

bool constant_time_equal(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

KeyRing::KeyRing(const std::vector<ApiKey>& keys) {
  for (const auto& k : keys) entries_.push_back({k.name, sha256_hex(k.secret)});
}

std::optional<std::string> KeyRing::authenticate(const std::string& header) const {
  const auto token = bearer_token(header);
  if (!token) return std::nullopt;
  const std::string digest = sha256_hex(*token);
  std::optional<std::string> found;
  for (const auto& e : entries_)  // every entry is compared, whichever matches
    if (constant_time_equal(e.digest, digest)) found = e.name;
  return found;
}

}  // namespace socsim::server
