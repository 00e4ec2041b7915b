// LLM scenario-program generator against the scripted OpenAI-compatible server: the world's
// places and the retrieved behaviour nodes reach the prompt; a valid answer compiles into a
// program that runs; an unknown ROI or node is quoted back with a pointer into the answer and
// repaired; an answer that never fits the world and an endpoint that is down give clear errors.
#include "core/scenario/program_llm.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/floorplan/offline.hpp"
#include "core/scenario/pipeline.hpp"
#include "core/scenario/program_check.hpp"
#include "core/scenario/scenario_intent.hpp"
#include "tests/core/llm/scripted_server.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::scenario {
namespace {

using socsim::testing::ScriptedServer;
using ::testing::HasSubstr;

class ProgramLlm : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = store::Store::open(dir_.file("socsim.db")).value();
    kb_ = std::make_unique<knowledge::KnowledgeBase>(*store_);
    auto constraints = kb_->constraints_for("hospital").value();
    floorplan::OfflineOptions o;
    o.seed = 3;
    world_ =
        floorplan::generate_floor_plan(floorplan::room_program("hospital"), constraints, o).value().world;
    client_ = socsim::testing::scripted_client(server_.base_url());
    generator_ = std::make_unique<llm::StructuredGenerator>(*client_, store_.get());
    request_.prompt = "two nurses wait near the reception while visitors walk to the corridor";
    request_.seed = 4;
    request_.duration_s = 5;
  }

  // A valid answer built from the world's own names.
  Json good_answer() const {
    const auto& queue = world_->roi(world_->rois_of_kind("queue_lane").at(0)).name;
    std::string corridor;
    for (const auto& z : world_->zones())
      if (z.type == "corridor") corridor = z.name;
    const std::string lobby =
        world_->zones()[0].name == corridor ? world_->zones()[1].name : world_->zones()[0].name;
    const std::string tree =
        "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Nurse\"><WaitAt agent_id=\"{id}\" location=\"" + queue +
        "\" duration=\"30\"/></BehaviorTree></root>";
    return Json{{"spotlight_agents",
                 {{{"id", "nurse"},
                   {"role", "nurse"},
                   {"spawn_roi", corridor},
                   {"behavior_tree", tree},
                   {"parameters", {{"count", 2}, {"speed", 1.2}}}}}},
                {"ambient_groups",
                 {{{"name", "visitors"},
                   {"description", "visitors walking to the corridor"},
                   {"start_roi", lobby},
                   {"goal_roi", corridor},
                   {"size", 6},
                   {"speed", 1.3}}}}};
  }

  std::string user_message(std::size_t call) const {
    return server_.seen().at(call).body["messages"].back()["content"];
  }

  ScriptedServer server_;
  socsim::testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<knowledge::KnowledgeBase> kb_;
  std::optional<world::World> world_;
  std::unique_ptr<llm::LlmClient> client_;
  std::unique_ptr<llm::StructuredGenerator> generator_;
  ProgramRequest request_;
  ScenarioLimits limits_;
};

TEST_F(ProgramLlm, WorldAndNodesReachThePromptAndAValidAnswerRuns) {
  auto direct = checked_program_from_answer(good_answer(), *world_, request_, limits_);
  ASSERT_TRUE(direct) << direct.error().message();
  server_.push_chat(ScriptedServer::chat(good_answer().dump()));
  auto g = generate_program_llm(*generator_, *world_, *kb_, request_, limits_);
  ASSERT_TRUE(g) << g.error().message();
  EXPECT_EQ(g->program["agents"][0]["count"], 2);
  EXPECT_EQ(g->program["ambient_groups"][0]["description"], "visitors walking to the corridor");
  EXPECT_EQ(g->provenance["llm"]["model"], "test-model");
  EXPECT_FALSE(g->provenance["knowledge"].empty());
  const std::string user = user_message(0);
  EXPECT_THAT(user, HasSubstr(world_->roi(world_->rois_of_kind("queue_lane").at(0)).name));
  EXPECT_THAT(user, HasSubstr("WaitAt"));
  EXPECT_THAT(user, HasSubstr("at most 2000 people"));
  EXPECT_EQ(server_.seen()[0].body["response_format"]["json_schema"]["name"], "scenario_program");

  auto sim = simulate_program(*world_, g->program, 4, 3.0, 0.1);
  ASSERT_TRUE(sim) << sim.error().message();
  EXPECT_EQ(sim->log.frame_count(), 31u);
  EXPECT_GE(sim->log.agent_count(), 2u);
}

