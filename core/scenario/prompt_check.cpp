#include "core/scenario/prompt_check.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "core/scenario/wordnet.hpp"

namespace socsim::scenario {
namespace {

// One code point and its length in bytes; nullopt on a malformed sequence.
std::optional<std::pair<char32_t, std::size_t>> decode(std::string_view s, std::size_t i) {
  const auto b0 = static_cast<unsigned char>(s[i]);
  if (b0 < 0x80) return std::make_pair(static_cast<char32_t>(b0), std::size_t{1});
  std::size_t n = 0;
  char32_t cp = 0;
  if ((b0 & 0xE0) == 0xC0) {
    n = 2;
    cp = b0 & 0x1F;
  } else if ((b0 & 0xF0) == 0xE0) {
    n = 3;
    cp = b0 & 0x0F;
  } else if ((b0 & 0xF8) == 0xF0) {
    n = 4;
    cp = b0 & 0x07;
  } else {
    return std::nullopt;
  }
  if (i + n > s.size()) return std::nullopt;
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(s[i + k]);
    if ((b & 0xC0) != 0x80) return std::nullopt;
    cp = (cp << 6) | (b & 0x3F);
  }
  static constexpr std::array<char32_t, 5> kMin = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
    return std::nullopt;  // overlong, surrogate
  return std::make_pair(cp, n);
}

bool is_space(char32_t c) {
  return c == ' ' || (c >= 0x09 && c <= 0x0D) || c == 0x85 || c == 0xA0 || c == 0x1680 ||
         (c >= 0x2000 && c <= 0x200B) || c == 0x2028 || c == 0x2029 || c == 0x202F || c == 0x205F ||
         c == 0x3000 || c == 0xFEFF;
}

bool is_latin_letter(char32_t c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
         (c >= 0xC0 && c <= 0x24F && c != 0xD7 && c != 0xF7) ||  // Latin-1 letters, Latin Extended-A/B
         (c >= 0x1E00 && c <= 0x1EFF);                           // Latin Extended Additional (Vietnamese …)
}

// A Latin letter in lower case with its accent dropped (loanwords: café, naïve, façade); letters
// beyond Latin-1 become '?', which no English word contains.
char folded(char32_t c) {
  if (c >= 'A' && c <= 'Z') return static_cast<char>(c - 'A' + 'a');
  if (c < 0x80) return static_cast<char>(c);
  if (c == 0xFF) return 'y';
  if (c < 0xC0 || c > 0xFF) return '?';
  // U+00C0 … U+00FF, upper and lower case share a row (the lower case one is 0x20 higher).
  static constexpr std::string_view kLatin1 = "aaaaaaaceeeeiiiidnooooo?ouuuuyts";
  return kLatin1[(c - 0xC0) % 0x20];
}

// Letters of the other scripts a prompt may be written in, by block; nullptr for everything else
// (digits, punctuation, symbols, emoji: they say nothing about the language).
const char* other_script(char32_t c) {
  struct Block {
    char32_t first, last;
    const char* name;
  };
  static constexpr std::array<Block, 27> kBlocks = {{
      {0x0370, 0x03FF, "Greek"},       {0x1F00, 0x1FFF, "Greek"},    {0x0400, 0x052F, "Cyrillic"},
      {0x2DE0, 0x2DFF, "Cyrillic"},    {0xA640, 0xA69F, "Cyrillic"}, {0x0530, 0x058F, "Armenian"},
      {0x0590, 0x05FF, "Hebrew"},      {0xFB1D, 0xFB4F, "Hebrew"},   {0x0600, 0x08FF, "Arabic"},
      {0xFB50, 0xFDFF, "Arabic"},      {0xFE70, 0xFEFF, "Arabic"},   {0x0900, 0x0DFF, "Indic"},
      {0x0E00, 0x0EFF, "Thai or Lao"}, {0x0F00, 0x0FFF, "Tibetan"},  {0x1000, 0x109F, "Myanmar"},
      {0x10A0, 0x10FF, "Georgian"},    {0x1100, 0x11FF, "Hangul"},   {0x3130, 0x318F, "Hangul"},
      {0xAC00, 0xD7AF, "Hangul"},      {0x1200, 0x139F, "Ethiopic"}, {0x1780, 0x17FF, "Khmer"},
      {0x3040, 0x30FF, "Kana"},        {0xFF66, 0xFF9F, "Kana"},     {0x2E80, 0x2FDF, "Han"},
      {0x3400, 0x9FFF, "Han"},         {0xF900, 0xFAFF, "Han"},      {0x20000, 0x3FFFF, "Han"},
  }};
  for (const auto& b : kBlocks)
    if (c >= b.first && c <= b.last) return b.name;
  return nullptr;
}

// Words a reader of English knows that WordNet leaves out: it holds nouns, verbs, adjectives
// and adverbs only.
const std::set<std::string, std::less<>>& function_words() {
  static const std::set<std::string, std::less<>> kWords = {
      "a",          "about",    "above",   "across",     "after",      "against",  "all",       "along",
      "also",       "although", "am",      "amid",       "among",      "amongst",  "an",        "and",
      "another",    "any",      "anybody", "anyone",     "anything",   "are",      "around",    "as",
      "at",         "be",       "because", "been",       "before",     "behind",   "being",     "below",
      "beneath",    "beside",   "besides", "between",    "beyond",     "both",     "but",       "by",
      "can",        "cannot",   "could",   "did",        "do",         "does",     "doing",     "done",
      "down",       "during",   "each",    "either",     "else",       "every",    "everybody", "everyone",
      "everything", "except",   "few",     "for",        "from",       "had",      "has",       "have",
      "having",     "he",       "her",     "here",       "hers",       "herself",  "him",       "himself",
      "his",        "how",      "i",       "if",         "in",         "inside",   "into",      "is",
      "it",         "its",      "itself",  "just",       "least",      "less",     "many",      "may",
      "me",         "might",    "mine",    "more",       "most",       "much",     "must",      "my",
      "near",       "neither",  "next",    "no",         "nobody",     "none",     "nor",       "not",
      "nothing",    "of",       "off",     "on",         "once",       "one",      "onto",      "or",
      "other",      "others",   "our",     "ours",       "out",        "outside",  "over",      "own",
      "per",        "s",        "several", "shall",      "she",        "should",   "since",     "so",
      "some",       "somebody", "someone", "something",  "such",       "than",     "that",      "the",
      "their",      "theirs",   "them",    "themselves", "then",       "there",    "these",     "they",
      "this",       "those",    "though",  "through",    "throughout", "till",     "to",        "too",
      "toward",     "towards",  "under",   "unless",     "until",      "up",       "upon",      "us",
      "via",        "was",      "we",      "were",       "what",       "whatever", "when",      "whenever",
      "where",      "whereas",  "whether", "which",      "while",      "who",      "whoever",   "whole",
      "whom",       "whose",    "why",     "will",       "with",       "within",   "without",   "would",
      "yet",        "you",      "your",    "yours",      "yourself",   "aren't",   "can't",     "couldn't",
      "didn't",     "doesn't",  "don't",   "hadn't",     "hasn't",     "haven't",  "go",        "hi",
      "ok",         "ox",       "tv",      "pc",         "id",         "uk",       "us",        "isn't",
      "shouldn't",  "they're",  "wasn't",  "we're",      "weren't",    "won't",    "wouldn't",  "you're",
  };
  return kWords;
}

}  // namespace

