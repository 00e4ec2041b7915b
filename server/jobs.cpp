#include "server/jobs.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iostream>

#include "core/common/ids.hpp"

namespace socsim::server {
namespace {
using store::Database;
using store::Dialect;

constexpr std::string_view kJobCursorPrefix = "j1.";
// Serialises the quota checks of concurrent submissions on every worker of one PostgreSQL database.
constexpr std::int64_t kQuotaLock = 0x736f637369;

constexpr const char* kColumns =
    "id, kind, status, progress, message, author, request, result, error, created_at, started_at, "
    "finished_at, worker, attempts, batch_id";

Json row_to_json(store::Statement& st) {
  Json j = {{"id", st.text(0)},        {"kind", st.text(1)},    {"status", st.text(2)},
            {"progress", st.real(3)},  {"message", st.text(4)}, {"author", st.text(5)},
            {"created_at", st.text(9)}};
  j["request"] = Json::parse(st.text(6));
  j["result"] = st.is_null(7) ? Json(nullptr) : Json::parse(st.text(7));
  j["error"] = st.is_null(8) ? Json(nullptr) : Json::parse(st.text(8));
  j["started_at"] = st.is_null(10) ? Json(nullptr) : Json(st.text(10));
  j["finished_at"] = st.is_null(11) ? Json(nullptr) : Json(st.text(11));
  j["worker"] = st.is_null(12) ? Json(nullptr) : Json(st.text(12));
  j["attempts"] = st.int64(13);
  j["batch_id"] = st.is_null(14) ? Json(nullptr) : Json(st.text(14));
  j["links"] = {{"self", "/api/v1/jobs/" + st.text(0)}};
  return j;
}

Error not_found(const std::string& id) {
  return Error(ErrorCode::kNotFound, "no job with id '" + id + "'");
}

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string default_worker_id() {
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  std::string h = host[0] ? host : "worker";
  return h + "-" + std::to_string(::getpid()) + "-" + random_id("").substr(0, 6);
}

Status exec_bound(Database& db, const std::string& sql, const std::function<void(store::Statement&)>& bind) {
  auto st = db.prepare(sql);
  if (!st) return tl::unexpected(st.error());
  bind(*st);
  return st->run();
}

Result<std::int64_t> count(Database& db, const std::string& sql,
                           const std::function<void(store::Statement&)>& bind) {
  auto st = db.prepare(sql);
  if (!st) return tl::unexpected(st.error());
  bind(*st);
  auto row = st->step();
  if (!row) return tl::unexpected(row.error());
  return *row ? st->int64(0) : 0;
}

std::string problem_text(ErrorCode code, const std::string& detail) {
  return canonical_json(Error(code, detail).to_problem());
}
}  // namespace

bool is_job_id(std::string_view s) {
  return is_random_id(s, "job_");
}

JobRunner::JobRunner(store::Store& store, EventHub& events, int workers, std::size_t max_queued,
                     std::size_t max_per_client)
    : JobRunner(store, events, [&] {
        JobRunnerOptions o;
        o.workers = workers;
        o.max_queued = max_queued;
        o.max_per_client = max_per_client;
        return o;
      }()) {}

JobRunner::JobRunner(store::Store& store, EventHub& events, JobRunnerOptions options)
    : store_(store), events_(events), options_(std::move(options)) {
  options_.max_per_client = std::max<std::size_t>(1, options_.max_per_client);
  options_.max_attempts = std::max(1, options_.max_attempts);
  if (options_.lease < std::chrono::milliseconds(300)) options_.lease = std::chrono::milliseconds(300);
  if (options_.worker_id.empty()) options_.worker_id = default_worker_id();
  heartbeat();  // registers this worker and fails what dead workers left pinned
  for (int i = 0; i < std::max(1, options_.workers); ++i) workers_.emplace_back([this] { work(); });
  keeper_ = std::thread([this] { keep(); });
}

JobRunner::~JobRunner() {
  shutdown();
}

void JobRunner::define(const std::string& kind, JobFactory factory) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    factories_[kind] = std::move(factory);
    woken_ = true;
  }
  cv_.notify_all();
}

