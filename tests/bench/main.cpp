// socsim-bench entry point: dispatches to the registered benchmark subcommands.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "tests/bench/bench.hpp"

namespace socsim::bench {

std::map<std::string, std::pair<std::string, BenchFn>>& registry() {
  static std::map<std::string, std::pair<std::string, BenchFn>> r;
  return r;
}

Registration::Registration(const char* name, const char* help, BenchFn fn) {
  registry()[name] = {help, std::move(fn)};
}

Args::Args(int argc, char** argv) {
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (a.rfind("--", 0) != 0) continue;
    a = a.substr(2);
    if (auto eq = a.find('='); eq != std::string::npos) {
      values_[a.substr(0, eq)] = a.substr(eq + 1);
    } else if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) {
      values_[a] = argv[++i];
    } else {
      values_[a] = "";
    }
  }
}

std::string Args::str(const std::string& key, const std::string& fallback) const {
  auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}
std::int64_t Args::integer(const std::string& key, std::int64_t fallback) const {
  auto it = values_.find(key);
  return it == values_.end() ? fallback : std::strtoll(it->second.c_str(), nullptr, 10);
}
double Args::number(const std::string& key, double fallback) const {
  auto it = values_.find(key);
  return it == values_.end() ? fallback : std::strtod(it->second.c_str(), nullptr);
}

double percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return 0.0;
  std::sort(samples.begin(), samples.end());
  const double rank = std::ceil(p / 100.0 * static_cast<double>(samples.size()));
  const auto idx = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(samples.size()))) - 1;
  return samples[idx];
}

}  // namespace socsim::bench

int main(int argc, char** argv) {
  using namespace socsim::bench;
  if (argc < 2 || registry().count(argv[1]) == 0) {
    std::cerr << "usage: socsim-bench <benchmark> [--option value ...]\n\nbenchmarks:\n";
    for (const auto& [name, entry] : registry()) std::cerr << "  " << name << "  " << entry.first << "\n";
    return argc < 2 ? 0 : 2;
  }
  return registry()[argv[1]].second(Args(argc - 1, argv + 1));
}