TEST_F(ProgramLlm, AnUnknownPlaceAndNodeAreQuotedBackWithPointersAndRepaired) {
  Json bad = good_answer();
  bad["spotlight_agents"][0]["spawn_roi"] = "helipad";
  bad["ambient_groups"][0]["goal_roi"] = "moon_base";
  server_.push_chat(ScriptedServer::chat(bad.dump()));
  server_.push_chat(ScriptedServer::chat(good_answer().dump()));
  auto g = generate_program_llm(*generator_, *world_, *kb_, request_, limits_);
  ASSERT_TRUE(g) << g.error().message();
  ASSERT_EQ(server_.count(), 2);
  const std::string repair = user_message(1);
  EXPECT_THAT(repair, HasSubstr("/spotlight_agents/0/spawn_roi"));
  EXPECT_THAT(repair, HasSubstr("helipad"));
  EXPECT_THAT(repair, HasSubstr("/ambient_groups/0/goal_roi"));
  EXPECT_EQ(g->provenance["llm"]["rounds"], 2);
}

TEST_F(ProgramLlm, AnAnswerThatNeverFitsTheWorldEndsWithAClearError) {
  Json bad = good_answer();
  std::string tree = bad["spotlight_agents"][0]["behavior_tree"];
  tree.replace(tree.find("WaitAt"), 6, "TeleportTo");
  bad["spotlight_agents"][0]["behavior_tree"] = tree;
  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(bad.dump()));
  auto g = generate_program_llm(*generator_, *world_, *kb_, request_, limits_);
  ASSERT_FALSE(g);
  EXPECT_EQ(g.error().code, ErrorCode::kValidation);
  EXPECT_EQ(server_.count(), 3);
  bool names_tree = false;
  for (const auto& e : g.error().errors)
    names_tree = names_tree || e.pointer == "/spotlight_agents/0/behavior_tree";
  EXPECT_TRUE(names_tree) << g.error().message();
  EXPECT_THAT(g.error().message(), HasSubstr("TeleportTo"));
}

TEST_F(ProgramLlm, DuplicateIdsAndTooManyPeopleArePointedAt) {
  Json bad = good_answer();
  bad["spotlight_agents"].push_back(bad["spotlight_agents"][0]);
  bad["ambient_groups"][0]["size"] = 5000;
  auto r = checked_program_from_answer(bad, *world_, request_, limits_);
  ASSERT_FALSE(r);
  std::string pointers;
  for (const auto& e : r.error().errors) pointers += e.pointer + " ";
  EXPECT_THAT(pointers, HasSubstr("/spotlight_agents/1/id"));
  EXPECT_THAT(r.error().message(), HasSubstr("2000"));
}

TEST_F(ProgramLlm, AnEndpointThatIsDownGivesAnUpstreamErrorNamingIt) {
  int port = 0;
  {
    ScriptedServer closed;
    port = closed.port();
  }
  auto client = socsim::testing::scripted_client("http://127.0.0.1:" + std::to_string(port));
  llm::StructuredGenerator gen(*client, nullptr);
  auto g = generate_program_llm(gen, *world_, *kb_, request_, limits_);
  ASSERT_FALSE(g);
  EXPECT_EQ(g.error().code, ErrorCode::kUpstream);
  EXPECT_THAT(g.error().detail, HasSubstr("127.0.0.1:" + std::to_string(port)));
}

