#include "core/llm/structured_generator.hpp"

#include <algorithm>
#include <chrono>

#include "core/llm/call_log.hpp"
#include "core/llm/response_cache.hpp"

namespace socsim::llm {
namespace {

using Clock = std::chrono::steady_clock;

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

Error not_json(const Error& parse_error) {
  Error e(ErrorCode::kValidation, "the answer is not valid JSON: " + parse_error.detail, parse_error.errors);
  for (auto& f : e.errors) f.message = "not valid JSON: " + f.message;
  return e;
}

std::string describe(const FieldError& e) {
  std::string where = e.pointer.empty() ? std::string("(whole answer)") : e.pointer;
  if (e.line > 0) where += " (line " + std::to_string(e.line) + ", column " + std::to_string(e.column) + ")";
  return where + ": " + e.message;
}

std::string bullet_list(const std::vector<FieldError>& problems) {
  std::string out;
  for (const auto& p : problems) out += "- " + describe(p) + "\n";
  return out;
}

std::string summary(const std::vector<FieldError>& problems) {
  std::string out;
  for (std::size_t i = 0; i < problems.size() && i < 3; ++i) out += (i ? "; " : "") + describe(problems[i]);
  if (problems.size() > 3) out += "; and " + std::to_string(problems.size() - 3) + " more";
  return out;
}

struct Checked {
  Json value;
  std::vector<FieldError> problems;
};

Checked check_answer(const std::string& content, const std::string& finish_reason, const JsonSchema& schema,
                     const SemanticCheck& semantic) {
  Checked out;
  auto parsed = extract_json_answer(content);
  if (!parsed) {
    out.problems = parsed.error().errors;
    if (out.problems.empty()) out.problems.push_back(FieldError{"", parsed.error().detail});
  } else {
    out.value = std::move(*parsed);
    out.problems = schema.validate(out.value, 30);
    if (out.problems.empty() && semantic) {
      Status s;
      try {
        s = semantic(out.value);
      } catch (const Json::exception& e) {  // a check reading a field the schema left optional
        s = fail(ErrorCode::kValidation, e.what());
      }
      if (!s) {
        out.problems = s.error().errors;
        if (out.problems.empty()) out.problems.push_back(FieldError{"", s.error().detail});
      }
    }
  }
  if (finish_reason == "length")
    out.problems.push_back(
        FieldError{"", "the answer was cut off at the token limit; answer more compactly"});
  return out;
}

}  // namespace

Result<Json> extract_json_answer(std::string_view text) {
  const std::string_view t = trim(text);
  if (t.empty())
    return fail(ErrorCode::kValidation, "the answer is empty", {FieldError{"", "the answer is empty"}});
  if (const auto fence = t.find("```"); fence != std::string_view::npos) {
    std::size_t start = t.find('\n', fence);
    start = start == std::string_view::npos ? t.size() : start + 1;
    std::size_t end = t.find("```", start);
    if (end == std::string_view::npos) end = t.size();  // an unterminated fence: the answer was cut off
    auto j = parse_json_untrusted(trim(t.substr(start, end - start)));
    if (j) return j;
    return tl::unexpected(not_json(j.error()));
  }
  auto direct = parse_json_untrusted(t);
  if (direct) return direct;
  const auto open = t.find_first_of("{[");
  if (open != std::string_view::npos && open > 0) {
    const char close = t[open] == '{' ? '}' : ']';
    const auto last = t.rfind(close);
    if (last != std::string_view::npos && last > open) {
      auto inner = parse_json_untrusted(t.substr(open, last - open + 1));
      if (inner) return inner;
    }
  }
  return tl::unexpected(not_json(direct.error()));
}

Json Generation::provenance() const {
  std::int64_t hits = 0, prompt_tokens = 0, completion_tokens = 0, latency = 0;
  for (const auto& c : calls) {
    hits += c.cache_hit ? 1 : 0;
    prompt_tokens += c.usage.prompt_tokens;
    completion_tokens += c.usage.completion_tokens;
    latency += c.latency_ms;
  }
  return Json{{"generator", "llm"},
              {"artifact", artifact},
              {"model", model},
              {"prompt_hash", prompt_hash},
              {"seed", seed},
              {"temperature", temperature},
              {"rounds", calls.size()},
              {"cache_hits", hits},
              {"prompt_tokens", prompt_tokens},
              {"completion_tokens", completion_tokens},
              {"latency_ms", latency}};
}

Result<Generation> StructuredGenerator::generate(const GenerationRequest& request) const {
  if (request.schema == nullptr)
    return fail(ErrorCode::kInternal, "generation of " + request.artifact + " without a schema");
  auto tpl = find_prompt_template(request.artifact);
  if (!tpl) return tl::unexpected(tpl.error());
  auto rendered = render_prompt(**tpl, request.variables);
  if (!rendered) return tl::unexpected(rendered.error());
  std::vector<ChatMessage> messages = std::move(*rendered);
  auto model = client_.config().resolve_model(request.model);
  if (!model) return tl::unexpected(model.error());
  auto repair_tpl = find_prompt_template("repair");
  if (!repair_tpl) return tl::unexpected(repair_tpl.error());
  const int rounds = std::clamp(request.repair_rounds.value_or(client_.config().repair_rounds), 0, 5);

  Generation gen;
  gen.artifact = request.artifact;
  gen.model = *model;
  gen.seed = request.seed;
  gen.temperature = request.temperature;
  const Json& schema = request.schema->document();
  std::vector<std::pair<CacheKey, CachedAnswer>> fresh;  // cached only once the whole generation succeeds
  std::vector<FieldError> problems;

  for (int round = 0; round <= rounds; ++round) {
    GenerationCall call;
    call.round = round;
    call.prompt_hash = chat_request_hash(messages, schema);
    if (round == 0) gen.prompt_hash = call.prompt_hash;
    const CacheKey key{*model, call.prompt_hash, request.seed, request.temperature};
    CallRecord record;
    record.job_id = request.job_id;
    record.artifact = request.artifact;
    record.model = *model;
    record.round = round;
    record.prompt_hash = call.prompt_hash;
    record.seed = request.seed;
    record.temperature = request.temperature;
    record.prompt = canonical_json(to_json(messages));

    const auto started = Clock::now();
    std::optional<CachedAnswer> cached;
    if (store_ != nullptr) {
      auto found = find_cached_answer(*store_, key);
      if (!found) return tl::unexpected(found.error());
      cached = std::move(*found);
    }
    std::string content, finish_reason;
    if (cached) {
      content = cached->content;
      finish_reason = cached->finish_reason;
      call.cache_hit = true;
      call.latency_ms = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - started).count();
    } else {
      ChatRequest chat;
      chat.messages = messages;
      chat.model = *model;
      chat.temperature = request.temperature;
      chat.seed = request.seed;
      chat.response_schema = ResponseSchema{request.artifact, schema};
      chat.cancel = request.cancel;
      auto answer = client_.chat(chat);
      if (!answer) {
        Error e = answer.error();
        e.detail = "generating " + request.artifact + ": " + e.detail;
        record.status = CallStatus::kError;
        record.error = e.detail;
        record.latency_ms =
            std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - started).count();
        if (store_ != nullptr) (void)record_call(*store_, record);  // the endpoint's error matters more
        return tl::unexpected(std::move(e));
      }
      content = std::move(answer->content);
      finish_reason = std::move(answer->finish_reason);
      call.usage = answer->usage;
      call.latency_ms = answer->latency_ms;
      fresh.push_back({key, CachedAnswer{content, finish_reason, answer->usage}});
    }