double LanguageReading::english_share() const {
  return words == 0 ? 1.0 : static_cast<double>(english_words) / static_cast<double>(words);
}

Status check_prompt_form(std::string_view prompt, const PromptRules& rules) {
  auto refuse = [](const std::string& detail, const std::string& message) {
    return fail(ErrorCode::kValidation, detail, {{"/prompt", message}});
  };
  if (prompt.empty())
    return refuse("the prompt is empty", "must not be empty: describe who is where doing what");
  if (prompt.size() > rules.max_bytes)
    return refuse("the prompt is too long", "must be at most " + std::to_string(rules.max_bytes) +
                                                " bytes (got " + std::to_string(prompt.size()) + ")");
  bool only_space = true;
  for (std::size_t i = 0; i < prompt.size();) {
    auto cp = decode(prompt, i);
    if (!cp)
      return refuse("the prompt is not UTF-8 text",
                    "byte " + std::to_string(i) + " starts no UTF-8 character");
    only_space = only_space && is_space(cp->first);
    i += cp->second;
  }
  if (only_space)
    return refuse("the prompt is only white space", "must contain words: describe who is where doing what");
  return {};
}

LanguageReading read_language(std::string_view prompt, const KnownWord& known) {
  LanguageReading r;
  std::map<std::string, std::size_t> scripts;
  std::vector<std::string> unknown;
  std::string word;     // lower case, accents folded ("café" → "cafe"): what is looked up
  std::string written;  // as written, for the message
  auto end_word = [&] {
    // "librarian's" → "librarian"; a lone apostrophe is no word.
    while (!word.empty() && word.back() == '\'') {
      word.pop_back();
      written.pop_back();
    }
    if (word.size() > 2 && word.compare(word.size() - 2, 2, "'s") == 0) {
      word.resize(word.size() - 2);
      written.resize(written.size() - 2);
    }
    if (!word.empty()) {
      ++r.words;
      if (known(word)) {
        ++r.english_words;
      } else if (unknown.size() < 3 && std::find(unknown.begin(), unknown.end(), written) == unknown.end()) {
        unknown.push_back(written);
      }
    }
    word.clear();
    written.clear();
  };
  for (std::size_t i = 0; i < prompt.size();) {
    auto cp = decode(prompt, i);
    if (!cp) {  // not text: ends the word, says nothing
      end_word();
      ++i;
      continue;
    }
    const char32_t c = cp->first;
    if (is_latin_letter(c)) {
      ++r.latin_letters;
      word.push_back(folded(c));
      written.append(prompt.substr(i, cp->second));
    } else if ((c == '\'' || c == 0x2019) && !word.empty()) {
      word.push_back('\'');
      written.push_back('\'');
    } else {
      end_word();
      if (const char* script = other_script(c)) {
        ++r.other_letters;
        ++scripts[script];
      }
    }
    i += cp->second;
  }
  end_word();
  std::size_t most = 0;
  for (const auto& [name, n] : scripts) {
    if (n > most) {
      most = n;
      r.other_script = name;
    }
  }
  for (std::size_t k = 0; k < unknown.size(); ++k)
    r.unknown_examples += (k == 0 ? "'" : ", '") + unknown[k] + "'";
  return r;
}