bool JobRunner::defines(const std::string& kind) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return factories_.count(kind) > 0;
}

Result<JobFn> JobRunner::build(const std::string& kind, const Json& spec, const std::string& author) const {
  JobFactory factory;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = factories_.find(kind);
    if (it == factories_.end())
      return fail(ErrorCode::kInternal, "no job kind '" + kind + "' on this server");
    factory = it->second;
  }
  return factory(spec, author);
}

std::vector<std::string> JobRunner::kinds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> v;
  for (const auto& [k, f] : factories_) v.push_back(k);
  return v;
}

void JobRunner::wake() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    woken_ = true;
  }
  cv_.notify_all();
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
  if (keeper_.joinable()) keeper_.join();
  // This worker's own jobs that never started end here; shared ones stay queued for the others.
  std::map<std::string, JobFn> left;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    left.swap(local_);
  }
  const std::string problem = problem_text(ErrorCode::kCancelled, "the server shut down");
  (void)store_.write([&](Database& db) -> Result<bool> {
    for (const auto& entry : left)
      if (auto s =
              exec_bound(db,
                         "UPDATE jobs SET status = 'cancelled', error = ?, finished_at = ? WHERE id = ? AND "
                         "status = 'queued'",
                         [&](store::Statement& st) {
                           st.bind(1, problem).bind(2, utc_now_rfc3339()).bind(3, entry.first);
                         });
          !s)
        return tl::unexpected(s.error());
    if (auto s = exec_bound(db, "DELETE FROM workers WHERE id = ?",
                            [&](store::Statement& st) { st.bind(1, options_.worker_id); });
        !s)
      return tl::unexpected(s.error());
    return true;
  });
  for (const auto& [id, fn] : left) events_.publish("jobs", {{"type", "job.cancelled"}, {"id", id}});
  done_cv_.notify_all();
}

Result<std::string> JobRunner::insert(const std::string& id, const std::string& kind, const Json& request,
                                      const std::optional<Json>& spec, const std::string& author,
                                      const std::string& client_key) {
  const std::string client = client_key.empty() ? author : client_key;
  const bool pinned = !spec.has_value();
  auto r = store_.write([&](Database& db) -> Result<bool> {
    if (db.dialect() == Dialect::kPostgres)
      if (auto s = exec_bound(db, "SELECT pg_advisory_xact_lock(?)",
                              [](store::Statement& st) { st.bind(1, kQuotaLock); });
          !s)
        return tl::unexpected(s.error());
    auto queued = count(db, "SELECT count(*) FROM jobs WHERE status = 'queued' AND batch_id IS NULL",
                        [](store::Statement&) {});
    if (!queued) return tl::unexpected(queued.error());
    if (static_cast<std::size_t>(*queued) >= options_.max_queued) {
      Error e(ErrorCode::kRateLimited,
              "the job queue is full (" + std::to_string(options_.max_queued) + " waiting); retry later");
      e.retry_after_s = 5;
      return tl::unexpected(e);
    }
    auto mine = count(db,
                      "SELECT count(*) FROM jobs WHERE status IN ('queued', 'running') AND client = ? AND "
                      "batch_id IS NULL",
                      [&](store::Statement& st) { st.bind(1, client); });
    if (!mine) return tl::unexpected(mine.error());
    if (static_cast<std::size_t>(*mine) >= options_.max_per_client) {
      Error e(ErrorCode::kRateLimited, "this client already has " + std::to_string(options_.max_per_client) +
                                           " jobs queued or running, the most one client may; retry when one "
                                           "has finished (see GET /api/v1/jobs)");
      e.retry_after_s = 5;
      return tl::unexpected(e);
    }
    if (auto s = exec_bound(
            db,
            "INSERT INTO jobs(id, kind, status, author, request, created_at, spec, client, pinned) "
            "VALUES (?, ?, 'queued', ?, ?, ?, ?, ?, ?)",
            [&](store::Statement& st) {
              st.bind(1, id).bind(2, kind).bind(3, author).bind(4, canonical_json(request));
              st.bind(5, utc_now_rfc3339());
              if (spec)
                st.bind(6, canonical_json(*spec));
              else
                st.bind_null(6);
              st.bind(7, client);
              if (pinned)
                st.bind(8, options_.worker_id);
              else
                st.bind_null(8);
            });
        !s)
      return tl::unexpected(s.error());
    return true;
  });
  if (!r) return tl::unexpected(r.error());
  return id;
}

