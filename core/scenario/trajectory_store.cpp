#include "core/scenario/trajectory_store.hpp"

#include "core/common/ids.hpp"

namespace socsim::scenario {

Status save_trajectory_log(store::Store& store, const TrajectoryLog& log) {
  const std::string blob = log.compressed();
  const std::size_t raw = log.encoded().size();
  return store.write([&](store::Database& db) -> Status {
    auto st = db.prepare(
        "INSERT INTO trajectory_logs(sha256, format, frames, agents, frame_interval, raw_bytes, data, "
        "created_at) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT(sha256) DO NOTHING");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, log.sha256())
        .bind(2, kTrajectoryFormat)
        .bind(3, static_cast<std::int64_t>(log.frame_count()))
        .bind(4, static_cast<std::int64_t>(log.agent_count()))
        .bind(5, log.frame_interval())
        .bind(6, static_cast<std::int64_t>(raw))
        .bind_blob(7, blob)
        .bind(8, utc_now_rfc3339());
    return st->run();
  });
}

Result<std::string> load_trajectory_blob(store::Store& store, std::string_view sha256) {
  return store.read([&](store::Database& db) -> Result<std::string> {
    auto st = db.prepare("SELECT data FROM trajectory_logs WHERE sha256 = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, sha256);
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) return fail(ErrorCode::kNotFound, "no trajectory log with sha256 " + std::string(sha256));
    return st->blob(0);
  });
}

Result<TrajectoryLog> load_trajectory_log(store::Store& store, std::string_view sha256) {
  auto blob = load_trajectory_blob(store, sha256);
  if (!blob) return tl::unexpected(blob.error());
  auto log = TrajectoryLog::from_compressed(*blob);
  if (!log) return log;
  if (log->sha256() != sha256)
    return fail(ErrorCode::kInternal,
                "stored trajectory log " + std::string(sha256) + " does not match its hash");
  return log;
}

}  // namespace socsim::scenario
