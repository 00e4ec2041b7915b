#pragma once
// Test data of the interop tests: our own pedsim scenario, the repo's example world and
// programs, and file access to the peers' files (tests skip when ../shared is absent).
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/crowd/program.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/interop/pedsim_program.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/world/world_yaml.hpp"

namespace socsim::interop::testing {

// A 24 x 12 m hall: entrance, a ticket queue growing west, a shop window attraction and a robot.
inline constexpr const char* kHall = R"(<?xml version="1.0" encoding="UTF-8"?>
<scenario>
  <obstacle x1="0" y1="0" x2="24" y2="0"/>
  <obstacle x1="24" y1="0" x2="24" y2="12"/>
  <obstacle x1="24" y1="12" x2="0" y2="12"/>
  <obstacle x1="0" y1="12" x2="0" y2="0"/>
  <waypoint id="door" x="2" y="6" r="1.5"/>
  <waypoint id="platform" x="21" y="3" r="2"/>
  <waypoint id="kiosk" x="12" y="10" r="1.5"/>
  <queue id="tickets" x="16" y="6" direction="180"/>
  <attraction id="window" x="12" y="11" width="6" height="1.5" strength="4"/>
  <agent x="4" y="6" n="10" dx="2" dy="3" type="0">
    <addwaypoint id="door"/>
    <addqueue id="tickets"/>
    <addwaypoint id="platform"/>
  </agent>
  <agent x="20" y="9" n="6" dx="2" dy="2" type="1">
    <addwaypoint id="kiosk"/>
    <addwaypoint id="door"/>
  </agent>
  <agent x="6" y="2" n="4" dx="1" dy="1" type="3">
    <addwaypoint id="platform"/>
    <addwaypoint id="door"/>
  </agent>
  <agent x="3" y="3" n="1" dx="0" dy="0" type="2">
    <addwaypoint id="platform"/>
    <addwaypoint id="door"/>
  </agent>
</scenario>
)";

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string peer(const std::string& dir, const std::string& file) {
  return std::string(SOCSIM_SHARED_DIR) + "/peers/" + dir + "/" + file;
}

inline std::string example(const std::string& file) {
  return read_text(std::string(SOCSIM_SOURCE_DIR) + "/schemas/examples/" + file);
}

inline world::World clinic() {
  return world::world_from_yaml(example("world_clinic.yaml")).value();
}

inline crowd::Program example_program(const std::string& file) {
  auto p = crowd::program_from_text(example(file));
  if (!p) ADD_FAILURE() << file << ": " << p.error().message();
  return p.value_or(crowd::Program{});
}

// kHall imported and simulated for `seconds` (seed 0), logged at 10 Hz.
struct HallRun {
  ImportedPedsim imported;
  scenario::TrajectoryLog log;
};
inline HallRun run_hall(double seconds) {
  auto in = import_pedsim_scenario(kHall);
  if (!in) throw std::runtime_error(in.error().message());
  auto runner = crowd::ScenarioRunner::create(&in->scenario.world, in->parsed, {});
  if (!runner) throw std::runtime_error(runner.error().message());
  scenario::TrajectoryRecorder recorder(0.1);
  (*runner)->run(
      seconds, [&](double t, std::span<const crowd::PedestrianState> s) { recorder.add(t, s); }, 2);
  return {std::move(*in), std::move(recorder).finish()};
}

}  // namespace socsim::interop::testing
