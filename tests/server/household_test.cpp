// Personas and households over HTTP: paginated personas, posted personas validated (422 with
// pointers, 409 on a taken id), offline generation, a household made by a job and stored, its
// objects at a time agreeing with a replay of its events, events by window and resident, hints,
// ProcTHOR export, statistics, and 404/422 for unknown ids and bad input.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using testing::TestServer;

using testing::get_json;

std::set<std::string> pointers(const Json& problem) {
  std::set<std::string> out;
  for (const auto& e : problem.value("errors", Json::array())) out.insert(e.value("pointer", ""));
  return out;
}

Json persona(const std::string& name, int age) {
  return {{"name", name},
          {"age", age},
          {"gender", "female"},
          {"routine", "She goes to bed at 11 pm and gets up at 7 am."},
          {"personality", {"curious"}},
          {"occupation", "She is a potter with a studio in the garden."},
          {"thoughts", "She is preparing a market stall."},
          {"lifestyle", "She lives alone and grows tomatoes."}};
}

TEST(HouseholdApi, PersonasArePaginatedPostedAndGenerated) {
  TestServer s;
  auto c = s.client();
  Json page = get_json(c, "/api/v1/personas?page_size=20");
  EXPECT_EQ(page["items"].size(), 20u);
  EXPECT_EQ(page["total"], 50);
  std::set<std::string> ids;
  for (std::string cursor = "";;) {
    Json p = get_json(c, "/api/v1/personas?page_size=20" + (cursor.empty() ? "" : "&cursor=" + cursor));
    for (const auto& i : p["items"]) ids.insert(i["id"].get<std::string>());
    if (p["next_cursor"].is_null()) break;
    cursor = p["next_cursor"];
  }
  EXPECT_EQ(ids.size(), 50u);
  EXPECT_EQ(get_json(c, "/api/v1/personas/margit-halvorsen")["builtin"], true);
  get_json(c, "/api/v1/personas/nobody-here", 404);

  auto created = c.Post("/api/v1/personas", persona("Ilse Brandt", 51).dump(), "application/json");
  ASSERT_TRUE(created);
  EXPECT_EQ(created->status, 201) << created->body;
  EXPECT_EQ(created->get_header_value("Location"), "/api/v1/personas/ilse-brandt");
  EXPECT_EQ(get_json(c, "/api/v1/personas/ilse-brandt")["builtin"], false);
  auto again = c.Post("/api/v1/personas", persona("Ilse Brandt", 51).dump(), "application/json");
  EXPECT_EQ(again->status, 409);
  auto bad = c.Post("/api/v1/personas", persona("Ilse Other", -4).dump(), "application/json");
  EXPECT_EQ(bad->status, 422);
  EXPECT_TRUE(pointers(Json::parse(bad->body)).count("/age"));
  EXPECT_EQ(get_json(c, "/api/v1/personas?page_size=100")["total"], 51);

  auto gen = c.Post("/api/v1/personas/generate",
                    R"({"count": 3, "seed": 8, "constraints": {"household_role": "grandparent"}})",
                    "application/json");
  ASSERT_TRUE(gen);
  ASSERT_EQ(gen->status, 200) << gen->body;
  Json g = Json::parse(gen->body);
  ASSERT_EQ(g["personas"].size(), 3u);
  for (const auto& p : g["personas"]) EXPECT_GE(p["age"].get<int>(), 55);
  auto stored =
      c.Post("/api/v1/personas/generate", R"({"count": 2, "seed": 8, "store": true})", "application/json");
  EXPECT_EQ(stored->status, 201);
  EXPECT_EQ(get_json(c, "/api/v1/personas?page_size=100")["total"], 53);
  auto wrong = c.Post("/api/v1/personas/generate",
                      R"({"count": 0, "constraints": {"gender": "robot"}, "colour": 1})", "application/json");
  EXPECT_EQ(wrong->status, 422);
  const auto ptrs = pointers(Json::parse(wrong->body));
  for (const char* want : {"/count", "/constraints/gender", "/colour"}) EXPECT_TRUE(ptrs.count(want)) << want;
  auto llm = c.Post("/api/v1/personas/generate", R"({"count": 1, "generator": "llm"})", "application/json");
  EXPECT_EQ(llm->status, 422);
  EXPECT_TRUE(pointers(Json::parse(llm->body)).count("/generator"));
}