Result<std::string> JobRunner::submit_spec(const std::string& kind, const Json& request, const Json& spec,
                                           const std::string& author, const std::string& client) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return fail(ErrorCode::kStoreBusy, "the server is shutting down");
  }
  auto id = insert(random_id("job_"), kind, request, spec, author, client);
  if (!id) return id;
  events_.publish("jobs", {{"type", "job.queued"}, {"id", *id}, {"kind", kind}});
  wake();
  return id;
}

Result<std::string> JobRunner::submit(const std::string& kind, const Json& request, const std::string& author,
                                      JobFn fn, const std::string& client) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return fail(ErrorCode::kStoreBusy, "the server is shutting down");
  }
  // The closure is registered before the row exists, so a worker that claims the row finds it.
  const std::string job_id = random_id("job_");
  {
    std::lock_guard<std::mutex> lock(mutex_);
    local_[job_id] = std::move(fn);
  }
  auto id = insert(job_id, kind, request, std::nullopt, author, client);
  if (!id) {
    std::lock_guard<std::mutex> lock(mutex_);
    local_.erase(job_id);
    return id;
  }
  events_.publish("jobs", {{"type", "job.queued"}, {"id", *id}, {"kind", kind}});
  wake();
  return id;
}

Result<std::vector<std::string>> JobRunner::insert_items(Database& db, const std::string& kind,
                                                         const std::string& author, const std::string& client,
                                                         const std::string& batch_id,
                                                         const std::vector<JobItem>& items) {
  std::vector<std::string> ids;
  ids.reserve(items.size());
  auto st = db.prepare(
      "INSERT INTO jobs(id, kind, status, author, request, created_at, spec, client, batch_id, batch_index) "
      "VALUES (?, ?, 'queued', ?, ?, ?, ?, ?, ?, ?)");
  if (!st) return tl::unexpected(st.error());
  const std::string now = utc_now_rfc3339();
  for (std::size_t i = 0; i < items.size(); ++i) {
    ids.push_back(random_id("job_"));
    st->reset();
    st->bind(1, ids.back()).bind(2, kind).bind(3, author).bind(4, canonical_json(items[i].request));
    st->bind(5, now).bind(6, canonical_json(items[i].spec)).bind(7, client).bind(8, batch_id);
    st->bind(9, static_cast<std::int64_t>(i));
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
  }
  return ids;
}

Result<std::optional<JobRunner::Claimed>> JobRunner::claim() {
  const auto known = kinds();
  const std::int64_t now = now_ms();
  // A read first, so that idle workers do not take the write lock on every poll.
  auto any = store_.read([&](Database& db) -> Result<std::int64_t> {
    return count(
        db,
        "SELECT count(*) FROM (SELECT 1 FROM jobs WHERE status = 'queued' OR (status = 'running' AND "
        "lease_expires < ?) LIMIT 1) AS w",
        [&](store::Statement& st) { st.bind(1, now); });
  });
  if (!any) return tl::unexpected(any.error());
  if (*any == 0) return std::optional<Claimed>{};
  std::string in = "NULL";  // kinds this worker can build; none still leaves its own jobs
  for (std::size_t i = 0; i < known.size(); ++i) in += ", ?" + std::to_string(6 + i);
  const bool pg = store_.dialect() == Dialect::kPostgres;
  const std::string sql =
      "UPDATE jobs SET status = 'running', worker = ?1, lease_expires = ?2, attempts = attempts + 1, "
      "started_at = COALESCE(started_at, ?3) WHERE seq = (SELECT seq FROM jobs WHERE (status = 'queued' OR "
      "(status = 'running' AND lease_expires < ?4)) AND cancel_requested = 0 AND attempts < ?5 AND "
      "((pinned IS NULL AND kind IN (" +
      in + ")) OR pinned = ?1) ORDER BY seq LIMIT 1" + (pg ? " FOR UPDATE SKIP LOCKED" : "") +
      ") RETURNING id, kind, author, spec, attempts, pinned";
  return store_.write([&](Database& db) -> Result<std::optional<Claimed>> {
    auto st = db.prepare(sql);
    if (!st) return tl::unexpected(st.error());
    st->bind(1, options_.worker_id)
        .bind(2, now + options_.lease.count())
        .bind(3, utc_now_rfc3339())
        .bind(4, now)
        .bind(5, static_cast<std::int64_t>(options_.max_attempts));
    for (std::size_t i = 0; i < known.size(); ++i) st->bind(static_cast<int>(6 + i), known[i]);
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) return std::optional<Claimed>{};
    Claimed c;
    c.id = st->text(0);
    c.kind = st->text(1);
    c.author = st->text(2);
    c.spec = st->is_null(3) ? Json(nullptr) : Json::parse(st->text(3));
    c.attempt = st->int64(4);
    c.pinned = !st->is_null(5);
    return std::optional<Claimed>(std::move(c));
  });
}

