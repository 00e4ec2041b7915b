#include "core/scenario/quantity.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace socsim::scenario {

namespace {

bool letter(unsigned char c) {
  return std::isalpha(c) != 0 || c >= 0x80;
}

// Multi-byte punctuation we read: en/em dash (ranges, clause breaks) and the typographic apostrophe.
std::size_t dash_at(std::string_view s, std::size_t i) {
  if (s.substr(i, 3) == "\xE2\x80\x93" || s.substr(i, 3) == "\xE2\x80\x94") return 3;
  return 0;
}
bool curly_apostrophe(std::string_view s, std::size_t i) {
  return s.substr(i, 3) == "\xE2\x80\x99";
}

constexpr std::array<std::pair<std::string_view, int>, 28> kCardinals = {{
    {"zero", 0},      {"one", 1},       {"two", 2},       {"three", 3},    {"four", 4},     {"five", 5},
    {"six", 6},       {"seven", 7},     {"eight", 8},     {"nine", 9},     {"ten", 10},     {"eleven", 11},
    {"twelve", 12},   {"thirteen", 13}, {"fourteen", 14}, {"fifteen", 15}, {"sixteen", 16}, {"seventeen", 17},
    {"eighteen", 18}, {"nineteen", 19}, {"twenty", 20},   {"thirty", 30},  {"forty", 40},   {"fifty", 50},
    {"sixty", 60},    {"seventy", 70},  {"eighty", 80},   {"ninety", 90},
}};

std::optional<int> cardinal_word(std::string_view w) {
  for (const auto& [word, v] : kCardinals)
    if (word == w) return v;
  return std::nullopt;
}

// "seventy-five" as one token.
std::optional<int> hyphenated_cardinal(std::string_view w) {
  const auto dash = w.find('-');
  if (dash == std::string_view::npos) return cardinal_word(w);
  auto tens = cardinal_word(w.substr(0, dash));
  auto unit = cardinal_word(w.substr(dash + 1));
  if (!tens || !unit || *tens < 20 || *tens % 10 != 0 || *unit < 1 || *unit > 9) return std::nullopt;
  return *tens + *unit;
}

bool word_at(const std::vector<TextToken>& t, std::size_t i, std::string_view w) {
  return i < t.size() && t[i].is(w);
}

// Number of tokens of a space-separated phrase at i (words only), 0 when it does not match.
std::size_t phrase_at(const std::vector<TextToken>& t, std::size_t i, std::string_view phrase) {
  std::size_t n = 0;
  std::size_t p = 0;
  while (p < phrase.size()) {
    const std::size_t q = std::min(phrase.find(' ', p), phrase.size());
    if (!word_at(t, i + n, phrase.substr(p, q - p))) return 0;
    ++n;
    p = q + 1;
  }
  return n;
}

std::string join(const std::vector<TextToken>& t, std::size_t i, std::size_t n) {
  std::string out;
  for (std::size_t k = i; k < i + n && k < t.size(); ++k) out += (out.empty() ? "" : " ") + t[k].text;
  return out;
}

Count with_words(Count c, const std::vector<TextToken>& t, std::size_t i, std::size_t n) {
  c.phrase = join(t, i, n);
  if (n > 0) c.span = Span{t[i].span.begin, t[std::min(i + n, t.size()) - 1].span.end};
  return c;
}

struct Vague {
  std::string_view phrase;
  double lo, hi;
};
// Longest first where one is a prefix of another.
constexpr std::array<Vague, 25> kVague = {{
    {"a large crowd of", 80, 200},
    {"a quartet of", 4, 4},
    {"a trio of", 3, 3},
    {"a pair of", 2, 2},
    {"a big crowd of", 80, 200},
    {"a small group of", 2, 5},
    {"a large group of", 10, 30},
    {"a big group of", 10, 30},
    {"a couple of", 2, 3},
    {"a handful of", 3, 6},
    {"a crowd of", 30, 80},
    {"a group of", 3, 8},
    {"a lot of", 10, 30},
    {"a couple", 2, 3},
    {"a handful", 3, 6},
    {"a few", 3, 5},
    {"couple of", 2, 3},
    {"dozens of", 24, 60},
    {"hundreds of", 200, 500},
    {"thousands of", 2000, 5000},
    {"lots of", 10, 30},
    {"several", 4, 7},
    {"numerous", 10, 30},
    {"many", 10, 30},
    {"few", 3, 5},
}};

constexpr std::array<std::string_view, 12> kApprox = {"approximately", "approx", "about", "around", "roughly",
                                                      "nearly",        "almost", "circa", "ca",     "some",
                                                      "perhaps",       "maybe"};

}  // namespace

