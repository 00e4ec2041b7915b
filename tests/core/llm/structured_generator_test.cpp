// StructuredGenerator against a scripted server: answers that are valid, fenced, truncated, off
// schema or semantically wrong; repair rounds that quote the problems; the SQLite cache and the
// per-job call log.
#include "core/llm/structured_generator.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/llm/call_log.hpp"
#include "tests/core/llm/scripted_server.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::llm {
namespace {

using socsim::testing::ScriptedServer;
using ::testing::HasSubstr;

// A persona answer schema, small enough to read in a test.
const Json kPersonaSchema = Json::parse(R"({
  "type": "object",
  "required": ["name", "age", "gender", "occupation", "routine", "personality", "thoughts", "lifestyle"],
  "additionalProperties": false,
  "properties": {
    "name": {"type": "string", "minLength": 1},
    "age": {"type": "integer", "minimum": 18, "maximum": 90},
    "gender": {"type": "string"},
    "occupation": {"type": "string"},
    "routine": {"type": "string"},
    "personality": {"type": "array", "items": {"type": "string"}, "minItems": 3},
    "thoughts": {"type": "string"},
    "lifestyle": {"type": "string"}
  }
})");

const char* kAda = R"({"name": "Ada Okafor", "age": 34, "gender": "female", "occupation": "night-shift nurse",
  "routine": "Sleeps until early afternoon.", "personality": ["calm", "tidy", "curious"],
  "thoughts": "Saving for a trip.", "lifestyle": "Cooks in batches on Sundays."})";

Json ada_with(const char* pointer, const Json& value) {
  Json j = Json::parse(kAda);
  j[Json::json_pointer(pointer)] = value;
  return j;
}

class StructuredGeneratorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto s = store::Store::open(dir_.file("socsim.db"));
    ASSERT_TRUE(s.has_value()) << s.error().message();
    store_ = std::move(*s);
    LlmConfig config;
    config.base_url = server_.base_url();
    config.model = "test-model";
    config.connect_timeout_ms = 500;
    config.attempt_timeout_ms = 2000;
    config.deadline_ms = 4000;
    config.max_retries = 1;
    config.initial_backoff_ms = 10;
    config.max_backoff_ms = 50;
    auto c = LlmClient::create(config);
    ASSERT_TRUE(c.has_value()) << c.error().message();
    client_ = std::move(*c);
    auto schema = JsonSchema::compile(kPersonaSchema);
    ASSERT_TRUE(schema.has_value());
    schema_ = std::make_unique<JsonSchema>(std::move(*schema));
  }

  GenerationRequest persona_request(std::int64_t seed = 7) {
    GenerationRequest r;
    r.artifact = "persona";
    r.variables = {{"guidance", "a shift worker"}, {"existing_personas", "(none yet)"}};
    r.schema = schema_.get();
    r.seed = seed;
    r.temperature = 0.7;
    r.job_id = "job-1";
    return r;
  }

  // The repair message the server received in request `i` (its last user message).
  std::string last_user_message(std::size_t i) {
    const auto seen = server_.seen();
    const Json& messages = seen.at(i).body["messages"];
    return messages.back()["content"];
  }

  ScriptedServer server_;
  socsim::testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<LlmClient> client_;
  std::unique_ptr<JsonSchema> schema_;
};