// Issue 16 #7: the program is read against the prompt's explicit facts ("two nurses").
TEST_F(ProgramLlm, AWrongCountIsQuotedAsAContradictionAndRepaired) {
  Json wrong = good_answer();
  wrong["spotlight_agents"][0]["parameters"]["count"] = 5;
  server_.push_chat(ScriptedServer::chat(wrong.dump()));
  server_.push_chat(ScriptedServer::chat(good_answer().dump()));
  auto g = generate_program_llm(*generator_, *world_, *kb_, request_, limits_);
  ASSERT_TRUE(g) << g.error().message();
  ASSERT_EQ(server_.count(), 2);
  const std::string repair = user_message(1);
  EXPECT_THAT(repair, HasSubstr("/spotlight_agents/0"));
  EXPECT_THAT(repair, HasSubstr("contradicts the prompt: the prompt says 'two nurses' (exactly 2)"));
  EXPECT_THAT(repair, HasSubstr("the program has 5 nurse"));
  EXPECT_EQ(g->program["agents"][0]["count"], 2);
}

TEST_F(ProgramLlm, AStubbornContradictionIsRefusedAfterOneRepairAndNothingIsCached) {
  Json wrong = good_answer();
  wrong["spotlight_agents"][0]["parameters"]["count"] = 5;
  wrong["spotlight_agents"].push_back(wrong["spotlight_agents"][0]);
  wrong["spotlight_agents"][1]["id"] = "doctor";
  wrong["spotlight_agents"][1]["role"] = "doctor";
  for (int i = 0; i < 2; ++i) server_.push_chat(ScriptedServer::chat(wrong.dump()));
  LlmProgramOptions one_round;
  one_round.repair_rounds = 1;
  auto g = generate_program_llm(*generator_, *world_, *kb_, request_, limits_, one_round);
  ASSERT_FALSE(g);
  EXPECT_EQ(g.error().code, ErrorCode::kValidation);  // 422, as every answer that fails its checks
  EXPECT_EQ(g.error().status(), 422);
  EXPECT_EQ(server_.count(), 2);
  EXPECT_THAT(g.error().detail, HasSubstr("still contradicts the prompt"));
  std::string pointers;
  for (const auto& e : g.error().errors) pointers += e.pointer + " ";
  EXPECT_THAT(pointers, HasSubstr("/spotlight_agents/1"));  // the doctors nobody asked for
  EXPECT_THAT(g.error().message(), HasSubstr("nobody asked for them"));
  // Nothing of the refused generation was stored: the same request asks the endpoint again (a
  // cached answer would be used without a call) and the good answer then passes.
  server_.push_chat(ScriptedServer::chat(good_answer().dump()));
  auto again = generate_program_llm(*generator_, *world_, *kb_, request_, limits_, one_round);
  ASSERT_TRUE(again) << again.error().message();
  EXPECT_EQ(server_.count(), 3);
}

TEST_F(ProgramLlm, AnLlmCardStoresTheIntentToo) {
  server_.push_chat(ScriptedServer::chat(good_answer().dump()));
  ScenarioConfig config;
  auto request = scenario_request_from_json(
      {{"prompt", request_.prompt}, {"seed", 4}, {"generator", "llm"}, {"duration_s", 2}}, config);
  ASSERT_TRUE(request) << request.error().message();
  ScenarioServices s{*kb_, generator_.get(), config, std::nullopt, {}, {}};
  auto out = run_scenario(*request, ScenarioWorld{*world_, "hospital", Json::object()}, s);
  ASSERT_TRUE(out) << out.error().message();
  EXPECT_EQ(out->card.intent, to_json(interpret_prompt(request_.prompt).value()));
  EXPECT_EQ(out->card.generator.name, "llm");
}

TEST_F(ProgramLlm, ARefusedProgramMakesNoCard) {
  Json wrong = good_answer();
  wrong["spotlight_agents"][0]["parameters"]["count"] = 7;
  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(wrong.dump()));
  ScenarioConfig config;
  auto request = scenario_request_from_json(
      {{"prompt", request_.prompt}, {"seed", 4}, {"generator", "llm"}, {"duration_s", 5}}, config);
  ASSERT_TRUE(request) << request.error().message();
  ScenarioServices s{*kb_, generator_.get(), config, std::nullopt, {}, {}};
  auto out = run_scenario(*request, ScenarioWorld{*world_, "hospital", Json::object()}, s);
  ASSERT_FALSE(out);  // no card content comes out, so the server stores nothing
  EXPECT_EQ(out.error().status(), 422);
  EXPECT_THAT(out.error().message(), HasSubstr("the program has 7 nurse"));
}

}  // namespace
}  // namespace socsim::scenario
