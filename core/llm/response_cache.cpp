#include "core/llm/response_cache.hpp"

#include "core/common/sha256.hpp"

namespace socsim::llm {

std::string chat_request_hash(const std::vector<ChatMessage>& messages, const Json& schema) {
  return sha256_hex(canonical_json(Json{{"messages", to_json(messages)}, {"schema", schema}}));
}

Result<std::optional<CachedAnswer>> find_cached_answer(store::Store& store, const CacheKey& key) {
  return store.read([&](store::Database& db) -> Result<std::optional<CachedAnswer>> {
    auto st = db.prepare(
        "SELECT response, finish_reason, prompt_tokens, completion_tokens FROM llm_cache "
        "WHERE model = ?1 AND request_hash = ?2 AND seed = ?3 AND temperature = ?4");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, key.model).bind(2, key.request_hash).bind(3, key.seed).bind(4, key.temperature);
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) return std::optional<CachedAnswer>();
    CachedAnswer a;
    a.content = st->text(0);
    a.finish_reason = st->text(1);
    a.usage.prompt_tokens = st->int64(2);
    a.usage.completion_tokens = st->int64(3);
    return std::optional<CachedAnswer>(std::move(a));
  });
}

Status cache_answers(store::Store& store, const std::vector<std::pair<CacheKey, CachedAnswer>>& entries) {
  if (entries.empty()) return {};
  return store.write([&](store::Database& db) -> Status {
    auto st = db.prepare(
        "INSERT INTO llm_cache (model, request_hash, seed, temperature, response, finish_reason, "
        "prompt_tokens, completion_tokens) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8) ON CONFLICT DO NOTHING");
    if (!st) return tl::unexpected(st.error());
    for (const auto& [key, answer] : entries) {
      st->reset();
      st->bind(1, key.model).bind(2, key.request_hash).bind(3, key.seed).bind(4, key.temperature);
      st->bind(5, answer.content).bind(6, answer.finish_reason);
      st->bind(7, answer.usage.prompt_tokens).bind(8, answer.usage.completion_tokens);
      if (auto s = st->run(); !s) return s;
    }
    return {};
  });
}

}  // namespace socsim::llm
