#pragma once
// Batch generation (issue 21): one request — prompts × seeds, N households over room and resident
// ranges, or navigation-benchmark splits × seeds — split into jobs in the shared queue that every
// worker on the database takes from; one progress view over the items; the results as a dataset
// (a tar of JSONL and trajectory logs, the same bytes every time it is asked for).
#include <optional>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/store/store.hpp"
#include "server/jobs.hpp"

namespace socsim::server {

struct BatchPlan {
  std::string kind;      // scenarios | households | navbench
  std::string job_kind;  // the queue's kind of each item
  Json request;          // normalised
  std::vector<JobItem> items;
};

constexpr std::size_t kMaxBatchItems = 10000;

// Reads and expands a batch request. Each item is checked by `check` (the item kind's own
// validation) and a problem points into the batch request (/prompts/2, /parameters/duration_s).
// `check` may propose a smaller resident count for a household item (see batches.cpp).
Result<BatchPlan> plan_batch(
    const Json& body, const std::function<Status(const std::string& job_kind, const Json& spec)>& check);

// Stores the batch and its items in one transaction; nothing is stored on failure.
Result<std::string> store_batch(store::Store& store, const BatchPlan& plan, const std::string& author,
                                const std::string& client);

// The batch with counts by status, progress and where its items ran.
Result<Json> batch_status(store::Store& store, const std::string& id);
Result<Json> list_batches(store::Store& store, std::size_t page_size,
                          const std::optional<std::string>& cursor);
// The items in order (job id, index, status, result or error), paged by index.
Result<Json> batch_items(store::Store& store, const std::string& id, std::size_t page_size, std::size_t from);
// Cancels the items still queued or running; returns how many it reached.
Result<std::int64_t> cancel_batch(store::Store& store, JobRunner& jobs, const std::string& id,
                                  const std::string& author, bool any_author);
// The dataset: batch.json, then per kind cards.jsonl + logs/{sha256}.socsim-traj, households.jsonl
// or results.jsonl, items in batch order. kConflict while items are still queued or running.
Result<std::string> export_batch(store::Store& store, const std::string& id);

bool is_batch_id(std::string_view s);

}  // namespace socsim::server
