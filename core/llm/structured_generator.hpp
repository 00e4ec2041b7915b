#pragma once
// The LLM path of every generated artifact: render the artifact's prompt template, ask the
// endpoint, read JSON out of the answer, check it against the artifact's schema and semantic
// rules, quote the problems back for a bounded number of repair rounds, and return only a value
// that passed — or a clear error. Answers are cached and every call is logged (core/llm/call_log).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/json_schema.hpp"
#include "core/llm/llm_client.hpp"
#include "core/llm/prompt_template.hpp"
#include "core/store/store.hpp"

namespace socsim::llm {

// Extracts one JSON value from an answer: the whole text, or a ```json fenced block, or the span
// from the first '{' / '[' to the last matching bracket when the model wrapped it in prose.
// kValidation (with line/column) when no JSON can be read.
Result<Json> extract_json_answer(std::string_view text);

// Rules a schema cannot express (areas ≥ code minimum, probabilities summing to one, …). Runs only
// on schema-valid values; its FieldErrors are quoted back to the model in a repair round.
using SemanticCheck = std::function<Status(const Json&)>;

struct GenerationRequest {
  std::string artifact;                // prompt template name: schemas/prompts/<artifact>.md
  PromptVariables variables;           // exactly the template's placeholders
  const JsonSchema* schema = nullptr;  // the answer's schema (required)
  SemanticCheck check;                 // optional
  std::optional<std::string> model;    // per-request model name; the URL never changes
  double temperature = 0.2;
  std::int64_t seed = 0;
  std::optional<std::string> job_id;  // for the call log
  std::optional<int> repair_rounds;   // default: LlmConfig::repair_rounds
  CancelToken cancel;
};

struct GenerationCall {
  int round = 0;
  std::string prompt_hash;
  bool cache_hit = false;
  TokenUsage usage;
  std::int64_t latency_ms = 0;
  std::string status;  // "ok" | "invalid" | "error"
};

struct Generation {
  Json value;  // schema- and check-valid
  std::string artifact;
  std::string model;
  std::string prompt_hash;  // of the first request: with model, seed and temperature it finds the cache
  std::int64_t seed = 0;
  double temperature = 0.0;
  std::vector<GenerationCall> calls;
  // For a card's provenance: {generator: "llm", artifact, model, prompt_hash, seed, temperature,
  // rounds, cache_hits, prompt_tokens, completion_tokens, latency_ms}.
  [[nodiscard]] Json provenance() const;
};

class StructuredGenerator {
 public:
  // `store` may be null: then nothing is cached or logged.
  StructuredGenerator(LlmClient& client, store::Store* store) : client_(client), store_(store) {}

  // kValidation: bad model name, or the final answer still failed its checks (detail and errors[]
  // name the fields of the answer); kUpstream / kUpstreamTimeout: the endpoint failed (detail
  // quotes its error); kStore*: the cache or log could not be written.
  [[nodiscard]] Result<Generation> generate(const GenerationRequest& request) const;

 private:
  LlmClient& client_;
  store::Store* store_;
};

}  // namespace socsim::llm