std::string_view to_string(CountKind kind) {
  switch (kind) {
    case CountKind::kExact:
      return "exact";
    case CountKind::kApprox:
      return "approx";
    case CountKind::kRange:
      return "range";
    case CountKind::kUnspecified:
      return "unspecified";
  }
  return "unspecified";
}

Count Count::exact(double v) {
  return Count{CountKind::kExact, v, v, v, {}, {}};
}
Count Count::approx(double v) {
  return Count{CountKind::kApprox, v, std::floor(v * 0.9 + 1e-9), std::ceil(v * 1.1 - 1e-9), {}, {}};
}
Count Count::range(double lo, double hi) {
  if (hi < lo) std::swap(lo, hi);
  return Count{CountKind::kRange, (lo + hi) / 2.0, lo, hi, {}, {}};
}

std::size_t Count::people() const {
  if (kind == CountKind::kUnspecified) return 0;
  return static_cast<std::size_t>(std::llround(std::max(0.0, value)));
}

Count& Count::times(double f) {
  value *= f;
  min *= f;
  max *= f;
  if (kind == CountKind::kRange) value = std::round(value);
  return *this;
}

Count& Count::plus(const Count& o) {
  if (!specified() || !o.specified()) {
    kind = CountKind::kUnspecified;
    return *this;
  }
  const bool both_exact = kind == CountKind::kExact && o.kind == CountKind::kExact;
  value += o.value;
  min += o.min;
  max += o.max;
  if (!both_exact)
    kind =
        (kind == CountKind::kRange || o.kind == CountKind::kRange) ? CountKind::kRange : CountKind::kApprox;
  return *this;
}

