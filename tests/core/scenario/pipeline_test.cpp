// Text to scenario end to end in core: a request is read with pointers for every bad field; an
// offline prompt becomes a world, a program, a simulation and the content of a card whose
// replay is bit-identical; seeds vary the result; cancellation stops the run.
#include "core/scenario/pipeline.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/world/world_document.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::scenario {
namespace {

using ::testing::HasSubstr;

class Pipeline : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = store::Store::open(dir_.file("socsim.db")).value();
    kb_ = std::make_unique<knowledge::KnowledgeBase>(*store_);
  }

  Result<ScenarioOutcome> run(const Json& body, const llm::CancelToken& cancel = {}) {
    auto request = scenario_request_from_json(body, config_);
    if (!request) return tl::unexpected(request.error());
    ScenarioServices s{*kb_, nullptr, config_, std::nullopt, cancel, {}};
    return run_scenario(*request, std::nullopt, s);
  }

  socsim::testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<knowledge::KnowledgeBase> kb_;
  ScenarioConfig config_;
};

std::vector<std::string> pointers(const Error& e) {
  std::vector<std::string> out;
  for (const auto& f : e.errors) out.push_back(f.pointer);
  return out;
}

TEST_F(Pipeline, RequestErrorsNameEveryBadField) {
  const Json body = {{"prompt", ""},
                     {"seed", -1},
                     {"generator", "gpt"},
                     {"duration_s", 100000},
                     {"agents", 0},
                     {"world_id", "wld_x"},
                     {"scene_graph", {{"rooms", Json::array()}}},
                     {"domain", "castle"},
                     {"colour", "red"},
                     {"tags", {1}}};
  auto r = scenario_request_from_json(body, config_);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kValidation);
  const auto p = pointers(r.error());
  for (const char* want :
       {"/prompt", "/seed", "/generator", "/duration_s", "/agents", "/domain", "/colour", "/tags/0", ""})
    EXPECT_THAT(p, ::testing::Contains(want)) << want;
}

TEST_F(Pipeline, AnOfflinePromptBecomesACardThatReplaysBitForBit) {
  const Json body = {
      {"prompt", "Patients queue at the reception desk of a small clinic while two nurses chat"},
      {"seed", 11},
      {"duration_s", 12}};
  auto out = run(body);
  ASSERT_TRUE(out) << out.error().message();
  const auto& card = out->card;
  EXPECT_EQ(card.seed, 11u);
  EXPECT_EQ(card.generator.name, "offline");
  EXPECT_EQ(card.domain.value_or(""), "hospital");
  EXPECT_THAT(card.tags, ::testing::Contains("scenario"));
  EXPECT_TRUE(card.world.contains("zones"));
  EXPECT_FALSE(card.program["agents"].empty());
  EXPECT_EQ(card.trajectory_log["sha256"], out->log.sha256());
  EXPECT_EQ(card.trajectory_log["frames"], 121);  // 0 … 12 s at 10 Hz
  EXPECT_GT(card.metrics["summary"]["agents"].get<int>(), 0);
  EXPECT_FALSE(card.provenance["categories"].empty());
  EXPECT_FALSE(card.title.empty());
  // The card stores what the prompt was understood to say.
  EXPECT_EQ(card.intent["prompt"], body["prompt"]);
  ASSERT_EQ(card.intent["groups"].size(), 2u) << card.intent.dump();
  EXPECT_EQ(card.intent["groups"][1]["role"], "nurse");
  EXPECT_EQ(card.intent["venue"]["type"], "hospital");

  // The card alone (through its JSON form) reproduces the trajectories.
  auto back = cards::parse_card_content(cards::content_to_json(card), cards::CardLimits{});
  ASSERT_TRUE(back) << back.error().message();
  auto replay = replay_card(*back);
  ASSERT_TRUE(replay) << replay.error().message();
  EXPECT_EQ(replay->log.sha256(), out->log.sha256());
  EXPECT_EQ(replay->log.encoded(), out->log.encoded());
}

TEST_F(Pipeline, TheSameRequestGivesTheSameCardAndAnotherSeedAnotherOne) {
  const Json body = {{"prompt", "A coffee break: staff gather around the coffee machine in the office"},
                     {"seed", 5},
                     {"duration_s", 6}};
  auto a = run(body);
  auto b = run(body);
  Json other = body;
  other["seed"] = 6;
  auto c = run(other);
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(canonical_json(cards::content_to_json(a->card)), canonical_json(cards::content_to_json(b->card)));
  EXPECT_NE(a->log.sha256(), c->log.sha256());
}

TEST_F(Pipeline, AGivenWorldIsUsedAsItIs) {
  auto first = run({{"prompt", "an office with a meeting room"}, {"seed", 2}, {"duration_s", 2}});
  ASSERT_TRUE(first) << first.error().message();
  auto world = world::world_from_document(first->card.world);
  ASSERT_TRUE(world);
  auto request = scenario_request_from_json(
      {{"prompt", "everyone evacuates the building"}, {"seed", 1}, {"duration_s", 4}}, config_);
  ASSERT_TRUE(request);
  ScenarioServices s{*kb_, nullptr, config_, std::nullopt, {}, {}};
  auto out = run_scenario(*request, ScenarioWorld{*world, "office", Json::object()}, s);
  ASSERT_TRUE(out) << out.error().message();
  EXPECT_EQ(out->card.world, first->card.world);
  EXPECT_THAT(out->card.tags, ::testing::Contains("emergency"));
}

TEST_F(Pipeline, LlmWithoutAnEndpointIsRefusedAndCancellationStopsTheRun) {
  auto llm = run({{"prompt", "a queue"}, {"generator", "llm"}});
  ASSERT_FALSE(llm);
  EXPECT_THAT(pointers(llm.error()), ::testing::Contains("/generator"));

  llm::CancelToken cancel;
  cancel.cancel();
  auto cancelled = run({{"prompt", "people walk through the lobby"}, {"duration_s", 30}}, cancel);
  ASSERT_FALSE(cancelled);
  EXPECT_EQ(cancelled.error().code, ErrorCode::kCancelled);
}

}  // namespace
}  // namespace socsim::scenario
