#include "core/scenario/intent.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

namespace socsim::scenario {

namespace {

std::vector<std::string> split_words(std::string_view phrase) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < phrase.size()) {
    const std::size_t j = phrase.find(' ', i);
    const std::size_t end = j == std::string_view::npos ? phrase.size() : j;
    if (end > i) out.emplace_back(phrase.substr(i, end - i));
    i = end + 1;
  }
  return out;
}

// Number of tokens the phrase covers at i (all in one clause), 0 when it does not match.
std::size_t match_at(const std::vector<Token>& t, std::size_t i, std::string_view phrase) {
  const std::vector<std::string> words = split_words(phrase);
  if (words.empty() || i + words.size() > t.size()) return 0;
  for (std::size_t k = 0; k < words.size(); ++k) {
    if (t[i + k].text != words[k] || t[i + k].clause != t[i].clause) return 0;
  }
  return words.size();
}

std::string join(const std::vector<Token>& t, std::size_t i, std::size_t n) {
  std::string out;
  for (std::size_t k = i; k < i + n && k < t.size(); ++k) out += (out.empty() ? "" : " ") + t[k].text;
  return out;
}

std::optional<double> parse_double(std::string_view s) {
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// Seconds per unit word; nullopt for words that are no time unit.
std::optional<double> unit_seconds(std::string_view w) {
  if (w == "s" || w == "sec" || w == "secs" || w == "second" || w == "seconds") return 1.0;
  if (w == "min" || w == "mins" || w == "minute" || w == "minutes") return 60.0;
  if (w == "h" || w == "hr" || w == "hrs" || w == "hour" || w == "hours") return 3600.0;
  return std::nullopt;
}

struct CountParse {
  double value = 0.0;
  std::size_t length = 0;
  bool approximate = false;
  bool bare_article = false;  // "a"/"an": a count only right before a role
  std::string phrase;
};

const CountWord* count_word_at(const std::vector<Token>& t, std::size_t i, std::size_t& length) {
  const CountWord* best = nullptr;
  length = 0;
  for (const CountWord& w : count_words()) {
    const std::size_t n = match_at(t, i, w.phrase);
    if (n > length) {
      length = n;
      best = &w;
    }
  }
  return best;
}

// A number in digits or words at i ("200", "twenty five", "two hundred", "2 dozen").
std::optional<CountParse> number_at(const std::vector<Token>& t, std::size_t i) {
  if (i >= t.size()) return std::nullopt;
  CountParse out;
  std::size_t k = i;
  double current = 0.0;
  if (t[k].number) {
    auto v = parse_double(t[k].text);
    if (!v) return std::nullopt;
    current = *v;
    ++k;
  } else {
    std::size_t n = 0;
    const CountWord* w = count_word_at(t, k, n);
    if (w == nullptr || w->approximate || n != 1 || w->multiplier || w->phrase == "a" || w->phrase == "an" ||
        w->phrase == "single")
      return std::nullopt;
    current = w->value;
    ++k;
    // "twenty five"
    if (current >= 20 && current < 100 && std::fmod(current, 10.0) == 0.0 && k < t.size() &&
        t[k].clause == t[i].clause) {
      std::size_t m = 0;
      const CountWord* u = count_word_at(t, k, m);
      if (u != nullptr && m == 1 && !u->approximate && !u->multiplier && u->value < 10 && u->phrase != "a" &&
          u->phrase != "an" && u->phrase != "single") {
        current += u->value;
        ++k;
      }
    }
  }
  // Multipliers: "two hundred", "2 dozen", then "and fifty".
  while (k < t.size() && t[k].clause == t[i].clause && (t[k].text == "hundred" || t[k].text == "dozen")) {
    current *= t[k].text == "hundred" ? 100.0 : 12.0;
    ++k;
    if (k + 1 < t.size() && t[k].text == "and") {
      if (auto rest = number_at(t, k + 1); rest && rest->value < 100) {
        current += rest->value;
        k = k + 1 + rest->length;
      }
    }
  }
  out.value = current;
  out.length = k - i;
  out.phrase = join(t, i, out.length);
  return out;
}

std::optional<CountParse> count_at(const std::vector<Token>& t, std::size_t i) {
  CountParse out;
  std::size_t k = i;
  // Approximation prefix ("about", "up to"); "some" is also a count word on its own.
  for (std::string_view a : approximation_phrases()) {
    const std::size_t n = match_at(t, k, a);
    if (n == 0) continue;
    if (a == "some" && !number_at(t, k + 1)) break;
    out.approximate = true;
    k += n;
    break;
  }
  if (auto num = number_at(t, k)) {
    out.value = num->value;
    out.length = k - i + num->length;
    out.phrase = join(t, i, out.length);
    return out;
  }
  std::size_t n = 0;
  const CountWord* w = count_word_at(t, k, n);
  if (w == nullptr) return std::nullopt;
  // "a crowd of 200", "a group of five"
  if (w->phrase.ends_with(" of") || w->phrase == "crowd of") {
    if (auto num = number_at(t, k + n)) {
      out.value = num->value;
      out.length = k - i + n + num->length;
      out.phrase = join(t, i, out.length);
      return out;
    }
  }
  out.value = w->value;
  out.approximate = out.approximate || w->approximate;
  out.bare_article = w->phrase == "a" || w->phrase == "an";
  out.length = k - i + n;
  out.phrase = join(t, i, out.length);
  return out;
}

const RoleWord* role_at(const std::vector<Token>& t, std::size_t i, std::size_t& length) {
  const RoleWord* best = nullptr;
  length = 0;
  for (const RoleWord& r : role_words()) {
    const std::size_t n = match_at(t, i, r.phrase);
    if (n > length) {
      length = n;
      best = &r;
    }
  }
  return best;
}

std::size_t preposition_at(const std::vector<Token>& t, std::size_t i) {
  for (std::string_view p : place_prepositions())
    if (const std::size_t n = match_at(t, i, p)) return n;
  return 0;
}

const PlacePhrase* place_phrase_at(const std::vector<Token>& t, std::size_t i, std::size_t& length) {
  const PlacePhrase* best = nullptr;
  length = 0;
  for (const PlacePhrase& p : place_phrases()) {
    const std::size_t n = match_at(t, i, p.phrase);
    if (n > length) {
      length = n;
      best = &p;
    }
  }
  return best;
}

bool is_determiner(std::string_view w) {
  return w == "the" || w == "a" || w == "an" || w == "our" || w == "their" || w == "this" || w == "that" ||
         w == "its" || w == "his" || w == "her" || w == "each" || w == "every" || w == "one" || w == "both";
}

// Words after a preposition that end a place phrase or show it is no place ("to leave", "in line").
bool ends_place(std::string_view w) {
  static const std::set<std::string_view> kStop = {
      "and",    "or",      "but",   "with",  "for",   "after", "before",  "when",  "until", "during",
      "who",    "which",   "where", "as",    "so",    "if",    "because", "then",  "be",    "get",
      "leave",  "go",      "see",   "do",    "have",  "make",  "take",    "wait",  "walk",  "run",
      "them",   "him",     "it",    "line",  "turn",  "turns", "order",   "front", "all",   "other",
      "others", "another", "time",  "while", "once",  "again", "is",      "are",   "was",   "were",
      "will",   "would",   "can",   "could", "should"};
  return kStop.count(w) != 0;
}

std::string singular(std::string w) {
  if (w.size() > 4 && w.ends_with("ies")) return w.substr(0, w.size() - 3) + "y";
  if (w.size() > 3 && w.ends_with("s") && !w.ends_with("ss")) w.pop_back();
  return w;
}

std::vector<std::string> name_tokens(std::string_view name) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) != 0 &&
        std::isdigit(static_cast<unsigned char>(c)) == 0) {
      cur.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    } else if (!cur.empty()) {
      out.push_back(singular(cur));
      cur.clear();
    }
  }
  if (!cur.empty()) out.push_back(singular(cur));
  return out;
}

