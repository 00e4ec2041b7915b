// /api/v1/scenarios over HTTP: a prompt becomes a job whose result is a scenario card with its
// trajectory log stored beside it; the log downloads and decodes to the card's hash; a replay job
// reproduces it bit for bit; bad requests name their fields; an LLM job runs against the scripted
// OpenAI-compatible server, its prompts, token counts and cache hits visible in the job's record.
#include <chrono>
#include <fstream>
#include <iterator>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/scenario/trajectory_log.hpp"
#include "tests/core/llm/scripted_server.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {

using ::testing::HasSubstr;
using testing::TestServer;

using socsim::testing::post;

Json finished_job(TestServer& s, httplib::Client& c, const httplib::Result& accepted) {
  EXPECT_TRUE(accepted);
  EXPECT_EQ(accepted->status, 202) << accepted->body;
  const std::string id = Json::parse(accepted->body)["id"];
  EXPECT_EQ(accepted->get_header_value("Location"), "/api/v1/jobs/" + id);
  EXPECT_TRUE(s.services().jobs->wait(id, std::chrono::seconds(60)));
  auto r = c.Get(("/api/v1/jobs/" + id).c_str());
  return Json::parse(r->body);
}

TEST(Scenarios, APromptBecomesACardWithItsTrajectoryLogAndReplaysIdentically) {
  TestServer s;
  auto c = s.client();
  const Json job = finished_job(
      s, c,
      post(
          c, "/api/v1/scenarios",
          {{"prompt", "visitors queue at the reception desk of a clinic"}, {"seed", 7}, {"duration_s", 10}}));
  ASSERT_EQ(job["status"], "succeeded") << job.dump();
  EXPECT_EQ(job["progress"], 1.0);
  const std::string card_id = job["result"]["card_id"];

  auto card_r = c.Get(("/api/v1/cards/" + card_id).c_str());
  ASSERT_EQ(card_r->status, 200);
  const Json card = Json::parse(card_r->body);
  EXPECT_EQ(card["seed"], 7);
  EXPECT_THAT(card["tags"], ::testing::Contains("queuing"));
  EXPECT_FALSE(card["program"]["agents"].empty());
  const std::string sha = card["trajectory_log"]["sha256"];

  auto log_r = c.Get(card["trajectory_log"]["uri"].get<std::string>().c_str());
  ASSERT_EQ(log_r->status, 200);
  EXPECT_EQ(log_r->get_header_value("ETag"), "\"" + sha + "\"");
  auto log = scenario::TrajectoryLog::from_compressed(log_r->body);
  ASSERT_TRUE(log) << log.error().message();
  EXPECT_EQ(log->sha256(), sha);
  EXPECT_EQ(log->frame_count(), 101u);

  const Json replay = finished_job(s, c, post(c, "/api/v1/cards/" + card_id + "/replay", Json::object()));
  ASSERT_EQ(replay["status"], "succeeded") << replay.dump();
  EXPECT_EQ(replay["result"]["identical"], true);
  EXPECT_EQ(replay["result"]["sha256"], sha);

  EXPECT_EQ(c.Get(("/api/v1/trajectories/" + std::string(64, 'a')).c_str())->status, 404);
}

TEST(Scenarios, BadRequestsNameTheirFields) {
  TestServer s;
  auto c = s.client();
  struct Case {
    Json body;
    std::string pointer;
    int status = 422;
  };
  const std::vector<Case> cases = {
      {{{"seed", 1}}, "/prompt"},
      {{{"prompt", "a queue"}, {"duration_s", 0}}, "/duration_s"},
      {{{"prompt", "a queue"}, {"agents", 100000}}, "/agents"},
      {{{"prompt", "a queue"}, {"generator", "llm"}}, "/generator"},
      {{{"prompt", "a queue"}, {"world_id", "wld_aaaaaaaaaaaaaaaaaaaa"}}, "/world_id"},
      {{{"prompt", "a queue"}, {"world", {{"zones", Json::array()}}}}, "/world"},
      {{{"prompt", "a queue"}, {"world", "zones: [\n  {name: a}\n"}},
       "/world",
       400},  // YAML syntax: line named
  };
  for (const auto& k : cases) {
    auto r = post(c, "/api/v1/scenarios", k.body);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, k.status) << k.body.dump() << " → " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    EXPECT_THAT(r->body, HasSubstr("\"" + k.pointer)) << r->body;
    if (k.status == 400) {
      EXPECT_THAT(r->body, HasSubstr("\"line\":3"));
    }
  }
}

