#include "core/llm/llm_config.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>

#include "core/llm/http_client.hpp"

namespace socsim::llm {
namespace {

FieldError env_error(std::string_view var, std::string message) {
  return FieldError{"", std::move(message), std::string(var), 0, 0};
}

class EnvReader {
 public:
  explicit EnvReader(const LlmConfig::Getenv& getenv) : getenv_(getenv) {}

  std::optional<std::string> text(const char* var) const {
    const char* v = getenv_(var);
    if (v == nullptr || *v == '\0') return std::nullopt;
    return std::string(v);
  }

  template <class Int>
  void integer(const char* var, Int& out, long long min, long long max) {
    auto v = text(var);
    if (!v) return;
    long long parsed = 0;
    const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), parsed);
    if (ec != std::errc() || end != v->data() + v->size()) {
      errors.push_back(env_error(var, "must be a whole number, got \"" + *v + "\""));
    } else if (parsed < min || parsed > max) {
      errors.push_back(env_error(
          var, "must be between " + std::to_string(min) + " and " + std::to_string(max) + ", got " + *v));
    } else {
      out = static_cast<Int>(parsed);
    }
  }

  void boolean(const char* var, bool& out) {
    auto v = text(var);
    if (!v) return;
    std::string s = *v;
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (s == "1" || s == "true" || s == "yes" || s == "on")
      out = true;
    else if (s == "0" || s == "false" || s == "no" || s == "off")
      out = false;
    else
      errors.push_back(env_error(var, "must be true or false, got \"" + *v + "\""));
  }

  std::vector<FieldError> errors;

 private:
  const LlmConfig::Getenv& getenv_;
};

bool plausible_model_name(std::string_view name) {
  if (name.empty() || name.size() > 200) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
           c == '_' || c == '-' || c == ':' || c == '/' || c == '@' || c == '+';
  });
}

Result<std::string> resolve(const LlmConfig& cfg, const std::optional<std::string>& requested,
                            const std::string& fallback) {
  if (!requested) {
    if (fallback.empty())
      return fail(ErrorCode::kValidation,
                  "no LLM model configured (set SOCSIM_LLM_MODEL or name one in the request)",
                  {FieldError{"/model", "is required: no default model is configured"}});
    return fallback;
  }
  if (!plausible_model_name(*requested))
    return fail(ErrorCode::kValidation, "model name is not valid",
                {FieldError{"/model", "must be 1-200 characters of letters, digits and . _ - : / @ +"}});
  // Without an allow-list only the configured model may be named: a client must not be able to
  // spend the operator's quota on a larger (dearer) model the endpoint happens to serve.
  const std::vector<std::string> allowed = cfg.allowed_models.empty() && !fallback.empty()
                                               ? std::vector<std::string>{fallback}
                                               : cfg.allowed_models;
  if (std::find(allowed.begin(), allowed.end(), *requested) == allowed.end()) {
    std::string list;
    for (const auto& m : allowed) list += (list.empty() ? "" : ", ") + m;
    if (list.empty()) list = "(none: no model is configured)";
    return fail(ErrorCode::kValidation, "model \"" + *requested + "\" is not allowed on this server",
                {FieldError{"/model", "must be one of: " + list}});
  }
  return *requested;
}

}  // namespace

Status LlmConfig::validate() {
  std::vector<FieldError> errors;
  const auto range = [&](const char* var, long long v, long long min, long long max) {
    if (v < min || v > max)
      errors.push_back(env_error(var, "must be between " + std::to_string(min) + " and " +
                                          std::to_string(max) + ", got " + std::to_string(v)));
  };
  range("SOCSIM_LLM_CONNECT_TIMEOUT_MS", connect_timeout_ms, 1, 600000);
  range("SOCSIM_LLM_TIMEOUT_MS", attempt_timeout_ms, 1, 3600000);
  range("SOCSIM_LLM_STALL_TIMEOUT_MS", stall_timeout_ms, 1000, 3600000);
  range("SOCSIM_LLM_DEADLINE_MS", deadline_ms, 1, 24 * 3600000LL);
  range("SOCSIM_LLM_MAX_RETRIES", max_retries, 0, 20);
  range("initial_backoff_ms", initial_backoff_ms, 1, 600000);
  range("max_backoff_ms", max_backoff_ms, initial_backoff_ms, 3600000);
  range("max_retry_after_s", max_retry_after_s, 0, 3600);
  range("SOCSIM_LLM_MAX_CONCURRENCY", max_concurrency, 1, 1024);
  range("SOCSIM_LLM_MAX_RESPONSE_BYTES", static_cast<long long>(max_response_bytes), 1024, 1LL << 30);
  range("SOCSIM_LLM_MAX_TOKENS", max_tokens, 0, 1 << 24);
  range("SOCSIM_LLM_REPAIR_ROUNDS", repair_rounds, 0, 5);
  if (!model.empty() && !plausible_model_name(model))
    errors.push_back(env_error("SOCSIM_LLM_MODEL", "is not a plausible model name"));
  if (!embedding_model.empty() && !plausible_model_name(embedding_model))
    errors.push_back(env_error("SOCSIM_LLM_EMBEDDING_MODEL", "is not a plausible model name"));
  for (const auto& m : allowed_models)
    if (!plausible_model_name(m))
      errors.push_back(env_error("SOCSIM_LLM_ALLOWED_MODELS", "\"" + m + "\" is not a model name"));

  if (!base_url.empty()) {
    auto url = parse_http_url(base_url);
    if (!url) {
      errors.push_back(env_error("SOCSIM_LLM_URL", url.error().detail));
    } else {
      std::string path = url->path;
      while (!path.empty() && path.back() == '/') path.pop_back();
      if (path.size() >= 3 && path.compare(path.size() - 3, 3, "/v1") == 0) path.resize(path.size() - 3);
      base_url = url->origin() + path;
    }
  }
  if (!errors.empty()) {
    std::string detail = "LLM configuration: " + errors.front().parameter + " " + errors.front().message;
    return fail(ErrorCode::kValidation, std::move(detail), std::move(errors));
  }
  return {};
}