Json to_json(const CategoryScore& c) {
  return Json{{"category", std::string(to_string(c.category))}, {"score", c.score}, {"phrases", c.phrases}};
}

void sort_scores(std::vector<CategoryScore>& v) {
  std::stable_sort(v.begin(), v.end(), [](const CategoryScore& a, const CategoryScore& b) {
    if (a.score != b.score) return a.score > b.score;
    return static_cast<int>(a.category) < static_cast<int>(b.category);
  });
}

}  // namespace

Intent parse_intent(std::string_view prompt) {
  Intent intent;
  intent.prompt = std::string(prompt);
  const std::vector<Token> t = tokenize(prompt);
  const std::size_t clauses = t.empty() ? 0 : t.back().clause + 1;
  intent.clauses.resize(clauses);
  for (std::size_t c = 0; c < clauses; ++c) intent.clauses[c].index = c;
  for (const Token& tok : t) {
    Clause& c = intent.clauses[tok.clause];
    c.text += (c.text.empty() ? "" : " ") + tok.text;
  }
  std::vector<bool> used(t.size(), false);  // tokens consumed by timing and counts

  // Timing: "after 20 seconds", "for two minutes", "90 s later", "half a minute".
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::string& w = t[i].text;
    const bool start = w == "after" || w == "at" || w == "in" || w == "from";
    const bool span = w == "for" || w == "lasting" || w == "during" || w == "over";
    std::size_t k = i + ((start || span) ? 1 : 0);
    if (k >= t.size()) continue;
    double value = 0.0;
    std::size_t n = 0;
    if (t[k].text == "half" && k + 2 < t.size() && (t[k + 1].text == "a" || t[k + 1].text == "an")) {
      value = 0.5;
      n = 2;
    } else if (auto num = number_at(t, k)) {
      value = num->value;
      n = num->length;
    } else if (t[k].text == "a" || t[k].text == "an") {
      value = 1.0;
      n = 1;
    } else if (!t[k].text.empty() && std::isdigit(static_cast<unsigned char>(t[k].text[0])) != 0) {
      // "20s", "2min": digits glued to the unit.
      const std::string& g = t[k].text;
      std::size_t d = 0;
      while (d < g.size() && (std::isdigit(static_cast<unsigned char>(g[d])) != 0 || g[d] == '.')) ++d;
      auto v = parse_double(std::string_view(g).substr(0, d));
      auto u = unit_seconds(std::string_view(g).substr(d));
      if (v && u) {
        const double seconds = *v * *u;
        const std::size_t len = k - i + 1;
        bool later = !(start || span) && k + 1 < t.size() && t[k + 1].text == "later";
        if (span)
          intent.timing.duration_s = seconds;
        else if (start || later)
          intent.timing.start_after_s = seconds;
        else
          continue;
        intent.timing.phrases.push_back(join(t, i, len + (later ? 1 : 0)));
        for (std::size_t m = i; m < i + len + (later ? 1 : 0); ++m) used[m] = true;
        continue;
      }
      continue;
    } else {
      continue;
    }
    if (k + n >= t.size()) continue;
    const auto unit = unit_seconds(t[k + n].text);
    if (!unit) continue;
    const double seconds = value * *unit;
    std::size_t end = k + n + 1;
    bool later = false;
    if (!(start || span)) {
      if (end < t.size() && t[end].text == "later") {
        later = true;
        ++end;
      } else {
        continue;  // a bare "two minutes" says nothing about when
      }
    }
    if (span)
      intent.timing.duration_s = seconds;
    else
      intent.timing.start_after_s = seconds;
    (void)later;
    intent.timing.phrases.push_back(join(t, i, end - i));
    for (std::size_t m = i; m < end; ++m) used[m] = true;
    i = end - 1;
  }

  // Roles, each with the count right before it ("two nurses", "about thirty hospital visitors").
  struct Pending {
    CountParse count;
    std::size_t start = 0;
    std::size_t end = 0;  // token after the count
  };
  std::optional<Pending> pending;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (used[i]) continue;
    std::size_t rn = 0;
    const RoleWord* r = role_at(t, i, rn);
    if (r != nullptr) {
      RoleMention m;
      m.role = std::string(r->role);
      m.phrase = join(t, i, rn);
      m.clause = t[i].clause;
      m.offset = t[i].offset;
      // Two role words in a row: a modifier ("elderly patients") keeps the first, else the second.
      std::size_t rn2 = 0;
      if (i + rn < t.size() && t[i + rn].clause == t[i].clause) {
        if (const RoleWord* r2 = role_at(t, i + rn, rn2)) {
          if (m.role != "elderly" && m.role != "child") m.role = std::string(r2->role);
          m.phrase += " " + join(t, i + rn, rn2);
          rn += rn2;
        }
      }
      if (pending && t[pending->start].clause == t[i].clause && i - pending->end <= 2) {
        m.count = static_cast<std::size_t>(std::llround(std::max(0.0, pending->count.value)));
        m.count_phrase = pending->count.phrase;
        m.approximate = pending->count.approximate;
      }
      pending.reset();
      intent.clauses[m.clause].roles.push_back(std::move(m));
      i += rn - 1;
      continue;
    }
    if (auto c = count_at(t, i)) {
      if (pending && !pending->count.bare_article && !intent.crowd_size) {
        // The previous count was bound to nothing: a crowd without a named role ("a crowd of 200").
        intent.crowd_size = static_cast<std::size_t>(std::llround(pending->count.value));
        intent.crowd_phrase = pending->count.phrase;
        intent.crowd_clause = t[pending->start].clause;
      }
      pending = Pending{*c, i, i + c->length};
      i += c->length - 1;
      continue;
    }
    if (pending &&
        (i - pending->end >= 2 || t[i].clause != t[pending->start].clause || preposition_at(t, i) > 0)) {
      if (!pending->count.bare_article && !intent.crowd_size &&
          pending->count.phrase.find("crowd") != std::string::npos) {
        intent.crowd_size = static_cast<std::size_t>(std::llround(pending->count.value));
        intent.crowd_phrase = pending->count.phrase;
        intent.crowd_clause = t[pending->start].clause;
      }
      pending.reset();
    }
  }
  if (pending && !pending->count.bare_article && !intent.crowd_size &&
      pending->count.phrase.find("crowd") != std::string::npos) {
    intent.crowd_size = static_cast<std::size_t>(std::llround(pending->count.value));
    intent.crowd_phrase = pending->count.phrase;
    intent.crowd_clause = t[pending->start].clause;
  }

  // Places: a preposition and the words after it, or a lexicon place phrase on its own.
  std::vector<bool> in_place(t.size(), false);
  std::vector<bool> after_preposition(t.size(), false);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (used[i]) continue;
    const std::size_t pn = preposition_at(t, i);
    if (pn == 0) continue;
    std::size_t k = i + pn;
    while (k < t.size() && t[k].clause == t[i].clause && is_determiner(t[k].text)) ++k;
    std::size_t end = k;
    while (end < t.size() && end - k < 4 && t[end].clause == t[i].clause && !used[end] &&
           !ends_place(t[end].text) && preposition_at(t, end) == 0 && !t[end].number) {
      std::size_t pn2 = 0;
      if (place_phrase_at(t, end, pn2) != nullptr) {  // "nurse station" is a place, not a nurse
        end = std::min(t.size(), end + pn2);
        continue;
      }
      std::size_t rn = 0;
      if (role_at(t, end, rn) != nullptr) break;
      ++end;
    }
    if (end == k) continue;
    PlaceMention m;
    m.preposition = join(t, i, pn);
    m.clause = t[i].clause;
    m.offset = t[k].offset;
    // The longest lexicon phrase inside the words, else the words themselves.
    std::size_t best_len = 0, best_at = k;
    const PlacePhrase* best = nullptr;
    for (std::size_t s = k; s < end; ++s) {
      std::size_t n = 0;
      const PlacePhrase* p = place_phrase_at(t, s, n);
      if (p != nullptr && n > best_len && s + n <= end) {
        best = p;
        best_len = n;
        best_at = s;
      }
    }
    if (best != nullptr) {
      m.lexicon = best;
      m.phrase = join(t, k, std::max(end, best_at + best_len) - k);
      m.words = split_words(best->phrase);
      for (std::size_t s = k; s < best_at; ++s) m.words.push_back(t[s].text);  // "north corridor"
    } else {
      m.phrase = join(t, k, end - k);
      for (std::size_t s = k; s < end; ++s) m.words.push_back(t[s].text);
    }
    for (std::size_t s = i; s < end; ++s) in_place[s] = after_preposition[s] = true;
    intent.clauses[m.clause].places.push_back(std::move(m));
    i = end - 1;
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (used[i] || in_place[i]) continue;
    std::size_t n = 0;
    const PlacePhrase* p = place_phrase_at(t, i, n);
    if (p == nullptr) continue;
    PlaceMention m;
    m.lexicon = p;
    m.phrase = join(t, i, n);
    m.words = split_words(p->phrase);
    m.clause = t[i].clause;
    m.offset = t[i].offset;
    for (std::size_t s = i; s < i + n; ++s) in_place[s] = true;
    intent.clauses[m.clause].places.push_back(std::move(m));
    i += n - 1;
  }

  // Categories: the longest lexicon phrase at each token; words inside a place phrase after a
  // preposition ("at the reception desk") count half — they say where, not what.
  std::map<Category, CategoryScore> total;
  std::vector<std::map<Category, CategoryScore>> per_clause(clauses);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (used[i]) continue;
    std::size_t best_n = 0;
    const CategoryPhrase* best = nullptr;
    for (const CategoryPhrase& p : category_phrases()) {
      const std::size_t n = match_at(t, i, p.phrase);
      if (n > best_n) {
        best_n = n;
        best = &p;
      }
    }
    if (best == nullptr) continue;
    bool placed = false;
    for (std::size_t s = i; s < i + best_n; ++s) placed = placed || after_preposition[s];
    const double w = best->weight * (placed ? 0.5 : 1.0);
    for (auto* scores : {&total, &per_clause[t[i].clause]}) {
      CategoryScore& s = (*scores)[best->category];
      s.category = best->category;
      s.score += w;
      s.phrases.emplace_back(best->phrase);
    }
    i += best_n - 1;
  }
  for (Clause& c : intent.clauses)
    std::stable_sort(c.places.begin(), c.places.end(),
                     [](const PlaceMention& x, const PlaceMention& y) { return x.offset < y.offset; });
  for (auto& [c, s] : total) intent.categories.push_back(s);
  sort_scores(intent.categories);
  for (std::size_t c = 0; c < clauses; ++c) {
    for (auto& [cat, s] : per_clause[c]) intent.clauses[c].categories.push_back(s);
    sort_scores(intent.clauses[c].categories);
  }
  return intent;
}

