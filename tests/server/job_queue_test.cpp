// The shared job queue (issue 21): a second worker on the same database (its own store connection
// and JobRunner, as a second process would have) takes jobs of kinds it defines, takes over a job
// whose worker's lease ran out and finishes it exactly once, passes a cancel on to the worker that
// runs a job, gets back the jobs a worker hands in when it shuts down, and fails jobs that only a
// dead worker could run. Run on SQLite and, by pg.server_api, on PostgreSQL.
#include <gtest/gtest.h>

#include <atomic>

#include "core/common/ids.hpp"
#include "server/jobs.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using testing::TestServer;

// A second worker on the server's database.
struct SecondWorker {
  std::unique_ptr<store::Store> store;
  EventHub events;
  std::unique_ptr<JobRunner> jobs;
  SecondWorker(const std::string& target, const std::string& name, std::chrono::milliseconds lease) {
    store = store::Store::open(target).value();
    JobRunnerOptions o;
    o.workers = 1;
    o.worker_id = name;
    o.lease = lease;
    o.poll = std::chrono::milliseconds(20);
    jobs = std::make_unique<JobRunner>(*store, events, o);
  }
  ~SecondWorker() { jobs->shutdown(); }
};

Status sql(store::Store& store, const std::string& text, const std::vector<std::string>& args) {
  return store.write([&](store::Database& db) -> Status {
    auto st = db.prepare(text);
    if (!st) return tl::unexpected(st.error());
    for (std::size_t i = 0; i < args.size(); ++i) st->bind(static_cast<int>(i + 1), args[i]);
    return st->run();
  });
}

TEST(JobQueue, AnotherWorkerRunsAKindItDefinesAndOnlyIt) {
  TestServer s;
  SecondWorker w(s.db_target(), "second", std::chrono::milliseconds(2000));
  std::atomic<int> runs{0};
  w.jobs->define("test.square", [&runs](const Json& spec, const std::string&) -> Result<JobFn> {
    if (!spec.contains("n")) return fail(ErrorCode::kValidation, "n is required", {{"/n", "required"}});
    const int n = spec["n"];
    return JobFn([n, &runs](const JobContext&) -> Result<Json> {
      ++runs;
      return Json{{"square", n * n}};
    });
  });
  // Submitted through the server's runner, which does not define the kind: only the second takes it.
  auto& jobs = *s.services().jobs;
  auto id = jobs.submit_spec("test.square", {{"n", 7}}, {{"n", 7}}, "anonymous");
  ASSERT_TRUE(id) << id.error().message();
  ASSERT_TRUE(jobs.wait(*id, std::chrono::seconds(20)));
  Json j = jobs.get(*id).value();
  EXPECT_EQ(j["status"], "succeeded");
  EXPECT_EQ(j["result"]["square"], 49);
  EXPECT_EQ(j["worker"], "second");
  EXPECT_EQ(j["attempts"], 1);
  EXPECT_EQ(runs.load(), 1);
  // A spec the factory refuses fails the job with the factory's problem.
  auto bad = jobs.submit_spec("test.square", Json::object(), Json::object(), "anonymous");
  ASSERT_TRUE(bad && jobs.wait(*bad, std::chrono::seconds(20)));
  Json f = jobs.get(*bad).value();
  EXPECT_EQ(f["status"], "failed");
  EXPECT_EQ(f["error"]["errors"][0]["pointer"], "/n");
}

TEST(JobQueue, AJobWhoseWorkerDiedIsFinishedOnceByAnother) {
  TestServer s;
  SecondWorker w(s.db_target(), "second", std::chrono::milliseconds(1000));
  std::atomic<int> runs{0};
  w.jobs->define("test.once", [&runs](const Json&, const std::string&) -> Result<JobFn> {
    return JobFn([&runs](const JobContext&) -> Result<Json> { return Json{{"run", ++runs}}; });
  });
  // A row as a worker that died mid-job leaves it: running, its lease run out, one attempt made.
  const std::string id = random_id("job_");
  ASSERT_TRUE(
      sql(s.store(),
          "INSERT INTO jobs(id, kind, status, author, request, created_at, spec, worker, lease_expires, "
          "attempts) VALUES (?, 'test.once', 'running', 'anonymous', '{}', '2026-01-01T00:00:00Z', '{}', "
          "'ghost', 1, 1)",
          {id}));
  w.jobs->wake();
  ASSERT_TRUE(w.jobs->wait(id, std::chrono::seconds(20)));
  Json j = w.jobs->get(id).value();
  EXPECT_EQ(j["status"], "succeeded");
  EXPECT_EQ(j["worker"], "second");
  EXPECT_EQ(j["attempts"], 2);
  EXPECT_EQ(runs.load(), 1);
  // A late finish by the dead attempt changes nothing (the attempt number fences it).
  ASSERT_TRUE(
      sql(s.store(),
          "UPDATE jobs SET status = 'failed' WHERE id = ? AND worker = 'ghost' AND attempts = 1 AND status = "
          "'running'",
          {id}));
  EXPECT_EQ(w.jobs->get(id).value()["status"], "succeeded");
  // A job claimed as many times as allowed is failed rather than tried again.
  const std::string poison = random_id("job_");
  ASSERT_TRUE(
      sql(s.store(),
          "INSERT INTO jobs(id, kind, status, author, request, created_at, spec, worker, lease_expires, "
          "attempts) VALUES (?, 'test.once', 'running', 'anonymous', '{}', '2026-01-01T00:00:00Z', '{}', "
          "'ghost', 1, 3)",
          {poison}));
  w.jobs->heartbeat();
  Json p = w.jobs->get(poison).value();
  EXPECT_EQ(p["status"], "failed");
  EXPECT_NE(p["error"]["detail"].get<std::string>().find("3 times"), std::string::npos);
  EXPECT_EQ(runs.load(), 1);
}