TEST_F(StructuredGeneratorTest, AValidAnswerIsReturnedWithItsProvenance) {
  server_.push_chat(ScriptedServer::chat(kAda, "stop", 300, 90));
  StructuredGenerator gen(*client_, store_.get());
  auto g = gen.generate(persona_request());
  ASSERT_TRUE(g.has_value()) << g.error().message();
  EXPECT_EQ(g->value["name"], "Ada Okafor");
  EXPECT_EQ(g->calls.size(), 1u);
  const Json p = g->provenance();
  EXPECT_EQ(p["generator"], "llm");
  EXPECT_EQ(p["model"], "test-model");
  EXPECT_EQ(p["prompt_tokens"], 300);
  EXPECT_EQ(p["completion_tokens"], 90);
  EXPECT_EQ(p["cache_hits"], 0);
  EXPECT_EQ(p["prompt_hash"].get<std::string>().size(), 64u);

  // The request is the persona template, rendered.
  const auto seen = server_.seen();
  const Json& messages = seen[0].body["messages"];
  EXPECT_EQ(messages[0]["role"], "system");
  EXPECT_THAT(messages[0]["content"].get<std::string>(), HasSubstr("eight fields"));
  EXPECT_THAT(messages[1]["content"].get<std::string>(),
              HasSubstr("Guidance for this character: a shift worker"));
  EXPECT_EQ(seen[0].body["response_format"]["json_schema"]["name"], "persona");
}

TEST_F(StructuredGeneratorTest, FencedJsonWithProseAroundItIsAccepted) {
  server_.push_chat(
      ScriptedServer::chat(std::string("Here is the character:\n```json\n") + kAda + "\n```\nEnjoy!"));
  StructuredGenerator gen(*client_, store_.get());
  auto g = gen.generate(persona_request());
  ASSERT_TRUE(g.has_value()) << g.error().message();
  EXPECT_EQ(g->value["age"], 34);
}

TEST_F(StructuredGeneratorTest, TruncatedJsonIsRepaired) {
  const std::string ada = kAda;
  server_.push_chat(ScriptedServer::chat(ada.substr(0, ada.size() / 2), "length"));
  server_.push_chat(ScriptedServer::chat(kAda));
  StructuredGenerator gen(*client_, store_.get());
  auto g = gen.generate(persona_request());
  ASSERT_TRUE(g.has_value()) << g.error().message();
  EXPECT_EQ(g->calls.size(), 2u);
  EXPECT_EQ(g->calls[0].status, "invalid");
  const std::string repair = last_user_message(1);
  EXPECT_THAT(repair, HasSubstr("not valid JSON"));
  EXPECT_THAT(repair, HasSubstr("cut off at the token limit"));
  // The repair round carries the broken answer so the model can see what it wrote.
  const auto seen = server_.seen();
  const Json& messages = seen[1].body["messages"];
  EXPECT_EQ(messages[messages.size() - 2]["role"], "assistant");
}

TEST_F(StructuredGeneratorTest, ASchemaViolationIsRepairedOnTheSecondRound) {
  server_.push_chat(ScriptedServer::chat(ada_with("/age", 7).dump()));
  server_.push_chat(ScriptedServer::chat(kAda));
  StructuredGenerator gen(*client_, store_.get());
  auto g = gen.generate(persona_request());
  ASSERT_TRUE(g.has_value()) << g.error().message();
  EXPECT_EQ(g->value["age"], 34);
  const std::string repair = last_user_message(1);
  EXPECT_THAT(repair, HasSubstr("- /age: must be >= 18, got 7"));
}

TEST_F(StructuredGeneratorTest, SemanticRuleFailuresAreQuotedAndRepaired) {
  server_.push_chat(ScriptedServer::chat(ada_with("/personality", Json{"calm", "calm", "tidy"}).dump()));
  server_.push_chat(ScriptedServer::chat(kAda));
  GenerationRequest r = persona_request();
  r.check = [](const Json& persona) -> Status {
    const auto& traits = persona["personality"];
    for (std::size_t i = 0; i < traits.size(); ++i)
      for (std::size_t j = i + 1; j < traits.size(); ++j)
        if (traits[i] == traits[j])
          return fail(ErrorCode::kValidation, "repeated trait",
                      {FieldError{"/personality/" + std::to_string(j), "repeats trait " + traits[j].dump()}});
    return {};
  };
  StructuredGenerator gen(*client_, store_.get());
  auto g = gen.generate(r);
  ASSERT_TRUE(g.has_value()) << g.error().message();
  EXPECT_THAT(last_user_message(1), HasSubstr("- /personality/1: repeats trait \"calm\""));
}

