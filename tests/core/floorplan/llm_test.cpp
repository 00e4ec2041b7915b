// LLM floor-plan generator against the scripted OpenAI-compatible server: the retrieved
// constraints and the scene graph reach the prompt; a valid answer becomes a compliant world;
// geometry and code failures are quoted back with pointers into the answer and repaired; an
// answer that never validates and an endpoint that is down give clear errors.
#include "core/floorplan/llm.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/world/world_yaml.hpp"
#include "tests/core/llm/scripted_server.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::floorplan {
namespace {

using socsim::testing::ScriptedServer;
using ::testing::HasSubstr;

class FloorplanLlm : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = store::Store::open(dir_.file("socsim.db")).value();
    kb_ = std::make_unique<knowledge::KnowledgeBase>(*store_);
    constraints_ = kb_->constraints_for("hospital").value();
    graph_ = room_program("hospital");
    client_ = socsim::testing::scripted_client(server_.base_url());
    generator_ = std::make_unique<llm::StructuredGenerator>(*client_, store_.get());
    OfflineOptions o;
    o.seed = 5;
    plan_ = generate_floor_plan(graph_, constraints_, o).value().world;  // a known-good answer to replay
  }

  std::string user_message(std::size_t call) const {
    return server_.seen().at(call).body["messages"].back()["content"];
  }

  ScriptedServer server_;
  socsim::testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<knowledge::KnowledgeBase> kb_;
  std::vector<knowledge::MergedConstraint> constraints_;
  SceneGraph graph_;
  std::unique_ptr<llm::LlmClient> client_;
  std::unique_ptr<llm::StructuredGenerator> generator_;
  std::optional<World> plan_;
};

TEST_F(FloorplanLlm, ConstraintsAndSceneGraphReachThePromptAndAValidAnswerBecomesACompliantWorld) {
  const Json answer = floor_plan_answer(*plan_);
  server_.push_chat(ScriptedServer::chat(answer.dump()));
  LlmFloorPlanOptions o;
  o.seed = 9;
  auto plan = generate_floor_plan_llm(*generator_, "a small hospital ward", graph_, constraints_, o);
  ASSERT_TRUE(plan) << plan.error().message();
  EXPECT_TRUE(plan->compliance.passed);
  EXPECT_EQ(plan->world.zones().size(), plan_->zones().size());
  EXPECT_EQ(plan->provenance["generator"], "llm");
  EXPECT_EQ(plan->provenance["llm"]["model"], "test-model");
  EXPECT_FALSE(plan->provenance["knowledge"].empty());
  // Furnished by room type like an offline plan.
  EXPECT_FALSE(plan->world.rois_of_kind("queue_lane").empty());

  const auto seen = server_.seen();
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].body["response_format"]["json_schema"]["name"], "floor_plan");
  const std::string user = user_message(0);
  EXPECT_THAT(user, HasSubstr("Building type: hospital"));
  EXPECT_THAT(user, HasSubstr("patient_room_04"));
  EXPECT_THAT(user, HasSubstr("corridor clear width (corridor): at least 2.438 m"));
  EXPECT_THAT(user, HasSubstr("patient bedroom area"));
}

TEST_F(FloorplanLlm, ACodeFailureIsQuotedBackWithItsPointerAndRepaired) {
  Json bad = floor_plan_answer(*plan_);
  std::size_t narrowed = 0;
  for (std::size_t i = 0; i < bad["doors"].size(); ++i)
    if (bad["doors"][i]["rooms"].size() == 2) {
      bad["doors"][i]["width"] = 0.9;  // below the 1.054 m of IBC 1010.1.1 for I-2
      narrowed = i;
      break;
    }
  server_.push_chat(ScriptedServer::chat(bad.dump()));
  server_.push_chat(ScriptedServer::chat(floor_plan_answer(*plan_).dump()));
  auto plan = generate_floor_plan_llm(*generator_, "", graph_, constraints_);
  ASSERT_TRUE(plan) << plan.error().message();
  ASSERT_EQ(server_.count(), 2);
  const std::string repair = user_message(1);
  EXPECT_THAT(repair, HasSubstr("/doors/" + std::to_string(narrowed) + "/width"));
  EXPECT_THAT(repair, HasSubstr("door_clear_width (ibc2018_1010_door_i2"));
  EXPECT_EQ(plan->provenance["llm"]["rounds"], 2);
}

TEST_F(FloorplanLlm, GeometryAndSceneGraphProblemsPointIntoTheAnswer) {
  Json bad = floor_plan_answer(*plan_);
  // The lobby–corridor door dropped, and another door moved off every wall.
  for (std::size_t i = 0; i < bad["doors"].size(); ++i) {
    const auto& r = bad["doors"][i]["rooms"];
    if (r.size() == 2 &&
        ((r[0] == "lobby" && r[1] == "corridor") || (r[0] == "corridor" && r[1] == "lobby"))) {
      bad["doors"].erase(i);
      break;
    }
  }
  bad["doors"][0]["position"] = Json::array({0.5, 0.5});
  auto result = floor_plan_from_answer(bad, graph_, constraints_);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().code, ErrorCode::kValidation);
  std::vector<std::string> pointers;
  std::string messages;
  for (const auto& e : result.error().errors) {
    pointers.push_back(e.pointer);
    messages += e.message + "\n";
  }
  EXPECT_THAT(pointers, ::testing::Contains("/doors/0/position")) << messages;
  EXPECT_THAT(messages, HasSubstr("no door connects 'corridor' and 'lobby'"));
}

TEST_F(FloorplanLlm, AnAnswerThatNeverValidatesEndsWithAClearErrorAfterTheRepairRounds) {
  Json bad = floor_plan_answer(*plan_);
  bad["rooms"][1]["polygon"] =
      Json::array({Json::array({0, 0}), Json::array({4, 4}), Json::array({4, 0}), Json::array({0, 4})});
  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(bad.dump()));
  auto plan = generate_floor_plan_llm(*generator_, "", graph_, constraints_);
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.error().code, ErrorCode::kValidation);
  EXPECT_EQ(server_.count(), 3);  // first answer + two repair rounds
  bool names_room = false;
  for (const auto& e : plan.error().errors) names_room = names_room || e.pointer == "/rooms/1/polygon";
  EXPECT_TRUE(names_room) << plan.error().message();
}

TEST_F(FloorplanLlm, AnEndpointThatIsDownGivesAnUpstreamErrorNamingIt) {
  int port = 0;
  {
    ScriptedServer closed;
    port = closed.port();
  }
  auto client = socsim::testing::scripted_client("http://127.0.0.1:" + std::to_string(port));
  llm::StructuredGenerator gen(*client, nullptr);
  auto plan = generate_floor_plan_llm(gen, "", graph_, constraints_);
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.error().code, ErrorCode::kUpstream);
  EXPECT_THAT(plan.error().detail, HasSubstr("127.0.0.1:" + std::to_string(port)));
}

}  // namespace
}  // namespace socsim::floorplan
