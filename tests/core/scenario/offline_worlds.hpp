#pragma once
// Worlds and knowledge for the offline scenario-generator tests: the seeded knowledge store in a
// temporary database, floor plans of the offline generator by domain and seed, and a small hall
// with two doors to the outside (the generated plans have one entrance).
#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "core/knowledge/knowledge_base.hpp"
#include "core/store/store.hpp"
#include "core/world/floorplan_offline.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::scenario::testing {

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
    world::OfflineOptions o;
    o.seed = seed;
    auto plan = world::generate_floor_plan(world::room_program(domain), constraints.value(), o);
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

}  // namespace socsim::scenario::testing
