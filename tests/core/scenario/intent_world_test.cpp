// What a prompt asks of the world reaches the world generator typed (world::WorldRequirements),
// a plan laid out from a prompt grows to hold the people it counts, and when a world cannot hold
// them every counted group keeps its share instead of the first one taking all the room.
#include "core/scenario/intent_world.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/scenario/pipeline.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/scenario/prompt_facts.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::scenario {
namespace {

using ::testing::HasSubstr;

world::WorldRequirements requirements_of(const std::string& prompt) {
  auto intent = interpret_prompt(prompt);
  EXPECT_TRUE(intent.has_value());
  return world_requirements(*intent);
}

TEST(IntentWorld, CountedFeaturesRoomsObjectsAndPeopleBecomeTypedRequirements) {
  const auto r = requirements_of(
      "Fire alarm in the hospital: about two hundred people leave through the two exits while a nurse "
      "stays in the waiting room next to the coffee machine.");
  const auto* exits = r.find(world::Feature::kExit);
  ASSERT_NE(exits, nullptr);
  EXPECT_EQ(exits->count, 2);
  EXPECT_FALSE(exits->at_least);
  ASSERT_TRUE(r.occupants.has_value());
  EXPECT_EQ(*r.occupants, 201);  // about 200 people and one nurse
  ASSERT_EQ(r.rooms.size(), 1u);
  EXPECT_EQ(r.rooms[0].name, "waiting room");
  ASSERT_EQ(r.objects.size(), 1u);
  EXPECT_EQ(r.objects[0].name, "coffee machine");
}

TEST(IntentWorld, RangesAreLowerBoundsAndAFeatureOnlyNamedIsAtLeastOne) {
  const auto r = requirements_of("Between three and five checkouts are open; shoppers walk to the exits.");
  const auto* checkouts = r.find(world::Feature::kCheckout);
  ASSERT_NE(checkouts, nullptr);
  EXPECT_EQ(checkouts->count, 3);
  EXPECT_TRUE(checkouts->at_least);
  const auto* exits = r.find(world::Feature::kExit);
  ASSERT_NE(exits, nullptr);
  EXPECT_EQ(exits->count, 1);
  EXPECT_TRUE(exits->at_least);
  EXPECT_FALSE(r.occupants.has_value());  // shoppers without a count
}

TEST(IntentWorld, EveryFixturePromptGivesRequirementsTheWorldReaderAccepts) {
  for (const char* file : {"everyday.jsonl", "unseen.jsonl", "probes.jsonl"})
    for (const auto& p :
         facts::load(std::string(SOCSIM_SOURCE_DIR) + "/tests/fixtures/prompts/" + std::string(file))) {
      const auto r = requirements_of(p.prompt);
      auto back = world::world_requirements_from_json(world::to_json(r));
      ASSERT_TRUE(back.has_value()) << p.id << ": " << back.error().message();
      EXPECT_EQ(world::to_json(*back), world::to_json(r)) << p.id;
    }
}

class IntentWorldScenario : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = store::Store::open(dir_.file("socsim.db")).value();
    kb_ = std::make_unique<knowledge::KnowledgeBase>(*store_);
  }
  socsim::testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<knowledge::KnowledgeBase> kb_;
  ScenarioConfig config_;
};

double people_in(const Json& program, const std::string& role) {
  return facts::program_people(program)[role];
}

TEST_F(IntentWorldScenario, APlanFromThePromptGrowsToHoldThePeopleItCounts) {
  const std::string prompt = "Six hundred shoppers walk through the shopping mall on a Saturday.";
  auto request = scenario_request_from_json({{"prompt", prompt}, {"seed", 2}}, config_);
  ASSERT_TRUE(request.has_value());
  auto world = world_for_request(*request, *kb_, nullptr, std::nullopt, {});
  ASSERT_TRUE(world.has_value()) << world.error().message();
  ASSERT_TRUE(world->provenance.contains("sized_for_people"));
  EXPECT_EQ(world->provenance["sized_for_people"]["people"], 600);
  EXPECT_EQ(world->requirements.occupants, 600);
  EXPECT_EQ(world->provenance["intent_requirements"]["requirements"]["occupants"], 600);
  ProgramRequest pr;
  pr.prompt = prompt;
  pr.seed = 2;
  auto program = generate_program_offline(world->world, *kb_, pr, config_.limits);
  ASSERT_TRUE(program.has_value()) << program.error().message();
  EXPECT_EQ(people_in(program->program, "shopper"), 600) << program->provenance["notes"].dump();
}

TEST_F(IntentWorldScenario, AWorldTooSmallKeepsEveryCountedGroupInProportionAndSaysSo) {
  // One 10 m × 8 m room: about 50 people fit at the generator's density.
  const std::string yaml = R"(name: "small_hall"
zones:
  - {name: "hall", type: "lobby", polygon: [[0, 0], [10, 0], [10, 8], [0, 8]]}
walls:
  - {start: [0, 0], end: [4, 0]}
  - {start: [5.2, 0], end: [10, 0]}
  - {start: [10, 0], end: [10, 8]}
  - {start: [10, 8], end: [0, 8]}
  - {start: [0, 8], end: [0, 0]}
doors:
  - {name: "main_door", pose: [4.6, 0, 0], width: 1.2, connects: ["hall"]}
)";
  auto world = world::world_from_yaml(yaml);
  ASSERT_TRUE(world.has_value()) << world.error().message();
  ProgramRequest pr;
  pr.prompt = "Three hundred fans and thirty stewards walk through the hall.";
  pr.seed = 1;
  auto program = generate_program_offline(*world, *kb_, pr, config_.limits);
  ASSERT_TRUE(program.has_value()) << program.error().message();
  const double fans = people_in(program->program, "fan"), stewards = people_in(program->program, "steward");
  EXPECT_GT(fans, 20);
  EXPECT_GE(stewards, 2);  // the stewards were not crowded out by the fans
  EXPECT_NEAR(fans / stewards, 10.0, 3.0);
  EXPECT_THAT(program->provenance["notes"].dump(), HasSubstr("every counted group was cut in proportion"));
}

}  // namespace
}  // namespace socsim::scenario
