#pragma once
// Long-running work as jobs, queued in the store's `jobs` table so that every worker on one
// database shares the queue (issue 21): a worker claims a job with a lease (PostgreSQL's FOR UPDATE
// SKIP LOCKED; SQLite's single writer), renews it while the job runs, and only the holder of the
// current attempt may finish it. A job whose worker died is claimed again once its lease has run
// out. Kinds defined with a factory can be run by any worker from the stored spec; a job submitted
// with a closure belongs to the worker that accepted it (pinned) and fails if that worker dies.
// Progress, results and problems are kept in the row; events go to the hub's "jobs" topic.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/llm/cancel_token.hpp"
#include "core/store/store.hpp"
#include "server/event_hub.hpp"

namespace socsim::server {

class JobContext {
 public:
  JobContext(std::string id, llm::CancelToken cancel,
             std::function<void(double, const std::string&)> progress)
      : id_(std::move(id)), cancel_(std::move(cancel)), progress_(std::move(progress)) {}
  [[nodiscard]] const std::string& id() const { return id_; }
  [[nodiscard]] const llm::CancelToken& cancel_token() const { return cancel_; }
  [[nodiscard]] bool cancelled() const { return cancel_.cancelled(); }
  // fraction in [0, 1]; written to the store at most every 200 ms.
  void progress(double fraction, const std::string& message) const { progress_(fraction, message); }

 private:
  std::string id_;
  llm::CancelToken cancel_;
  std::function<void(double, const std::string&)> progress_;
};

// The work: returns the result document (stored in jobs.result) or an Error (stored as a problem).
// A job that any worker may run must be idempotent in what it stores (it may run again after its
// worker died mid-way): derive stored ids from the job id, insert with ON CONFLICT DO NOTHING.
using JobFn = std::function<Result<Json>(const JobContext&)>;

// Rebuilds a kind's work from the spec stored with the job (and the author it runs for).
using JobFactory = std::function<Result<JobFn>(const Json& spec, const std::string& author)>;

struct JobPage {
  std::vector<Json> items;
  std::optional<std::string> next_cursor;
};

struct JobRunnerOptions {
  int workers = 2;                         // threads taking jobs in this process
  std::size_t max_queued = 64;             // jobs waiting over all workers (batch items not counted)
  std::size_t max_per_client = 8;          // queued + running per client (batch items not counted)
  std::string worker_id;                   // empty: host name, process id and a random suffix
  std::string public_url;                  // where clients reach this worker (recorded in `workers`)
  std::chrono::milliseconds lease{30000};  // a claimed job is this worker's until then, renewed
  std::chrono::milliseconds poll{250};     // how often an idle worker looks for work
  int max_attempts = 3;                    // claims of one job (a job that kills its worker stops there)
};

// One job of a batch: what is shown (request) and what any worker needs to run it (spec).
struct JobItem {
  Json request;
  Json spec;
};

class JobRunner {
 public:
  JobRunner(store::Store& store, EventHub& events, JobRunnerOptions options);
  JobRunner(store::Store& store, EventHub& events, int workers = 2, std::size_t max_queued = 64,
            std::size_t max_per_client = 8);
  ~JobRunner();
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  // Lets this worker take jobs of `kind` from the shared queue, built by `factory`.
  void define(const std::string& kind, JobFactory factory);
  [[nodiscard]] bool defines(const std::string& kind) const;
  // The work `kind`'s factory makes of `spec` (to check a request before queueing it).
  Result<JobFn> build(const std::string& kind, const Json& spec, const std::string& author) const;

  // Records the job for any worker that defines `kind` (spec: what the factory reads).
  // kRateLimited (429, with retry_after_s) when the queue is full or `client` (the author when
  // empty) already has max_per_client jobs queued or running.
  Result<std::string> submit_spec(const std::string& kind, const Json& request, const Json& spec,
                                  const std::string& author, const std::string& client = {});
  // Records a job that only this worker runs (its work is a closure over this process's state).
  Result<std::string> submit(const std::string& kind, const Json& request, const std::string& author,
                             JobFn fn, const std::string& client = {});
  // Inserts a batch's items as jobs inside the caller's write transaction (no quota: the batch is
  // the unit a client asked for); call wake() after the commit.
  static Result<std::vector<std::string>> insert_items(store::Database& db, const std::string& kind,
                                                       const std::string& author, const std::string& client,
                                                       const std::string& batch_id,
                                                       const std::vector<JobItem>& items);
  void wake();

  // The job record: id, kind, status, progress, message, author, request, result, error, times,
  // worker, attempts, batch.
  Result<Json> get(const std::string& id);
  Result<JobPage> list(std::size_t page_size, const std::optional<std::string>& cursor,
                       const std::optional<std::string>& kind, const std::optional<std::string>& status);
  // Cancels a queued or running job (its author, or anyone on an open server), whichever worker
  // runs it: a running job on another worker is told at that worker's next heartbeat.
  Status cancel(const std::string& id, const std::string& author, bool any_author);
  // Blocks until the job has finished (for the CLI and tests); false on timeout.
  bool wait(const std::string& id, std::chrono::milliseconds timeout);
  // Stops taking jobs, hands shared jobs under way back to the queue (another worker finishes
  // them), cancels this worker's own jobs and joins the threads.
  void shutdown();

  [[nodiscard]] const std::string& worker_id() const { return options_.worker_id; }
  // One heartbeat now: renew leases, pass on cancellations, fail jobs of dead workers (tests).
  void heartbeat();

 private:
  struct Claimed {
    std::string id, kind, author;
    Json spec;
    std::int64_t attempt = 0;
    bool pinned = false;
  };
  void work();
  void keep();
  Result<std::optional<Claimed>> claim();
  void run_claimed(const Claimed& job);
  Status finish(const Claimed& job, const std::string& status, const std::optional<Json>& result,
                const std::optional<Json>& error);
  Result<std::string> insert(const std::string& id, const std::string& kind, const Json& request,
                             const std::optional<Json>& spec, const std::string& author,
                             const std::string& client);
  std::vector<std::string> kinds() const;

  store::Store& store_;
  EventHub& events_;
  JobRunnerOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::condition_variable done_cv_;
  std::map<std::string, JobFactory> factories_;
  std::map<std::string, JobFn> local_;               // pinned jobs not yet claimed
  std::map<std::string, llm::CancelToken> running_;  // jobs under way here
  bool stopping_ = false;
  bool woken_ = false;
  std::vector<std::thread> workers_;
  std::thread keeper_;
};

bool is_job_id(std::string_view s);

}  // namespace socsim::server