// Issue 14 #11: generator and store were read with json::value(), which throws on a wrong type (500).
TEST(HouseholdApi, PersonaGenerationFieldsOfTheWrongTypeAre422) {
  TestServer s;
  auto c = s.client();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"count": 1, "store": "yes"})", "/store"},
      {R"({"count": 1, "store": 1})", "/store"},
      {R"({"count": 1, "generator": 5})", "/generator"},
      {R"({"count": 1, "generator": {"name": "offline"}})", "/generator"},
      {R"({"count": 1, "generator": "llm", "model": 7})", "/model"},
      {R"({"count": 1, "generator": "offline", "model": "gpt-4o"})", "/model"}};
  for (const auto& [body, pointer] : cases) {
    auto r = c.Post("/api/v1/personas/generate", body, "application/json");
    ASSERT_TRUE(r) << body;
    EXPECT_EQ(r->status, 422) << body << " → " << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    EXPECT_TRUE(pointers(Json::parse(r->body)).count(pointer)) << body << " → " << r->body;
  }
  // null is not given: the defaults (offline, not stored) apply.
  auto defaults = c.Post("/api/v1/personas/generate", R"({"count": 1, "generator": null, "store": null})",
                         "application/json");
  ASSERT_TRUE(defaults);
  EXPECT_EQ(defaults->status, 200) << defaults->body;
}