Status check_prompt_language(std::string_view prompt, const KnownWord& known, const PromptRules& rules) {
  const LanguageReading r = read_language(prompt, known);
  const std::size_t letters = r.latin_letters + r.other_letters;
  if (letters > 0 &&
      static_cast<double>(r.other_letters) > rules.max_other_script_share * static_cast<double>(letters)) {
    return fail(
        ErrorCode::kValidation, "the prompt is not in English",
        {{"/prompt", "socsim reads English prompts; this one is written in " + r.other_script + " script (" +
                         std::to_string(r.other_letters) + " of its " + std::to_string(letters) +
                         " letters). Please describe the scenario in English."}});
  }
  if (r.words >= rules.min_words_for_language && r.english_share() < rules.min_english_share) {
    return fail(ErrorCode::kValidation, "the prompt is not in English",
                {{"/prompt", "socsim reads English prompts; only " + std::to_string(r.english_words) +
                                 " of its " + std::to_string(r.words) +
                                 " words are English words it knows (not: " + r.unknown_examples +
                                 "). Please describe the scenario in English."}});
  }
  return {};
}

Status check_prompt_content(const ScenarioIntent& intent) {
  const bool people = !intent.groups.empty() || intent.background || !intent.density.empty();
  const bool place = intent.venue.has_value() || !intent.world.rooms.empty() ||
                     !intent.world.features.empty() || !intent.world.objects.empty();
  const bool activity = std::any_of(intent.categories.begin(), intent.categories.end(),
                                    [](const CategoryMention& c) { return c.score > 0.0; });
  if (people || place || activity || !intent.robots.empty()) return {};
  std::string ignored;
  for (const auto& w : intent.warnings) {
    if (w.span.end > w.span.begin) ignored += (ignored.empty() ? " (" : "; ") + w.message;
  }
  if (!ignored.empty()) ignored += ")";
  return fail(ErrorCode::kValidation, "the prompt names no person, place or activity",
              {{"/prompt",
                "found no people (\"three nurses\", \"visitors\"), no place (\"a library\", \"the waiting "
                "room\", \"two exits\") and no activity (\"queue\", \"evacuate\", \"chat\") to build a "
                "scenario from" +
                    ignored}});
}

Status check_prompt(std::string_view prompt, const ScenarioIntent& intent, const KnownWord& known,
                    const PromptRules& rules) {
  if (auto s = check_prompt_form(prompt, rules); !s) return s;
  if (auto s = check_prompt_language(prompt, known, rules); !s) return s;
  return check_prompt_content(intent);
}

KnownWord english_words(const WordNet& wordnet) {
  return [&wordnet](std::string_view w) {
    if (function_words().count(w) > 0) return true;
    // WordNet's one- and two-letter entries are abbreviations and symbols (la, de, es, en):
    // French and Spanish articles would pass as English.
    if (w.size() <= 2 || w.find_first_not_of("abcdefghijklmnopqrstuvwxyz'") != std::string_view::npos)
      return false;
    // Nouns by their common senses only ("der", "gare" are known as names or abbreviations). One
    // cached lookup gives the other parts of speech too, and the intent reader asks for the same words.
    const NounEntry& e = wordnet.noun(w);
    return !e.senses.empty() || e.verb || e.adjective || e.adverb;
  };
}

}  // namespace socsim::scenario