Json to_json(const Intent& intent) {
  Json categories = Json::array();
  for (const CategoryScore& c : intent.categories) categories.push_back(to_json(c));
  Json clauses = Json::array();
  for (const Clause& c : intent.clauses) {
    Json cats = Json::array();
    for (const CategoryScore& s : c.categories) cats.push_back(to_json(s));
    Json roles = Json::array();
    for (const RoleMention& r : c.roles) {
      Json j{{"role", r.role}, {"phrase", r.phrase}};
      if (r.count) {
        j["count"] = *r.count;
        j["count_phrase"] = r.count_phrase;
        j["approximate"] = r.approximate;
      }
      roles.push_back(std::move(j));
    }
    Json places = Json::array();
    for (const PlaceMention& p : c.places) {
      Json j{{"phrase", p.phrase}, {"words", p.words}, {"preposition", p.preposition}};
      if (p.lexicon != nullptr) j["lexicon"] = std::string(p.lexicon->phrase);
      places.push_back(std::move(j));
    }
    clauses.push_back(Json{
        {"index", c.index}, {"text", c.text}, {"categories", cats}, {"roles", roles}, {"places", places}});
  }
  Json timing = Json::object();
  if (intent.timing.start_after_s) timing["start_after_s"] = *intent.timing.start_after_s;
  if (intent.timing.duration_s) timing["duration_s"] = *intent.timing.duration_s;
  timing["phrases"] = intent.timing.phrases;
  Json out{{"categories", categories}, {"clauses", clauses}, {"timing", timing}};
  if (intent.crowd_size) out["crowd"] = Json{{"size", *intent.crowd_size}, {"phrase", intent.crowd_phrase}};
  return out;
}

