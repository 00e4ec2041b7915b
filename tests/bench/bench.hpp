#pragma once
// socsim-bench: one program, one subcommand per area (`socsim-bench crowd --agents 10000`).
// Each benchmark prints one JSON object per line on stdout, so results can be piped to jq and
// recorded in docs/PERFORMANCE.md with the command that produced them.
#include <chrono>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace socsim::bench {

// Command-line options of one subcommand: --key value pairs and bare --flags.
class Args {
 public:
  Args(int argc, char** argv);
  [[nodiscard]] bool has(const std::string& key) const { return values_.count(key) > 0; }
  [[nodiscard]] std::string str(const std::string& key, const std::string& fallback) const;
  [[nodiscard]] std::int64_t integer(const std::string& key, std::int64_t fallback) const;
  [[nodiscard]] double number(const std::string& key, double fallback) const;

 private:
  std::map<std::string, std::string> values_;
};

using BenchFn = std::function<int(const Args&)>;

struct Registration {
  Registration(const char* name, const char* help, BenchFn fn);
};

std::map<std::string, std::pair<std::string, BenchFn>>& registry();

// Prints one result line.
inline void emit(const nlohmann::json& line) {
  std::cout << line.dump() << std::endl;
}

// Percentile (0..100) of samples by nearest rank; sorts a copy.
double percentile(std::vector<double> samples, double p);

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
inline double ms_since(std::chrono::steady_clock::time_point t0) {
  return seconds_since(t0) * 1e3;
}

}  // namespace socsim::bench

#define SOCSIM_BENCH_CAT2(a, b) a##b
#define SOCSIM_BENCH_CAT(a, b) SOCSIM_BENCH_CAT2(a, b)
// SOCSIM_BENCH("crowd", "help text", [](const Args& a) { ...; return 0; });
#define SOCSIM_BENCH(name, help, fn) \
  static const ::socsim::bench::Registration SOCSIM_BENCH_CAT(socsim_bench_reg_, __COUNTER__)(name, help, fn)
