#pragma once
// Per-client token buckets: `rate` requests per second with bursts up to `burst`.
#include <chrono>
#include <mutex>
#include <string>
#include <unordered_map>

namespace socsim::server {

class RateLimiter {
 public:
  RateLimiter(double rate_per_s, double burst) : rate_(rate_per_s), burst_(burst) {}
  // 0 when the request may proceed, else the whole seconds to wait (for Retry-After).
  int admit(const std::string& client);
  [[nodiscard]] bool enabled() const { return rate_ > 0; }

 private:
  struct Bucket {
    double tokens;
    std::chrono::steady_clock::time_point last;
  };
  double rate_;
  double burst_;
  std::mutex mutex_;
  std::unordered_map<std::string, Bucket> buckets_;
  std::size_t admissions_ = 0;
};

}  // namespace socsim::server
