// LlmClient against a scripted OpenAI-compatible server over real HTTP on 127.0.0.1: answers,
// timeouts, 429 with Retry-After, 5xx, dropped connections, response_format fallback, redirects,
// size limits, cancellation, the concurrency limit and embeddings.
#include "core/llm/llm_client.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/core/llm/scripted_server.hpp"

namespace socsim::llm {
namespace {

using socsim::testing::ScriptedServer;
using ::testing::HasSubstr;
using Clock = std::chrono::steady_clock;

std::int64_t ms_since(Clock::time_point t) {
  return std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - t).count();
}

// Small timeouts and back-offs so the whole file runs in a few seconds.
LlmConfig quick_config(const std::string& url) {
  LlmConfig c;
  c.base_url = url;
  c.model = "test-model";
  c.api_key = "sk-test";
  c.connect_timeout_ms = 500;
  c.attempt_timeout_ms = 2000;
  c.stall_timeout_ms = 2000;
  c.deadline_ms = 5000;
  c.max_retries = 2;
  c.initial_backoff_ms = 20;
  c.max_backoff_ms = 100;
  c.max_retry_after_s = 5;
  return c;
}

std::unique_ptr<LlmClient> client_for(const LlmConfig& config) {
  auto c = LlmClient::create(config);
  EXPECT_TRUE(c.has_value()) << (c ? "" : c.error().message());
  return std::move(*c);
}

ChatRequest hello() {
  ChatRequest r;
  r.messages = {{"system", "You are terse."}, {"user", "Say hi as JSON."}};
  r.temperature = 0.3;
  r.seed = 42;
  r.response_schema = ResponseSchema{"greeting", Json::parse(R"({"type": "object", "required": ["text"]})")};
  return r;
}

TEST(LlmClient, SendsAnOpenAiChatRequestAndReadsTheAnswer) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::chat(R"({"text": "hi"})", "stop", 31, 7));
  auto client = client_for(quick_config(server.base_url() + "/v1/"));  // trailing /v1/ is normalised away
  auto answer = client->chat(hello());
  ASSERT_TRUE(answer.has_value()) << answer.error().message();
  EXPECT_EQ(answer->content, R"({"text": "hi"})");
  EXPECT_EQ(answer->finish_reason, "stop");
  EXPECT_EQ(answer->usage.prompt_tokens, 31);
  EXPECT_EQ(answer->usage.completion_tokens, 7);
  EXPECT_EQ(answer->attempts, 1);
  EXPECT_TRUE(answer->structured_output);
  EXPECT_GE(answer->latency_ms, 0);

  const auto seen = server.seen();
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].path, "/v1/chat/completions");
  EXPECT_EQ(seen[0].authorization, "Bearer sk-test");
  const Json& body = seen[0].body;
  EXPECT_EQ(body["model"], "test-model");
  EXPECT_EQ(body["seed"], 42);
  EXPECT_DOUBLE_EQ(body["temperature"].get<double>(), 0.3);
  EXPECT_EQ(body["messages"].size(), 2u);
  EXPECT_EQ(body["messages"][1]["content"], "Say hi as JSON.");
  EXPECT_EQ(body["response_format"]["type"], "json_schema");
  EXPECT_EQ(body["response_format"]["json_schema"]["name"], "greeting");
  EXPECT_EQ(body["response_format"]["json_schema"]["schema"]["required"][0], "text");
}

TEST(LlmClient, ASlowAnswerFailsWithinTheDeadline) {
  ScriptedServer server;
  for (int i = 0; i < 3; ++i) server.push_chat(ScriptedServer::delayed(ScriptedServer::chat("{}"), 3000));
  auto config = quick_config(server.base_url());
  config.attempt_timeout_ms = 300;
  config.deadline_ms = 700;
  auto client = client_for(config);
  const auto start = Clock::now();
  auto answer = client->chat(hello());
  const auto elapsed = ms_since(start);
  ASSERT_FALSE(answer.has_value());
  EXPECT_EQ(answer.error().code, ErrorCode::kUpstreamTimeout);
  EXPECT_THAT(answer.error().detail, HasSubstr("no answer within"));
  EXPECT_THAT(answer.error().detail, HasSubstr(server.base_url()));
  EXPECT_GE(elapsed, 300);
  EXPECT_LE(elapsed, 700 + 250);  // deadline + scheduling margin
}

TEST(LlmClient, RateLimitHonoursRetryAfterThenSucceeds) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::error(429, "slow down", {{"Retry-After", "1"}}));
  server.push_chat(ScriptedServer::chat(R"({"text": "hi"})"));
  auto client = client_for(quick_config(server.base_url()));
  const auto start = Clock::now();
  auto answer = client->chat(hello());
  ASSERT_TRUE(answer.has_value()) << answer.error().message();
  EXPECT_GE(ms_since(start), 1000);  // waited as told, not the 20 ms back-off
  EXPECT_EQ(answer->attempts, 2);
  EXPECT_EQ(server.count(), 2);
}

