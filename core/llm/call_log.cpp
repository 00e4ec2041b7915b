#include "core/llm/call_log.hpp"

namespace socsim::llm {

std::string_view to_string(CallStatus status) {
  switch (status) {
    case CallStatus::kOk:
      return "ok";
    case CallStatus::kInvalid:
      return "invalid";
    case CallStatus::kError:
      return "error";
  }
  return "error";
}

Result<std::int64_t> record_call(store::Store& store, const CallRecord& r) {
  return store.write([&](store::Database& db) -> Result<std::int64_t> {
    auto st = db.prepare(
        "INSERT INTO llm_calls (job_id, artifact, model, round, prompt_hash, seed, temperature, prompt, "
        "response, "
        "prompt_tokens, completion_tokens, latency_ms, cache_hit, status, error) "
        "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15)");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, r.job_id).bind(2, r.artifact).bind(3, r.model).bind(4, r.round).bind(5, r.prompt_hash);
    st->bind(6, r.seed).bind(7, r.temperature).bind(8, r.prompt).bind(9, r.response);
    st->bind(10, r.usage.prompt_tokens).bind(11, r.usage.completion_tokens).bind(12, r.latency_ms);
    st->bind(13, r.cache_hit ? 1 : 0).bind(14, std::string(to_string(r.status))).bind(15, r.error);
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    return db.last_insert_rowid();
  });
}

Result<Json> job_llm_calls(store::Store& store, std::string_view job_id) {
  return store.read([&](store::Database& db) -> Result<Json> {
    auto st = db.prepare(
        "SELECT id, artifact, model, round, prompt_hash, seed, temperature, prompt, response, prompt_tokens, "
        "completion_tokens, latency_ms, cache_hit, status, error, created_at FROM llm_calls "
        "WHERE job_id = ?1 ORDER BY id");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, job_id);
    Json calls = Json::array();
    std::int64_t hits = 0, prompt_tokens = 0, completion_tokens = 0, latency = 0;
    while (true) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      Json prompt = Json::parse(st->text(7), nullptr, /*allow_exceptions=*/false);  // json_valid by CHECK
      Json call = {{"id", st->int64(0)},
                   {"artifact", st->text(1)},
                   {"model", st->text(2)},
                   {"round", st->int64(3)},
                   {"prompt_hash", st->text(4)},
                   {"seed", st->int64(5)},
                   {"temperature", st->real(6)},
                   {"prompt", std::move(prompt)},
                   {"response", st->is_null(8) ? Json() : Json(st->text(8))},
                   {"prompt_tokens", st->int64(9)},
                   {"completion_tokens", st->int64(10)},
                   {"latency_ms", st->int64(11)},
                   {"cache_hit", st->int64(12) != 0},
                   {"status", st->text(13)},
                   {"error", st->is_null(14) ? Json() : Json(st->text(14))},
                   {"created_at", st->text(15)}};
      hits += st->int64(12);
      prompt_tokens += st->int64(9);
      completion_tokens += st->int64(10);
      latency += st->int64(11);
      calls.push_back(std::move(call));
    }
    const auto n = static_cast<std::int64_t>(calls.size());
    return Json{{"job_id", std::string(job_id)},
                {"calls", std::move(calls)},
                {"totals",
                 {{"calls", n},
                  {"cache_hits", hits},
                  {"prompt_tokens", prompt_tokens},
                  {"completion_tokens", completion_tokens},
                  {"latency_ms", latency}}}};
  });
}

}  // namespace socsim::llm
