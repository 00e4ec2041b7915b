// Every venue type × 10 seeds: the offline plan is valid, every zone and entity reachable by a
// person 0.5 m wide, no footprint overlapping a wall, a door or another footprint, the
// compliance report passing and the requested features present.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/floorplan/offline.hpp"
#include "core/knowledge/types.hpp"
#include "core/world/layout_check.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::floorplan {
namespace {

class Venues : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new socsim::testing::TempDir();
    store_ = store::Store::open(dir_->file("kb.db")).value().release();
    kb_ = new knowledge::KnowledgeBase(*store_);
  }
  static void TearDownTestSuite() {
    delete kb_;
    delete store_;
    delete dir_;
  }
  static std::vector<knowledge::MergedConstraint> constraints(const std::string& type) {
    auto c = kb_->constraints_for(type);
    EXPECT_TRUE(c.has_value());
    return c.value_or(std::vector<knowledge::MergedConstraint>{});
  }
  static socsim::testing::TempDir* dir_;
  static store::Store* store_;
  static knowledge::KnowledgeBase* kb_;
};
socsim::testing::TempDir* Venues::dir_ = nullptr;
store::Store* Venues::store_ = nullptr;
knowledge::KnowledgeBase* Venues::kb_ = nullptr;

TEST_F(Venues, EveryTypeTenSeedsIsCleanAndCompliant) {
  for (std::string_view type : knowledge::building_types()) {
    const auto cs = constraints(std::string(type));
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
      OfflineOptions o;
      o.seed = seed;
      auto plan = generate_floor_plan(room_program(type), cs, o);
      EXPECT_TRUE(plan) << type << " seed " << seed << ": " << plan.error().message();
      if (!plan) continue;
      EXPECT_TRUE(plan->compliance.passed) << type << " seed " << seed;
      const LayoutCheck check = check_layout(plan->world);
      EXPECT_TRUE(check.ok()) << type << " seed " << seed << ":\n" << check.summary();
    }
  }
}

}  // namespace
}  // namespace socsim::floorplan
