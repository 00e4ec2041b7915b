// Jobs over HTTP: progress and result, failure as a problem document, cancellation, restart
// recovery, pagination. The job bodies here are small computations defined by the test.
#include <gtest/gtest.h>

#include <atomic>

#include "server/jobs.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using testing::TestServer;

using testing::get_json;

TEST(Jobs, ReportProgressThenResult) {
  TestServer s;
  auto& jobs = *s.services().jobs;
  std::atomic<bool> release{false};
  auto id = jobs.submit("sum", {{"n", 100}}, "anonymous", [&](const JobContext& ctx) -> Result<Json> {
    long sum = 0;
    for (int i = 1; i <= 100; ++i) sum += i;
    ctx.progress(0.5, "half way");
    while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return Json{{"sum", sum}};
  });
  ASSERT_TRUE(id);
  auto c = s.client();
  for (int i = 0; i < 200 && get_json(c, "/api/v1/jobs/" + *id)["status"] != "running"; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  Json running = get_json(c, "/api/v1/jobs/" + *id);
  EXPECT_EQ(running["status"], "running");
  EXPECT_EQ(running["kind"], "sum");
  EXPECT_EQ(running["request"]["n"], 100);
  release = true;
  ASSERT_TRUE(jobs.wait(*id, std::chrono::seconds(10)));
  Json done = get_json(c, "/api/v1/jobs/" + *id);
  EXPECT_EQ(done["status"], "succeeded");
  EXPECT_EQ(done["progress"], 1.0);
  EXPECT_EQ(done["result"]["sum"], 5050);
  EXPECT_FALSE(done["finished_at"].is_null());
}

TEST(Jobs, FailureIsStoredAsAProblem) {
  TestServer s;
  auto& jobs = *s.services().jobs;
  auto id = jobs.submit("broken", Json::object(), "anonymous", [](const JobContext&) -> Result<Json> {
    return fail(ErrorCode::kValidation, "the generated plan has a room below the code minimum",
                {{"/rooms/2/area", "6.1 m² < 7.5 m² (NDSS 2015)"}});
  });
  ASSERT_TRUE(id && jobs.wait(*id, std::chrono::seconds(10)));
  auto c = s.client();
  Json j = get_json(c, "/api/v1/jobs/" + *id);
  EXPECT_EQ(j["status"], "failed");
  EXPECT_EQ(j["error"]["status"], 422);
  EXPECT_EQ(j["error"]["errors"][0]["pointer"], "/rooms/2/area");
}

TEST(Jobs, CancelStopsARunningJob) {
  TestServer s;
  auto& jobs = *s.services().jobs;
  auto id = jobs.submit("long", Json::object(), "anonymous", [](const JobContext& ctx) -> Result<Json> {
    for (int i = 0; i < 10000 && !ctx.cancelled(); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return Json{{"finished", true}};
  });
  ASSERT_TRUE(id);
  auto c = s.client();
  for (int i = 0; i < 200 && get_json(c, "/api/v1/jobs/" + *id)["status"] != "running"; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  auto del = c.Delete(("/api/v1/jobs/" + *id).c_str());
  ASSERT_TRUE(del);
  EXPECT_EQ(del->status, 202);
  ASSERT_TRUE(jobs.wait(*id, std::chrono::seconds(10)));
  EXPECT_EQ(get_json(c, "/api/v1/jobs/" + *id)["status"], "cancelled");
  auto again = c.Delete(("/api/v1/jobs/" + *id).c_str());
  EXPECT_EQ(again->status, 409);
}

// Issue 14 #8: one client could fill the whole queue (64) and starve everyone else. Each key (or
// address, on a server without keys) may have max_jobs_per_client queued or running; the next
// submission is 429 with Retry-After, while other clients are still served.
TEST(Jobs, OneClientCannotTakeEveryJobSlot) {
  ServerConfig cfg;
  cfg.api_keys = parse_api_keys("alice:alice-secret-0123456789,bob:bob-secret-0123456789").value();
  cfg.max_jobs_per_client = 2;
  cfg.job_workers = 1;
  // Declared before the server: its job worker may still be running the last job (which reads
  // release) when the test returns, until the server's destructor stops it.
  std::atomic<bool> release{false};
  const auto blocking = [&](const JobContext& ctx) -> Result<Json> {
    while (!release && !ctx.cancelled()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return Json::object();
  };
  TestServer s(cfg);
  auto& jobs = *s.services().jobs;
  std::vector<std::string> held;
  for (int i = 0; i < 2; ++i) held.push_back(jobs.submit("hold", Json::object(), "alice", blocking).value());
  auto third = jobs.submit("hold", Json::object(), "alice", blocking);
  ASSERT_FALSE(third);
  EXPECT_EQ(third.error().code, ErrorCode::kRateLimited);
  EXPECT_GT(third.error().retry_after_s, 0);

  const std::string navbench = R"({"split": "normal", "scenes": 1, "seed": 1, "tasks_per_scene": 1})";
  auto c = s.client();
  auto refused = c.Post("/api/v1/navbench", {{"Authorization", "Bearer alice-secret-0123456789"}}, navbench,
                        "application/json");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 429) << refused->body;
  EXPECT_EQ(refused->get_header_value("Content-Type"), "application/problem+json");
  EXPECT_FALSE(refused->get_header_value("Retry-After").empty());
  auto other = c.Post("/api/v1/navbench", {{"Authorization", "Bearer bob-secret-0123456789"}}, navbench,
                      "application/json");
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 202) << "another key still gets a slot: " << other->body;
  ASSERT_TRUE(jobs.cancel(Json::parse(other->body)["id"], "bob", false));

  // A finished job frees its slot.
  release = true;
  for (const auto& id : held) ASSERT_TRUE(jobs.wait(id, std::chrono::seconds(10)));
  bool again = false;
  for (int i = 0; i < 100 && !again; ++i) {
    again = jobs.submit("tiny", Json::object(), "alice", blocking).has_value();
    if (!again) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(again);
}

TEST(Jobs, UnknownJobsAndBadQueriesAreProblems) {
  TestServer s;
  auto c = s.client();
  EXPECT_EQ(c.Get("/api/v1/jobs/job_00000000000000000000")->status, 404);
  EXPECT_EQ(c.Get("/api/v1/jobs/not-a-job")->status, 404);
  EXPECT_EQ(c.Get("/api/v1/jobs?status=sleeping")->status, 422);
  EXPECT_EQ(c.Get("/api/v1/jobs?cursor=zzz")->status, 400);
}

TEST(Jobs, ListPagesThroughEveryJob) {
  TestServer s;
  auto& jobs = *s.services().jobs;
  std::set<std::string> ids;
  for (int i = 0; i < 7; ++i) {
    auto id = jobs.submit("tiny", {{"i", i}}, "anonymous", [i](const JobContext&) -> Result<Json> {
      return Json{{"i", i}};
    });
    ASSERT_TRUE(id);
    ids.insert(*id);
  }
  for (const auto& id : ids) ASSERT_TRUE(jobs.wait(id, std::chrono::seconds(10)));
  auto c = s.client();
  std::set<std::string> seen;
  std::string url = "/api/v1/jobs?page_size=3";
  for (int g = 0; g < 5; ++g) {
    Json page = get_json(c, url);
    for (const auto& j : page["items"]) seen.insert(j["id"].get<std::string>());
    if (page["next_cursor"].is_null()) break;
    url = "/api/v1/jobs?page_size=3&cursor=" + page["next_cursor"].get<std::string>();
  }
  EXPECT_EQ(seen, ids);
}

TEST(Jobs, ARestartMarksInterruptedJobsFailed) {
  ::socsim::testing::TempDir dir;
  auto store = store::Store::open(dir.file("jobs.db")).value();
  EventHub hub;
  std::string id;
  {
    JobRunner runner(*store, hub, 1);
    std::atomic<bool> started{false};
    id = runner
             .submit("slow", Json::object(), "anonymous",
                     [&](const JobContext& ctx) -> Result<Json> {
                       started = true;
                       while (!ctx.cancelled()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
                       return Json::object();
                     })
             .value();
    while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    // Simulate a crash: the row says running when the next process starts.
    ASSERT_TRUE(store->write([&](store::Database& db) -> Result<bool> {
      if (auto s = db.exec("CREATE TABLE crash_marker(x INTEGER)"); !s) return tl::unexpected(s.error());
      return true;
    }));
    runner.shutdown();
  }
  ASSERT_TRUE(store->write([&](store::Database& db) -> Result<bool> {
    auto st = db.prepare("UPDATE jobs SET status = 'running' WHERE id = ?");
    st->bind(1, id);
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    return true;
  }));
  JobRunner next(*store, hub, 1);
  Json j = next.get(id).value();
  EXPECT_EQ(j["status"], "failed");
  EXPECT_NE(j["error"]["detail"].get<std::string>().find("restarted"), std::string::npos);
}

}  // namespace
}  // namespace socsim::server