TEST(HouseholdApi, HouseholdJobStoresASceneThatAnswersQueries) {
  TestServer s;
  auto c = s.client();
  auto post = c.Post("/api/v1/households", R"({"rooms": 6, "residents": 2, "days": 2, "seed": 7})",
                     "application/json");
  ASSERT_TRUE(post);
  ASSERT_EQ(post->status, 202) << post->body;
  const std::string location = post->get_header_value("Location");
  ASSERT_EQ(location.rfind("/api/v1/jobs/", 0), 0u);
  const std::string job_id = location.substr(13);
  ASSERT_TRUE(s.services().jobs->wait(job_id, std::chrono::seconds(60)));
  Json job = get_json(c, location);
  ASSERT_EQ(job["status"], "succeeded") << job.dump();
  const std::string id = job["result"]["household_id"];
  const std::string base = "/api/v1/households/" + id;

  Json h = get_json(c, base);
  EXPECT_EQ(h["residents"].size(), 2u);
  EXPECT_EQ(h["schedules"].size(), 2u);
  EXPECT_EQ(h["end"], 2 * 86400);
  EXPECT_GE(h["house"]["rooms"].size(), 6u);
  EXPECT_FALSE(h["house"]["receptacles"].empty());
  EXPECT_EQ(get_json(c, "/api/v1/households")["items"][0]["id"], id);

  // objects?t= agrees with replaying the events from the start.
  const Json start = get_json(c, base + "/objects?t=0");
  std::map<std::string, std::string> where;
  for (const auto& o : start["objects"]) where[o["id"]] = o["receptacle"];
  std::vector<Json> events;
  for (std::string cursor = "0";;) {
    Json page = get_json(c, base + "/events?page_size=100&cursor=" + cursor);
    for (const auto& e : page["items"]) events.push_back(e);
    if (page["next_cursor"].is_null()) break;
    cursor = page["next_cursor"];
  }
  ASSERT_FALSE(events.empty());
  std::sort(events.begin(), events.end(), [](const Json& a, const Json& b) {
    return a["end"] != b["end"] ? a["end"] < b["end"] : a["index"] < b["index"];
  });
  const std::int64_t t = 86400 + 13 * 3600;
  for (const auto& e : events)
    if (e["end"].get<std::int64_t>() <= t)
      for (const auto& m : e["relocations"]) where[m["object"]] = m["to"];
  const Json at = get_json(c, base + "/objects?t=" + std::to_string(t));
  int differs_from_start = 0;
  for (std::size_t i = 0; i < at["objects"].size(); ++i) {
    const Json& o = at["objects"][i];
    EXPECT_EQ(where[o["id"]], o["receptacle"]) << o["id"];
    differs_from_start += o["receptacle"] != start["objects"][i]["receptacle"];
  }
  EXPECT_GT(differs_from_start, 0) << "a day and a half of activities moves some objects";

  Json window = get_json(c, base + "/events?from=28800&to=36000&resident=1");
  for (const auto& e : window["items"]) {
    EXPECT_EQ(e["resident"], 1);
    EXPECT_LT(e["start"].get<int>(), 36000);
    EXPECT_GT(e["end"].get<int>(), 28800);
  }
  Json hint = get_json(c, base + "/hint?resident=0&object=Mug&t=" + std::to_string(t));
  EXPECT_FALSE(hint["text"].get<std::string>().empty());
  Json exported = get_json(c, base + "/export?format=procthor&t=" + std::to_string(t));
  EXPECT_TRUE(exported.contains("rooms") && exported.contains("objects"));
  Json plan = get_json(c, base);
  ASSERT_TRUE(plan["house"].contains("windows"));
  EXPECT_FALSE(plan["house"]["windows"].empty()) << "generated houses have windows (issue 18)";
  for (const auto& w : plan["house"]["windows"]) EXPECT_GT(w["width"].get<double>(), 0.5);
  Json stats = get_json(c, base + "/statistics");
  EXPECT_TRUE(stats.contains("paper"));
  // Issue 18: waking activities per persona-day, median length and "leave home" share, with
  // DynamicTHOR's figures beside them.
  ASSERT_TRUE(stats.contains("days_of_activities"));
  EXPECT_GT(stats["days_of_activities"]["per_persona_day"]["mean"].get<double>(), 0.0);
  EXPECT_GT(stats["days_of_activities"]["median_minutes"].get<double>(), 0.0);
  EXPECT_EQ(stats["days_of_activities"]["dynamic_thor"]["median_minutes"], 20.0);

  get_json(c, base + "/objects?t=-5", 422);
  Json bad_t = get_json(c, base + "/objects?t=999999999", 422);
  EXPECT_EQ(bad_t["errors"][0]["parameter"], "t");
  get_json(c, base + "/objects", 422);
  get_json(c, base + "/export?format=obj", 422);
  get_json(c, "/api/v1/households/hh_0000000000000000dead", 404);
  get_json(c, "/api/v1/households/hh_0000000000000000dead/objects?t=0", 404);
}

TEST(HouseholdApi, BadHouseholdRequestsAreNamed) {
  TestServer s;
  auto c = s.client();
  auto r = c.Post("/api/v1/households", R"({"rooms": 0, "days": 100, "residents": ["ben-okafor", 4]})",
                  "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  const auto p = pointers(Json::parse(r->body));
  for (const char* want : {"/rooms", "/days", "/residents/1"})
    EXPECT_TRUE(p.count(want)) << want << " in " << r->body;
  auto unknown = c.Post("/api/v1/households",
                        R"({"rooms": 5, "residents": ["ben-okafor", "no-such-person"]})", "application/json");
  EXPECT_EQ(unknown->status, 422);
  EXPECT_TRUE(pointers(Json::parse(unknown->body)).count("/residents/1"));
  auto house = c.Post("/api/v1/households", R"({"house": {"rooms": "many"}})", "application/json");
  EXPECT_EQ(house->status, 422);
  for (const auto& ptr : pointers(Json::parse(house->body))) EXPECT_EQ(ptr.rfind("/house", 0), 0u) << ptr;
  auto llm = c.Post("/api/v1/households", R"({"rooms": 5, "generator": "llm"})", "application/json");
  EXPECT_EQ(llm->status, 422);
}

}  // namespace
}  // namespace socsim::server
