#pragma once
// LLM answers cached in SQLite, keyed by (model, SHA-256 of the full request, seed, temperature),
// so a repeated request costs nothing and a card can be regenerated exactly.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/llm/llm_client.hpp"
#include "core/store/store.hpp"

namespace socsim::llm {

struct CacheKey {
  std::string model;
  std::string request_hash;  // sha256_hex of canonical JSON {messages, schema}
  std::int64_t seed = 0;
  double temperature = 0.0;
};

struct CachedAnswer {
  std::string content;
  std::string finish_reason;
  TokenUsage usage;  // what the original call cost
};

// The request hash of a chat: messages and answer schema in canonical JSON.
std::string chat_request_hash(const std::vector<ChatMessage>& messages, const Json& schema);

Result<std::optional<CachedAnswer>> find_cached_answer(store::Store& store, const CacheKey& key);
// Stores all entries in one transaction (an existing entry for a key is kept).
Status cache_answers(store::Store& store, const std::vector<std::pair<CacheKey, CachedAnswer>>& entries);

}  // namespace socsim::llm
