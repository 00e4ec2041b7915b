#include "core/llm/llm_client.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/common/rng.hpp"
#include "core/llm/http_client.hpp"
#include "core/llm/prompt_template.hpp"

namespace socsim::llm {

using Clock = std::chrono::steady_clock;

namespace {

std::int64_t ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration_cast<std::chrono::milliseconds>(b - a).count();
}

// The server's own explanation from an error body (OpenAI, vLLM, llama.cpp and Ollama shapes), or
// the start of the raw body.
std::string server_message(const std::string& body) {
  if (body.empty()) return "(empty body)";
  auto j = parse_json_untrusted(body, 16);
  if (j && j->is_object()) {
    const Json& v = *j;
    if (auto e = v.find("error"); e != v.end()) {
      if (e->is_string()) return e->get<std::string>();
      if (e->is_object())
        if (auto m = e->find("message"); m != e->end() && m->is_string()) return m->get<std::string>();
    }
    for (const char* key : {"message", "detail"})
      if (auto m = v.find(key); m != v.end() && m->is_string()) return m->get<std::string>();
  }
  std::string raw = body.substr(0, 300);
  for (char& c : raw)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return raw + (body.size() > 300 ? "…" : "");
}

TokenUsage read_usage(const Json& body) {
  TokenUsage u;
  if (auto it = body.find("usage"); it != body.end() && it->is_object()) {
    if (auto p = it->find("prompt_tokens"); p != it->end() && p->is_number_integer())
      u.prompt_tokens = p->get<std::int64_t>();
    if (auto c = it->find("completion_tokens"); c != it->end() && c->is_number_integer())
      u.completion_tokens = c->get<std::int64_t>();
  }
  return u;
}

bool retryable_status(long status) {
  return status == 408 || status == 429 || (status >= 500 && status != 501);
}

}  // namespace

Json to_json(const std::vector<ChatMessage>& messages) {
  Json out = Json::array();
  for (const auto& m : messages) out.push_back({{"role", m.role}, {"content", m.content}});
  return out;
}

Result<ParsedChat> parse_chat_completion(const Json& body) {
  const auto bad = [](const std::string& why) {
    return fail(ErrorCode::kUpstream, "not a chat completion: " + why);
  };
  if (!body.is_object()) return bad("the body is not a JSON object");
  auto choices = body.find("choices");
  if (choices == body.end() || !choices->is_array() || choices->empty()) return bad("no choices[]");
  const Json& choice = (*choices)[0];
  if (!choice.is_object()) return bad("choices[0] is not an object");
  auto message = choice.find("message");
  if (message == choice.end() || !message->is_object()) return bad("no choices[0].message");
  ParsedChat out;
  if (auto fr = choice.find("finish_reason"); fr != choice.end() && fr->is_string())
    out.finish_reason = fr->get<std::string>();
  auto content = message->find("content");
  if (content == message->end() || !content->is_string()) {
    if (auto refusal = message->find("refusal"); refusal != message->end() && refusal->is_string())
      return fail(ErrorCode::kUpstream, "the model refused: " + refusal->get<std::string>());
    return bad("choices[0].message.content is not text");
  }
  out.content = content->get<std::string>();
  out.usage = read_usage(body);
  return out;
}

struct LlmClient::Call {
  Clock::time_point start = Clock::now();
  Clock::time_point deadline;
  int attempts = 0;
  long last_status = 0;
};

LlmClient::LlmClient(LlmConfig config)
    : config_(std::move(config)),
      jitter_state_(static_cast<std::uint64_t>(Clock::now().time_since_epoch().count())) {}

Result<std::unique_ptr<LlmClient>> LlmClient::create(LlmConfig config) {
  if (auto s = config.validate(); !s) return tl::unexpected(s.error());
  if (!config.configured())
    return fail(ErrorCode::kValidation, "no LLM endpoint configured (set SOCSIM_LLM_URL)",
                {FieldError{"", "is not set", "SOCSIM_LLM_URL", 0, 0}});
  return std::unique_ptr<LlmClient>(new LlmClient(std::move(config)));
}

bool LlmClient::structured_output_available() const {
  return config_.structured_output == StructuredOutput::kOn ||
         (config_.structured_output == StructuredOutput::kAuto && !response_format_rejected_.load());
}

bool LlmClient::acquire_slot(const CancelToken& cancel, Clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(slots_mutex_);
  while (slots_in_use_ >= config_.max_concurrency) {
    if (cancel.cancelled() || Clock::now() >= deadline) return false;
    // Short waits so a cancelled or expired call leaves the queue promptly.
    slots_cv_.wait_until(lock, std::min(deadline, Clock::now() + std::chrono::milliseconds(50)));
  }
  ++slots_in_use_;
  return true;
}

void LlmClient::release_slot() {
  {
    std::lock_guard<std::mutex> lock(slots_mutex_);
    --slots_in_use_;
  }
  slots_cv_.notify_one();
}