TEST(JobQueue, CancelReachesTheWorkerRunningTheJob) {
  TestServer s;
  SecondWorker w(s.db_target(), "second", std::chrono::milliseconds(600));
  std::atomic<bool> started{false};
  w.jobs->define("test.long", [&started](const Json&, const std::string&) -> Result<JobFn> {
    return JobFn([&started](const JobContext& ctx) -> Result<Json> {
      started = true;
      for (int i = 0; i < 20000 && !ctx.cancelled(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      return Json{{"finished", true}};
    });
  });
  auto& jobs = *s.services().jobs;
  auto id = jobs.submit_spec("test.long", Json::object(), Json::object(), "anonymous");
  ASSERT_TRUE(id);
  for (int i = 0; i < 1000 && !started; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(started);
  auto c = s.client();
  auto del = c.Delete(("/api/v1/jobs/" + *id).c_str());
  ASSERT_TRUE(del);
  EXPECT_EQ(del->status, 202);
  ASSERT_TRUE(jobs.wait(*id, std::chrono::seconds(10)));
  Json j = jobs.get(*id).value();
  EXPECT_EQ(j["status"], "cancelled");
  EXPECT_EQ(j["worker"], "second");
}

TEST(JobQueue, AWorkerThatShutsDownHandsItsJobsBack) {
  TestServer s;
  std::atomic<int> runs{0};
  const auto factory = [&runs](const Json&, const std::string&) -> Result<JobFn> {
    return JobFn([&runs](const JobContext& ctx) -> Result<Json> {
      ++runs;
      for (int i = 0; i < 400 && !ctx.cancelled(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      if (ctx.cancelled()) return fail(ErrorCode::kCancelled, "stopped");
      return Json{{"done", true}};
    });
  };
  std::string id;
  {
    SecondWorker first(s.db_target(), "first", std::chrono::milliseconds(2000));
    first.jobs->define("test.handback", factory);
    id = s.services().jobs->submit_spec("test.handback", Json::object(), Json::object(), "anonymous").value();
    for (int i = 0; i < 1000 && runs == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ASSERT_EQ(runs.load(), 1);
  }  // shuts down mid-job
  Json back = s.services().jobs->get(id).value();
  EXPECT_EQ(back["status"], "queued");
  EXPECT_EQ(back["attempts"], 0);
  SecondWorker next(s.db_target(), "next", std::chrono::milliseconds(2000));
  next.jobs->define("test.handback", factory);
  ASSERT_TRUE(next.jobs->wait(id, std::chrono::seconds(20)));
  Json j = next.jobs->get(id).value();
  EXPECT_EQ(j["status"], "succeeded");
  EXPECT_EQ(j["worker"], "next");
}

TEST(JobQueue, JobsOnlyADeadWorkerCouldRunFail) {
  TestServer s;
  // A closure job pinned to a worker with no heartbeat (it was killed) is failed by the others.
  const std::string id = random_id("job_");
  ASSERT_TRUE(sql(s.store(),
                  "INSERT INTO jobs(id, kind, status, author, request, created_at, pinned) VALUES (?, 'x', "
                  "'queued', 'anonymous', '{}', '2026-01-01T00:00:00Z', 'gone-worker')",
                  {id}));
  s.services().jobs->heartbeat();
  Json j = s.services().jobs->get(id).value();
  EXPECT_EQ(j["status"], "failed");
  EXPECT_NE(j["error"]["detail"].get<std::string>().find("stopped or restarted"), std::string::npos);
}

}  // namespace
}  // namespace socsim::server