// Issue 14 #11: a world of 1e308 metres was accepted and stored with the scenario.
TEST(Scenarios, AnInlineWorldBeyondTheCoordinateRangeIs422) {
  TestServer s;
  auto c = s.client();
  const Json world = {
      {"name", "huge"},
      {"zones",
       Json::array({{{"name", "hall"},
                     {"type", "hall"},
                     {"polygon", Json::array({Json::array({0, 0}), Json::array({1e308, 0}),
                                              Json::array({1e308, 1e308}), Json::array({0, 1e308})})}}})}};
  auto r = post(c, "/api/v1/scenarios", {{"prompt", "people walk through the hall"}, {"world", world}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422) << r->body;
  EXPECT_EQ(Json::parse(r->body)["errors"][0]["pointer"], "/world/zones/0/polygon/1") << r->body;
}

TEST(Scenarios, AgentCountsAndDurationsAreBoundedByConfig) {
  ServerConfig config;
  config.max_scenario_agents = 10;
  config.max_scenario_seconds = 8;
  TestServer s(config);
  auto c = s.client();
  auto r =
      post(c, "/api/v1/scenarios",
           {{"prompt", "a crowd of two hundred people walks through"}, {"agents", 11}, {"duration_s", 9}});
  ASSERT_EQ(r->status, 422) << r->body;
  EXPECT_THAT(r->body, HasSubstr("\"/agents\""));
  EXPECT_THAT(r->body, HasSubstr("\"/duration_s\""));
  // Within the bounds, a prompt asking for more people gets at most the configured number.
  const Json job =
      finished_job(s, c,
                   post(c, "/api/v1/scenarios",
                        {{"prompt", "a crowd of two hundred people walks through"}, {"duration_s", 3}}));
  ASSERT_EQ(job["status"], "succeeded") << job.dump();
  EXPECT_LE(job["result"]["trajectory_log"]["agents"].get<int>(), 10);
}

TEST(Scenarios, AStoredWorldIsUsedByItsId) {
  TestServer s;
  auto c = s.client();
  auto w = post(c, "/api/v1/worlds", {{"prompt", "an office with two meeting rooms"}, {"seed", 3}});
  ASSERT_EQ(w->status, 201) << w->body;
  const std::string world_id = Json::parse(w->body)["id"];
  const Json job = finished_job(
      s, c,
      post(c, "/api/v1/scenarios",
           {{"prompt", "a fire drill: everyone evacuates"}, {"world_id", world_id}, {"duration_s", 5}}));
  ASSERT_EQ(job["status"], "succeeded") << job.dump();
  const Json card =
      Json::parse(c.Get(("/api/v1/cards/" + job["result"]["card_id"].get<std::string>()).c_str())->body);
  EXPECT_EQ(card["provenance"]["world_id"], world_id);
  EXPECT_EQ(card["domain"], "office");
}

// Fig. 3 of paper 001 exactly as printed (tests/fixtures/paper001_fig3_as_printed.yaml: the
// zone named only, one wall, '↳' where the listing wraps): it validates with warnings, then
// a scenario runs in it.
TEST(Scenarios, PaperFigure3AsPrintedValidatesAndSimulates) {
  TestServer s;
  auto c = s.client();
  std::ifstream in(std::string(SOCSIM_SOURCE_DIR) + "/tests/fixtures/paper001_fig3_as_printed.yaml",
                   std::ios::binary);
  const std::string fig3((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_THAT(fig3, HasSubstr("  - name: canteen_hall\nwalls:"));

  auto v = c.Post("/api/v1/worlds/validate", fig3, "application/yaml");
  ASSERT_TRUE(v);
  ASSERT_EQ(v->status, 200) << v->body;
  const Json report = Json::parse(v->body);
  EXPECT_EQ(report["valid"], true);
  EXPECT_EQ(report["zones"], 1);
  EXPECT_EQ(report["walls"], 5);
  EXPECT_EQ(report["area"], 80.0);
  ASSERT_EQ(report["warnings"].size(), 3u) << report["warnings"].dump();
  EXPECT_EQ(report["warnings"][1]["pointer"], "/zones/0/polygon");
  EXPECT_EQ(report["warnings"][1]["line"], 3);
  EXPECT_THAT(report["warnings"][1]["message"].get<std::string>(), HasSubstr("x 0 .. 10, y 0 .. 8"));
  EXPECT_EQ(report["compliance"]["building_type"], "canteen");

  const Json job =
      finished_job(s, c,
                   post(c, "/api/v1/scenarios",
                        {{"prompt", "students queue at the food counter, then sit down at a table"},
                         {"world", fig3},
                         {"seed", 3},
                         {"duration_s", 10}}));
  ASSERT_EQ(job["status"], "succeeded") << job.dump();
  EXPECT_GT(job["result"]["trajectory_log"]["agents"].get<int>(), 0);
  const Json card =
      Json::parse(c.Get(("/api/v1/cards/" + job["result"]["card_id"].get<std::string>()).c_str())->body);
  EXPECT_EQ(card["domain"], "canteen");
  EXPECT_EQ(card["provenance"]["world"]["warnings"].size(), 3u);
  EXPECT_EQ(card["world"]["zones"][0]["polygon"], Json::parse("[[0, 0], [10, 0], [10, 8], [0, 8]]"));
}

TEST(Scenarios, AnLlmJobRecordsItsPromptsTokensAndCacheHits) {
  socsim::testing::ScriptedServer llm;
  ServerConfig config;
  config.llm.base_url = llm.base_url();
  config.llm.model = "scripted";
  config.llm.max_retries = 0;
  config.api_keys = parse_api_keys("alice:alice-secret-0123456789,bob:bob-secret-0123456789").value();
  TestServer s(config);
  auto c = s.client();
  c.set_default_headers({{"Authorization", "Bearer alice-secret-0123456789"}});
  // A stored world, so that only the scenario program comes from the model.
  auto w = post(c, "/api/v1/worlds", {{"prompt", "a clinic"}, {"seed", 1}, {"domain", "hospital"}});
  ASSERT_EQ(w->status, 201) << w->body;
  const std::string world_id = Json::parse(w->body)["id"];
  const Json world = Json::parse(c.Get(("/api/v1/worlds/" + world_id).c_str())->body)["world"];
  std::string zone_a = world["zones"][0]["name"], zone_b = world["zones"][1]["name"];
  const Json answer = {
      {"spotlight_agents",
       {{{"id", "nurse"},
         {"role", "nurse"},
         {"spawn_roi", zone_a},
         {"behavior_tree",
          "<root BTCPP_format=\"4\"><BehaviorTree ID=\"N\"><WaitAt agent_id=\"{id}\" location=\"" + zone_b +
              "\" duration=\"20\"/></BehaviorTree></root>"}}}},
      {"ambient_groups",
       {{{"name", "visitors"},
         {"description", "visitors walking in"},
         {"start_roi", zone_a},
         {"goal_roi", zone_b},
         {"size", 4},
         {"speed", 1.2}}}}};
  llm.push_chat(socsim::testing::ScriptedServer::chat(answer.dump(), "stop", 900, 150));
  const Json body = {{"prompt", "a nurse waits while visitors walk in"},
                     {"world_id", world_id},
                     {"generator", "llm"},
                     {"seed", 2},
                     {"duration_s", 4}};
  const Json job = finished_job(s, c, post(c, "/api/v1/scenarios", body));
  ASSERT_EQ(job["status"], "succeeded") << job.dump();
  ASSERT_TRUE(job["llm"].is_object()) << job.dump();
  EXPECT_EQ(job["llm"]["totals"]["prompt_tokens"], 900);
  EXPECT_EQ(job["llm"]["calls"][0]["artifact"], "scenario_program");
  EXPECT_THAT(job["llm"]["calls"][0]["prompt"].dump(), HasSubstr("a nurse waits while visitors walk in"));
  // Issue 14 #12: the prompts and answers are the author's; another key, or none, sees the
  // counts only (a server without keys authenticates nobody, so there nobody sees them).
  for (const char* other : {"Bearer bob-secret-0123456789", ""}) {
    auto peek = s.client();
    if (*other) peek.set_default_headers({{"Authorization", other}});
    const Json seen = Json::parse(peek.Get(("/api/v1/jobs/" + job["id"].get<std::string>()).c_str())->body);
    EXPECT_EQ(seen["llm"]["totals"]["prompt_tokens"], 900);
    EXPECT_TRUE(seen["llm"]["calls"][0]["prompt"].is_null()) << other;
    EXPECT_TRUE(seen["llm"]["calls"][0]["response"].is_null()) << other;
    EXPECT_THAT(seen.dump(), ::testing::Not(HasSubstr("visitors walking in"))) << other;
  }
  const Json card =
      Json::parse(c.Get(("/api/v1/cards/" + job["result"]["card_id"].get<std::string>()).c_str())->body);
  EXPECT_EQ(card["generator"]["name"], "llm");
  EXPECT_EQ(card["generator"]["model"], "scripted");
  EXPECT_EQ(card["provenance"]["program"]["llm"]["prompt_tokens"], 900);
  EXPECT_EQ(llm.count(), 1);

  // The same request again: answered from the cache, nothing sent to the endpoint.
  const Json again = finished_job(s, c, post(c, "/api/v1/scenarios", body));
  ASSERT_EQ(again["status"], "succeeded") << again.dump();
  EXPECT_EQ(llm.count(), 1);
  EXPECT_EQ(again["llm"]["totals"]["cache_hits"], 1);
  const Json card2 =
      Json::parse(c.Get(("/api/v1/cards/" + again["result"]["card_id"].get<std::string>()).c_str())->body);
  EXPECT_EQ(card2["provenance"]["program"]["llm"]["cache_hits"], 1);
  EXPECT_EQ(card2["trajectory_log"]["sha256"], card["trajectory_log"]["sha256"]);
}

// Issue 14 #12: the model a request names was passed to the endpoint unchecked (any model it
// serves, at the operator's cost); now it must be allowed, by default the configured one alone.
TEST(Scenarios, ARequestedModelMustBeAllowed) {
  socsim::testing::ScriptedServer llm;
  ServerConfig config;
  config.llm.base_url = llm.base_url();
  config.llm.model = "scripted";
  config.llm.max_retries = 0;
  TestServer s(config);
  auto c = s.client();
  const Json base = {{"prompt", "people walk through an office"}, {"generator", "llm"}, {"duration_s", 2}};
  for (const char* path : {"/api/v1/scenarios", "/api/v1/worlds"}) {
    Json body = base;
    if (std::string(path) == "/api/v1/worlds") body.erase("duration_s");
    body["model"] = "gpt-4o-expensive";
    auto r = post(c, path, body);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422) << path << ": " << r->body;
    EXPECT_EQ(Json::parse(r->body)["errors"][0]["pointer"], "/model") << r->body;
  }
  auto jobs = Json::parse(c.Get("/api/v1/jobs")->body);
  EXPECT_TRUE(jobs["items"].empty()) << "nothing is queued for a refused model";
  EXPECT_EQ(llm.count(), 0);
}

}  // namespace
}  // namespace socsim::server