std::vector<TextToken> tokenize_text(std::string_view s) {
  std::vector<TextToken> out;
  std::size_t sentence = 0;
  std::size_t i = 0;
  auto push = [&](TextToken t) {
    t.sentence = sentence;
    out.push_back(std::move(t));
  };
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (std::isspace(c) != 0) {
      ++i;
      continue;
    }
    if (const std::size_t d = dash_at(s, i)) {
      TextToken t{TextToken::Kind::kPunct, "-", {i, i + d}};
      // A dash between numbers is a range ("20–30"); between words it ends a clause.
      const bool range = !out.empty() && out.back().kind == TextToken::Kind::kNumber && i + d < s.size() &&
                         std::isdigit(static_cast<unsigned char>(s[i + d])) != 0;
      if (!range) {
        t.text = "—";
        ++sentence;
        push(std::move(t));
        i += d;
        continue;
      }
      push(std::move(t));
      i += d;
      continue;
    }
    if (std::isdigit(c) != 0) {
      std::size_t j = i;
      std::string digits;
      while (j < s.size()) {
        const auto d = static_cast<unsigned char>(s[j]);
        if (std::isdigit(d) != 0) {
          digits.push_back(static_cast<char>(d));
          ++j;
        } else if (d == ',' && j + 3 < s.size() + 1 && j + 3 <= s.size() &&
                   std::isdigit(static_cast<unsigned char>(s[j + 1])) != 0 &&
                   std::isdigit(static_cast<unsigned char>(s[j + 2])) != 0 &&
                   std::isdigit(static_cast<unsigned char>(s[j + 3])) != 0 &&
                   (j + 4 >= s.size() || std::isdigit(static_cast<unsigned char>(s[j + 4])) == 0)) {
          ++j;  // thousands separator: "1,500"
        } else if (d == '.' && j + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[j + 1])) != 0) {
          digits.push_back('.');
          ++j;
        } else {
          break;
        }
      }
      TextToken t{TextToken::Kind::kNumber, digits, {i, j}};
      t.number = std::strtod(digits.c_str(), nullptr);
      // "40-odd", "30-ish": one word, an approximate count.
      if (j + 1 < s.size() && s[j] == '-' && letter(static_cast<unsigned char>(s[j + 1])) &&
          (s.substr(j + 1, 3) == "odd" || s.substr(j + 1, 3) == "ish")) {
        TextToken w{TextToken::Kind::kWord, std::string(s.substr(i, j + 4 - i)), {i, j + 4}};
        for (char& ch : w.text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        push(std::move(w));
        i = j + 4;
        continue;
      }
      // Glued letters ("20s", "9am", "2nd") make a word, not a count.
      if (j < s.size() && letter(static_cast<unsigned char>(s[j])) && dash_at(s, j) == 0) {
        while (j < s.size() && letter(static_cast<unsigned char>(s[j]))) ++j;
        t.kind = TextToken::Kind::kWord;
        t.text = std::string(s.substr(i, j - i));
        for (char& ch : t.text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        t.span.end = j;
      }
      push(std::move(t));
      i = j;
      continue;
    }
    if (letter(c)) {
      std::size_t j = i;
      std::string word;
      bool possessive = false;
      while (j < s.size()) {
        const auto d = static_cast<unsigned char>(s[j]);
        if (dash_at(s, j) != 0) break;
        if (letter(d)) {
          word.push_back(static_cast<char>(std::tolower(d)));
          ++j;
          continue;
        }
        const bool apostrophe = d == '\'' || curly_apostrophe(s, j);
        const std::size_t alen = d == '\'' ? 1 : 3;
        if (apostrophe) {
          const std::size_t k = j + alen;
          if (k < s.size() && (s[k] == 's' || s[k] == 'S') &&
              (k + 1 >= s.size() || !letter(static_cast<unsigned char>(s[k + 1])))) {
            possessive = true;  // "hospital's" (or "there's": see below)
            j = k + 1;
            break;
          }
          if (!word.empty() && word.back() == 's' &&
              (k >= s.size() || !letter(static_cast<unsigned char>(s[k])))) {
            possessive = true;  // "nurses'"
            j = k;
            break;
          }
          if (k < s.size() && letter(static_cast<unsigned char>(s[k]))) {  // "o'clock", "don't"
            word.push_back('\'');
            j = k;
            continue;
          }
          break;
        }
        if (d == '-' && j + 1 < s.size() && letter(static_cast<unsigned char>(s[j + 1])) && !word.empty()) {
          word.push_back('-');
          ++j;
          continue;
        }
        if (d == '.' && (word == "approx" || word == "ca")) {  // "approx. 30"
          ++j;
          break;
        }
        break;
      }
      TextToken t{TextToken::Kind::kWord, word, {i, j}};
      static const std::array<std::string_view, 8> kIs = {"there", "it",  "that", "what",
                                                          "he",    "she", "who",  "here"};
      if (possessive && std::find(kIs.begin(), kIs.end(), word) != kIs.end()) {
        push(t);
        push(TextToken{TextToken::Kind::kWord, "is", {j - 2, j}});
      } else {
        t.possessive = possessive;
        push(std::move(t));
      }
      i = j;
      continue;
    }
    // Punctuation: one byte (or a skipped UTF-8 symbol).
    std::string p(1, static_cast<char>(c));
    std::size_t len = 1;
    if (c >= 0x80) {
      while (i + len < s.size() && (static_cast<unsigned char>(s[i + len]) & 0xC0) == 0x80) ++len;
      p = std::string(s.substr(i, len));
    }
    const bool ends = p == "." || p == ";" || p == ":" || p == "!" || p == "?";
    if (p == "-") {
      const bool range = !out.empty() && out.back().kind == TextToken::Kind::kNumber && i + 1 < s.size() &&
                         std::isdigit(static_cast<unsigned char>(s[i + 1])) != 0;
      if (!range) {
        ++sentence;
        push(TextToken{TextToken::Kind::kPunct, "—", {i, i + 1}});
        i += 1;
        continue;
      }
    }
    push(TextToken{TextToken::Kind::kPunct, p, {i, i + len}});
    if (ends) ++sentence;
    i += len;
  }
  return out;
}