TEST_F(StructuredGeneratorTest, AnAnswerThatNeverValidatesIsAValidationErrorNamingTheField) {
  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(ada_with("/age", "thirty").dump()));
  StructuredGenerator gen(*client_, store_.get());
  auto g = gen.generate(persona_request());
  ASSERT_FALSE(g.has_value());
  EXPECT_EQ(g.error().code, ErrorCode::kValidation);
  EXPECT_THAT(g.error().detail, HasSubstr("persona answer still failed its checks after 2 repair rounds"));
  EXPECT_THAT(g.error().detail, HasSubstr("/age: must be of type integer, got string"));
  ASSERT_EQ(g.error().errors.size(), 1u);
  EXPECT_EQ(g.error().errors[0].pointer, "/age");
  EXPECT_EQ(server_.count(), 3);  // first answer + 2 repair rounds, then stop

  // Nothing invalid was cached: the same request asks the endpoint again.
  server_.push_chat(ScriptedServer::chat(kAda));
  ASSERT_TRUE(gen.generate(persona_request()).has_value());
  EXPECT_EQ(server_.count(), 4);
}

TEST_F(StructuredGeneratorTest, ARepeatedRequestIsServedFromTheCacheAndLoggedAsAHit) {
  server_.push_chat(ScriptedServer::chat(kAda, "stop", 300, 90));
  StructuredGenerator gen(*client_, store_.get());
  auto first = gen.generate(persona_request());
  ASSERT_TRUE(first.has_value()) << first.error().message();
  auto second = gen.generate(persona_request());
  ASSERT_TRUE(second.has_value()) << second.error().message();
  EXPECT_EQ(server_.count(), 1);
  EXPECT_EQ(second->value, first->value);
  EXPECT_TRUE(second->calls[0].cache_hit);
  EXPECT_EQ(second->provenance()["prompt_tokens"], 0);
  EXPECT_EQ(second->prompt_hash, first->prompt_hash);

  auto record = job_llm_calls(*store_, "job-1");
  ASSERT_TRUE(record.has_value()) << record.error().message();
  const Json& calls = (*record)["calls"];
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[0]["cache_hit"], false);
  EXPECT_EQ(calls[0]["prompt_tokens"], 300);
  EXPECT_EQ(calls[0]["status"], "ok");
  EXPECT_EQ(calls[0]["artifact"], "persona");
  EXPECT_EQ(calls[0]["prompt"][1]["role"], "user");
  EXPECT_THAT(calls[0]["response"].get<std::string>(), HasSubstr("Ada Okafor"));
  EXPECT_EQ(calls[1]["cache_hit"], true);
  EXPECT_EQ(calls[1]["prompt_tokens"], 0);
  EXPECT_EQ((*record)["totals"]["cache_hits"], 1);
  EXPECT_EQ((*record)["totals"]["prompt_tokens"], 300);

  // Another seed is another request.
  server_.push_chat(ScriptedServer::chat(kAda));
  ASSERT_TRUE(gen.generate(persona_request(8)).has_value());
  EXPECT_EQ(server_.count(), 2);
}

TEST_F(StructuredGeneratorTest, ARepairedGenerationReplaysExactlyFromTheCache) {
  server_.push_chat(ScriptedServer::chat(ada_with("/age", 7).dump()));
  server_.push_chat(ScriptedServer::chat(kAda));
  StructuredGenerator gen(*client_, store_.get());
  auto first = gen.generate(persona_request());
  ASSERT_TRUE(first.has_value()) << first.error().message();
  auto replay = gen.generate(persona_request());
  ASSERT_TRUE(replay.has_value()) << replay.error().message();
  EXPECT_EQ(server_.count(), 2);
  EXPECT_EQ(replay->value, first->value);
  ASSERT_EQ(replay->calls.size(), 2u);
  EXPECT_TRUE(replay->calls[0].cache_hit);
  EXPECT_TRUE(replay->calls[1].cache_hit);
}

