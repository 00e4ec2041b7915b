#pragma once
// Content-addressed storage of trajectory logs in the SQLite store (table trajectory_logs).
#include <string_view>

#include "core/common/error.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/store/store.hpp"

namespace socsim::scenario {

// Idempotent: a log already stored under its hash is left as it is.
Status save_trajectory_log(store::Store& store, const TrajectoryLog& log);
// kNotFound when no log has that hash.
Result<TrajectoryLog> load_trajectory_log(store::Store& store, std::string_view sha256);
// The compressed bytes as stored (for download without decoding).
Result<std::string> load_trajectory_blob(store::Store& store, std::string_view sha256);

}  // namespace socsim::scenario
