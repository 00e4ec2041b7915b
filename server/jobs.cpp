#include "server/jobs.hpp"

#include <chrono>

#include "core/common/ids.hpp"

namespace socsim::server {
namespace {
using store::Database;

constexpr std::string_view kJobCursorPrefix = "j1.";

Json row_to_json(store::Statement& st) {
  Json j = {{"id", st.text(0)},        {"kind", st.text(1)},    {"status", st.text(2)},
            {"progress", st.real(3)},  {"message", st.text(4)}, {"author", st.text(5)},
            {"created_at", st.text(9)}};
  j["request"] = Json::parse(st.text(6));
  j["result"] = st.is_null(7) ? Json(nullptr) : Json::parse(st.text(7));
  j["error"] = st.is_null(8) ? Json(nullptr) : Json::parse(st.text(8));
  j["started_at"] = st.is_null(10) ? Json(nullptr) : Json(st.text(10));
  j["finished_at"] = st.is_null(11) ? Json(nullptr) : Json(st.text(11));
  j["links"] = {{"self", "/api/v1/jobs/" + st.text(0)}};
  return j;
}

constexpr const char* kColumns =
    "id, kind, status, progress, message, author, request, result, error, created_at, started_at, "
    "finished_at";

Error not_found(const std::string& id) {
  return Error(ErrorCode::kNotFound, "no job with id '" + id + "'");
}
}  // namespace

bool is_job_id(std::string_view s) {
  return is_random_id(s, "job_");
}

JobRunner::JobRunner(store::Store& store, EventHub& events, int workers, std::size_t max_queued,
                     std::size_t max_per_client)
    : store_(store),
      events_(events),
      max_queued_(max_queued),
      max_per_client_(std::max<std::size_t>(1, max_per_client)) {
  (void)store_.write([](Database& db) -> Result<bool> {
    auto st = db.prepare(
        "UPDATE jobs SET status = 'failed', finished_at = ?, error = ? WHERE status IN ('queued', "
        "'running')");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, utc_now_rfc3339())
        .bind(2,
              canonical_json(
                  Error(ErrorCode::kInternal, "the server restarted before this job finished").to_problem()));
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    return true;
  });
  for (int i = 0; i < std::max(1, workers); ++i) workers_.emplace_back([this] { work(); });
}

JobRunner::~JobRunner() {
  shutdown();
}

void JobRunner::shutdown() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_ && workers_.empty()) return;
    stopping_ = true;
    for (auto& [id, token] : running_) token.cancel();
  }
  cv_.notify_all();
  for (auto& t : workers_) t.join();
  workers_.clear();
  for (auto& p : queue_)
    (void)set_status(p.id, "cancelled", std::nullopt,
                     Error(ErrorCode::kCancelled, "the server shut down").to_problem());
  queue_.clear();
}

Result<std::string> JobRunner::submit(const std::string& kind, const Json& request, const std::string& author,
                                      JobFn fn, const std::string& client_key) {
  const std::string client = client_key.empty() ? author : client_key;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return fail(ErrorCode::kStoreBusy, "the server is shutting down");
    if (queue_.size() >= max_queued_) {
      Error e(ErrorCode::kRateLimited,
              "the job queue is full (" + std::to_string(max_queued_) + " waiting); retry later");
      e.retry_after_s = 5;
      return tl::unexpected(e);
    }
    if (per_client_[client] >= max_per_client_) {
      Error e(ErrorCode::kRateLimited, "this client already has " + std::to_string(max_per_client_) +
                                           " jobs queued or running, the most one client may; retry when one "
                                           "has finished (see GET /api/v1/jobs)");
      e.retry_after_s = 5;
      return tl::unexpected(e);
    }
    ++per_client_[client];  // held from here, so that concurrent submits cannot overshoot
  }
  const std::string id = random_id("job_");
  auto r = store_.write([&](Database& db) -> Result<bool> {
    auto st = db.prepare(
        "INSERT INTO jobs(id, kind, status, author, request, created_at) VALUES (?, ?, 'queued', ?, ?, ?)");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id).bind(2, kind).bind(3, author).bind(4, canonical_json(request)).bind(5, utc_now_rfc3339());
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    return true;
  });
  if (!r) {
    std::lock_guard<std::mutex> lock(mutex_);
    release(client);
    return tl::unexpected(r.error());
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back({id, std::move(fn), llm::CancelToken(), client});
  }
  cv_.notify_one();
  events_.publish("jobs", {{"type", "job.queued"}, {"id", id}, {"kind", kind}});
  return id;
}

void JobRunner::work() {
  for (;;) {
    Pending job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      cv_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      job = std::move(queue_.front());
      queue_.pop_front();
      running_[job.id] = job.cancel;
    }
    run_one(job);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      running_.erase(job.id);
      release(job.client);
    }
    done_cv_.notify_all();
  }
}

