#pragma once
// What the crowd tests share: a simulation from a config, runner options, a file's text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/crowd/crowd_simulation.hpp"
#include "core/crowd/scenario_runner.hpp"

namespace socsim::crowd::fixtures {

inline CrowdSimulation make(SimulationConfig config = {}) {
  auto sim = CrowdSimulation::create(config);
  EXPECT_TRUE(sim) << sim.error().message();
  return std::move(*sim);
}

inline RunnerOptions options(std::uint64_t seed, unsigned threads = 1, std::filesystem::path base = {}) {
  RunnerOptions o;
  o.seed = seed;
  o.threads = threads;
  o.base_dir = std::move(base);
  return o;
}

// A program from its JSON text; a failed test when it does not read.
inline Program program(const char* text) {
  auto p = program_from_text(text);
  EXPECT_TRUE(p) << p.error().message();
  return *p;
}

inline std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace socsim::crowd::fixtures
