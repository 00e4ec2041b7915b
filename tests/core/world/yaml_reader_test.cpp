// Strict YAML reading: scalar typing, positions by JSON pointer, and refusal of anchors,
// aliases (alias bombs), tags, duplicate keys, extra documents, oversize input and deep nesting.
#include "core/world/yaml_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::world {
namespace {

using ::testing::HasSubstr;

TEST(YamlReader, PlainScalarsAreTypedQuotedOnesAreStrings) {
  auto j =
      parse_yaml_untrusted("a: 3\nb: 2.5\nc: \"2.5\"\nd: true\ne: ~\nf: canteen\ng: 1e-3\nh: 'yes'\ni: -7\n");
  ASSERT_TRUE(j) << j.error().message();
  EXPECT_TRUE((*j)["a"].is_number_integer());
  EXPECT_DOUBLE_EQ((*j)["b"].get<double>(), 2.5);
  EXPECT_EQ((*j)["c"], "2.5");
  EXPECT_EQ((*j)["d"], true);
  EXPECT_TRUE((*j)["e"].is_null());
  EXPECT_EQ((*j)["f"], "canteen");
  EXPECT_DOUBLE_EQ((*j)["g"].get<double>(), 0.001);
  EXPECT_EQ((*j)["h"], "yes");
  EXPECT_EQ((*j)["i"], -7);
}

TEST(YamlReader, PositionsAreRecordedPerPointer) {
  SourcePositions pos;
  auto j = parse_yaml_untrusted("zones:\n  - name: hall\n    polygon: [[0, 0], [1, 0]]\n", &pos);
  ASSERT_TRUE(j);
  EXPECT_EQ(pos.find("/zones/0/name"), (std::pair{2, 11}));
  EXPECT_EQ(pos.find("/zones/0/polygon/1/0"), (std::pair{3, 24}));
  // A missing field is placed where its object starts.
  EXPECT_EQ(pos.find("/zones/0/type"), (std::pair{2, 5}));
}

TEST(YamlReader, AnchorsAndAliasesAreRefusedWithTheirLine) {
  auto j = parse_yaml_untrusted("a: &x [1, 2]\nb: *x\n");
  ASSERT_FALSE(j);
  EXPECT_EQ(j.error().code, ErrorCode::kBadRequest);
  EXPECT_THAT(j.error().detail, HasSubstr("anchors and aliases are not allowed"));
  EXPECT_EQ(j.error().errors.at(0).line, 1);
}

TEST(YamlReader, AliasBombIsRefusedQuickly) {
  // The classic "billion laughs": each level repeats the previous nine times.
  std::string bomb = "a: &a [\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\"]\n";
  for (char c = 'b'; c <= 'i'; ++c) {
    const char prev = static_cast<char>(c - 1);
    bomb += std::string(1, c) + ": &" + c + " [";
    for (int k = 0; k < 9; ++k) bomb += std::string(k ? "," : "") + "*" + prev;
    bomb += "]\n";
  }
  auto j = parse_yaml_untrusted(bomb);
  ASSERT_FALSE(j);
  EXPECT_THAT(j.error().detail, HasSubstr("anchors and aliases"));
}

TEST(YamlReader, NodeCountAndSizeAreCapped) {
  std::string many = "[";
  for (int i = 0; i < 2000; ++i) many += "0,";
  many += "0]";
  auto j = parse_yaml_untrusted(many, nullptr, YamlLimits{1 << 20, 1000});
  ASSERT_FALSE(j);
  EXPECT_THAT(j.error().detail, HasSubstr("more than 1000 nodes"));
  auto big = parse_yaml_untrusted(std::string(100, 'x'), nullptr, YamlLimits{50, 1000});
  ASSERT_FALSE(big);
  EXPECT_EQ(big.error().code, ErrorCode::kPayloadTooLarge);
}

TEST(YamlReader, DeepNestingIsAnErrorNotACrash) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  auto j = parse_yaml_untrusted(deep);
  ASSERT_FALSE(j);
  EXPECT_EQ(j.error().code, ErrorCode::kBadRequest);
}

TEST(YamlReader, TagsDuplicateKeysAndSecondDocumentsAreRefused) {
  auto tagged = parse_yaml_untrusted("a: !!python/object x\n");
  ASSERT_FALSE(tagged);
  EXPECT_THAT(tagged.error().detail, HasSubstr("tags are not supported"));
  auto dup = parse_yaml_untrusted("a: 1\nb: 2\na: 3\n");
  ASSERT_FALSE(dup);
  EXPECT_THAT(dup.error().detail, HasSubstr("duplicate key 'a' (line 3, column 1)"));
  auto two = parse_yaml_untrusted("a: 1\n---\nb: 2\n");
  ASSERT_FALSE(two);
  EXPECT_THAT(two.error().detail, HasSubstr("only one YAML document"));
  auto complex_key = parse_yaml_untrusted("? [a, b]\n: 1\n");
  ASSERT_FALSE(complex_key);
  EXPECT_THAT(complex_key.error().detail, HasSubstr("only plain text keys"));
}

TEST(YamlReader, NonFiniteNumbersAndSyntaxErrorsNameTheirPlace) {
  auto inf = parse_yaml_untrusted("x: 1\ny: .inf\n");
  ASSERT_FALSE(inf);
  EXPECT_THAT(inf.error().detail, HasSubstr("'.inf' is not a finite number (line 2, column 4)"));
  auto bad = parse_yaml_untrusted("zones:\n  - name: a\n    polygon: [[0, 0], [1, 0]\n");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().code, ErrorCode::kBadRequest);
  EXPECT_GT(bad.error().errors.at(0).line, 0);
}

TEST(YamlReader, EmptyTextIsNull) {
  auto j = parse_yaml_untrusted("# only a comment\n");
  ASSERT_TRUE(j);
  EXPECT_TRUE(j->is_null());
}

}  // namespace
}  // namespace socsim::world
