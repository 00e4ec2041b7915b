// Evaluation jobs (POST /api/v1/evaluations): the built-in planners over cards × seeds on a real
// server; the table's shape, its bytes the same for the same request, the problems of bad requests,
// and (heavy) 20 cards × 3 seeds × 3 planners in which the straight line collides most.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {

using testing::get_json;

// A corridor 20 m × 4 m; the robot crosses it from x = 2 to x = 18 while people walk against it
// (and, on every other card, one crosses its path). Card k varies the people's number and places.
Json encounter_card(int k, bool with_robot = true) {
  const auto w =
      world::world_from_yaml("zones:\n  - {name: corridor, polygon: [[0, 0], [20, 0], [20, 4], [0, 4]]}\n");
  Json agents = Json::array();
  const int walkers = 1 + k % 3;
  for (int i = 0; i < walkers; ++i) {
    const double y = 2.0 + 0.6 * ((i % 3) - 1) + 0.1 * (k % 4);
    agents.push_back({{"name", "walker_" + std::to_string(i)},
                      {"position", {11.0 + 2.5 * i + 0.5 * (k % 5), y}},
                      {"speed", 1.0},
                      {"goals", {{1.0, y}}},
                      {"cyclic_goals", false}});
  }
  if (k % 2 == 1)
    agents.push_back({{"name", "crosser"},
                      {"position", {7.0 + k % 4, 0.5}},
                      {"speed", 0.8},
                      {"goals", {{7.0 + k % 4, 3.5}}},
                      {"cyclic_goals", false}});
  Json program{{"name", "encounter " + std::to_string(k)}, {"agents", agents}};
  if (with_robot) program["robot"] = {{"position", {2.0, 2.0}}, {"speed", 1.0}, {"goals", {{18.0, 2.0}}}};
  return {{"title", "corridor encounter " + std::to_string(k)},
          {"prompt", "a robot crosses a corridor against the flow"},
          {"seed", k},
          {"world", world::world_to_document(w.value())},
          {"program", program}};
}

std::vector<std::string> post_cards(httplib::Client& c, int n, bool with_robot = true) {
  std::vector<std::string> ids;
  for (int k = 0; k < n; ++k) {
    auto r = testing::post(c, "/api/v1/cards", encounter_card(k, with_robot));
    EXPECT_TRUE(r && r->status == 201) << (r ? r->body : "no answer");
    ids.push_back(r ? Json::parse(r->body).value("id", "") : "");
  }
  return ids;
}

const Json kPlanners = {"builtin:straight", "builtin:social_force", "builtin:orca"};

// Queues the evaluation and waits for it; the evaluation's record.
Json evaluate(testing::TestServer& s, const Json& body, std::chrono::seconds timeout) {
  auto c = s.client();
  auto r = testing::post(c, "/api/v1/evaluations", body);
  EXPECT_TRUE(r && r->status == 202) << (r ? r->body : "no answer");
  if (!r || r->status != 202) return {};
  const std::string id = Json::parse(r->body)["id"];
  EXPECT_TRUE(s.services().jobs->wait(id, timeout));
  return get_json(c, "/api/v1/evaluations/" + id);
}

TEST(Evaluations, ASmallEvaluationGivesTheTableAndTheSameBytesEveryTime) {
  testing::TestServer s;
  auto c = s.client();
  const auto cards = post_cards(c, 3);
  const Json body{{"cards", cards}, {"seeds", {1, 2}}, {"planners", kPlanners}, {"time_limit_s", 25}};
  const Json a = evaluate(s, body, std::chrono::seconds(60));
  ASSERT_EQ(a["status"], "succeeded") << a.dump();
  EXPECT_EQ(a["kind"], "evaluation");
  const Json& table = a["result"]["table"];
  ASSERT_EQ(table["cells"].size(), 9u);
  EXPECT_EQ(table["cells"][0]["card"], cards[0]);
  EXPECT_EQ(table["cells"][0]["planner"], "builtin:straight");
  EXPECT_EQ(table["cells"][0]["episodes"], 2);
  ASSERT_EQ(table["planners"].size(), 3u);
  for (const Json& p : table["planners"]) {
    EXPECT_EQ(p["episodes"], 6);
    for (const char* m : {"success", "collision", "collision_person", "collision_wall", "path_length",
                          "minimum_distance_to_people", "intimate_space_intrusions", "time_to_reach_goal"})
      ASSERT_TRUE(p["metrics"].contains(m)) << m;
    const Json& success = p["metrics"]["success"];
    EXPECT_EQ(success["n"], 3);
    ASSERT_TRUE(success["ci95"].is_array());
    EXPECT_LE(success["ci95"][0].get<double>(), success["mean"].get<double>());
  }
  EXPECT_EQ(table["ranking"]["collision"].size(), 3u);
  EXPECT_EQ(a["result"]["episodes"].size(), 18u);

  const Json b = evaluate(s, body, std::chrono::seconds(60));
  EXPECT_EQ(a["result"].dump(), b["result"].dump());
  EXPECT_NE(a["id"], b["id"]);

  const Json list = get_json(c, "/api/v1/evaluations?page_size=1");
  ASSERT_EQ(list["items"].size(), 1u);
  EXPECT_EQ(list["items"][0]["kind"], "evaluation");
  ASSERT_TRUE(list["next_cursor"].is_string());
  const Json rest =
      get_json(c, "/api/v1/evaluations?page_size=5&cursor=" + list["next_cursor"].get<std::string>());
  EXPECT_EQ(rest["items"].size(), 1u);
  EXPECT_TRUE(rest["next_cursor"].is_null());
}

