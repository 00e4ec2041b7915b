// pedsim_ros scenario import: our own small scenarios for each rule, and the six real files
// from ../shared/peers/pedsim (skipped when absent): all import except corridor.xml, whose
// robot_goal waypoint lies outside its walls, and each exports back to pedsim XML that
// imports again.
#include "core/world/pedsim_import.hpp"

#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/geometry/planar.hpp"
#include "core/world/world_export.hpp"
#include "core/world/xml_reader.hpp"
#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using ::testing::HasSubstr;

constexpr const char* kBoxScenario = R"(<?xml version="1.0" encoding="UTF-8"?>
<scenario>
  <obstacle x1="0" y1="0" x2="20" y2="0"/>
  <obstacle x1="20" y1="0" x2="20" y2="10"/>
  <obstacle x1="20" y1="10" x2="0" y2="10"/>
  <obstacle x1="0" y1="10" x2="0" y2="0"/>
  <waypoint id="entry" x="2" y="5" r="1.5" b="1"/>
  <waypoint id="shop" x="18" y="8" r="3"/>
  <queue id="till" x="15" y="2" direction="180"/>
  <attraction id="window" x="10" y="9" width="6" height="1" strength="2"/>
  <agent x="3" y="5" n="12" dx="1" dy="2" type="0">
    <addwaypoint id="entry"/>
    <addqueue id="till"/>
    <addwaypoint id="shop"/>
  </agent>
  <agent x="4" y="4" n="1" dx="0" dy="0" type="2"/>
</scenario>
)";

std::string peers(const char* file) {
  return std::string(SOCSIM_SHARED_DIR) + "/peers/pedsim/" + file;
}

TEST(PedsimImport, BoxScenarioBecomesAWorldAndPlainScenarioData) {
  auto s = import_pedsim(kBoxScenario);
  ASSERT_TRUE(s) << s.error().message();
  EXPECT_TRUE(s->enclosed);
  const World& w = s->world;
  EXPECT_EQ(w.walls().size(), 4u);
  EXPECT_NEAR(w.area(), 200.0, 1e-9);
  // shop's circle (r = 3 at 2 m from two walls) is clipped to the walls.
  const Roi& shop = w.roi(w.find_roi("shop").value());
  EXPECT_EQ(shop.kind, "waypoint");
  EXPECT_LT(geometry::area(shop.polygon), 3.14159 * 9 * 0.8);
  EXPECT_EQ(w.roi(w.find_roi("till").value()).kind, "queue_lane");
  EXPECT_TRUE(w.entities().empty());
  EXPECT_EQ(w.roi(w.find_roi("window").value()).kind, "area");
  ASSERT_EQ(s->agents.size(), 2u);
  EXPECT_EQ(s->agents[0].count, 12);
  ASSERT_EQ(s->agents[0].route.size(), 3u);
  EXPECT_EQ(s->agents[0].route[1].kind, PedsimRouteStep::Kind::kQueue);
  EXPECT_EQ(s->agents[1].type, 2);
  EXPECT_EQ(s->waypoints[0].behaviour, 1);
  EXPECT_DOUBLE_EQ(s->attractions[0].strength, 2.0);
}

TEST(PedsimImport, MistakesNameTheElementAndLine) {
  std::string text = kBoxScenario;
  text.replace(text.find("<addqueue id=\"till\"/>"), 21, "<addqueue id=\"tills\"/>");
  text.replace(text.find("r=\"3\""), 5, "r=\"x\"");
  auto s = import_pedsim(text);
  ASSERT_FALSE(s);
  ASSERT_EQ(s.error().errors.size(), 2u);
  EXPECT_EQ(s.error().errors[0].pointer, "/waypoints/1");
  EXPECT_EQ(s.error().errors[0].line, 8);
  EXPECT_THAT(s.error().errors[0].message, HasSubstr("r=\"x\" of <waypoint> is not a number"));
  EXPECT_EQ(s.error().errors[1].pointer, "/agents/0/route/1");
  EXPECT_EQ(s.error().errors[1].line, 13);
  EXPECT_THAT(s.error().errors[1].message, HasSubstr("unknown queue 'tills'"));
}

TEST(PedsimImport, UnknownElementsAndAttributesAreRefused) {
  auto s = import_pedsim(
      "<scenario>\n<obstacle x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\" z=\"1\"/>\n<robot/>\n</scenario>");
  ASSERT_FALSE(s);
  EXPECT_THAT(s.error().errors.at(0).message, HasSubstr("unknown attribute 'z'"));
  EXPECT_THAT(s.error().errors.at(1).message, HasSubstr("unknown pedsim element <robot>"));
  EXPECT_EQ(s.error().errors.at(1).line, 3);
}

TEST(PedsimImport, PeerCorridorNamesTheWaypointOutsideItsWalls) {
  const std::string path = peers("corridor.xml");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "peer file " << path << " is absent";
  auto s = import_pedsim(testing::read_text(path));
  ASSERT_FALSE(s);
  ASSERT_EQ(s.error().errors.size(), 1u) << s.error().message();
  const FieldError& fe = s.error().errors[0];
  EXPECT_EQ(fe.pointer, "/waypoints/2");
  EXPECT_EQ(fe.line, 13);
  EXPECT_EQ(fe.message,
            "waypoint 'robot_goal' at (22, 27) lies outside the walls (the obstacles enclose x -0.5 .. 29.5, "
            "y -0.5 .. 14.5)");
}

TEST(PedsimImport, EveryOtherPeerScenarioImportsAndExportsBack) {
  for (const char* file : {"airport.xml", "airport_activities.xml", "contexts_queueing.xml", "scene1.xml",
                           "social_contexts.xml"}) {
    const std::string path = peers(file);
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "peer file " << path << " is absent";
    auto s = import_pedsim(testing::read_text(path));
    ASSERT_TRUE(s) << file << ": " << s.error().message();
    EXPECT_FALSE(s->agents.empty()) << file;
    const std::string back = export_pedsim(s->world);
    auto again = import_pedsim(back);
    ASSERT_TRUE(again) << file << " re-import: " << again.error().message();
    EXPECT_EQ(again->world.walls().size(), s->world.walls().size()) << file;
    EXPECT_EQ(again->queues.size(), s->queues.size()) << file;
    // Queue heads and directions survive the round trip.
    for (std::size_t q = 0; q < s->queues.size(); ++q) {
      EXPECT_NEAR(again->queues[q].position.x, s->queues[q].position.x, 1e-6) << file;
      EXPECT_NEAR(again->queues[q].position.y, s->queues[q].position.y, 1e-6) << file;
      EXPECT_NEAR(std::fmod(again->queues[q].direction_deg - s->queues[q].direction_deg + 720.0, 360.0), 0.0,
                  1e-4)
          << file;
    }
  }
}

}  // namespace
}  // namespace socsim::world
