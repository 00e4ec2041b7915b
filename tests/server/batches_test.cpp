// POST /api/v1/batches over HTTP: a scenario batch is split into queue items and finishes; its
// items and counts are shown; the export is a tar with the same bytes each time; bad requests are
// 422 problems pointing into the batch request and store nothing; cancel ends what is left.
#include <gtest/gtest.h>

#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using testing::get_json;
using testing::TestServer;

Json post(httplib::Client& c, const std::string& path, const Json& body, int expect) {
  auto r = c.Post(path.c_str(), body.dump(), "application/json");
  EXPECT_TRUE(r);
  if (!r) return Json();
  EXPECT_EQ(r->status, expect) << r->body;
  return Json::parse(r->body);
}

Json wait_batch(httplib::Client& c, const std::string& id) {
  Json b;
  for (int i = 0; i < 1200; ++i) {
    b = get_json(c, "/api/v1/batches/" + id);
    if (b["status"] != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return b;
}

TEST(Batches, AScenarioBatchRunsEveryItemAndExportsTheSameBytes) {
  TestServer s;
  auto c = s.client();
  Json made = post(c, "/api/v1/batches",
                   {{"kind", "scenarios"},
                    {"prompts", {"a small cafe with 6 customers", "a library reading room with 4 readers"}},
                    {"seeds", {{"first", 5}, {"count", 2}}},
                    {"parameters", {{"duration_s", 3}}}},
                   202);
  ASSERT_EQ(made["total"], 4);
  const std::string id = made["id"];
  Json b = wait_batch(c, id);
  ASSERT_EQ(b["status"], "succeeded") << b.dump();
  EXPECT_EQ(b["counts"]["succeeded"], 4);
  EXPECT_EQ(b["progress"], 1.0);
  Json items = get_json(c, "/api/v1/batches/" + id + "/items?page_size=3");
  ASSERT_EQ(items["items"].size(), 3u);
  EXPECT_EQ(items["items"][1]["item"]["seed"], 6);
  EXPECT_EQ(items["items"][2]["item"]["prompt"], "a library reading room with 4 readers");
  Json rest = get_json(
      c, "/api/v1/batches/" + id + "/items?page_size=3&cursor=" + items["next_cursor"].get<std::string>());
  ASSERT_EQ(rest["items"].size(), 1u);
  EXPECT_TRUE(rest["next_cursor"].is_null());
  // Each item's card is named after its job and is in the catalogue.
  for (const auto& it : items["items"]) {
    const std::string card = it["result"]["card_id"];
    EXPECT_EQ(card.substr(4), it["job_id"].get<std::string>().substr(4));
    EXPECT_EQ(c.Get(("/api/v1/cards/" + card).c_str())->status, 200);
  }
  auto one = c.Get(("/api/v1/batches/" + id + "/export").c_str());
  auto two = c.Get(("/api/v1/batches/" + id + "/export").c_str());
  ASSERT_TRUE(one && two);
  ASSERT_EQ(one->status, 200);
  EXPECT_EQ(one->get_header_value("Content-Type"), "application/x-tar");
  EXPECT_EQ(one->body, two->body);
  // ustar members: batch.json, cards.jsonl (4 lines), one trajectory log per card.
  EXPECT_EQ(one->body.substr(0, 10), "batch.json");
  EXPECT_NE(one->body.find("cards.jsonl"), std::string::npos);
  std::size_t logs = 0;
  for (auto at = one->body.find("logs/"); at != std::string::npos; at = one->body.find("logs/", at + 1))
    if (at % 512 == 0) ++logs;
  EXPECT_EQ(logs, 4u);
  Json list = get_json(c, "/api/v1/batches");
  ASSERT_EQ(list["items"].size(), 1u);
  EXPECT_EQ(list["items"][0]["id"], id);
}

TEST(Batches, BadRequestsPointIntoTheBatchAndStoreNothing) {
  TestServer s;
  auto c = s.client();
  Json e =
      post(c, "/api/v1/batches", {{"kind", "scenarios"}, {"prompts", {"a cafe", ""}}, {"seeds", {1}}}, 422);
  EXPECT_EQ(e["errors"][0]["pointer"], "/prompts/1");
  e = post(c, "/api/v1/batches",
           {{"kind", "scenarios"},
            {"prompt", "a hospital corridor"},
            {"seeds", {1}},
            {"parameters", {{"duration_s", -1}}}},
           422);
  EXPECT_EQ(e["errors"][0]["pointer"], "/parameters/duration_s");
  e = post(c, "/api/v1/batches", {{"kind", "scenarios"}, {"prompt", "a cafe"}, {"seeds", {{"count", 0}}}},
           422);
  EXPECT_EQ(e["errors"][0]["pointer"], "/seeds/count");
  e = post(c, "/api/v1/batches",
           {{"kind", "scenarios"}, {"prompt", "a cafe"}, {"seeds", {{"first", 1}, {"count", 20000}}}}, 422);
  e = post(c, "/api/v1/batches", {{"kind", "households"}, {"count", 2}, {"rooms", {8, 3}}}, 422);
  EXPECT_EQ(e["errors"][0]["pointer"], "/rooms");
  e = post(c, "/api/v1/batches", {{"kind", "teleports"}}, 422);
  EXPECT_EQ(e["errors"][0]["pointer"], "/kind");
  e = post(c, "/api/v1/batches", {{"kind", "navbench"}, {"splits", {"easy"}}, {"seeds", {1}}}, 422);
  EXPECT_EQ(e["errors"][0]["pointer"], "/splits/0");
  EXPECT_EQ(get_json(c, "/api/v1/batches")["items"].size(), 0u);
  EXPECT_EQ(get_json(c, "/api/v1/jobs")["items"].size(), 0u);
  EXPECT_EQ(c.Get("/api/v1/batches/bat_00000000000000000000")->status, 404);
  EXPECT_EQ(c.Get("/api/v1/batches/nope/export")->status, 404);
}

TEST(Batches, HouseholdsOverRangesAndCancellation) {
  TestServer s;
  auto c = s.client();
  Json made = post(
      c, "/api/v1/batches",
      {{"kind", "households"}, {"count", 3}, {"rooms", {2, 5}}, {"residents", {1, 3}}, {"seed", 9}}, 202);
  const std::string id = made["id"];
  Json b = wait_batch(c, id);
  ASSERT_EQ(b["status"], "succeeded") << b.dump();
  Json items = get_json(c, "/api/v1/batches/" + id + "/items");
  for (const auto& it : items["items"]) {
    EXPECT_GE(it["item"]["rooms"].get<int>(), 2);
    EXPECT_LE(it["item"]["rooms"].get<int>(), 5);
    EXPECT_EQ(
        c.Get(("/api/v1/households/" + it["result"]["household_id"].get<std::string>()).c_str())->status,
        200);
  }
  auto tar = c.Get(("/api/v1/batches/" + id + "/export").c_str());
  ASSERT_EQ(tar->status, 200);
  EXPECT_NE(tar->body.find("households.jsonl"), std::string::npos);

  // A larger batch, cancelled: what had not finished ends cancelled; export then works.
  Json big = post(c, "/api/v1/batches",
                  {{"kind", "scenarios"},
                   {"prompt", "a busy station concourse with 200 travellers"},
                   {"seeds", {{"first", 1}, {"count", 40}}}},
                  202);
  const std::string bid = big["id"];
  auto early = c.Get(("/api/v1/batches/" + bid + "/export").c_str());
  EXPECT_EQ(early->status, 409);
  auto del = c.Delete(("/api/v1/batches/" + bid).c_str());
  ASSERT_EQ(del->status, 202) << del->body;
  Json after = wait_batch(c, bid);
  EXPECT_EQ(after["status"], "cancelled") << after.dump();
  EXPECT_GT(after["counts"]["cancelled"].get<int>(), 30);
  EXPECT_EQ(c.Delete(("/api/v1/batches/" + bid).c_str())->status, 409);
  EXPECT_EQ(c.Get(("/api/v1/batches/" + bid + "/export").c_str())->status, 200);
}

}  // namespace
}  // namespace socsim::server