TEST(Evaluations, BadRequestsAreProblemsWithPointers) {
  testing::TestServer s;
  auto c = s.client();
  const auto cards = post_cards(c, 1);
  const auto robotless = post_cards(c, 1, false);
  const auto problem = [&c](const Json& body, int status) {
    auto r = testing::post(c, "/api/v1/evaluations", body);
    EXPECT_TRUE(r);
    if (!r) return Json();
    EXPECT_EQ(r->status, status) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    return Json::parse(r->body);
  };
  const Json ok{{"cards", cards}, {"seeds", {1}}, {"planners", kPlanners}};
  Json body = ok;
  body["cards"] = {cards[0], "card_nope"};
  EXPECT_EQ(problem(body, 404)["errors"][0]["pointer"], "/cards/1");
  body = ok;
  body["cards"] = robotless;
  EXPECT_EQ(problem(body, 422)["errors"][0]["pointer"], "/cards/0");
  body["robot"] = {{"start", {{"x", 2}, {"y", 2}, {"yaw", 0}}}, {"goal", {{"x", 18}, {"y", 2}}}};
  body["seeds"] = {1};
  body["client"] = "builtin:orca";
  body.erase("planners");
  auto r = testing::post(c, "/api/v1/evaluations", body);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 202) << r->body;
  body = ok;
  body["seeds"] = Json::array();
  for (int k = 0; k < 100; ++k) body["seeds"].push_back(k);
  body["cards"] = {cards[0], robotless[0], "c3", "c4"};
  EXPECT_EQ(problem(body, 422)["errors"][0]["pointer"], "");  // 4 × 100 × 3 > 1000 episodes
  body = ok;
  body["planners"] = {"builtin:teleport"};
  EXPECT_EQ(problem(body, 422)["errors"][0]["pointer"], "/planners/0");
  body["planners"] = {"external"};
  EXPECT_EQ(problem(body, 422)["errors"][0]["pointer"], "/planners/0");
  body = ok;
  body["seeds"] = {1, -1};
  body["time_limit_s"] = -3;
  body["extra"] = true;
  const Json many = problem(body, 422);
  std::vector<std::string> pointers;
  for (const Json& e : many["errors"]) pointers.push_back(e["pointer"]);
  EXPECT_NE(std::find(pointers.begin(), pointers.end(), "/seeds/1"), pointers.end()) << many.dump();
  EXPECT_NE(std::find(pointers.begin(), pointers.end(), "/time_limit_s"), pointers.end()) << many.dump();
  EXPECT_NE(std::find(pointers.begin(), pointers.end(), "/extra"), pointers.end()) << many.dump();
  auto missing = c.Get("/api/v1/evaluations/job_nope");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
}

// Heavy: the acceptance of issue 19 — 20 cards × 3 seeds × 3 planners; the straight line collides most.
TEST(EvaluationsHeavy, TwentyCardsThreeSeedsThreePlannersRankTheStraightLineWorstOnCollisions) {
  testing::TestServer s;
  auto c = s.client();
  const auto cards = post_cards(c, 20);
  // People yield to a visible robot so well that nobody collides; an invisible robot (people do
  // not see it, as in the planners' own test) leaves the avoiding to the planner.
  const Json robot{{"start", {{"x", 2}, {"y", 2}, {"yaw", 0}}},
                   {"goal", {{"x", 18}, {"y", 2}}},
                   {"visible", false},
                   {"limits", {{"max_speed", 1.0}}}};
  const Json e = evaluate(s,
                          {{"cards", cards},
                           {"seeds", {1, 2, 3}},
                           {"planners", kPlanners},
                           {"time_limit_s", 30},
                           {"robot", robot}},
                          std::chrono::seconds(600));
  ASSERT_EQ(e["status"], "succeeded") << e.dump();
  const Json& table = e["result"]["table"];
  for (const Json& line : table["summary"]) std::cout << line.get<std::string>() << "\n";
  EXPECT_EQ(table["ranking"]["collision"].back(), "builtin:straight") << table["ranking"].dump();
  const auto collision = [&table](std::size_t p) {
    return table["planners"][p]["metrics"]["collision"]["mean"].get<double>();
  };
  EXPECT_GT(collision(0), collision(1));
  EXPECT_GT(collision(0), collision(2));
}

}  // namespace
}  // namespace socsim::server
