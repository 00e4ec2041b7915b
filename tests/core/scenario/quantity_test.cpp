// Quantities as prompts state them: digits and thousands separators, cardinal words up to the
// thousands, dozens, ranges, approximations, bounds and the documented ranges of vague words.
#include "core/scenario/quantity.hpp"

#include <gtest/gtest.h>

namespace socsim::scenario {
namespace {

Count read_count(const std::string& text) {
  const auto t = tokenize_text(text);
  auto q = quantity_at(t, 0);
  if (!q) return Count{};
  return q->count;
}

void expect_exact(const std::string& text, double v) {
  const Count c = read_count(text);
  EXPECT_EQ(c.kind, CountKind::kExact) << text;
  EXPECT_EQ(c.value, v) << text;
}

void expect_range(const std::string& text, double lo, double hi, CountKind kind = CountKind::kRange) {
  SCOPED_TRACE(text);
  const Count c = read_count(text);
  EXPECT_EQ(c.kind, kind) << text;
  EXPECT_EQ(c.min, lo) << text;
  EXPECT_EQ(c.max, hi) << text;
}

TEST(Quantity, DigitsAndWords) {
  expect_exact("12 patients", 12);
  expect_exact("1,500 fans", 1500);
  expect_exact("twelve patients", 12);
  expect_exact("seventy-five children", 75);
  expect_exact("twenty five pupils", 25);
  expect_exact("one hundred delegates", 100);
  expect_exact("a hundred guests", 100);
  expect_exact("two hundred and fifty pupils", 250);
  expect_exact("two thousand fans", 2000);
  expect_exact("a thousand passengers", 1000);
  expect_exact("three thousand four hundred and twelve runners", 3412);
  expect_exact("2 thousand fans", 2000);
}

TEST(Quantity, Dozens) {
  expect_exact("a dozen nurses", 12);
  expect_exact("two dozen mourners", 24);
  expect_exact("half a dozen guards", 6);
  expect_range("dozens of students", 24, 60);
  expect_range("hundreds of commuters", 200, 500);
  expect_range("thousands of fans", 2000, 5000);
}

TEST(Quantity, VagueWordsMapToDocumentedRanges) {
  expect_range("a couple of colleagues", 2, 3);
  expect_range("a few teachers", 3, 5);
  expect_range("a handful of fans", 3, 6);
  expect_range("several nurses", 4, 7);
  expect_range("some visitors", 3, 8);
  expect_range("many shoppers", 10, 30);
  expect_range("lots of people", 10, 30);
  expect_range("a group of tourists", 3, 8);
  expect_range("a crowd of fans", 30, 80);
}

TEST(Quantity, Ranges) {
  expect_range("between 20 and 30 visitors", 20, 30);
  expect_range("between twenty and thirty visitors", 20, 30);
  expect_range("from 20 to 30 visitors", 20, 30);
  expect_range("20-30 visitors", 20, 30);
  expect_range(
      "20\xE2\x80\x93"
      "30 visitors",
      20, 30);  // en dash
  expect_range("20 to 30 visitors", 20, 30);
  expect_range("two or three nurses", 2, 3);
}

TEST(Quantity, ApproximationsHoldWithinTenPercent) {
  for (const std::string text :
       {"about 200 people", "around 200 people", "roughly 200 people", "approximately 200 people",
        "nearly 200 people", "some 200 people", "200 or so people", "about two hundred people"}) {
    const Count c = read_count(text);
    EXPECT_EQ(c.kind, CountKind::kApprox) << text;
    EXPECT_EQ(c.value, 200) << text;
    EXPECT_EQ(c.min, 180) << text;
    EXPECT_EQ(c.max, 220) << text;
  }
}

TEST(Quantity, BoundsAndExactness) {
  expect_range("at least 40 people", 40, 50);
  expect_range("more than 40 people", 41, 50);
  expect_range("up to 40 people", 20, 40);
  expect_exact("exactly forty people", 40);
  expect_exact("a group of 15 tourists", 15);
  expect_exact("a crowd of 400 fans", 400);
}

TEST(Quantity, ArticlesAndTimesAreNoCounts) {
  const auto t = tokenize_text("a nurse");
  EXPECT_FALSE(quantity_at(t, 0));
  const auto u = tokenize_text("9am");
  EXPECT_FALSE(quantity_at(u, 0));  // digits glued to letters make a word
}

TEST(Quantity, ProductsAndSums) {
  Count c = Count::exact(25);
  c.times(2);
  EXPECT_EQ(c.kind, CountKind::kExact);
  EXPECT_EQ(c.value, 50);
  Count a = Count::approx(100);
  a.plus(Count::exact(2));
  EXPECT_EQ(a.kind, CountKind::kApprox);
  EXPECT_EQ(a.value, 102);
  Count u;
  u.plus(Count::exact(2));
  EXPECT_FALSE(u.specified());
}

TEST(Tokens, SpansPossessivesAndSentences) {
  const std::string text = "The hospital's ward: nurses' station, 1,500 fans.";
  const auto t = tokenize_text(text);
  ASSERT_GE(t.size(), 8u);
  EXPECT_EQ(t[1].text, "hospital");
  EXPECT_TRUE(t[1].possessive);
  EXPECT_EQ(text.substr(t[1].span.begin, t[1].span.end - t[1].span.begin), "hospital's");
  EXPECT_EQ(t[4].text, "nurses");
  EXPECT_TRUE(t[4].possessive);
  EXPECT_GT(t[4].sentence, t[1].sentence);  // the colon ends a clause
  const auto n =
      std::find_if(t.begin(), t.end(), [](const TextToken& x) { return x.kind == TextToken::Kind::kNumber; });
  ASSERT_NE(n, t.end());
  EXPECT_EQ(n->number, 1500);
}

}  // namespace
}  // namespace socsim::scenario
