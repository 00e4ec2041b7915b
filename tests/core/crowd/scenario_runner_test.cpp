// ScenarioRunner: frames are bit-identical for the same inputs and seed (also across thread
// counts), the seed matters, and the queue scenario serves patients in the order they joined,
// one at a time, after timed service.
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

namespace socsim::crowd {
namespace {
using fixtures::options;
using fixtures::read;

const std::filesystem::path kExamples = std::filesystem::path(SOCSIM_SOURCE_DIR) / "schemas/examples";

struct Loaded {
  world::World world;
  Program program;
};

Loaded load(const char* program_file) {
  auto w = world::world_from_yaml(read(kExamples / "world_clinic.yaml"));
  auto p = program_from_text(read(kExamples / program_file));
  EXPECT_TRUE(w && p);
  return {*w, *p};
}

std::vector<double> trajectory(const Loaded& l, std::uint64_t seed, unsigned threads, double seconds) {
  auto runner = ScenarioRunner::create(&l.world, l.program, options(seed, threads));
  EXPECT_TRUE(runner) << runner.error().message();
  std::vector<double> out;
  (*runner)->run(seconds, [&](double t, std::span<const PedestrianState> states) {
    out.push_back(t);
    for (const PedestrianState& s : states) {
      out.insert(out.end(), {s.pose.x, s.pose.y, s.pose.yaw, s.twist.vx, s.twist.vy});
      out.push_back(static_cast<double>(s.activity));
    }
  });
  return out;
}

TEST(ScenarioRunner, SameInputsAndSeedGiveBitIdenticalFrames) {
  for (const char* file : {"program_queue.json", "program_ambient.json"}) {
    SCOPED_TRACE(file);
    const Loaded l = load(file);
    const auto a = trajectory(l, 42, 1, 15.0);
    const auto b = trajectory(l, 42, 1, 15.0);
    const auto c = trajectory(l, 42, 2, 15.0);
    const auto d = trajectory(l, 43, 1, 15.0);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(double)));
    ASSERT_EQ(a.size(), c.size());
    EXPECT_EQ(0, std::memcmp(a.data(), c.data(), a.size() * sizeof(double)));
    EXPECT_NE(a, d);
  }
}

// A person whose last goal is an exit leaves the simulation there (activity "exited") instead of
// standing in the way of those behind; on_arrival says otherwise where given, and an agent with
// several goals leaves only at the last one.
TEST(ScenarioRunner, AgentsLeaveAtAnExitTheyWalkTo) {
  auto w = world::world_from_yaml(R"(name: "exit test"
units: {length: m, angle: rad}
origin: [0, 0]
zones:
  - {name: "hall", type: "corridor", polygon: [[0, 0], [12, 0], [12, 4], [0, 4]]}
segmentation:
  - {name: "way_out", kind: "exit", polygon: [[10, 1], [12, 1], [12, 3], [10, 3]]}
  - {name: "desk", kind: "counter_area", polygon: [[5, 3], [6, 3], [6, 4], [5, 4]]}
)");
  ASSERT_TRUE(w) << w.error().message();
  auto p = program_from_text(R"({"agents": [
    {"name": "leaver", "position": [1, 1], "goals": ["way_out"], "cyclic_goals": false},
    {"name": "stayer", "position": [1, 2], "goals": ["way_out"], "cyclic_goals": false, "on_arrival": "stand"},
    {"name": "errand", "position": [1, 3], "goals": ["desk", [3, 2]], "cyclic_goals": false, "on_arrival": "exit"},
    {"name": "walker", "position": [2, 1], "goals": ["way_out", [2, 1]]},
    {"name": "visitor", "position": [2, 3], "goals": ["desk"], "cyclic_goals": false}]})");
  ASSERT_TRUE(p) << p.error().message();
  auto created = ScenarioRunner::create(&*w, *p, options(3));
  ASSERT_TRUE(created) << created.error().message();
  ScenarioRunner& run = **created;
  std::map<std::uint32_t, double> exited_at;
  bool errand_left_early = false;
  for (int k = 0; k < 800; ++k) {  // 40 s
    run.step();
    for (std::uint32_t i = 0; i < 5; ++i) {
      const PedestrianState s = run.sim().state(AgentId(i));
      if (s.activity == Activity::kExited && exited_at.count(i) == 0) {
        exited_at[i] = run.sim().time();
        if (i == 2) errand_left_early = std::hypot(s.pose.x - 3.0, s.pose.y - 2.0) > 1.0;
      }
    }
  }
  EXPECT_EQ(exited_at.count(0), 1u) << "the leaver walked to the exit and went out";
  EXPECT_EQ(exited_at.count(1), 0u) << "on_arrival stand: stays at the exit";
  EXPECT_EQ(exited_at.count(2), 1u) << "on_arrival exit: leaves at its last goal";
  EXPECT_FALSE(errand_left_early) << "not at the desk, its first goal";
  EXPECT_EQ(exited_at.count(3), 0u) << "cyclic goals never end";
  EXPECT_EQ(exited_at.count(4), 0u) << "a counter is not an exit";
  const PedestrianState stayer = run.sim().state(AgentId(1));
  EXPECT_GT(stayer.pose.x, 9.5) << "the stayer stands at the exit";
}

