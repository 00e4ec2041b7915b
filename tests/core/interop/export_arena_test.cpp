// world + program → Arena-Rosnav scenario JSON: the fields Arena's scenario task reads (robots with
// start/goal, obstacles static/dynamic with pos [x, y, theta], model, type, waypoints and
// waypoint_mode, map, resets), one dynamic obstacle per person (the robot is the robot), waypoints
// where the routes stop, poses in the map frame, and the same bytes for the same seed.
#include "core/interop/export_arena.hpp"

#include <gtest/gtest.h>

#include "core/common/json_io.hpp"
#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

void expect_pose(const Json& p, const std::string& where) {
  ASSERT_TRUE(p.is_array()) << where;
  ASSERT_EQ(p.size(), 3u) << where;
  for (const Json& v : p) EXPECT_TRUE(v.is_number()) << where;
}

// The shape of Arena's scenario files (arena_bringup/configs/scenarios/_SCHEMA.json and theirs).
Json checked(const std::string& text) {
  const Json doc = Json::parse(text);
  EXPECT_EQ(doc.size(), 4u) << doc.dump();
  EXPECT_TRUE(doc["map"].is_string());
  EXPECT_TRUE(doc["resets"].is_number_integer());
  const Json& robots = doc["robots"];
  EXPECT_EQ(robots.size(), 1u);
  expect_pose(robots[0]["start"], "robot start");
  expect_pose(robots[0]["goal"], "robot goal");
  for (const Json& o : doc["obstacles"]["static"]) {
    EXPECT_TRUE(o["name"].is_string() && o["model"].is_string());
    expect_pose(o["pos"], o["name"]);
  }
  for (const Json& o : doc["obstacles"]["dynamic"]) {
    const std::string name = o["name"];
    expect_pose(o["pos"], name);
    EXPECT_TRUE(o["type"] == "adult" || o["type"] == "child" || o["type"] == "elder") << name;
    EXPECT_EQ(o["model"], "actor1");
    EXPECT_EQ(o["waypoint_mode"], 2);
    EXPECT_FALSE(o["waypoints"].empty()) << name;
    for (const Json& w : o["waypoints"]) expect_pose(w, name);
  }
  EXPECT_TRUE(doc["obstacles"]["interactive"].is_array());
  return doc;
}

TEST(ExportArena, PedsimHallPeopleBecomeDynamicObstaclesAndTheRobotKeepsItsGoal) {
  auto in = import_pedsim_scenario(testing::kHall);
  ASSERT_TRUE(in) << in.error().message();
  ArenaExportOptions options;
  options.seed = 3;
  auto text = export_arena_scenario(in->scenario.world, in->parsed, options);
  ASSERT_TRUE(text) << text.error().message();
  const Json doc = checked(*text);
  EXPECT_EQ(doc["obstacles"]["dynamic"].size(), 20u);  // 21 agents, one of them the robot
  EXPECT_EQ(doc["map"], "pedsim_scenario");
  // The queuing people: the door, the queue's head, the platform.
  const Json& first = doc["obstacles"]["dynamic"][0];
  ASSERT_EQ(first["waypoints"].size(), 3u);
  EXPECT_NEAR(first["waypoints"][2][0].get<double>(), 21.0, 2.5);
  // The robot (pedsim type 2) starts at (3, 3) and goes to the platform, then the door: its goal is
  // the stop farthest from its start, the platform (21, 3).
  EXPECT_NEAR(doc["robots"][0]["start"][0].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(doc["robots"][0]["start"][1].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(doc["robots"][0]["goal"][0].get<double>(), 21.0, 2.1);
  // Every pose lies inside the hall.
  for (const Json& o : doc["obstacles"]["dynamic"])
    for (const Json& w : o["waypoints"]) {
      EXPECT_GE(w[0].get<double>(), 0.0);
      EXPECT_LE(w[0].get<double>(), 24.0);
      EXPECT_GE(w[1].get<double>(), 0.0);
      EXPECT_LE(w[1].get<double>(), 12.0);
    }
  // Same seed, same bytes; another seed moves where people start.
  EXPECT_EQ(*text, export_arena_scenario(in->scenario.world, in->parsed, options).value());
  options.seed = 4;
  EXPECT_NE(*text, export_arena_scenario(in->scenario.world, in->parsed, options).value());
}

TEST(ExportArena, ClinicProgramsExportWithTheirEntitiesAndAMapFramePose) {
  world::World w = testing::clinic();
  for (const char* file : {"program_queue.json", "program_ambient.json", "program_evacuation.json"}) {
    const crowd::Program p = testing::example_program(file);
    auto text = export_arena_scenario(w, p);
    ASSERT_TRUE(text) << file << ": " << text.error().message();
    const Json doc = checked(*text);
    EXPECT_EQ(doc["obstacles"]["static"].size(), w.entities().size()) << file;
    EXPECT_EQ(doc["map"], w.name());
    // The program's robot, or without one two places people go to: never start = goal.
    const Json& r = doc["robots"][0];
    EXPECT_GT(std::hypot(r["goal"][0].get<double>() - r["start"][0].get<double>(),
                         r["goal"][1].get<double>() - r["start"][1].get<double>()),
              1.0)
        << file;
  }
  // A program that names a place the world lacks is refused as the runner refuses it.
  crowd::Program bad = testing::example_program("program_queue.json");
  ASSERT_FALSE(bad.agents.empty());
  bad.agents[0].goals = {crowd::ProgramPoint{"no_such_place", {}, "/agents/0/goals/0"}};
  auto refused = export_arena_scenario(w, bad);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message().find("no_such_place"), std::string::npos) << refused.error().message();
}

}  // namespace
}  // namespace socsim::interop
