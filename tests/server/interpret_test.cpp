// POST /api/v1/scenarios/interpret over HTTP: a prompt's ScenarioIntent with spans into the prompt;
// bad prompts (empty, white space, too long, another language, nothing a person, place or
// activity) are 422 problem documents at /prompt there and on POST /api/v1/scenarios, where
// nothing is queued or stored for them (the job list and the catalogue stay as they were).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {

using ::testing::HasSubstr;
using testing::TestServer;

using socsim::testing::post;

std::string spanned(const std::string& prompt, const Json& span) {
  return prompt.substr(span[0].get<std::size_t>(), span[1].get<std::size_t>() - span[0].get<std::size_t>());
}

TEST(Interpret, APromptGivesItsIntentWithSpans) {
  TestServer s;
  auto c = s.client();
  const std::string prompt = "A library that is empty except for 3 librarians shelving books";
  auto r = post(c, "/api/v1/scenarios/interpret", {{"prompt", prompt}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  const Json intent = Json::parse(r->body);
  EXPECT_EQ(intent["version"], 1);
  EXPECT_EQ(intent["prompt"], prompt);
  ASSERT_EQ(intent["groups"].size(), 1u) << intent.dump();
  const Json& g = intent["groups"][0];
  EXPECT_EQ(g["role"], "librarian");
  EXPECT_EQ(g["count"]["kind"], "exact");
  EXPECT_EQ(g["count"]["value"], 3);
  EXPECT_EQ(spanned(prompt, g["span"]), "3 librarians");
  EXPECT_EQ(intent["venue"]["type"], "library");
  EXPECT_EQ(spanned(prompt, intent["venue"]["span"]), "library");
  EXPECT_EQ(intent["exclusivity"]["exclusive"], true);
  EXPECT_EQ(intent["total"]["value"], 3);
  // Nothing is stored by reading a prompt.
  EXPECT_EQ(Json::parse(c.Get("/api/v1/jobs")->body)["items"].size(), 0u);
}

TEST(Interpret, TheRequestIsAnObjectWithAStringPrompt) {
  TestServer s;
  auto c = s.client();
  for (const auto& [body, pointer] : std::vector<std::pair<Json, std::string>>{
           {Json::object(), "/prompt"},
           {{{"prompt", 7}}, "/prompt"},
           {{{"prompt", "three nurses"}, {"seed", 1}}, "/seed"},
           {Json::array(), ""},
       }) {
    auto r = post(c, "/api/v1/scenarios/interpret", body);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422) << body.dump() << " → " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    EXPECT_EQ(Json::parse(r->body)["errors"][0]["pointer"], pointer) << r->body;
  }
  auto bad = c.Post("/api/v1/scenarios/interpret", "{\"prompt\":", "application/json");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
}

struct BadPrompt {
  std::string prompt;
  std::string detail;   // the problem's detail
  std::string message;  // a part of the /prompt error's message
};

std::vector<BadPrompt> bad_prompts(std::size_t max_bytes) {
  return {
      {" \t\n  ", "the prompt is only white space", "must contain words"},
      {std::string(max_bytes + 1, 'a'), "the prompt is too long",
       "at most " + std::to_string(max_bytes) + " bytes"},
      {"Drei Bibliothekare stellen Bücher in der leeren Bibliothek ins Regal", "the prompt is not in English",
       "socsim reads English prompts; only 4 of its 10 words"},
      {"Три врача идут по коридору больницы", "the prompt is not in English", "written in Cyrillic script"},
      {"Lorem ipsum dolor sit amet", "the prompt is not in English", "(not: 'Lorem', 'ipsum', 'amet')"},
      {"hello there", "the prompt names no person, place or activity", "found no people"},
  };
}

TEST(Interpret, BadPromptsAre422AtPrompt) {
  TestServer s;
  auto c = s.client();
  auto empty = post(c, "/api/v1/scenarios/interpret", {{"prompt", ""}});
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty->status, 422);
  EXPECT_EQ(Json::parse(empty->body)["detail"], "the prompt is empty");
  EXPECT_EQ(Json::parse(empty->body)["errors"][0]["pointer"], "/prompt");
  for (const auto& b : bad_prompts(ServerConfig{}.max_prompt_bytes)) {
    auto r = post(c, "/api/v1/scenarios/interpret", {{"prompt", b.prompt}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422) << b.prompt << " → " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    const Json p = Json::parse(r->body);
    EXPECT_EQ(p["detail"], b.detail) << r->body;
    ASSERT_EQ(p["errors"].size(), 1u) << r->body;
    EXPECT_EQ(p["errors"][0]["pointer"], "/prompt");
    EXPECT_THAT(p["errors"][0]["message"].get<std::string>(), HasSubstr(b.message));
  }
}

TEST(Interpret, RefusedScenarioPromptsQueueAndStoreNothing) {
  TestServer s;
  auto c = s.client();
  // One scenario that is accepted, so the lists are not trivially empty.
  auto ok = post(c, "/api/v1/scenarios", {{"prompt", "two nurses chat in the corridor"}, {"duration_s", 2}});
  ASSERT_TRUE(ok);
  ASSERT_EQ(ok->status, 202) << ok->body;
  ASSERT_TRUE(s.services().jobs->wait(Json::parse(ok->body)["id"], std::chrono::seconds(60)));
  const std::string jobs_before = c.Get("/api/v1/jobs?page_size=100")->body;
  const std::string cards_before = c.Get("/api/v1/cards?page_size=100")->body;
  ASSERT_EQ(Json::parse(jobs_before)["items"].size(), 1u);
  ASSERT_EQ(Json::parse(cards_before)["items"].size(), 1u);

  auto bad = bad_prompts(ServerConfig{}.max_prompt_bytes);
  bad.erase(bad.begin() + 1);  // over the limit: the request reader says it (next test)
  for (const auto& b : bad) {
    auto r = post(c, "/api/v1/scenarios", {{"prompt", b.prompt}, {"seed", 1}, {"duration_s", 5}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422) << b.prompt << " → " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    const Json p = Json::parse(r->body);
    EXPECT_EQ(p["detail"], b.detail) << r->body;
    EXPECT_EQ(p["errors"][0]["pointer"], "/prompt");
    EXPECT_THAT(p["errors"][0]["message"].get<std::string>(), HasSubstr(b.message));
  }
  for (const Json& prompt : {Json(""), Json(std::string(ServerConfig{}.max_prompt_bytes + 1, 'a'))}) {
    auto r = post(c, "/api/v1/scenarios", {{"prompt", prompt}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422) << r->body;
    EXPECT_EQ(Json::parse(r->body)["errors"][0]["pointer"], "/prompt");
  }
  EXPECT_EQ(c.Get("/api/v1/jobs?page_size=100")->body, jobs_before);
  EXPECT_EQ(c.Get("/api/v1/cards?page_size=100")->body, cards_before);
  EXPECT_EQ(Json::parse(c.Get("/api/v1/health")->body)["database"]["cards"], 1);
}

TEST(Interpret, TheLimitIsTheServersPromptLimit) {
  ServerConfig config;
  config.max_prompt_bytes = 64;
  TestServer s(config);
  auto c = s.client();
  auto r = post(c, "/api/v1/scenarios/interpret", {{"prompt", "three nurses " + std::string(60, 'x')}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_THAT(r->body, HasSubstr("must be at most 64 bytes (got 73)"));
}

}  // namespace
}  // namespace socsim::server
