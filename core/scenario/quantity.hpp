#pragma once
// The words of a prompt with their byte spans, and the quantities they state: digits ("1,500"),
// cardinal words up to the thousands ("two hundred and fifty", "seventy-five"), dozens, ranges
// ("20-30", "between 20 and 30", "two or three"), approximations ("about", "roughly", "40 or so")
// and vague words, which map to documented ranges:
//   a couple (of) 2-3 · a few 3-5 · a handful (of) 3-6 · several 4-7 · some 3-8 · many, lots of,
//   a lot of, numerous 10-30 · dozens of 24-60 · hundreds of 200-500 · thousands of 2000-5000 ·
//   a (small) group of 3-8 (2-5) · a large group of 10-30 · a crowd of 30-80 · a large crowd of 80-200.
// Approximate counts hold within ±10 %; "at least N" is N-1.25N, "more than N"/"over N" N+1-1.25N,
// "up to N"/"at most N"/"no more than N" N/2-N.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace socsim::scenario {

struct Span {
  std::size_t begin = 0;  // byte offsets into the prompt, [begin, end)
  std::size_t end = 0;
};

struct TextToken {
  enum class Kind { kWord, kNumber, kPunct };
  Kind kind = Kind::kWord;
  std::string text;  // lower case; punctuation as written ("," ";" "-" "—")
  Span span;
  double number = 0.0;       // kNumber: its value ("1,500" → 1500)
  bool possessive = false;   // "hospital's", "nurses'": the 's is not a token of its own
  std::size_t sentence = 0;  // split at . ! ? ; : and dashes between words
  [[nodiscard]] bool is(std::string_view w) const { return kind == Kind::kWord && text == w; }
};

std::vector<TextToken> tokenize_text(std::string_view prompt);

enum class CountKind { kExact, kApprox, kRange, kUnspecified };
std::string_view to_string(CountKind kind);

struct Count {
  CountKind kind = CountKind::kUnspecified;
  double value = 0.0;  // exact or central value (range: midpoint)
  double min = 0.0;
  double max = 0.0;
  std::string phrase;  // the words it came from
  Span span;

  static Count exact(double v);
  static Count approx(double v);
  static Count range(double lo, double hi);
  [[nodiscard]] bool specified() const { return kind != CountKind::kUnspecified; }
  // The number of people to simulate: exact value, rounded central value of the others.
  [[nodiscard]] std::size_t people() const;
  Count& times(double factor);  // products: "two classes of 25 each"
  Count& plus(const Count& other);
};

// A quantity starting at token i: its count and how many tokens it spans. Never consumes a bare
// article ("a", "an"), which the noun-phrase reader treats as one.
struct QuantityMatch {
  Count count;
  std::size_t length = 0;
};
std::optional<QuantityMatch> quantity_at(const std::vector<TextToken>& tokens, std::size_t i);

// A cardinal number in words or digits at token i (no approximations or vague words):
// "two hundred and fifty" → 250, "seventy-five" → 75, "1,500" → 1500, "a thousand" → 1000.
std::optional<std::pair<double, std::size_t>> cardinal_at(const std::vector<TextToken>& tokens,
                                                          std::size_t i);

}  // namespace socsim::scenario
