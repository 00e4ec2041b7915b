#include "core/common/ids.hpp"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <random>

namespace socsim {
namespace {
constexpr std::string_view kCrockford = "0123456789abcdefghjkmnpqrstvwxyz";
}

std::string random_id(std::string_view prefix) {
  static thread_local std::mt19937_64 gen{std::random_device{}()};
  std::string id(prefix);
  std::uint64_t a = gen(), b = gen();
  for (int i = 0; i < 20; ++i) {
    std::uint64_t& src = i < 12 ? a : b;
    id.push_back(kCrockford[src & 31u]);
    src >>= 5u;
  }
  return id;
}

bool is_random_id(std::string_view s, std::string_view prefix) {
  if (s.size() != prefix.size() + 20 || s.substr(0, prefix.size()) != prefix) return false;
  for (char ch : s.substr(prefix.size()))
    if (kCrockford.find(ch) == std::string_view::npos) return false;
  return true;
}

std::string utc_now_rfc3339() {
  const auto now = std::chrono::system_clock::now();
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms));
  return buf;
}

}  // namespace socsim