std::optional<std::pair<double, std::size_t>> cardinal_at(const std::vector<TextToken>& t, std::size_t i) {
  if (i >= t.size()) return std::nullopt;
  if (t[i].kind == TextToken::Kind::kNumber) {
    double v = t[i].number;
    std::size_t n = 1;
    if (word_at(t, i + 1, "thousand")) {
      v *= 1000;
      ++n;
    } else if (word_at(t, i + 1, "hundred")) {
      v *= 100;
      ++n;
    } else if (word_at(t, i + 1, "dozen")) {
      v *= 12;
      ++n;
    }
    return std::make_pair(v, n);
  }
  if (t[i].kind != TextToken::Kind::kWord) return std::nullopt;
  std::size_t k = i;
  double total = 0.0;
  double current = 0.0;
  bool any = false;
  // "a hundred", "a thousand", "a dozen"
  if ((t[k].text == "a" || t[k].text == "one") &&
      (word_at(t, k + 1, "hundred") || word_at(t, k + 1, "thousand") || word_at(t, k + 1, "dozen")) &&
      t[k].text == "a") {
    current = 1;
    any = true;
    ++k;
  }
  if (word_at(t, k, "half") && word_at(t, k + 1, "a") && word_at(t, k + 2, "dozen")) {
    return std::make_pair(6.0, k + 3 - i);
  }
  while (k < t.size() && t[k].kind == TextToken::Kind::kWord) {
    const std::string& w = t[k].text;
    if (auto v = hyphenated_cardinal(w)) {
      if (any && current != 0 && std::fmod(current, 100.0) != 0 && current >= 10 && *v >= 10) break;
      // "twenty five"
      if (any && current >= 20 && std::fmod(current, 10.0) == 0 && *v < 10 && std::fmod(current, 100.0) != 0)
        current += *v;
      else if (any && current != 0 && std::fmod(current, 100.0) != 0)
        break;
      else
        current += *v;
      any = true;
      ++k;
      continue;
    }
    if (any && (w == "hundred")) {
      current = (current == 0 ? 1 : current) * 100;
      ++k;
      if (word_at(t, k, "and") && k + 1 < t.size() && hyphenated_cardinal(t[k + 1].text)) ++k;
      continue;
    }
    if (any && w == "thousand") {
      total += (current == 0 ? 1 : current) * 1000;
      current = 0;
      ++k;
      if (word_at(t, k, "and") && k + 1 < t.size() && hyphenated_cardinal(t[k + 1].text)) ++k;
      continue;
    }
    if (any && w == "dozen") {
      current = (current == 0 ? 1 : current) * 12;
      ++k;
      break;
    }
    break;
  }
  if (!any) return std::nullopt;
  // A lone "a" is an article, not a number.
  if (k == i + 1 && t[i].text == "a") return std::nullopt;
  return std::make_pair(total + current, k - i);
}