TEST(LlmClient, ARetryAfterLongerThanWeWaitFailsAtOnce) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::error(429, "quota exceeded", {{"Retry-After", "3600"}}));
  auto client = client_for(quick_config(server.base_url()));
  const auto start = Clock::now();
  auto answer = client->chat(hello());
  ASSERT_FALSE(answer.has_value());
  EXPECT_LT(ms_since(start), 500);
  EXPECT_EQ(answer.error().code, ErrorCode::kUpstream);
  EXPECT_THAT(answer.error().detail, HasSubstr("HTTP 429: quota exceeded"));
  EXPECT_THAT(answer.error().detail, HasSubstr("Retry-After 3600 s"));
}

TEST(LlmClient, ServerErrorIsRetriedThenSucceeds) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::error(500, "model crashed"));
  server.push_chat(ScriptedServer::chat(R"({"text": "hi"})"));
  auto client = client_for(quick_config(server.base_url()));
  auto answer = client->chat(hello());
  ASSERT_TRUE(answer.has_value()) << answer.error().message();
  EXPECT_EQ(answer->attempts, 2);
}

TEST(LlmClient, ExhaustedRetriesNameTheEndpointsError) {
  ScriptedServer server;
  for (int i = 0; i < 3; ++i) server.push_chat(ScriptedServer::error(503, "overloaded, try later"));
  auto client = client_for(quick_config(server.base_url()));
  auto answer = client->chat(hello());
  ASSERT_FALSE(answer.has_value());
  EXPECT_EQ(answer.error().code, ErrorCode::kUpstream);
  EXPECT_THAT(answer.error().detail, HasSubstr("HTTP 503: overloaded, try later"));
  EXPECT_THAT(answer.error().detail, HasSubstr("gave up after 3 attempts"));
  EXPECT_EQ(server.count(), 3);  // 1 + max_retries, no more
}

TEST(LlmClient, ClientErrorsAreNotRetried) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::error(401, "invalid api key"));
  auto config = quick_config(server.base_url());
  config.structured_output = StructuredOutput::kOff;
  auto client = client_for(config);
  auto answer = client->chat(hello());
  ASSERT_FALSE(answer.has_value());
  EXPECT_THAT(answer.error().detail, HasSubstr("HTTP 401: invalid api key"));
  EXPECT_EQ(server.count(), 1);
}

TEST(LlmClient, AConnectionDroppedMidAnswerIsRetried) {
  ScriptedServer server;
  auto dropped = ScriptedServer::chat(R"({"text": "hi"})");
  dropped.drop_midway = true;
  server.push_chat(dropped);
  server.push_chat(ScriptedServer::chat(R"({"text": "hi"})"));
  auto client = client_for(quick_config(server.base_url()));
  auto answer = client->chat(hello());
  ASSERT_TRUE(answer.has_value()) << answer.error().message();
  EXPECT_EQ(answer->attempts, 2);
}

TEST(LlmClient, RejectedResponseFormatFallsBackToAnInstructionAndIsRemembered) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::error(400, "unknown field: response_format"));
  server.push_chat(ScriptedServer::chat(R"({"text": "hi"})"));
  server.push_chat(ScriptedServer::chat(R"({"text": "again"})"));
  auto client = client_for(quick_config(server.base_url()));
  auto answer = client->chat(hello());
  ASSERT_TRUE(answer.has_value()) << answer.error().message();
  EXPECT_FALSE(answer->structured_output);
  EXPECT_FALSE(client->structured_output_available());

  const auto seen = server.seen();
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_TRUE(seen[0].body.contains("response_format"));
  EXPECT_FALSE(seen[1].body.contains("response_format"));
  const std::string system = seen[1].body["messages"][0]["content"];
  EXPECT_THAT(system, HasSubstr("You are terse."));
  EXPECT_THAT(system, HasSubstr("Answer with exactly one JSON value"));
  EXPECT_THAT(system, HasSubstr("\"required\""));  // the schema itself is quoted

  ASSERT_TRUE(client->chat(hello()).has_value());
  EXPECT_FALSE(server.seen()[2].body.contains("response_format"));  // not tried again
}

