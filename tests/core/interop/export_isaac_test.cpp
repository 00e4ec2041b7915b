// world + program → Isaac Sim files: the USD stage, an IRA 1.x configuration read back with
// yaml-cpp (one character group per program entry, counts adding up to the people, ranges from
// their routes, the stage named), and omni.anim.people commands in their grammar, one character
// per person, with the queue's service as an Idle.
#include "core/interop/export_isaac.hpp"

#include <set>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

using ::testing::HasSubstr;

struct Commands {
  std::set<std::string> characters;
  std::size_t go_to = 0, idle = 0;
  std::string error;
};

// "<Character> GoTo x y z yaw|_" and "<Character> Idle seconds", '#' comments.
Commands read_commands(const std::string& text) {
  Commands c;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string who, verb;
    words >> who >> verb;
    if (who.rfind("Character", 0) != 0) c.error = "not a character: " + line;
    c.characters.insert(who);
    if (verb == "GoTo") {
      double x, y, z;
      std::string yaw;
      if (!(words >> x >> y >> z >> yaw) ||
          (yaw != "_" && yaw.find_first_not_of("-0123456789.") != std::string::npos))
        c.error = "bad GoTo: " + line;
      ++c.go_to;
    } else if (verb == "Idle") {
      double s;
      if (!(words >> s) || s <= 0) c.error = "bad Idle: " + line;
      ++c.idle;
    } else {
      c.error = "unknown command: " + line;
    }
  }
  return c;
}

TEST(ExportIsaac, ClinicQueueBecomesAStageAConfigAndCommands) {
  const world::World w = testing::clinic();
  const crowd::Program p = testing::example_program("program_queue.json");
  IsaacExportOptions options;
  options.seed = 5;
  options.duration_s = 90;
  auto files = export_isaac(w, p, options);
  ASSERT_TRUE(files) << files.error().message();
  ASSERT_EQ(files->size(), 3u);
  EXPECT_EQ((*files)[0].path, "world.usda");
  EXPECT_EQ((*files)[0].content.rfind("#usda 1.0\n", 0), 0u);

  const YAML::Node config = YAML::Load((*files)[1].content)["isaacsim.replicator.agent"];
  ASSERT_TRUE(config.IsMap());
  EXPECT_EQ(config["version"].as<std::string>(), "1.6.0");
  EXPECT_EQ(config["seed"].as<int>(), 5);
  EXPECT_DOUBLE_EQ(config["simulation_duration"].as<double>(), 90.0);
  EXPECT_EQ(config["environment"]["base_stage_asset_path"].as<std::string>(), "world.usda");
  std::size_t people = 0;
  for (const auto& g : config["character"]["groups"]) {
    const YAML::Node group = g.second;
    people += group["num"].as<std::size_t>();
    const YAML::Node wander = group["routines"][0]["wander"];
    const auto speed = wander["walk"]["speed_range"].as<std::vector<double>>();
    ASSERT_EQ(speed.size(), 2u);
    EXPECT_GT(speed[0], 0.0);
    EXPECT_LE(speed[0], speed[1]);
    const auto idle = wander["idle"][0]["time_range"].as<std::vector<double>>();
    EXPECT_LE(idle[0], idle[1]);
  }
  std::size_t expected = 0;
  for (const auto& a : p.agents) expected += a.count;
  for (const auto& a : p.ambient_groups) expected += a.size;
  EXPECT_EQ(people, expected);

  const Commands c = read_commands((*files)[2].content);
  ASSERT_TRUE(c.error.empty()) << c.error;
  EXPECT_EQ(c.characters.size(), expected);
  EXPECT_GT(c.go_to, 0u);
  EXPECT_GT(c.idle, 0u);  // the reception's service
  EXPECT_TRUE(c.characters.count("Character") && c.characters.count("Character_01"));

  // Same seed, same bytes.
  const auto again = export_isaac(w, p, options).value();
  for (std::size_t i = 0; i < again.size(); ++i) EXPECT_EQ(again[i].content, (*files)[i].content);
}

TEST(ExportIsaac, EveryExampleProgramExportsAndABadOneIsRefused) {
  const world::World w = testing::clinic();
  for (const char* file : {"program_ambient.json", "program_evacuation.json"}) {
    auto files = export_isaac(w, testing::example_program(file));
    ASSERT_TRUE(files) << file << ": " << files.error().message();
    EXPECT_NO_THROW(YAML::Load((*files)[1].content)) << file;
    EXPECT_TRUE(read_commands((*files)[2].content).error.empty()) << file;
  }
  crowd::Program bad = testing::example_program("program_queue.json");
  bad.agents[0].goals = {crowd::ProgramPoint{"no_such_place", {}, "/agents/0/goals/0"}};
  auto refused = export_isaac(w, bad);
  ASSERT_FALSE(refused);
  EXPECT_THAT(refused.error().message(), HasSubstr("no_such_place"));
}

}  // namespace
}  // namespace socsim::interop