std::optional<QuantityMatch> quantity_at(const std::vector<TextToken>& t, std::size_t i) {
  if (i >= t.size()) return std::nullopt;
  auto done = [&](Count c, std::size_t n) { return QuantityMatch{with_words(std::move(c), t, i, n), n}; };
  auto number_then_range = [&](double a, std::size_t at, std::size_t n) -> std::optional<QuantityMatch> {
    // "20-30", "20 to 30", "two or three"
    std::size_t k = at + n;
    if (k < t.size() && (t[k].text == "-" || t[k].is("to") || t[k].is("or"))) {
      if (auto b = cardinal_at(t, k + 1); b && b->first > a)
        return done(Count::range(a, b->first), k + 1 + b->second - i);
      // "40 or so"
      if (t[k].is("or") && word_at(t, k + 1, "so")) return done(Count::approx(a), k + 2 - i);
    }
    if (k < t.size() && t[k].text == "-ish") return done(Count::approx(a), k + 1 - i);
    return std::nullopt;
  };

  // Ranges: "between 20 and 30", "from 20 to 30".
  if (t[i].is("between") || t[i].is("from")) {
    if (auto a = cardinal_at(t, i + 1)) {
      const std::size_t k = i + 1 + a->second;
      if (k < t.size() && (t[k].is("and") || t[k].is("to") || t[k].text == "-"))
        if (auto b = cardinal_at(t, k + 1))
          return done(Count::range(a->first, b->first), k + 1 + b->second - i);
    }
    return std::nullopt;
  }
  // Bounds.
  struct Bound {
    std::string_view phrase;
    int kind;  // 0 at least, 1 more than, 2 up to
  };
  static constexpr std::array<Bound, 8> kBounds = {{{"at least", 0},
                                                    {"no fewer than", 0},
                                                    {"more than", 1},
                                                    {"over", 1},
                                                    {"up to", 2},
                                                    {"at most", 2},
                                                    {"no more than", 2},
                                                    {"fewer than", 2}}};
  for (const Bound& b : kBounds) {
    if (const std::size_t n = phrase_at(t, i, b.phrase)) {
      if (auto a = cardinal_at(t, i + n)) {
        const double v = a->first;
        Count c = b.kind == 0   ? Count::range(v, std::ceil(v * 1.25))
                  : b.kind == 1 ? Count::range(v + 1, std::max(v + 1, std::ceil(v * 1.25)))
                                : Count::range(std::max(1.0, std::ceil(v / 2)), v);
        return done(c, n + a->second);
      }
    }
  }
  // Exactness markers.
  if (t[i].is("exactly") || t[i].is("precisely")) {
    if (auto a = cardinal_at(t, i + 1)) return done(Count::exact(a->first), 1 + a->second);
  }
  // Approximations: "about 200", "some 35", "nearly a thousand", "about a dozen".
  for (std::string_view a : kApprox) {
    if (!t[i].is(a)) continue;
    if (auto v = cardinal_at(t, i + 1)) {
      if (auto r = number_then_range(v->first, i + 1, v->second)) return r;
      return done(Count::approx(v->first), 1 + v->second);
    }
    if (a == "some") break;  // "some" alone is vague (below)
    return std::nullopt;
  }
  // Vague words.
  for (const Vague& v : kVague) {
    if (const std::size_t n = phrase_at(t, i, v.phrase)) {
      // "a group of 15", "a crowd of 400": the number says how many.
      if (v.phrase.ends_with(" of"))
        if (auto num = cardinal_at(t, i + n)) {
          if (auto r = number_then_range(num->first, i + n, num->second)) return r;
          return done(Count::exact(num->first), n + num->second);
        }
      // "a pair of", "a trio of": exactly that many.
      return done(v.lo == v.hi ? Count::exact(v.lo) : Count::range(v.lo, v.hi), n);
    }
  }
  if (t[i].is("some")) return done(Count::range(3, 8), 1);
  // "twenty-odd", "40-ish", "30-odd": approximately.
  if (t[i].kind == TextToken::Kind::kWord && (t[i].text.ends_with("-odd") || t[i].text.ends_with("-ish"))) {
    const std::string head = t[i].text.substr(0, t[i].text.size() - 4);
    std::optional<double> v;
    if (auto w = hyphenated_cardinal(head))
      v = *w;
    else if (!head.empty() && std::all_of(head.begin(), head.end(), [](char ch) {
               return std::isdigit(static_cast<unsigned char>(ch)) != 0;
             }))
      v = std::strtod(head.c_str(), nullptr);
    if (v) return done(Count::approx(*v), 1);
  }
  // Plain numbers.
  if (auto v = cardinal_at(t, i)) {
    if (auto r = number_then_range(v->first, i, v->second)) return r;
    return done(Count::exact(v->first), v->second);
  }
  return std::nullopt;
}

}  // namespace socsim::scenario