TEST(LlmClient, AnEndpointThatIsDownFailsFastNamingTheError) {
  int port = 0;
  {
    ScriptedServer gone;  // bind a free port, then release it: nothing listens there any more
    port = gone.port();
  }
  auto client = client_for(quick_config("http://127.0.0.1:" + std::to_string(port)));
  const auto start = Clock::now();
  auto answer = client->chat(hello());
  ASSERT_FALSE(answer.has_value());
  EXPECT_LE(ms_since(start), 500);  // within the connect timeout: refused is not retried
  EXPECT_EQ(answer.error().code, ErrorCode::kUpstream);
  EXPECT_THAT(answer.error().detail, HasSubstr("127.0.0.1:" + std::to_string(port)));
  EXPECT_THAT(answer.error().detail,
              HasSubstr("onnect"));  // "Failed to connect … Couldn't connect to server"
  EXPECT_EQ(answer.error().to_problem()["status"], 502);
}

TEST(LlmClient, CancellationStopsACallInFlight) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::delayed(ScriptedServer::chat("{}"), 5000));
  auto client = client_for(quick_config(server.base_url()));
  ChatRequest request = hello();
  std::thread canceller([token = request.cancel] {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    token.cancel();
  });
  const auto start = Clock::now();
  auto answer = client->chat(request);
  canceller.join();
  ASSERT_FALSE(answer.has_value());
  EXPECT_THAT(answer.error().detail, HasSubstr("cancelled"));
  EXPECT_LT(ms_since(start), 600);
}

TEST(LlmClient, CancellationStopsARetryAfterWait) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::error(429, "slow down", {{"Retry-After", "4"}}));
  auto client = client_for(quick_config(server.base_url()));
  ChatRequest request = hello();
  std::thread canceller([token = request.cancel] {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    token.cancel();
  });
  const auto start = Clock::now();
  auto answer = client->chat(request);
  canceller.join();
  ASSERT_FALSE(answer.has_value());
  EXPECT_THAT(answer.error().detail, HasSubstr("cancelled"));
  EXPECT_LT(ms_since(start), 600);
  EXPECT_EQ(server.count(), 1);
}

TEST(LlmClient, ConcurrentCallsAreLimited) {
  ScriptedServer server;
  for (int i = 0; i < 5; ++i)
    server.push_chat(ScriptedServer::delayed(ScriptedServer::chat(R"({"text": "hi"})"), 150));
  auto config = quick_config(server.base_url());
  config.max_concurrency = 2;
  auto client = client_for(config);
  std::vector<std::thread> threads;
  std::atomic<int> ok{0};
  for (int i = 0; i < 5; ++i)
    threads.emplace_back([&] {
      if (client->chat(hello()).has_value()) ++ok;
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(ok.load(), 5);
  EXPECT_EQ(server.max_in_flight(), 2);
}

TEST(LlmClient, RedirectsToAnotherOriginAreRefusedAndSameOriginOnesFollowed) {
  ScriptedServer server;
  const std::string other_origin =
      "http://localhost:" + std::to_string(server.port()) + "/v1/chat/completions";
  server.push_chat(ScriptedServer::Step{307, "", {{"Location", other_origin}}, 0, false});
  auto client = client_for(quick_config(server.base_url()));
  auto refused = client->chat(hello());
  ASSERT_FALSE(refused.has_value());
  EXPECT_THAT(refused.error().detail, HasSubstr("another origin"));
  EXPECT_EQ(server.count(), 1);

  server.push_chat(ScriptedServer::Step{308, "", {{"Location", "/moved/v1/chat/completions"}}, 0, false});
  server.push("/moved/v1/chat/completions", ScriptedServer::chat(R"({"text": "moved"})"));
  auto followed = client->chat(hello());
  ASSERT_TRUE(followed.has_value()) << followed.error().message();
  EXPECT_EQ(followed->content, R"({"text": "moved"})");
  EXPECT_EQ(server.seen().back().path, "/moved/v1/chat/completions");
  EXPECT_TRUE(server.seen().back().body.contains("messages"));  // still a POST with its body
}

TEST(LlmClient, AnOversizedResponseIsRefused) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::chat(std::string(64 * 1024, 'x')));
  auto config = quick_config(server.base_url());
  config.max_response_bytes = 16 * 1024;
  auto client = client_for(config);
  auto answer = client->chat(hello());
  ASSERT_FALSE(answer.has_value());
  EXPECT_THAT(answer.error().detail, HasSubstr("larger than 16384 bytes"));
}

TEST(LlmClient, ABodyThatIsNotAChatCompletionIsAnUpstreamError) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::Step{200, R"({"object": "list", "data": []})", {}, 0, false});
  server.push_chat(ScriptedServer::Step{200, "<html>proxy login</html>", {}, 0, false});
  auto client = client_for(quick_config(server.base_url()));
  auto a = client->chat(hello());
  ASSERT_FALSE(a.has_value());
  EXPECT_THAT(a.error().detail, HasSubstr("not a chat completion: no choices[]"));
  auto b = client->chat(hello());
  ASSERT_FALSE(b.has_value());
  EXPECT_THAT(b.error().detail, HasSubstr("not JSON"));
}