void JobRunner::work() {
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      cv_.wait_for(lock, options_.poll, [&] { return stopping_ || woken_; });
      if (stopping_) return;
      woken_ = false;
    }
    for (;;) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) return;
      }
      auto c = claim();
      if (!c) {
        std::cerr << "socsim: could not take a job from the queue: " << c.error().message() << "\n";
        break;
      }
      if (!*c) break;
      run_claimed(**c);
      done_cv_.notify_all();
    }
  }
}

void JobRunner::run_claimed(const Claimed& job) {
  llm::CancelToken token;
  JobFn fn;
  std::optional<Error> cannot;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (job.pinned) {
      auto it = local_.find(job.id);
      if (it != local_.end()) {
        fn = std::move(it->second);
        local_.erase(it);
      }
    }
    running_[job.id] = token;
  }
  if (!job.pinned) {
    auto factory = [&]() -> std::optional<JobFactory> {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = factories_.find(job.kind);
      if (it == factories_.end()) return std::nullopt;
      return it->second;
    }();
    if (!factory) {
      cannot = Error(ErrorCode::kInternal, "this worker cannot run jobs of kind '" + job.kind + "'");
    } else {
      auto built = (*factory)(job.spec, job.author);
      if (built)
        fn = std::move(*built);
      else
        cannot = built.error();
    }
  } else if (!fn) {
    cannot = Error(ErrorCode::kInternal, "the worker that accepted this job stopped before it started");
  }
  events_.publish("jobs", {{"type", "job.running"}, {"id", job.id}, {"worker", options_.worker_id}});
  Result<Json> result = tl::unexpected(cannot.value_or(Error(ErrorCode::kInternal, "")));
  if (!cannot) {
    auto last_write = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    JobContext ctx(job.id, token, [&](double fraction, const std::string& message) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_write < std::chrono::milliseconds(200)) return;
      last_write = now;
      const double f = std::clamp(fraction, 0.0, 1.0);
      (void)store_.write([&](Database& db) -> Result<bool> {
        if (auto s = exec_bound(db,
                                "UPDATE jobs SET progress = ?, message = ? WHERE id = ? AND worker = ? AND "
                                "attempts = ?",
                                [&](store::Statement& st) {
                                  st.bind(1, f).bind(2, message).bind(3, job.id).bind(4, options_.worker_id);
                                  st.bind(5, job.attempt);
                                });
            !s)
          return tl::unexpected(s.error());
        return true;
      });
      events_.publish("jobs",
                      {{"type", "job.progress"}, {"id", job.id}, {"progress", f}, {"message", message}});
    });
    result = [&]() -> Result<Json> {
      try {
        return fn(ctx);
      } catch (const std::exception& e) {
        return fail(ErrorCode::kInternal, std::string("the job failed: ") + e.what());
      }
    }();
  }
  bool stopping = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping = stopping_;
    running_.erase(job.id);
  }
  if (token.cancelled() && stopping && !job.pinned) {
    // Shutting down: hand the job back, so another worker (or this one, restarted) runs it.
    (void)store_.write([&](Database& db) -> Result<bool> {
      if (auto s = exec_bound(db,
                              "UPDATE jobs SET status = 'queued', worker = NULL, lease_expires = NULL, "
                              "attempts = attempts - 1 WHERE id = ? AND worker = ? AND attempts = ? AND "
                              "status = 'running'",
                              [&](store::Statement& st) {
                                st.bind(1, job.id).bind(2, options_.worker_id).bind(3, job.attempt);
                              });
          !s)
        return tl::unexpected(s.error());
      return true;
    });
    events_.publish("jobs", {{"type", "job.queued"}, {"id", job.id}, {"kind", job.kind}});
    return;
  }
  if (token.cancelled()) {
    (void)finish(job, "cancelled", std::nullopt,
                 Error(ErrorCode::kCancelled, stopping ? "the server shut down" : "cancelled on request")
                     .to_problem());
  } else if (result) {
    (void)finish(job, "succeeded", *result, std::nullopt);
  } else {
    (void)finish(job, "failed", std::nullopt, result.error().to_problem("/api/v1/jobs/" + job.id));
  }
}

