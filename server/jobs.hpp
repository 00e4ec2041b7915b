#pragma once
// Long-running work as jobs: a bounded worker pool, records in the `jobs` table (status,
// progress, result or problem), cancellation, and events on the hub's "jobs" topic.
#include <condition_variable>
#include <deque>
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
using JobFn = std::function<Result<Json>(const JobContext&)>;

struct JobPage {
  std::vector<Json> items;
  std::optional<std::string> next_cursor;
};

class JobRunner {
 public:
  // Marks jobs left queued or running by a previous process as failed (interrupted).
  // max_per_client bounds the jobs one client has queued or running, so that one client cannot
  // fill the queue and starve everyone else.
  JobRunner(store::Store& store, EventHub& events, int workers = 2, std::size_t max_queued = 64,
            std::size_t max_per_client = 8);
  ~JobRunner();
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  // Records the job and queues it. kRateLimited (429, with retry_after_s) when the queue is full or
  // `client` (the author when empty) already has max_per_client jobs queued or running.
  Result<std::string> submit(const std::string& kind, const Json& request, const std::string& author,
                             JobFn fn, const std::string& client = {});
  // The job record: id, kind, status, progress, message, author, request, result, error, times.
  Result<Json> get(const std::string& id);
  Result<JobPage> list(std::size_t page_size, const std::optional<std::string>& cursor,
                       const std::optional<std::string>& kind, const std::optional<std::string>& status);
  // Cancels a queued or running job (its author, or anyone on an open server).
  Status cancel(const std::string& id, const std::string& author, bool any_author);
  // Blocks until the job has finished (for the CLI and tests); false on timeout.
  bool wait(const std::string& id, std::chrono::milliseconds timeout);
  // Cancels what is running, drops the queue and joins the workers.
  void shutdown();

 private:
  struct Pending {
    std::string id;
    JobFn fn;
    llm::CancelToken cancel;
    std::string client;
  };
  void release(const std::string& client);  // under mutex_
  void work();
  void run_one(Pending& job);
  Status set_status(const std::string& id, const std::string& status, const std::optional<Json>& result,
                    const std::optional<Json>& error);

  store::Store& store_;
  EventHub& events_;
  std::size_t max_queued_;
  std::size_t max_per_client_;
  std::map<std::string, std::size_t> per_client_;  // queued + running
  std::mutex mutex_;
  std::condition_variable cv_;
  std::condition_variable done_cv_;
  std::deque<Pending> queue_;
  std::map<std::string, llm::CancelToken> running_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

bool is_job_id(std::string_view s);

}  // namespace socsim::server