// Paper 001 Table II "Queuing": five patients join the reception queue and are served one by
// one (8 ± 2 s each) in the order they joined; nobody is served while another one is.
TEST(ScenarioRunner, QueueServesInJoiningOrderOneAtATime) {
  const Loaded l = load("program_queue.json");
  auto created = ScenarioRunner::create(&l.world, l.program, options(9));
  ASSERT_TRUE(created) << created.error().message();
  ScenarioRunner& run = **created;
  BtEnvironment& env = run.environment();
  std::vector<AgentId> joined;
  int max_served_at_once = 0;
  std::map<std::uint32_t, double> served_at;
  for (int k = 0; k < 2400 && env.service_log().size() < 5; ++k) {  // up to 120 s
    run.step();
    const BtEnvironment::Queue* q = env.queue("reception_queue");
    ASSERT_NE(q, nullptr);
    for (AgentId id : q->members)
      if (std::find(joined.begin(), joined.end(), id) == joined.end()) joined.push_back(id);
    // Members keep their order: the line only ever loses its head.
    for (std::size_t i = 1; i < q->members.size(); ++i)
      EXPECT_LT(std::find(joined.begin(), joined.end(), q->members[i - 1]),
                std::find(joined.begin(), joined.end(), q->members[i]));
    int serving = 0;
    for (std::uint32_t i = 1; i <= 5; ++i)
      if (run.sim().state(AgentId(i)).activity == Activity::kInteracting) ++serving;
    max_served_at_once = std::max(max_served_at_once, serving);
    for (const auto& [queue, id] : env.service_log()) served_at.try_emplace(id.value(), run.time());
  }
  ASSERT_EQ(env.service_log().size(), 5u) << "all five served within 120 s";
  EXPECT_EQ(max_served_at_once, 1);
  ASSERT_EQ(joined.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_EQ(env.service_log()[i].second, joined[i]) << "service order = joining order";
  // Timed service: consecutive departures at least service_time − spread (6 s) apart.
  for (std::size_t i = 1; i < 5; ++i)
    EXPECT_GE(served_at[joined[i].value()] - served_at[joined[i - 1].value()], 6.0 - 1e-9);
  EXPECT_TRUE(run.errors().empty()) << run.errors().front();
}

TEST(ScenarioRunner, FramesCarryTableIFieldsAndTheRunningNode) {
  const Loaded l = load("program_queue.json");
  auto run = ScenarioRunner::create(&l.world, l.program, options(2));
  ASSERT_TRUE(run);
  std::vector<PedestrianState> last;
  (*run)->run(
      3.0, [&](double, std::span<const PedestrianState> s) { last.assign(s.begin(), s.end()); }, 20);
  ASSERT_EQ(last.size(), 7u);  // receptionist, five patients, robot
  EXPECT_EQ(last[0].role, "receptionist");
  EXPECT_EQ(last[1].role, "patient");
  EXPECT_THAT(last[1].metadata.bt_node, ::testing::AnyOf("JoinQueue", "ServeAtCounter"));
  EXPECT_EQ(last[6].role, "robot");
  EXPECT_EQ((*run)->agents()[6].kind, AgentKind::kRobot);
  const RunMetrics m = (*run)->metrics();
  ASSERT_TRUE(m.robot.has_value());
  EXPECT_GT(m.robot->path_length, 0.5);
  EXPECT_EQ(m.agents.size(), 6u);
}

}  // namespace
}  // namespace socsim::crowd