    Checked checked = check_answer(content, finish_reason, *request.schema, request.check);
    problems = std::move(checked.problems);
    call.status = problems.empty() ? "ok" : "invalid";
    record.response = content;
    record.usage = call.usage;
    record.latency_ms = call.latency_ms;
    record.cache_hit = call.cache_hit;
    record.status = problems.empty() ? CallStatus::kOk : CallStatus::kInvalid;
    if (!problems.empty()) record.error = summary(problems);
    gen.calls.push_back(call);
    if (store_ != nullptr)
      if (auto logged = record_call(*store_, record); !logged) return tl::unexpected(logged.error());

    if (problems.empty()) {
      if (store_ != nullptr)
        if (auto s = cache_answers(*store_, fresh); !s) return tl::unexpected(s.error());
      gen.value = std::move(checked.value);
      return gen;
    }
    if (round < rounds) {
      auto repair = render_prompt(**repair_tpl, {{"problems", bullet_list(problems)}});
      if (!repair) return tl::unexpected(repair.error());
      messages.push_back(ChatMessage{"assistant", content});
      messages.push_back(ChatMessage{"user", repair->back().content});
    }
  }
  std::string detail = "the LLM's " + request.artifact + " answer still failed its checks after " +
                       std::to_string(rounds) + " repair round" + (rounds == 1 ? "" : "s") + ": " +
                       summary(problems);
  return fail(ErrorCode::kValidation, std::move(detail), std::move(problems));
}

}  // namespace socsim::llm