int LlmClient::backoff_ms(int retry) {
  const double base =
      std::min<double>(config_.max_backoff_ms, config_.initial_backoff_ms * std::pow(2.0, retry));
  double u;
  {
    std::lock_guard<std::mutex> lock(jitter_mutex_);
    Rng rng(jitter_state_++);
    u = rng.uniform();
  }
  return static_cast<int>(base * (0.5 + 0.5 * u));  // "equal jitter": spreads clients, keeps the floor
}

Result<Json> LlmClient::post(const std::string& path, const Json& body, const CancelToken& cancel,
                             Call& call) {
  const std::string url = endpoint(path);
  const std::string text = body.dump(-1, ' ', false, Json::error_handler_t::replace);
  std::vector<std::string> headers;
  if (!config_.api_key.empty()) headers.push_back("Authorization: Bearer " + config_.api_key);
  const auto upstream = [&](ErrorCode code, const std::string& what) {
    return fail(code, "LLM endpoint " + url + ": " + what);
  };
  const auto cancelled = [&] { return upstream(ErrorCode::kUpstream, "request cancelled"); };

  for (int attempt = 0;; ++attempt) {
    if (cancel.cancelled()) return cancelled();
    if (!acquire_slot(cancel, call.deadline)) {
      if (cancel.cancelled()) return cancelled();
      return upstream(ErrorCode::kUpstreamTimeout, "no free request slot within the deadline of " +
                                                       std::to_string(config_.deadline_ms) + " ms");
    }
    const auto remaining = ms_between(Clock::now(), call.deadline);
    HttpLimits limits;
    limits.connect_timeout_ms = config_.connect_timeout_ms;
    limits.timeout_ms = static_cast<int>(
        std::max<std::int64_t>(1, std::min<std::int64_t>(config_.attempt_timeout_ms, remaining)));
    limits.stall_timeout_ms = config_.stall_timeout_ms;
    limits.max_response_bytes = config_.max_response_bytes;
    auto r = http_post_json(url, text, headers, limits, cancel);
    release_slot();
    ++call.attempts;

    ErrorCode code = ErrorCode::kUpstream;
    std::string what;
    int wait_ms = -1;  // < 0: not retryable
    if (!r) {
      const TransportError& e = r.error();
      call.last_status = 0;
      if (e.kind == TransportFailure::kCancelled) return cancelled();
      what = e.message;
      if (e.kind == TransportFailure::kTimeout) {
        code = ErrorCode::kUpstreamTimeout;
        what = "no answer within " + std::to_string(limits.timeout_ms) + " ms (" + e.message + ")";
        wait_ms = backoff_ms(attempt);
      } else if (e.kind == TransportFailure::kBroken) {
        wait_ms = backoff_ms(attempt);
      }
    } else if (r->status >= 200 && r->status < 300) {
      call.last_status = r->status;
      auto j = parse_json_untrusted(r->body);
      if (!j)
        return upstream(ErrorCode::kUpstream, "answered HTTP " + std::to_string(r->status) +
                                                  " with a body that is not JSON (" + j.error().detail + ")");
      return std::move(*j);
    } else {
      call.last_status = r->status;
      what = "HTTP " + std::to_string(r->status) + ": " + server_message(r->body);
      if (retryable_status(r->status)) {
        if (r->retry_after_s && (r->status == 429 || r->status == 503)) {
          if (*r->retry_after_s > config_.max_retry_after_s)
            return upstream(ErrorCode::kUpstream,
                            what + " (Retry-After " + std::to_string(*r->retry_after_s) +
                                " s is longer than the " + std::to_string(config_.max_retry_after_s) +
                                " s we wait)");
          wait_ms = *r->retry_after_s * 1000;
        } else {
          wait_ms = backoff_ms(attempt);
        }
      }
    }
    if (wait_ms < 0) return upstream(code, what);
    if (attempt >= config_.max_retries)
      return upstream(code, what + " (gave up after " + std::to_string(call.attempts) + " attempts)");
    const auto resume = Clock::now() + std::chrono::milliseconds(wait_ms);
    if (resume >= call.deadline)
      return upstream(code, what + " (after " + std::to_string(call.attempts) +
                                " attempts; the next would pass the " + std::to_string(config_.deadline_ms) +
                                " ms deadline)");
    if (!cancel.sleep_until(resume)) return cancelled();
  }
}

