#pragma once
// Worlds, knowledge and runs for the offline scenario-generator tests: the seeded knowledge store in a
// temporary database, floor plans of the offline generator by domain and seed, and a small hall
// with two doors to the outside (the generated plans have one entrance).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/floorplan/offline.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/scenario/program_offline.hpp"
#include "core/store/store.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::scenario::testing {

inline bool has_tag(const crowd::PedestrianState& s, const std::string& tag) {
  return std::find(s.metadata.tags.begin(), s.metadata.tags.end(), tag) != s.metadata.tags.end();
}
inline double speed(const crowd::PedestrianState& s) {
  return std::hypot(s.twist.vx, s.twist.vy);
}

class OfflineWorlds {
 public:
  OfflineWorlds() {
    store_ = store::Store::open(dir_.file("kb.db")).value();
    kb_ = std::make_unique<knowledge::KnowledgeBase>(*store_);
  }
  [[nodiscard]] const knowledge::KnowledgeBase& kb() const { return *kb_; }

  // The offline floor plan of a domain's room programme (hospital, office, residential, warehouse …).
  const world::World& plan(const std::string& domain, std::uint64_t seed = 1) {
    const std::string key = domain + "#" + std::to_string(seed);
    if (auto it = worlds_.find(key); it != worlds_.end()) return *it->second;
    auto constraints = kb_->constraints_for(domain);
    EXPECT_TRUE(constraints.has_value());
    floorplan::OfflineOptions o;
    o.seed = seed;
    auto plan = floorplan::generate_floor_plan(floorplan::room_program(domain), constraints.value(), o);
    EXPECT_TRUE(plan.has_value()) << domain << ": " << plan.error().message();
    return *worlds_.emplace(key, std::make_unique<world::World>(std::move(plan->world))).first->second;
  }

  // A 16 m × 8 m hall with a door to the outside at each end and a side room; exits are 15 m apart.
  const world::World& two_exits() {
    if (two_exits_) return *two_exits_;
    const char* yaml = R"(name: "two_exit_hall"
units: {length: m, angle: rad}
zones:
  - {name: "hall", type: "concourse", polygon: [[0, 0], [16, 0], [16, 8], [0, 8]]}
  - {name: "side_room", type: "meeting_room", polygon: [[6, 8], [10, 8], [10, 12], [6, 12]]}
walls:
  - {start: [0, 0], end: [16, 0]}
  - {start: [16, 0], end: [16, 3.5]}
  - {start: [16, 4.5], end: [16, 8]}
  - {start: [16, 8], end: [10, 8]}
  - {start: [0, 8], end: [6, 8]}
  - {start: [0, 8], end: [0, 4.5]}
  - {start: [0, 3.5], end: [0, 0]}
  - {start: [6, 8], end: [6, 12]}
  - {start: [6, 12], end: [10, 12]}
  - {start: [10, 12], end: [10, 8]}
  - {start: [6, 8], end: [7.5, 8]}
  - {start: [8.5, 8], end: [10, 8]}
doors:
  - {name: "west_exit", pose: [0, 4, 0], width: 1.0, connects: ["hall"]}
  - {name: "east_exit", pose: [16, 4, 0], width: 1.0, connects: ["hall"]}
  - {name: "side_door", pose: [8, 8, 1.5707963267948966], width: 1.0, connects: ["hall", "side_room"]}
segmentation:
  - {name: "west_entrance", kind: "entrance", polygon: [[0, 3], [1, 3], [1, 5], [0, 5]]}
  - {name: "east_entrance", kind: "entrance", polygon: [[15, 3], [16, 3], [16, 5], [15, 5]]}
entities:
  - {type: "water_dispenser", name: "hall_water_dispenser", pose: [8, 0.4, 1.5707963267948966], affordances: ["drink"]}
)";
    auto w = world::world_from_yaml(yaml);
    EXPECT_TRUE(w.has_value()) << w.error().message();
    two_exits_ = std::make_unique<world::World>(std::move(w.value()));
    return *two_exits_;
  }

 private:
  socsim::testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<knowledge::KnowledgeBase> kb_;
  std::map<std::string, std::unique_ptr<world::World>> worlds_;
  std::unique_ptr<world::World> two_exits_;
};

using crowd::PedestrianState;

// One frame of a run (every second decision step: 10 Hz).
struct Frame {
  double t = 0.0;
  std::vector<PedestrianState> states;
};

struct Simulated {
  GeneratedProgram generated;
  std::unique_ptr<crowd::ScenarioRunner> runner;
  std::vector<Frame> frames;
};

// Generates the offline program for a prompt and runs it, keeping the frames (SOCSIM_DUMP_FRAMES=1
// prints the program and the positions every 2 s).
inline Simulated simulate(const world::World& w, const knowledge::KnowledgeBase& kb,
                          const std::string& prompt, double seconds, std::uint64_t seed = 3) {
  Simulated r;
  ProgramRequest req;
  req.prompt = prompt;
  req.seed = seed;
  req.duration_s = seconds;
  auto g = generate_program_offline(w, kb, req, ScenarioLimits{});
  EXPECT_TRUE(g.has_value()) << (g ? "" : g.error().message());
  if (!g) return r;
  r.generated = std::move(*g);
  auto program = crowd::program_from_json(r.generated.program);
  EXPECT_TRUE(program.has_value());
  crowd::RunnerOptions o;
  o.seed = seed;
  o.record_metrics = false;
  auto runner = crowd::ScenarioRunner::create(&w, *program, o);
  EXPECT_TRUE(runner.has_value()) << (runner ? "" : runner.error().message());
  if (!runner) return r;
  r.runner = std::move(*runner);
  r.runner->run(
      seconds,
      [&](double t, std::span<const PedestrianState> s) {
        r.frames.push_back(Frame{t, {s.begin(), s.end()}});
      },
      2);
  EXPECT_THAT(r.runner->errors(), ::testing::IsEmpty());
  if (std::getenv("SOCSIM_DUMP_FRAMES") != nullptr) {
    std::cerr << r.generated.program.dump(1) << "\n" << r.generated.provenance["notes"].dump() << "\n";
    for (const Frame& f : r.frames) {
      if (std::fmod(f.t + 1e-9, 2.0) > 0.1) continue;
      std::cerr << "t=" << f.t;
      for (const PedestrianState& s : f.states)
        std::cerr << " | " << s.id.value() << " " << s.role << " (" << std::round(s.pose.x * 10) / 10 << ","
                  << std::round(s.pose.y * 10) / 10 << ") " << crowd::activity_name(s.activity) << " "
                  << s.metadata.bt_node;
      std::cerr << "\n";
    }
  }
  return r;
}

}  // namespace socsim::scenario::testing
