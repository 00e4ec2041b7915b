// LlmConfig: reading SOCSIM_LLM_* variables, naming the variable of every bad value, normalising
// the base URL and checking per-request model names.
#include "core/llm/llm_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

namespace socsim::llm {
namespace {

using ::testing::HasSubstr;

Result<LlmConfig> from(const std::map<std::string, std::string>& env) {
  return LlmConfig::from_environment([&](const char* name) -> const char* {
    auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
}

TEST(LlmConfig, WithNothingSetNoEndpointIsConfigured) {
  auto c = from({});
  ASSERT_TRUE(c.has_value()) << c.error().message();
  EXPECT_FALSE(c->configured());
  EXPECT_EQ(c->structured_output, StructuredOutput::kAuto);
  EXPECT_EQ(c->max_retries, 3);
}

TEST(LlmConfig, ReadsEveryVariable) {
  auto c = from({{"SOCSIM_LLM_URL", "http://gpu-box:8000/v1/"},
                 {"SOCSIM_LLM_MODEL", "Qwen/Qwen2.5-7B-Instruct"},
                 {"SOCSIM_LLM_EMBEDDING_MODEL", "nomic-embed-text"},
                 {"SOCSIM_LLM_API_KEY", "sk-123"},
                 {"SOCSIM_LLM_ALLOWED_MODELS", " Qwen/Qwen2.5-7B-Instruct , llama3.1:8b,"},
                 {"SOCSIM_LLM_CONNECT_TIMEOUT_MS", "1500"},
                 {"SOCSIM_LLM_TIMEOUT_MS", "60000"},
                 {"SOCSIM_LLM_STALL_TIMEOUT_MS", "30000"},
                 {"SOCSIM_LLM_DEADLINE_MS", "90000"},
                 {"SOCSIM_LLM_MAX_RETRIES", "5"},
                 {"SOCSIM_LLM_MAX_CONCURRENCY", "2"},
                 {"SOCSIM_LLM_MAX_RESPONSE_BYTES", "65536"},
                 {"SOCSIM_LLM_STRUCTURED_OUTPUT", "off"},
                 {"SOCSIM_LLM_STRICT_SCHEMA", "true"},
                 {"SOCSIM_LLM_MAX_TOKENS", "4096"},
                 {"SOCSIM_LLM_REPAIR_ROUNDS", "1"}});
  ASSERT_TRUE(c.has_value()) << c.error().message();
  EXPECT_EQ(c->base_url, "http://gpu-box:8000");
  EXPECT_EQ(c->model, "Qwen/Qwen2.5-7B-Instruct");
  EXPECT_EQ(c->embedding_model, "nomic-embed-text");
  EXPECT_EQ(c->api_key, "sk-123");
  EXPECT_EQ(c->allowed_models, (std::vector<std::string>{"Qwen/Qwen2.5-7B-Instruct", "llama3.1:8b"}));
  EXPECT_EQ(c->connect_timeout_ms, 1500);
  EXPECT_EQ(c->attempt_timeout_ms, 60000);
  EXPECT_EQ(c->stall_timeout_ms, 30000);
  EXPECT_EQ(c->deadline_ms, 90000);
  EXPECT_EQ(c->max_retries, 5);
  EXPECT_EQ(c->max_concurrency, 2);
  EXPECT_EQ(c->max_response_bytes, 65536u);
  EXPECT_EQ(c->structured_output, StructuredOutput::kOff);
  EXPECT_TRUE(c->strict_schema);
  EXPECT_EQ(c->max_tokens, 4096);
  EXPECT_EQ(c->repair_rounds, 1);
}

TEST(LlmConfig, BaseUrlsAreNormalised) {
  EXPECT_EQ(from({{"SOCSIM_LLM_URL", "https://api.openai.com/v1"}})->base_url, "https://api.openai.com");
  EXPECT_EQ(from({{"SOCSIM_LLM_URL", "http://localhost:11434"}})->base_url, "http://localhost:11434");
  EXPECT_EQ(from({{"SOCSIM_LLM_URL", "https://proxy.lab:443/llm/v1/"}})->base_url, "https://proxy.lab/llm");
  EXPECT_EQ(from({{"SOCSIM_LLM_URL", "http://[::1]:8080"}})->base_url, "http://[::1]:8080");
}

TEST(LlmConfig, EveryBadValueIsNamedByItsVariable) {
  auto c = from({{"SOCSIM_LLM_MAX_RETRIES", "three"},
                 {"SOCSIM_LLM_CONNECT_TIMEOUT_MS", "0"},
                 {"SOCSIM_LLM_STRUCTURED_OUTPUT", "maybe"},
                 {"SOCSIM_LLM_STRICT_SCHEMA", "perhaps"}});
  ASSERT_FALSE(c.has_value());
  EXPECT_EQ(c.error().code, ErrorCode::kValidation);
  std::vector<std::string> vars;
  for (const auto& e : c.error().errors) vars.push_back(e.parameter);
  EXPECT_THAT(vars,
              ::testing::UnorderedElementsAre("SOCSIM_LLM_MAX_RETRIES", "SOCSIM_LLM_CONNECT_TIMEOUT_MS",
                                              "SOCSIM_LLM_STRUCTURED_OUTPUT", "SOCSIM_LLM_STRICT_SCHEMA"));
  EXPECT_THAT(c.error().detail, HasSubstr("SOCSIM_LLM_"));
}

TEST(LlmConfig, UrlsOtherThanPlainHttpEndpointsAreRefused) {
  for (const char* url : {"file:///etc/passwd", "gopher://x", "http://user:pw@host", "http://host/?q=1",
                          "not a url", "http://"}) {
    auto c = from({{"SOCSIM_LLM_URL", url}});
    ASSERT_FALSE(c.has_value()) << url;
    EXPECT_EQ(c.error().errors.at(0).parameter, "SOCSIM_LLM_URL") << url;
  }
}

// Issue 14 #8: a hung endpoint held a job worker for up to 600 s by default.
TEST(LlmConfig, DefaultsHoldAWorkerAMinuteAtMost) {
  const LlmConfig c;
  EXPECT_LE(c.deadline_ms, 60000);
  EXPECT_LE(c.attempt_timeout_ms, c.deadline_ms);
  auto env = LlmConfig::from_environment([](const char*) -> const char* { return nullptr; });
  ASSERT_TRUE(env.has_value());
  EXPECT_LE(env->deadline_ms, 60000);
}

TEST(LlmConfig, ResolvesPerRequestModelNames) {
  LlmConfig c;
  c.model = "default-model";
  EXPECT_EQ(*c.resolve_model(std::nullopt), "default-model");
  EXPECT_EQ(*c.resolve_model("default-model"), "default-model");
  // Issue 14 #12: without an allow-list only the configured model may be named.
  auto other = c.resolve_model("llama3.1:8b");
  ASSERT_FALSE(other.has_value());
  EXPECT_EQ(other.error().errors.at(0).pointer, "/model");
  EXPECT_THAT(other.error().errors.at(0).message, HasSubstr("default-model"));
  EXPECT_EQ(*c.resolve_embedding_model(std::nullopt), "default-model");
  c.allowed_models = {"default-model", "llama3.1:8b"};
  EXPECT_EQ(*c.resolve_model("llama3.1:8b"), "llama3.1:8b");
  EXPECT_FALSE(c.resolve_model("").has_value());
  EXPECT_FALSE(c.resolve_model("a b").has_value());
  EXPECT_FALSE(c.resolve_model(std::string(201, 'm')).has_value());
  c.allowed_models = {"default-model"};
  auto refused = c.resolve_model("llama3.1:8b");
  ASSERT_FALSE(refused.has_value());
  EXPECT_EQ(refused.error().errors.at(0).pointer, "/model");
  EXPECT_THAT(refused.error().errors.at(0).message, HasSubstr("default-model"));
  LlmConfig none;
  EXPECT_EQ(none.resolve_model(std::nullopt).error().errors.at(0).pointer, "/model");
}

}  // namespace
}  // namespace socsim::llm