Result<ChatResponse> LlmClient::chat(const ChatRequest& request) {
  auto model = config_.resolve_model(request.model);
  if (!model) return tl::unexpected(model.error());
  if (request.messages.empty()) return fail(ErrorCode::kInternal, "chat request without messages");

  Call call;
  call.deadline = call.start + std::chrono::milliseconds(config_.deadline_ms);
  const auto build = [&](bool with_response_format) -> Result<Json> {
    std::vector<ChatMessage> messages = request.messages;
    Json body = {{"model", *model}, {"temperature", request.temperature}};
    if (request.seed) body["seed"] = *request.seed;
    if (config_.max_tokens > 0) body["max_tokens"] = config_.max_tokens;
    if (request.response_schema && with_response_format) {
      body["response_format"] = {{"type", "json_schema"},
                                 {"json_schema",
                                  {{"name", request.response_schema->name},
                                   {"schema", request.response_schema->schema},
                                   {"strict", config_.strict_schema}}}};
    } else if (request.response_schema) {
      // No structured output: ask in words (schemas/prompts/json_only.md).
      auto tpl = find_prompt_template("json_only");
      if (!tpl) return tl::unexpected(tpl.error());
      auto rendered = render_prompt(**tpl, {{"schema", request.response_schema->schema.dump(2)}});
      if (!rendered) return tl::unexpected(rendered.error());
      const std::string instruction = rendered->front().content;
      if (messages.front().role == "system")
        messages.front().content += "\n\n" + instruction;
      else
        messages.insert(messages.begin(), ChatMessage{"system", instruction});
    }
    body["messages"] = to_json(messages);
    return body;
  };

  bool use_response_format = request.response_schema.has_value() && structured_output_available();
  auto body = build(use_response_format);
  if (!body) return tl::unexpected(body.error());
  auto answer = post("/v1/chat/completions", *body, request.cancel, call);
  if (!answer && use_response_format && config_.structured_output == StructuredOutput::kAuto &&
      (call.last_status == 400 || call.last_status == 422)) {
    // Servers without structured output reject response_format with 400/422: ask in words instead,
    // once per request, and for the rest of this client's life.
    response_format_rejected_.store(true);
    use_response_format = false;
    body = build(false);
    if (!body) return tl::unexpected(body.error());
    const Error first = answer.error();
    answer = post("/v1/chat/completions", *body, request.cancel, call);
    if (!answer)
      answer.error().detail += " (after the endpoint had rejected response_format: " + first.detail + ")";
  }
  if (!answer) return tl::unexpected(answer.error());
  auto parsed = parse_chat_completion(*answer);
  if (!parsed) {
    return fail(ErrorCode::kUpstream,
                "LLM endpoint " + endpoint("/v1/chat/completions") + ": " + parsed.error().detail);
  }
  ChatResponse out;
  out.content = std::move(parsed->content);
  out.finish_reason = std::move(parsed->finish_reason);
  out.model = *model;
  out.usage = parsed->usage;
  out.latency_ms = ms_between(call.start, Clock::now());
  out.attempts = call.attempts;
  out.structured_output = use_response_format;
  return out;
}

Result<EmbeddingResponse> LlmClient::embed(const EmbeddingRequest& request) {
  auto model = config_.resolve_embedding_model(request.model);
  if (!model) return tl::unexpected(model.error());
  EmbeddingResponse out;
  out.model = *model;
  if (request.inputs.empty()) return out;
  Call call;
  call.deadline = call.start + std::chrono::milliseconds(config_.deadline_ms);
  const Json body = {{"model", *model}, {"input", request.inputs}};
  auto answer = post("/v1/embeddings", body, request.cancel, call);
  if (!answer) return tl::unexpected(answer.error());
  const auto bad = [&](const std::string& why) {
    return fail(ErrorCode::kUpstream,
                "LLM endpoint " + endpoint("/v1/embeddings") + ": not an embedding list: " + why);
  };
  auto data = answer->find("data");
  if (!answer->is_object() || data == answer->end() || !data->is_array()) return bad("no data[]");
  if (data->size() != request.inputs.size())
    return bad(std::to_string(data->size()) + " embeddings for " + std::to_string(request.inputs.size()) +
               " inputs");
  out.vectors.assign(request.inputs.size(), {});
  for (std::size_t i = 0; i < data->size(); ++i) {
    const Json& item = (*data)[i];
    if (!item.is_object()) return bad("data[" + std::to_string(i) + "] is not an object");
    std::size_t index = i;
    if (auto idx = item.find("index"); idx != item.end()) {
      if (!idx->is_number_unsigned() || idx->get<std::size_t>() >= request.inputs.size())
        return bad("data[" + std::to_string(i) + "].index is out of range");
      index = idx->get<std::size_t>();
    }
    if (!out.vectors[index].empty()) return bad("two embeddings for input " + std::to_string(index));
    auto emb = item.find("embedding");
    if (emb == item.end() || !emb->is_array() || emb->empty())
      return bad("data[" + std::to_string(i) + "].embedding is not a list of numbers");
    std::vector<float>& v = out.vectors[index];
    v.reserve(emb->size());
    for (const Json& x : *emb) {
      if (!x.is_number() || !std::isfinite(x.get<double>()))
        return bad("data[" + std::to_string(i) + "].embedding holds a value that is not a finite number");
      v.push_back(x.get<float>());
    }
  }
  for (const auto& v : out.vectors)
    if (v.size() != out.vectors[0].size())
      return bad("embeddings of different lengths (" + std::to_string(v.size()) + " and " +
                 std::to_string(out.vectors[0].size()) + ")");
  out.usage = read_usage(*answer);
  out.latency_ms = ms_between(call.start, Clock::now());
  out.attempts = call.attempts;
  return out;
}

}  // namespace socsim::llm