void JobRunner::run_one(Pending& job) {
  (void)store_.write([&](Database& db) -> Result<bool> {
    auto st = db.prepare("UPDATE jobs SET status = 'running', started_at = ? WHERE id = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, utc_now_rfc3339()).bind(2, job.id);
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    return true;
  });
  events_.publish("jobs", {{"type", "job.running"}, {"id", job.id}});
  auto last_write = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  JobContext ctx(job.id, job.cancel, [&](double fraction, const std::string& message) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_write < std::chrono::milliseconds(200)) return;
    last_write = now;
    const double f = std::clamp(fraction, 0.0, 1.0);
    (void)store_.write([&](Database& db) -> Result<bool> {
      auto st = db.prepare("UPDATE jobs SET progress = ?, message = ? WHERE id = ?");
      if (!st) return tl::unexpected(st.error());
      st->bind(1, f).bind(2, message).bind(3, job.id);
      if (auto s = st->run(); !s) return tl::unexpected(s.error());
      return true;
    });
    events_.publish("jobs",
                    {{"type", "job.progress"}, {"id", job.id}, {"progress", f}, {"message", message}});
  });
  Result<Json> result = [&]() -> Result<Json> {
    try {
      return job.fn(ctx);
    } catch (const std::exception& e) {
      return fail(ErrorCode::kInternal, std::string("the job failed: ") + e.what());
    }
  }();
  if (job.cancel.cancelled()) {
    (void)set_status(job.id, "cancelled", std::nullopt,
                     Error(ErrorCode::kCancelled, "cancelled on request").to_problem());
  } else if (result) {
    (void)set_status(job.id, "succeeded", *result, std::nullopt);
  } else {
    (void)set_status(job.id, "failed", std::nullopt, result.error().to_problem("/api/v1/jobs/" + job.id));
  }
}

Status JobRunner::set_status(const std::string& id, const std::string& status,
                             const std::optional<Json>& result, const std::optional<Json>& error) {
  auto r = store_.write([&](Database& db) -> Result<bool> {
    auto st = db.prepare(
        "UPDATE jobs SET status = ?, result = ?, error = ?, finished_at = ?,"
        " progress = CASE WHEN ? = 'succeeded' THEN 1 ELSE progress END WHERE id = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, status);
    if (result)
      st->bind(2, canonical_json(*result));
    else
      st->bind_null(2);
    if (error)
      st->bind(3, canonical_json(*error));
    else
      st->bind_null(3);
    st->bind(4, utc_now_rfc3339()).bind(5, status).bind(6, id);
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    return true;
  });
  events_.publish("jobs", {{"type", "job." + status}, {"id", id}});
  if (!r) return tl::unexpected(r.error());
  return {};
}

void JobRunner::release(const std::string& client) {
  auto it = per_client_.find(client);
  if (it == per_client_.end()) return;
  if (--it->second == 0) per_client_.erase(it);
}

Result<Json> JobRunner::get(const std::string& id) {
  if (!is_job_id(id)) return tl::unexpected(not_found(id));
  return store_.read([&](Database& db) -> Result<Json> {
    auto st = db.prepare(std::string("SELECT ") + kColumns + " FROM jobs WHERE id = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id);
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) return tl::unexpected(not_found(id));
    return row_to_json(*st);
  });
}

Result<JobPage> JobRunner::list(std::size_t page_size, const std::optional<std::string>& cursor,
                                const std::optional<std::string>& kind,
                                const std::optional<std::string>& status) {
  std::optional<std::int64_t> before;
  if (cursor) {
    const std::string digits =
        cursor->rfind(kJobCursorPrefix, 0) == 0 ? cursor->substr(kJobCursorPrefix.size()) : "";
    if (digits.empty() || digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos)
      return fail(ErrorCode::kBadRequest, "the cursor is not one this server issued",
                  {{"", "use next_cursor from a previous page", "cursor", 0, 0}});
    before = std::stoll(digits);
  }
  std::string sql = std::string("SELECT ") + kColumns + ", seq FROM jobs WHERE TRUE";
  if (before) sql += " AND seq < :before";
  if (kind) sql += " AND kind = :kind";
  if (status) sql += " AND status = :status";
  sql += " ORDER BY seq DESC LIMIT :limit";
  return store_.read([&](Database& db) -> Result<JobPage> {
    auto st = db.prepare(sql);
    if (!st) return tl::unexpected(st.error());
    int i = 1;
    if (before) st->bind(i++, *before);
    if (kind) st->bind(i++, *kind);
    if (status) st->bind(i++, *status);
    st->bind(i, static_cast<std::int64_t>(page_size + 1));
    JobPage page;
    std::int64_t last = 0;
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      if (page.items.size() == page_size) {
        page.next_cursor = std::string(kJobCursorPrefix) + std::to_string(last);
        break;
      }
      last = st->int64(12);
      Json j = row_to_json(*st);
      j.erase("result");  // lists stay small; GET /jobs/{id} has it
      page.items.push_back(std::move(j));
    }
    return page;
  });
}

Status JobRunner::cancel(const std::string& id, const std::string& author, bool any_author) {
  auto job = get(id);
  if (!job) return tl::unexpected(job.error());
  if (!any_author && (*job)["author"] != author)
    return fail(ErrorCode::kForbidden, "only the job's author may cancel it");
  const std::string status = (*job)["status"];
  if (status != "queued" && status != "running")
    return fail(ErrorCode::kConflict, "the job has already finished (" + status + ")");
  std::unique_lock<std::mutex> lock(mutex_);
  for (auto it = queue_.begin(); it != queue_.end(); ++it) {
    if (it->id == id) {
      release(it->client);
      queue_.erase(it);
      lock.unlock();
      return set_status(id, "cancelled", std::nullopt,
                        Error(ErrorCode::kCancelled, "cancelled on request").to_problem());
    }
  }
  if (auto it = running_.find(id); it != running_.end()) it->second.cancel();
  return {};
}

bool JobRunner::wait(const std::string& id, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    auto job = get(id);
    if (job) {
      const std::string s = (*job)["status"];
      if (s != "queued" && s != "running") return true;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    if (done_cv_.wait_until(
            lock, std::min(deadline, std::chrono::steady_clock::now() + std::chrono::milliseconds(50))) ==
            std::cv_status::timeout &&
        std::chrono::steady_clock::now() >= deadline)
      return false;
  }
}

}  // namespace socsim::server