TEST_F(StructuredGeneratorTest, AnEndpointFailureIsAnUpstreamErrorAndIsLogged) {
  for (int i = 0; i < 2; ++i) server_.push_chat(ScriptedServer::error(500, "CUDA out of memory"));
  StructuredGenerator gen(*client_, store_.get());
  auto g = gen.generate(persona_request());
  ASSERT_FALSE(g.has_value());
  EXPECT_EQ(g.error().code, ErrorCode::kUpstream);
  EXPECT_THAT(g.error().detail, HasSubstr("generating persona"));
  EXPECT_THAT(g.error().detail, HasSubstr("HTTP 500: CUDA out of memory"));
  auto record = job_llm_calls(*store_, "job-1");
  ASSERT_TRUE(record.has_value());
  ASSERT_EQ((*record)["calls"].size(), 1u);
  EXPECT_EQ((*record)["calls"][0]["status"], "error");
  EXPECT_TRUE((*record)["calls"][0]["response"].is_null());
  EXPECT_THAT((*record)["calls"][0]["error"].get<std::string>(), HasSubstr("CUDA out of memory"));
}

TEST_F(StructuredGeneratorTest, WorksWithoutAStore) {
  server_.push_chat(ScriptedServer::chat(kAda));
  server_.push_chat(ScriptedServer::chat(kAda));
  StructuredGenerator gen(*client_, nullptr);
  ASSERT_TRUE(gen.generate(persona_request()).has_value());
  ASSERT_TRUE(gen.generate(persona_request()).has_value());
  EXPECT_EQ(server_.count(), 2);  // no cache
}

TEST_F(StructuredGeneratorTest, MisuseIsReportedNotSent) {
  StructuredGenerator gen(*client_, store_.get());
  GenerationRequest r = persona_request();
  r.variables.erase("guidance");
  auto missing = gen.generate(r);
  ASSERT_FALSE(missing.has_value());
  EXPECT_THAT(missing.error().detail, HasSubstr("{{guidance}}"));
  r = persona_request();
  r.artifact = "limerick";
  EXPECT_THAT(gen.generate(r).error().detail, HasSubstr("no prompt template named \"limerick\""));
  r = persona_request();
  r.model = "bad model name";
  EXPECT_EQ(gen.generate(r).error().errors.at(0).pointer, "/model");
  EXPECT_EQ(server_.count(), 0);
}

TEST(ExtractJsonAnswer, ReadsPlainFencedAndWrappedJson) {
  EXPECT_EQ(*extract_json_answer(R"( {"a": 1} )"), Json::parse(R"({"a": 1})"));
  EXPECT_EQ(*extract_json_answer("```json\n[1, 2]\n```"), Json::parse("[1, 2]"));
  EXPECT_EQ(*extract_json_answer("```\n{\"a\": 2}\n```"), Json::parse(R"({"a": 2})"));
  EXPECT_EQ(*extract_json_answer("Sure! {\"a\": {\"b\": 3}} Hope that helps."),
            Json::parse(R"({"a": {"b": 3}})"));
}

TEST(ExtractJsonAnswer, ReportsWhyNothingCouldBeRead) {
  auto empty = extract_json_answer("   ");
  ASSERT_FALSE(empty.has_value());
  EXPECT_THAT(empty.error().detail, HasSubstr("empty"));
  auto cut = extract_json_answer("{\"a\": [1, 2,\n  3");
  ASSERT_FALSE(cut.has_value());
  EXPECT_EQ(cut.error().code, ErrorCode::kValidation);
  EXPECT_THAT(cut.error().detail, HasSubstr("not valid JSON"));
  ASSERT_FALSE(cut.error().errors.empty());
  EXPECT_EQ(cut.error().errors[0].line, 2);
  auto deep = extract_json_answer(std::string(500, '[') + std::string(500, ']'));
  EXPECT_FALSE(deep.has_value());  // nesting limit of parse_json_untrusted
}

}  // namespace
}  // namespace socsim::llm