TEST(LlmClient, ModelMayBeChosenPerRequestButOnlyByAPlausibleName) {
  ScriptedServer server;
  server.push_chat(ScriptedServer::chat(R"({"text": "hi"})"));
  auto config = quick_config(server.base_url());
  config.allowed_models = {"test-model", "meta-llama/Llama-3.1-8B-Instruct"};
  auto client = client_for(config);
  ChatRequest r = hello();
  r.model = "meta-llama/Llama-3.1-8B-Instruct";
  ASSERT_TRUE(client->chat(r).has_value());
  EXPECT_EQ(server.seen()[0].body["model"], "meta-llama/Llama-3.1-8B-Instruct");

  r.model = "gpt-4o";
  auto not_allowed = client->chat(r);
  ASSERT_FALSE(not_allowed.has_value());
  EXPECT_EQ(not_allowed.error().code, ErrorCode::kValidation);
  EXPECT_EQ(not_allowed.error().errors.at(0).pointer, "/model");
  r.model = "http://evil.example/v1";
  auto bad = client->chat(r);
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().code, ErrorCode::kValidation);
  EXPECT_EQ(server.count(), 1);  // neither reached the endpoint
}

TEST(LlmClient, EmbeddingsComeBackInInputOrder) {
  ScriptedServer server;
  const Json body = {
      {"object", "list"},
      {"data",
       {{{"index", 1}, {"embedding", {0.0, 1.0, 0.5}}}, {{"index", 0}, {"embedding", {1.0, 0.0, 0.25}}}}},
      {"usage", {{"prompt_tokens", 9}, {"total_tokens", 9}}}};
  server.push("/v1/embeddings", ScriptedServer::Step{200, body.dump(), {}, 0, false});
  auto config = quick_config(server.base_url());
  config.embedding_model = "embed-small";
  auto client = client_for(config);
  EmbeddingRequest r;
  r.inputs = {"patient bedroom", "queue at counter"};
  auto e = client->embed(r);
  ASSERT_TRUE(e.has_value()) << e.error().message();
  ASSERT_EQ(e->vectors.size(), 2u);
  EXPECT_EQ(e->vectors[0], (std::vector<float>{1.0f, 0.0f, 0.25f}));
  EXPECT_EQ(e->vectors[1], (std::vector<float>{0.0f, 1.0f, 0.5f}));
  EXPECT_EQ(e->usage.prompt_tokens, 9);
  EXPECT_EQ(e->model, "embed-small");
  const auto seen = server.seen();
  EXPECT_EQ(seen[0].path, "/v1/embeddings");
  EXPECT_EQ(seen[0].body["model"], "embed-small");
  EXPECT_EQ(seen[0].body["input"][1], "queue at counter");
}

TEST(LlmClient, EmbeddingAnswersThatDoNotFitTheInputsAreRefused) {
  ScriptedServer server;
  server.push("/v1/embeddings",
              ScriptedServer::Step{200, R"({"data": [{"index": 0, "embedding": [1, 2]}]})", {}, 0, false});
  server.push(
      "/v1/embeddings",
      ScriptedServer::Step{200,
                           R"({"data": [{"index": 0, "embedding": [1, 2]}, {"index": 1, "embedding": [1]}]})",
                           {},
                           0,
                           false});
  auto client = client_for(quick_config(server.base_url()));
  EmbeddingRequest r;
  r.inputs = {"a", "b"};
  auto short_answer = client->embed(r);
  ASSERT_FALSE(short_answer.has_value());
  EXPECT_THAT(short_answer.error().detail, HasSubstr("1 embeddings for 2 inputs"));
  auto ragged = client->embed(r);
  ASSERT_FALSE(ragged.has_value());
  EXPECT_THAT(ragged.error().detail, HasSubstr("different lengths"));
}

TEST(LlmClient, RefusesToStartWithoutAUsableEndpoint) {
  LlmConfig none;
  auto a = LlmClient::create(none);
  ASSERT_FALSE(a.has_value());
  EXPECT_EQ(a.error().errors.at(0).parameter, "SOCSIM_LLM_URL");
  LlmConfig ftp;
  ftp.base_url = "ftp://example.com";
  auto b = LlmClient::create(ftp);
  ASSERT_FALSE(b.has_value());
  EXPECT_THAT(b.error().detail, HasSubstr("http or https"));
}

}  // namespace
}  // namespace socsim::llm
