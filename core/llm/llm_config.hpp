#pragma once
// Where the LLM endpoint is and how patiently to talk to it, read from SOCSIM_LLM_* variables.
// The URL comes only from configuration; a request may choose the model name, never the URL.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::llm {

// Whether chat requests carry response_format {type: json_schema}. kAuto sends it and falls back
// to a "answer only JSON" instruction for the rest of the process when the server rejects it.
enum class StructuredOutput { kAuto, kOn, kOff };

struct LlmConfig {
  std::string base_url;                     // e.g. "https://api.openai.com"; empty = no endpoint configured
  std::string model;                        // default chat model
  std::string embedding_model;              // default embedding model; empty = `model`
  std::string api_key;                      // sent as "Authorization: Bearer …" when not empty
  std::vector<std::string> allowed_models;  // per-request model names allowed; empty: only `model`

  int connect_timeout_ms = 5000;
  // A hung endpoint holds a job worker until the deadline, so the defaults are one minute a call.
  int attempt_timeout_ms = 60000;  // one HTTP exchange, from connect to the last byte
  int stall_timeout_ms = 30000;    // abort when under 1 byte/s this long (non-streaming servers send
                                   // nothing while generating, so this also bounds generation time)
  int deadline_ms = 60000;         // one call: all attempts and back-off waits together
  int max_retries = 3;             // extra attempts after timeouts, 429 and 5xx
  int initial_backoff_ms = 500;    // doubled per retry, capped at max_backoff_ms, with jitter
  int max_backoff_ms = 20000;
  int max_retry_after_s = 60;  // a longer Retry-After fails the call instead of waiting
  int max_concurrency = 4;     // requests in flight per client
  std::size_t max_response_bytes = 8u << 20;
  StructuredOutput structured_output = StructuredOutput::kAuto;
  bool strict_schema = false;  // response_format.json_schema.strict
  int max_tokens = 0;          // 0 = the server's default
  int repair_rounds = 2;       // StructuredGenerator: answers re-requested after a failed check

  [[nodiscard]] bool configured() const { return !base_url.empty(); }

  // Checks ranges and the URL (http/https with a host, no credentials, query or fragment) and
  // normalises it: a trailing "/" or "/v1" is dropped, since the client appends "/v1/...".
  Status validate();

  // The model for one request: the configured default, or `requested` after checking it is a
  // plausible model name in allowed_models (the default model alone when that list is empty).
  // kValidation at "/model".
  [[nodiscard]] Result<std::string> resolve_model(const std::optional<std::string>& requested) const;
  [[nodiscard]] Result<std::string> resolve_embedding_model(
      const std::optional<std::string>& requested) const;

  using Getenv = std::function<const char*(const char*)>;
  // Reads SOCSIM_LLM_URL, _MODEL, _API_KEY, _EMBEDDING_MODEL, _ALLOWED_MODELS (comma list),
  // _CONNECT_TIMEOUT_MS, _TIMEOUT_MS, _STALL_TIMEOUT_MS, _DEADLINE_MS, _MAX_RETRIES,
  // _MAX_CONCURRENCY, _MAX_RESPONSE_BYTES, _STRUCTURED_OUTPUT (auto|on|off), _STRICT_SCHEMA
  // (true|false), _MAX_TOKENS, _REPAIR_ROUNDS. A bad value is kValidation naming the variable.
  static Result<LlmConfig> from_environment(const Getenv& getenv);
  static Result<LlmConfig> from_environment();
};

}  // namespace socsim::llm
