#pragma once
// Deterministic random numbers that are identical on every platform and standard library.
// Algorithm: PCG32 (O'Neill 2014, "XSH RR" output, 64-bit LCG state) seeded through SplitMix64.
// std::uniform_*_distribution is deliberately not used: its output differs between libraries.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string_view>
#include <vector>

namespace socsim {

// SplitMix64 (Steele, Lea, Flood 2014): used to expand one seed into well-mixed words.
constexpr std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// FNV-1a 64: stable hash of a label, used to derive independent sub-streams ("rooms", "agent:17").
constexpr std::uint64_t fnv1a64(std::string_view s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

class Rng {
 public:
  explicit constexpr Rng(std::uint64_t seed, std::uint64_t stream = 0) {
    std::uint64_t sm = seed;
    const std::uint64_t init_state = splitmix64(sm);
    std::uint64_t sm2 = stream ^ 0xDA3E39CB94B95BDBULL;
    inc_ = (splitmix64(sm2) << 1u) | 1u;
    state_ = 0;
    next_u32();
    state_ += init_state;
    next_u32();
  }

  // An independent generator for a named purpose; the parent's sequence is not consumed.
  [[nodiscard]] Rng fork(std::string_view label) const {
    return Rng(state_ ^ fnv1a64(label), inc_ ^ fnv1a64(label));
  }

  constexpr std::uint32_t next_u32() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  constexpr std::uint64_t next_u64() {
    const std::uint64_t hi = next_u32();
    return (hi << 32u) | next_u32();
  }
  // Uniform in [0, 1) with 53 random bits.
  constexpr double uniform() { return static_cast<double>(next_u64() >> 11u) * 0x1.0p-53; }
  constexpr double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n) without modulo bias (rejection sampling). n must be > 0.
  constexpr std::uint32_t below(std::uint32_t n) {
    const std::uint32_t threshold = (0u - n) % n;
    for (;;) {
      const std::uint32_t r = next_u32();
      if (r >= threshold) return r % n;
    }
  }
  // Uniform integer in [lo, hi] inclusive.
  constexpr std::int64_t between(std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(below(static_cast<std::uint32_t>(hi - lo + 1)));
  }
  constexpr bool chance(double p) { return uniform() < p; }
  // Standard normal by Box–Muller (the cosine branch only, so one call = two uniforms).
  double normal(double mean = 0.0, double sd = 1.0) {
    double u1 = uniform();
    if (u1 <= 0.0) u1 = 0x1.0p-53;
    const double u2 = uniform();
    return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  // Index drawn with probability proportional to weights (non-negative, not all zero).
  std::size_t weighted(std::span<const double> weights) {
    double total = 0.0;
    for (double w : weights) total += w > 0.0 ? w : 0.0;
    if (total <= 0.0) return below(static_cast<std::uint32_t>(weights.size()));
    double r = uniform() * total;
    for (std::size_t i = 0; i < weights.size(); ++i) {
      const double w = weights[i] > 0.0 ? weights[i] : 0.0;
      if (r < w) return i;
      r -= w;
    }
    for (std::size_t i = weights.size(); i-- > 0;)
      if (weights[i] > 0.0) return i;
    return 0;
  }
  template <class T>
  void shuffle(std::vector<T>& v) {  // Fisher–Yates
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[below(static_cast<std::uint32_t>(i))]);
  }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[below(static_cast<std::uint32_t>(v.size()))];
  }

 public:
  // Same state and stream: the same numbers from here on (a memo of work done from this state).
  friend bool operator==(const Rng&, const Rng&) = default;

 private:
  std::uint64_t state_ = 0;
  std::uint64_t inc_ = 1;
};

}  // namespace socsim