Status JobRunner::finish(const Claimed& job, const std::string& status, const std::optional<Json>& result,
                         const std::optional<Json>& error) {
  int changed = 0;
  auto r = store_.write([&](Database& db) -> Result<bool> {
    auto st = db.prepare(
        "UPDATE jobs SET status = ?, result = ?, error = ?, finished_at = ?, lease_expires = NULL,"
        " progress = CASE WHEN ? = 'succeeded' THEN 1 ELSE progress END"
        " WHERE id = ? AND worker = ? AND attempts = ? AND status = 'running'");
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
    st->bind(4, utc_now_rfc3339()).bind(5, status).bind(6, job.id).bind(7, options_.worker_id);
    st->bind(8, job.attempt);
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    changed = db.changes();
    return true;
  });
  if (!r) return tl::unexpected(r.error());
  if (changed == 0) {
    // The lease ran out while the job ran (this worker stalled) and another attempt owns the job.
    std::cerr << "socsim: job " << job.id << " attempt " << job.attempt
              << " finished after its lease was lost; the result is dropped\n";
    return {};
  }
  events_.publish("jobs", {{"type", "job." + status}, {"id", job.id}});
  return {};
}

void JobRunner::keep() {
  const auto beat = std::min<std::chrono::milliseconds>(options_.lease / 3, std::chrono::milliseconds(1000));
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      // Wakes for stopping only (woken_ is the workers' signal).
      if (cv_.wait_for(lock, beat, [&] { return stopping_; })) return;
    }
    heartbeat();
  }
}

