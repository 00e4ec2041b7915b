// Scenario programs: the examples in schemas/examples/ match schemas/program.schema.json, parse
// and run; bad programs are refused with every problem's JSON pointer.
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/json_schema.hpp"
#include "core/crowd/program.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

namespace socsim::crowd {
namespace {
using fixtures::options;
using fixtures::read;

using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::filesystem::path kSchemas = std::filesystem::path(SOCSIM_SOURCE_DIR) / "schemas";

TEST(Program, ExamplesMatchTheSchemaParseAndRun) {
  auto schema = JsonSchema::compile(*parse_json_untrusted(read(kSchemas / "program.schema.json")));
  ASSERT_TRUE(schema) << schema.error().message();
  auto world = world::world_from_yaml(read(kSchemas / "examples/world_clinic.yaml"));
  ASSERT_TRUE(world);
  int seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSchemas / "examples")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("program_", 0) != 0) continue;
    SCOPED_TRACE(name);
    ++seen;
    auto json = parse_json_untrusted(read(entry.path()));
    ASSERT_TRUE(json);
    const auto violations = schema->validate(*json);
    EXPECT_TRUE(violations.empty()) << violations.front().pointer << ": " << violations.front().message;
    auto program = program_from_json(*json);
    ASSERT_TRUE(program) << program.error().message();
    auto runner = ScenarioRunner::create(&*world, *program, options(1, 1, kSchemas / "examples"));
    ASSERT_TRUE(runner) << runner.error().message();
    (*runner)->run(5.0);
    EXPECT_TRUE((*runner)->errors().empty()) << (*runner)->errors().front();
  }
  EXPECT_GE(seen, 3);
}

TEST(Program, EveryBadFieldIsReportedWithItsPointer) {
  auto p = program_from_text(R"({
    "dt": 0.5, "colour": "red",
    "agents": [{"position": [0, 0], "spawn": "lobby", "on_arrival": "out"}, {"position": [1], "goals": [3, {"place": "a", "position": [0, 0]}]},
               {"spawn": "lobby", "count": 2, "behavior": {"xml": "<root/>", "file": "a.xml"}}],
    "groups": [{"id": 1, "agents": [0, 7]}],
    "ambient_groups": [{"name": "a", "start": [], "goal": ["x"], "size": 3, "on_arrival": "fly",
                        "field": {"values": [[[0, 0]], [[0]]]}}],
    "robot": {"speed": 9}})");
  ASSERT_FALSE(p);
  std::vector<std::string> pointers;
  for (const FieldError& e : p.error().errors) pointers.push_back(e.pointer);
  EXPECT_THAT(pointers,
              ElementsAre("/colour", "/dt", "/agents/0", "/agents/0/on_arrival", "/agents/1/position",
                          "/agents/1/goals/0", "/agents/1/goals/1", "/agents/2/behavior",
                          "/groups/0/agents/1", "/ambient_groups/0/start", "/ambient_groups/0/on_arrival",
                          "/ambient_groups/0/field/values/1/0", "/robot/position", "/robot/speed"));
  EXPECT_EQ(p.error().code, ErrorCode::kValidation);

  auto syntax = program_from_text("{\"agents\": [}");
  ASSERT_FALSE(syntax);
  EXPECT_EQ(syntax.error().code, ErrorCode::kBadRequest);

  auto period = program_from_text(R"({"dt": 0.05, "decision_period": 0.12})");
  ASSERT_FALSE(period);
  EXPECT_EQ(period.error().errors.at(0).pointer, "/decision_period");
}

TEST(Program, RunnerChecksNamesAgainstTheWorld) {
  auto world = world::world_from_yaml(read(kSchemas / "examples/world_clinic.yaml"));
  ASSERT_TRUE(world);
  auto p = program_from_text(R"({
    "agents": [{"spawn": "cafeteria"}, {"position": [1, 1], "goals": ["reception_counter", "nowhere"], "role": "pilot"},
               {"position": [2, 2], "behavior": "missing"}, {"position": [3, 3], "behavior": {"file": "no_such.xml"}}],
    "ambient_groups": [{"name": "g", "start": ["entrance_area"], "goal": ["bed_01"], "size": 1}]})");
  ASSERT_TRUE(p) << p.error().message();
  auto runner = ScenarioRunner::create(&*world, *p, {});
  ASSERT_FALSE(runner);
  std::vector<std::string> pointers;
  for (const FieldError& e : runner.error().errors) pointers.push_back(e.pointer);
  EXPECT_THAT(pointers, ElementsAre("/ambient_groups/0/goal/0"));  // a POI is not a region
  EXPECT_THAT(runner.error().errors[0].message, HasSubstr("no ROI or zone named 'bed_01'"));

  p->ambient_groups.clear();
  runner = ScenarioRunner::create(&*world, *p, {});
  ASSERT_FALSE(runner);
  pointers.clear();
  for (const FieldError& e : runner.error().errors) pointers.push_back(e.pointer);
  EXPECT_THAT(pointers, ElementsAre("/agents/0/spawn", "/agents/1/goals/1", "/agents/1/role",
                                    "/agents/2/behavior", "/agents/3/behavior"));
}

}  // namespace
}  // namespace socsim::crowd