Result<std::string> LlmConfig::resolve_model(const std::optional<std::string>& requested) const {
  return resolve(*this, requested, model);
}

Result<std::string> LlmConfig::resolve_embedding_model(const std::optional<std::string>& requested) const {
  return resolve(*this, requested, embedding_model.empty() ? model : embedding_model);
}

Result<LlmConfig> LlmConfig::from_environment(const Getenv& getenv) {
  LlmConfig cfg;
  EnvReader env(getenv);
  cfg.base_url = env.text("SOCSIM_LLM_URL").value_or("");
  cfg.model = env.text("SOCSIM_LLM_MODEL").value_or("");
  cfg.embedding_model = env.text("SOCSIM_LLM_EMBEDDING_MODEL").value_or("");
  cfg.api_key = env.text("SOCSIM_LLM_API_KEY").value_or("");
  if (auto list = env.text("SOCSIM_LLM_ALLOWED_MODELS")) {
    std::size_t start = 0;
    while (start <= list->size()) {
      std::size_t end = list->find(',', start);
      if (end == std::string::npos) end = list->size();
      std::string item = list->substr(start, end - start);
      item.erase(0, item.find_first_not_of(" \t"));
      item.erase(item.find_last_not_of(" \t") + 1);
      if (!item.empty()) cfg.allowed_models.push_back(item);
      start = end + 1;
    }
  }
  env.integer("SOCSIM_LLM_CONNECT_TIMEOUT_MS", cfg.connect_timeout_ms, 1, 600000);
  env.integer("SOCSIM_LLM_TIMEOUT_MS", cfg.attempt_timeout_ms, 1, 3600000);
  env.integer("SOCSIM_LLM_STALL_TIMEOUT_MS", cfg.stall_timeout_ms, 1000, 3600000);
  env.integer("SOCSIM_LLM_DEADLINE_MS", cfg.deadline_ms, 1, 24 * 3600000LL);
  env.integer("SOCSIM_LLM_MAX_RETRIES", cfg.max_retries, 0, 20);
  env.integer("SOCSIM_LLM_MAX_CONCURRENCY", cfg.max_concurrency, 1, 1024);
  env.integer("SOCSIM_LLM_MAX_RESPONSE_BYTES", cfg.max_response_bytes, 1024, 1LL << 30);
  env.integer("SOCSIM_LLM_MAX_TOKENS", cfg.max_tokens, 0, 1 << 24);
  env.integer("SOCSIM_LLM_REPAIR_ROUNDS", cfg.repair_rounds, 0, 5);
  env.boolean("SOCSIM_LLM_STRICT_SCHEMA", cfg.strict_schema);
  if (auto mode = env.text("SOCSIM_LLM_STRUCTURED_OUTPUT")) {
    if (*mode == "auto")
      cfg.structured_output = StructuredOutput::kAuto;
    else if (*mode == "on")
      cfg.structured_output = StructuredOutput::kOn;
    else if (*mode == "off")
      cfg.structured_output = StructuredOutput::kOff;
    else
      env.errors.push_back(
          env_error("SOCSIM_LLM_STRUCTURED_OUTPUT", "must be auto, on or off, got \"" + *mode + "\""));
  }
  if (!env.errors.empty()) {
    std::string detail =
        "LLM configuration: " + env.errors.front().parameter + " " + env.errors.front().message;
    return fail(ErrorCode::kValidation, std::move(detail), std::move(env.errors));
  }
  if (cfg.deadline_ms < cfg.attempt_timeout_ms && !getenv("SOCSIM_LLM_DEADLINE_MS"))
    cfg.deadline_ms = cfg.attempt_timeout_ms;
  if (auto s = cfg.validate(); !s) return tl::unexpected(s.error());
  return cfg;
}

Result<LlmConfig> LlmConfig::from_environment() {
  return from_environment([](const char* name) -> const char* { return std::getenv(name); });
}

}  // namespace socsim::llm