void JobRunner::heartbeat() {
  const std::int64_t now = now_ms();
  const std::int64_t lease = options_.lease.count();
  std::vector<std::string> cancelled;
  auto r = store_.write([&](Database& db) -> Result<bool> {
    if (auto s =
            exec_bound(db,
                       "INSERT INTO workers(id, public_url, heartbeat_ms, started_at) VALUES (?, ?, ?, ?) "
                       "ON CONFLICT(id) DO UPDATE SET heartbeat_ms = excluded.heartbeat_ms",
                       [&](store::Statement& st) {
                         st.bind(1, options_.worker_id).bind(2, options_.public_url).bind(3, now);
                         st.bind(4, utc_now_rfc3339());
                       });
        !s)
      return tl::unexpected(s.error());
    if (auto s =
            exec_bound(db, "UPDATE jobs SET lease_expires = ? WHERE worker = ? AND status = 'running'",
                       [&](store::Statement& st) { st.bind(1, now + lease).bind(2, options_.worker_id); });
        !s)
      return tl::unexpected(s.error());
    {
      auto st =
          db.prepare("SELECT id FROM jobs WHERE worker = ? AND status = 'running' AND cancel_requested <> 0");
      if (!st) return tl::unexpected(st.error());
      st->bind(1, options_.worker_id);
      for (;;) {
        auto row = st->step();
        if (!row) return tl::unexpected(row.error());
        if (!*row) break;
        cancelled.push_back(st->text(0));
      }
    }
    const std::string at = utc_now_rfc3339();
    // Jobs only a dead worker could run (its heartbeat is older than a lease, or it left).
    if (auto s = exec_bound(
            db,
            "UPDATE jobs SET status = 'failed', finished_at = ?, lease_expires = NULL, error = ? WHERE "
            "status IN "
            "('queued', 'running') AND pinned IS NOT NULL AND pinned <> ? AND NOT EXISTS (SELECT 1 FROM "
            "workers w WHERE w.id = jobs.pinned AND w.heartbeat_ms >= ?)",
            [&](store::Statement& st) {
              st.bind(1, at)
                  .bind(2, problem_text(ErrorCode::kInternal,
                                        "the server that accepted this job stopped or restarted before it "
                                        "finished; submit it again"))
                  .bind(3, options_.worker_id)
                  .bind(4, now - lease);
            });
        !s)
      return tl::unexpected(s.error());
    // Shared jobs whose worker died: cancelled if that was asked, failed after the last attempt;
    // the others wait for a claim.
    if (auto s = exec_bound(
            db,
            "UPDATE jobs SET status = 'cancelled', finished_at = ?, lease_expires = NULL, error = ? "
            "WHERE status = 'running' AND lease_expires < ? AND cancel_requested <> 0",
            [&](store::Statement& st) {
              st.bind(1, at)
                  .bind(2, problem_text(ErrorCode::kCancelled, "cancelled on request"))
                  .bind(3, now);
            });
        !s)
      return tl::unexpected(s.error());
    if (auto s = exec_bound(db,
                            "UPDATE jobs SET status = 'failed', finished_at = ?, lease_expires = NULL, error "
                            "= ? WHERE status = "
                            "'running' AND lease_expires < ? AND attempts >= ?",
                            [&](store::Statement& st) {
                              st.bind(1, at)
                                  .bind(2, problem_text(ErrorCode::kInternal,
                                                        "the worker running this job stopped " +
                                                            std::to_string(options_.max_attempts) +
                                                            " times while it ran; it is not tried again"))
                                  .bind(3, now)
                                  .bind(4, static_cast<std::int64_t>(options_.max_attempts));
                            });
        !s)
      return tl::unexpected(s.error());
    if (auto s = exec_bound(db, "DELETE FROM workers WHERE heartbeat_ms < ?",
                            [&](store::Statement& st) { st.bind(1, now - 86'400'000); });
        !s)
      return tl::unexpected(s.error());
    return true;
  });
  if (!r) {
    std::cerr << "socsim: job heartbeat failed: " << r.error().message() << "\n";
    return;
  }
  if (!cancelled.empty()) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& id : cancelled)
      if (auto it = running_.find(id); it != running_.end()) it->second.cancel();
  }
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
      last = st->int64(15);
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
  bool was_queued = false;
  auto r = store_.write([&](Database& db) -> Result<bool> {
    if (auto s =
            exec_bound(db,
                       "UPDATE jobs SET status = 'cancelled', error = ?, finished_at = ? WHERE id = ? AND "
                       "status = 'queued'",
                       [&](store::Statement& st) {
                         st.bind(1, problem_text(ErrorCode::kCancelled, "cancelled on request"))
                             .bind(2, utc_now_rfc3339())
                             .bind(3, id);
                       });
        !s)
      return tl::unexpected(s.error());
    was_queued = db.changes() > 0;
    if (!was_queued)
      if (auto s = exec_bound(db, "UPDATE jobs SET cancel_requested = 1 WHERE id = ? AND status = 'running'",
                              [&](store::Statement& st) { st.bind(1, id); });
          !s)
        return tl::unexpected(s.error());
    return true;
  });
  if (!r) return tl::unexpected(r.error());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (was_queued) local_.erase(id);
    if (auto it = running_.find(id); it != running_.end()) it->second.cancel();
  }
  if (was_queued) {
    events_.publish("jobs", {{"type", "job.cancelled"}, {"id", id}});
    done_cv_.notify_all();
  }
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
