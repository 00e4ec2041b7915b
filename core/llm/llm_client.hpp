#pragma once
// Client for any OpenAI-compatible endpoint: POST {base}/v1/chat/completions and /v1/embeddings,
// with bounded retries (timeouts, 429 with Retry-After, 5xx), a concurrency limit, cancellation,
// and token usage and latency for every call. Thread-safe.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/llm/cancel_token.hpp"
#include "core/llm/llm_config.hpp"

namespace socsim::llm {

struct ChatMessage {
  std::string role;  // "system" | "user" | "assistant"
  std::string content;
};
Json to_json(const std::vector<ChatMessage>& messages);

struct ResponseSchema {
  std::string name;  // ^[A-Za-z0-9_-]{1,64}$, e.g. the artifact name
  Json schema;
};

struct ChatRequest {
  std::vector<ChatMessage> messages;
  std::optional<std::string> model;  // per-request model name (checked); the URL is never per request
  double temperature = 0.0;
  std::optional<std::int64_t> seed;
  std::optional<ResponseSchema> response_schema;  // ask for JSON matching this schema
  CancelToken cancel;
};

struct TokenUsage {
  std::int64_t prompt_tokens = 0;
  std::int64_t completion_tokens = 0;
};

struct ChatResponse {
  std::string content;
  std::string finish_reason;  // "stop", "length" (cut off at the token limit), …
  std::string model;          // as named in the request
  TokenUsage usage;
  std::int64_t latency_ms = 0;  // whole call, retries and waits included
  int attempts = 0;
  bool structured_output = false;  // response_format was sent and accepted
};

struct EmbeddingRequest {
  std::vector<std::string> inputs;
  std::optional<std::string> model;
  CancelToken cancel;
};

struct EmbeddingResponse {
  std::vector<std::vector<float>> vectors;  // one per input, in input order
  std::string model;
  TokenUsage usage;
  std::int64_t latency_ms = 0;
  int attempts = 0;
};

class LlmClient {
 public:
  // Validates the configuration; kValidation when it is unusable or no URL is configured.
  static Result<std::unique_ptr<LlmClient>> create(LlmConfig config);
  LlmClient(const LlmClient&) = delete;
  LlmClient& operator=(const LlmClient&) = delete;

  // Errors: kUpstream (endpoint unreachable, HTTP error, malformed answer, cancelled — the detail
  // names the endpoint's own message), kUpstreamTimeout (no answer within the timeouts),
  // kValidation (bad model name).
  Result<ChatResponse> chat(const ChatRequest& request);
  Result<EmbeddingResponse> embed(const EmbeddingRequest& request);

  [[nodiscard]] const LlmConfig& config() const { return config_; }
  // False once the server has rejected response_format (kAuto mode); then JSON is asked for in words.
  [[nodiscard]] bool structured_output_available() const;
  [[nodiscard]] std::string endpoint(std::string_view path) const {
    return config_.base_url + std::string(path);
  }

 private:
  explicit LlmClient(LlmConfig config);
  struct Call;
  Result<Json> post(const std::string& path, const Json& body, const CancelToken& cancel, Call& call);
  bool acquire_slot(const CancelToken& cancel, std::chrono::steady_clock::time_point deadline);
  void release_slot();
  int backoff_ms(int retry);

  LlmConfig config_;
  std::atomic<bool> response_format_rejected_{false};
  std::mutex slots_mutex_;
  std::condition_variable slots_cv_;
  int slots_in_use_ = 0;
  std::mutex jitter_mutex_;
  std::uint64_t jitter_state_;
};

// Reads the answer text out of a chat.completion body; kUpstream naming what is missing.
struct ParsedChat {
  std::string content;
  std::string finish_reason;
  TokenUsage usage;
};
Result<ParsedChat> parse_chat_completion(const Json& body);

}  // namespace socsim::llm
