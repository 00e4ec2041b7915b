#pragma once
// The record of every LLM call (prompt, answer, tokens, latency, cache hit, outcome), so a job's
// record can show how its artifacts were generated and what they cost.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/llm/llm_client.hpp"
#include "core/store/store.hpp"

namespace socsim::llm {

enum class CallStatus { kOk, kInvalid, kError };  // answer accepted / answer failed its checks / no answer
std::string_view to_string(CallStatus status);

struct CallRecord {
  std::optional<std::string> job_id;
  std::string artifact;  // template name, or "embedding"
  std::string model;
  int round = 0;  // 0 = first answer, 1.. = repair rounds
  std::string prompt_hash;
  std::int64_t seed = 0;
  double temperature = 0.0;
  std::string prompt;  // the messages as JSON text
  std::optional<std::string> response;
  TokenUsage usage;  // zero on a cache hit: it cost nothing
  std::int64_t latency_ms = 0;
  bool cache_hit = false;
  CallStatus status = CallStatus::kOk;
  std::optional<std::string> error;
};

// Appends one row; returns its id.
Result<std::int64_t> record_call(store::Store& store, const CallRecord& record);

// {"job_id", "calls": [{id, artifact, model, round, prompt_hash, seed, temperature, prompt (messages),
//  response, prompt_tokens, completion_tokens, latency_ms, cache_hit, status, error, created_at}],
//  "totals": {calls, cache_hits, prompt_tokens, completion_tokens, latency_ms}} in call order.
Result<Json> job_llm_calls(store::Store& store, std::string_view job_id);

}  // namespace socsim::llm