std::string_view to_string(ResolvedPlace::Kind kind) {
  switch (kind) {
    case ResolvedPlace::Kind::kRoi:
      return "roi";
    case ResolvedPlace::Kind::kEntity:
      return "poi";
    case ResolvedPlace::Kind::kDoor:
      return "door";
    case ResolvedPlace::Kind::kZone:
      return "zone";
  }
  return "roi";
}

std::optional<ResolvedPlace> resolve_place(const PlaceMention& mention, const world::World& world) {
  // Name words: the lexicon's curated ones and the mention's words without generic nouns
  // ("room" alone would match every room).
  static const std::set<std::string> kGeneric = {"room",   "area",   "zone",   "place",    "space",
                                                 "spot",   "side",   "end",    "part",     "corner",
                                                 "middle", "center", "centre", "building", "floor"};
  std::vector<std::string> words;
  if (mention.lexicon != nullptr)
    for (std::string_view w : mention.lexicon->name_words) words.push_back(singular(std::string(w)));
  for (const std::string& w : mention.words)
    if (kGeneric.count(singular(w)) == 0) words.push_back(singular(w));
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());

  std::optional<ResolvedPlace> best;
  auto consider = [&](const std::string& name, ResolvedPlace::Kind kind, const std::string& type, double base,
                      std::string why) {
    double score = base;
    const std::vector<std::string> nt = name_tokens(name);
    const std::vector<std::string> tt = name_tokens(type);
    for (const std::string& w : words) {
      if (std::find(nt.begin(), nt.end(), w) != nt.end()) {
        score += 1.0;
        why += (why.empty() ? "" : ", ") + std::string("name word '") + w + "'";
      } else if (std::find(tt.begin(), tt.end(), w) != tt.end()) {
        score += 0.5;
        why += (why.empty() ? "" : ", ") + std::string("type word '") + w + "'";
      }
    }
    if (score < 1.0) return;
    if (!best || score > best->score + 1e-9) best = ResolvedPlace{name, kind, type, score, why};
  };
  auto rank = [](const std::vector<std::string_view>& list,
                 std::string_view v) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < list.size(); ++i)
      if (list[i] == v) return i;
    return std::nullopt;
  };
  const PlacePhrase* lex = mention.lexicon;
  for (const world::Entity& e : world.entities()) {
    double base = 0.0;
    std::string why;
    if (lex != nullptr)
      if (auto r = rank(lex->entity_types, e.type)) {
        base = 3.0 - 0.1 * static_cast<double>(*r);
        why = "entity type " + e.type;
      }
    consider(e.name, ResolvedPlace::Kind::kEntity, e.type, base, why);
  }
  for (const world::Roi& r : world.rois()) {
    double base = 0.0;
    std::string why;
    if (lex != nullptr)
      if (auto k = rank(lex->roi_kinds, r.kind)) {
        base = 2.5 - 0.1 * static_cast<double>(*k);
        why = "ROI kind " + r.kind;
      }
    consider(r.name, ResolvedPlace::Kind::kRoi, r.kind, base, why);
  }
  for (const world::Zone& z : world.zones()) {
    double base = 0.0;
    std::string why;
    if (lex != nullptr)
      if (auto k = rank(lex->zone_types, z.type)) {
        base = 2.0 - 0.1 * static_cast<double>(*k);
        why = "zone type " + z.type;
      }
    consider(z.name, ResolvedPlace::Kind::kZone, z.type, base, why);
  }
  for (const world::Door& d : world.doors()) {
    double base = 0.0;
    std::string why;
    if (lex != nullptr && lex->doors && (!lex->exterior || !d.other)) {
      base = lex->exterior ? 2.2 : 1.5;
      why = d.other ? "door" : "door to the outside";
    }
    consider(d.name, ResolvedPlace::Kind::kDoor, "door", base, why);
  }
  return best;
}

Json to_json(const ResolvedPlace& place) {
  return Json{{"name", place.name},
              {"kind", std::string(to_string(place.kind))},
              {"type", place.type},
              {"score", place.score},
              {"why", place.why}};
}

}  // namespace socsim::scenario
