// Untrusted JSON: positions in syntax errors, the depth limit, and canonical bytes.
#include "core/common/json_io.hpp"
#include "core/common/json_check.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace socsim {

TEST(JsonIo, SyntaxErrorNamesLineAndColumn) {
  auto r = parse_json_untrusted("{\n  \"a\": 1,\n  \"b\": ]\n}");
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kBadRequest);
  ASSERT_EQ(r.error().errors.size(), 1u);
  EXPECT_EQ(r.error().errors[0].line, 3);
  EXPECT_EQ(r.error().errors[0].column, 8);
  EXPECT_NE(r.error().detail.find("line 3"), std::string::npos);
}

TEST(JsonIo, DeepNestingIsRejectedNotCrashing) {
  std::string deep(200000, '[');
  deep += std::string(200000, ']');
  auto r = parse_json_untrusted(deep);
  ASSERT_FALSE(r.has_value());
  EXPECT_NE(r.error().detail.find("nesting"), std::string::npos);
  std::string ok(64, '[');
  ok += std::string(64, ']');
  EXPECT_TRUE(parse_json_untrusted(ok).has_value());
  std::string over(65, '[');
  over += std::string(65, ']');
  EXPECT_FALSE(parse_json_untrusted(over).has_value());
}

// Issue 14 #12: nlohmann keeps the last of two equal keys, so a body could carry one value for
// a validator that reads the first and another for whatever reads the last.
TEST(JsonIo, DuplicateKeysAreRefusedWithTheirPointer) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"a": 1, "a": 2})", "/a"},
      {R"({"a": {"b": [1, {"c": 1, "d": 2, "c": 3}]}})", "/a/b/1/c"},
      {R"([{"x": 1}, {"x": 1, "y/z": 2, "y/z": 3}])", "/1/y~1z"},
      {R"({"s": [[], {}, 3, {"k": 0, "k": 0}]})", "/s/3/k"}};
  for (const auto& [text, pointer] : cases) {
    auto r = parse_json_untrusted(text);
    ASSERT_FALSE(r.has_value()) << text;
    EXPECT_EQ(r.error().code, ErrorCode::kBadRequest);
    ASSERT_EQ(r.error().errors.size(), 1u);
    EXPECT_EQ(r.error().errors[0].pointer, pointer) << text;
  }
  // The same key in different objects is fine.
  EXPECT_TRUE(parse_json_untrusted(R"({"a": {"k": 1}, "b": {"k": 1}, "c": [{"k": 1}, {"k": 2}]})"));
}

// Found by tests/server/bad_input_property_test.cpp: nlohmann throws out_of_range (not
// parse_error) for a number beyond a double, which reached the request boundary as a 500.
TEST(JsonIo, NumbersBeyondADoubleAre400WithTheirPointer) {
  for (const std::string& n : std::vector<std::string>{"1e400", "-1e400", std::string(400, '9')}) {
    auto r = parse_json_untrusted(R"({"a": [1, {"b": )" + n + "}]}");
    ASSERT_FALSE(r.has_value()) << n;
    EXPECT_EQ(r.error().code, ErrorCode::kBadRequest);
    EXPECT_EQ(r.error().errors.at(0).pointer, "/a/1/b");
  }
  auto top = parse_json_untrusted("[0, 1e999]");
  ASSERT_FALSE(top.has_value());
  EXPECT_EQ(top.error().errors.at(0).pointer, "/1");
  EXPECT_TRUE(parse_json_untrusted("1e308").has_value());
}

TEST(JsonIo, CanonicalFormSortsKeysAndRoundTrips) {
  auto a = parse_json_untrusted(R"({"b": [1, 2.5, 0.1], "a": {"y": "é", "x": null}})");
  auto b = parse_json_untrusted(R"({"a":{"x":null,"y":"é"},"b":[1,2.5,0.1]})");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(canonical_json(*a), canonical_json(*b));
  EXPECT_EQ(canonical_json(*a), R"({"a":{"x":null,"y":"é"},"b":[1,2.5,0.1]})");
  auto again = parse_json_untrusted(canonical_json(*a));
  EXPECT_EQ(canonical_json(*again), canonical_json(*a));
}

// Found by tests/fuzz (program_json, card_import, procthor_json): nlohmann throws out_of_range,
// not parse_error, for a number literal beyond double; it escaped every JSON reader.
TEST(JsonIo, NumberBeyondDoubleIsABadRequestWithItsPosition) {
  auto r = parse_json_untrusted("{\"agents\": [{\"speed\":\n 1e400}]}");
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kBadRequest);
  ASSERT_EQ(r.error().errors.size(), 1u);
  EXPECT_EQ(r.error().errors[0].line, 2);
  EXPECT_EQ(r.error().errors[0].column, 2);
  EXPECT_NE(r.error().errors[0].message.find("1e400"), std::string::npos);
  EXPECT_FALSE(parse_json_untrusted("-1E+999999999999").has_value());
  EXPECT_TRUE(parse_json_untrusted("[1.7976931348623157e308, 18446744073709551616]").has_value());
}

TEST(JsonIo, InvalidUtf8IsASyntaxError) {
  EXPECT_FALSE(parse_json_untrusted("{\"a\": \"\xff\"}").has_value());
}

TEST(JsonChecker, CollectsEveryBadFieldWithPointer) {
  auto j = parse_json_untrusted(R"({"title": 5, "tags": "x", "seed": -1, "extra/key": true})");
  ASSERT_TRUE(j);
  JsonChecker c;
  c.only_keys(*j, "", {"title", "tags", "seed", "prompt"});
  c.string(*j, "", "title", true);
  c.array(*j, "", "tags", false);
  c.integer(*j, "", "seed", true, 0);
  c.string(*j, "", "prompt", true);
  ASSERT_EQ(c.errors().size(), 5u);
  std::vector<std::string> ptrs;
  for (const auto& e : c.errors()) ptrs.push_back(e.pointer);
  EXPECT_EQ(ptrs, (std::vector<std::string>{"/extra~1key", "/title", "/tags", "/seed", "/prompt"}));
}

}  // namespace socsim
