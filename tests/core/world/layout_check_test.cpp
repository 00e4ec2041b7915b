// Layout checks by footprint: a small shop drawn below, with one mistake of each kind the
// check reports (overlap, furniture on a wall, blocking a door, outside its zone, walled in),
// and the same shop without them passing.
//
//   y=6 +-------------------+-----+
//       |                   |     |   shop: 0..10 × 0..6, store: 10..13 × 0..6
//       |   shelves         d2    |   d1 entrance on y = 0 at x = 5, d2 shop–store at (10, 3)
//       |                   |     |
//   y=0 +--------d1---------+-----+
#include "core/world/layout_check.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/geometry/planar.hpp"
#include "core/world/footprint.hpp"
#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using ::testing::HasSubstr;

std::string shop(const std::string& entities) {
  return R"(zones:
  - {name: shop, type: sales_floor, polygon: [[0, 0], [10, 0], [10, 6], [0, 6]]}
  - {name: store, type: stock_room, polygon: [[10, 0], [13, 0], [13, 6], [10, 6]]}
doors:
  - {name: d1, pose: [5, 0], width: 1.8, connects: [shop]}
  - {name: d2, pose: [10, 3], width: 1.0, connects: [shop, store]}
entities:
)" + entities;
}

TEST(LayoutCheck, FootprintsFollowTheYaw) {
  const Polygon q = footprint_polygon("counter", Pose2{2, 3, 0});  // 1.8 wide across x-facing: along y
  const auto b = geometry::bounds(q.outer);
  EXPECT_DOUBLE_EQ(b.width(), 0.7);
  EXPECT_DOUBLE_EQ(b.height(), 1.8);
  const auto turned = geometry::bounds(footprint_polygon("counter", Pose2{2, 3, 1.5707963267948966}).outer);
  EXPECT_DOUBLE_EQ(turned.width(), 1.8);
  EXPECT_DOUBLE_EQ(turned.height(), 0.7);
  EXPECT_GT(geometry::signed_area(q.outer), 0.0);
  EXPECT_DOUBLE_EQ(footprint_of("unknown_gadget").width, 0.6);
}

TEST(LayoutCheck, ATidyShopPasses) {
  const World w = testing::load(shop(R"(  - {type: shelf, name: s1, pose: [2, 4.5, 1.5707963267948966]}
  - {type: shelf, name: s2, pose: [3.9, 4.5, 1.5707963267948966]}
  - {type: counter, name: till, pose: [7, 2, 1.5707963267948966], affordances: [pay]}
  - {type: rack, name: r1, pose: [11.5, 5.3, 1.5707963267948966]}
)"));
  const LayoutCheck c = check_layout(w);
  EXPECT_TRUE(c.ok()) << c.summary();
  EXPECT_EQ(c.entities_checked, 4u);
  EXPECT_EQ(c.reachable_entities, 4u);
}

TEST(LayoutCheck, EachKindOfMistakeIsNamed) {
  const World w = testing::load(shop(R"(  - {type: shelf, name: s1, pose: [2, 4.5, 1.5707963267948966]}
  - {type: shelf, name: s2, pose: [3, 4.5, 1.5707963267948966]}
  - {type: shelf, name: on_wall, pose: [6, 5.9, 1.5707963267948966]}
  - {type: counter, name: at_door, pose: [6.6, 0.5, 1.5707963267948966]}
  - {type: bed, name: in_two_rooms, pose: [9.9, 1.2]}
  - {type: rack, name: a, pose: [12.0, 4.5, 1.5707963267948966]}
  - {type: shelf, name: walled_in, pose: [12.7, 3.0, 0]}
  - {type: rack, name: b, pose: [12.0, 1.5, 1.5707963267948966]}
  - {type: rack, name: c, pose: [11.9, 3.0, 0]}
)"));
  const LayoutCheck c = check_layout(w);
  EXPECT_FALSE(c.ok());
  auto has = [&](const std::string& kind, const std::string& element) {
    for (const auto& f : c.findings)
      if (f.kind == kind && f.element == element) return true;
    return false;
  };
  EXPECT_TRUE(has("entity_overlap", "s1")) << c.summary();
  EXPECT_TRUE(has("entity_on_wall", "on_wall")) << c.summary();
  EXPECT_TRUE(has("entity_outside_zone", "on_wall")) << c.summary();
  EXPECT_TRUE(has("entity_blocks_door", "at_door")) << c.summary();
  EXPECT_TRUE(has("entity_outside_zone", "in_two_rooms")) << c.summary();
  EXPECT_TRUE(has("entity_unreachable", "walled_in")) << c.summary();
  for (const char* fine : {"s1", "a", "b", "c"}) EXPECT_FALSE(has("entity_unreachable", fine)) << fine;
  EXPECT_FALSE(has("entity_overlap", "a")) << c.summary();
  EXPECT_THAT(c.summary(), HasSubstr("entities 's1' (shelf) and 's2' (shelf) overlap by"));
}

TEST(LayoutCheck, AZoneBehindFurnitureIsUnreachable) {
  // A shelf across the store door: the store cannot be entered by a person 0.5 m wide.
  const World w = testing::load(shop("  - {type: rack, name: plug, pose: [10.6, 3, 0]}\n"));
  const LayoutCheck c = check_layout(w);
  EXPECT_EQ(c.count("zone_unreachable"), 1u) << c.summary();
  EXPECT_EQ(c.findings.front().kind, "entity_blocks_door");
}

}  // namespace
}  // namespace socsim::world
