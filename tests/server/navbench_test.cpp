// The navigation benchmark over HTTP: a job (202 + Location, progress, the table as JSON), bad
// requests named field by field, the same request giving the same table, and the replay of one
// episode with the house, the path and the receptacles visited.
#include <gtest/gtest.h>

#include <set>

#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using testing::TestServer;

Json post(httplib::Client& c, const Json& body, int expected_status) {
  auto r = c.Post("/api/v1/navbench", body.dump(), "application/json");
  EXPECT_TRUE(r);
  EXPECT_EQ(r->status, expected_status) << r->body;
  return Json::parse(r->body);
}

Json finished(TestServer& s, httplib::Client& c, const std::string& id) {
  EXPECT_TRUE(s.services().jobs->wait(id, std::chrono::seconds(300)));
  auto r = c.Get(("/api/v1/jobs/" + id).c_str());
  EXPECT_TRUE(r);
  return Json::parse(r->body);
}

TEST(NavbenchRoutes, BadRequestsNameTheirFields) {
  TestServer s;
  auto c = s.client();
  Json p = post(c, {{"split", "medium"}, {"scenes", 0}}, 422);
  std::set<std::string> pointers;
  for (const auto& e : p["errors"]) pointers.insert(e["pointer"].get<std::string>());
  EXPECT_EQ(pointers, (std::set<std::string>{"/split", "/scenes", "/seed"}));
  auto r = c.Post("/api/v1/navbench", "{\"split\": ", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
}

TEST(NavbenchRoutes, ABenchmarkJobGivesTheTableAndReplaysEpisodes) {
  TestServer s;
  auto c = s.client();
  const Json request = {{"split", "normal"}, {"scenes", 3}, {"seed", 5}, {"training_houses", 60}};
  auto r = c.Post("/api/v1/navbench", request.dump(), "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 202) << r->body;
  const Json job = Json::parse(r->body);
  const std::string id = job["id"];
  EXPECT_EQ(r->get_header_value("Location"), "/api/v1/jobs/" + id);
  EXPECT_EQ(job["kind"], "navbench");

  const Json done = finished(s, c, id);
  ASSERT_EQ(done["status"], "succeeded") << done.dump();
  const Json& result = done["result"];
  EXPECT_EQ(result["split"], "normal");
  ASSERT_EQ(result["methods"].size(), 7u);
  for (const auto& [key, m] : result["methods"].items()) {
    EXPECT_GE(m["SR"].get<double>(), 0.0) << key;
    EXPECT_LE(m["SR"].get<double>(), 100.0) << key;
    EXPECT_LE(m["SPL"].get<double>(), m["SR"].get<double>() + 1e-9) << key;
  }
  const int tasks = result["tasks"];
  ASSERT_GT(tasks, 0);
  EXPECT_EQ(result["episodes"].size(), static_cast<std::size_t>(tasks));

  // The same request gives the same table.
  const Json again = post(c, request, 202);
  EXPECT_EQ(finished(s, c, again["id"])["result"]["methods"], result["methods"]);

  auto e = c.Get(("/api/v1/navbench/" + id + "/episodes/0").c_str());
  ASSERT_TRUE(e);
  ASSERT_EQ(e->status, 200) << e->body;
  const Json episode = Json::parse(e->body);
  EXPECT_FALSE(episode["house"]["rooms"].empty());
  EXPECT_EQ(episode["target"]["type"], result["episodes"][0]["target"]);
  const Json& greedy = episode["methods"]["Uniform+Greedy"];
  EXPECT_EQ(greedy["steps"], result["episodes"][0]["outcomes"]["Uniform+Greedy"]["steps"]);
  EXPECT_EQ(greedy["path"].size(), greedy["steps"].get<std::size_t>() + 1);

  auto one = c.Get(("/api/v1/navbench/" + id + "/episodes/0?method=SP%2BCEG").c_str());
  ASSERT_TRUE(one);
  ASSERT_EQ(one->status, 200);
  EXPECT_EQ(Json::parse(one->body)["methods"].size(), 1u);

  EXPECT_EQ(c.Get(("/api/v1/navbench/" + id + "/episodes/" + std::to_string(tasks)).c_str())->status, 404);
  EXPECT_EQ(c.Get(("/api/v1/navbench/" + id + "/episodes/first").c_str())->status, 422);
  EXPECT_EQ(c.Get(("/api/v1/navbench/" + id + "/episodes/0?method=Oracle").c_str())->status, 422);
  EXPECT_EQ(c.Get("/api/v1/navbench/job_doesnotexist/episodes/0")->status, 404);
}

}  // namespace
}  // namespace socsim::server
