#pragma once
// Whether a prompt can become a scenario, decided before any job is queued: its form (not empty,
// not only white space, within the byte limit, UTF-8), its language (socsim reads English: most
// letters Latin, most words English words) and its content (a person, a place or an activity the
// reader understood). Every refusal is kValidation (422) at /prompt with a message that says why.
// Pure: the words a reader knows come in as a function (english_words() wraps WordNet).
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "core/common/error.hpp"
#include "core/scenario/scenario_intent.hpp"

namespace socsim::scenario {

class WordNet;

// Whether a lower-case word (ASCII letters, possibly with non-ASCII Latin letters) is English.
using KnownWord = std::function<bool(std::string_view)>;

struct PromptRules {
  std::size_t max_bytes = 4000;
  // Non-English when more than this share of the letters belongs to another script (Cyrillic,
  // Greek, Arabic, Hebrew, Devanagari, Han, Kana, Hangul, Thai …).
  double max_other_script_share = 0.2;
  // Non-English when fewer than this share of the words are English words; judged only from
  // this many words on (a two-word prompt of names is left to the content check).
  double min_english_share = 0.5;
  std::size_t min_words_for_language = 3;
};

// How the language rule saw a prompt (for messages, tests and the docs' figures).
struct LanguageReading {
  std::size_t latin_letters = 0;
  std::size_t other_letters = 0;
  std::string other_script;  // the most frequent other script ("Cyrillic"), "" when none
  std::size_t words = 0;     // words of Latin letters
  std::size_t english_words = 0;
  std::string unknown_examples;  // up to three words not known, quoted, for the message

  [[nodiscard]] double english_share() const;
};

// Empty, white space only, over the limit, not UTF-8.
Status check_prompt_form(std::string_view prompt, const PromptRules& rules);

LanguageReading read_language(std::string_view prompt, const KnownWord& known);
// Another script, or too few English words: "socsim reads English prompts …".
Status check_prompt_language(std::string_view prompt, const KnownWord& known, const PromptRules& rules);

// No people, no venue or named room or feature, no robot and no Table II activity: nothing to
// simulate. Density or background words ("a busy afternoon") count as people.
Status check_prompt_content(const ScenarioIntent& intent);

// Form, then language, then content (`intent` is the prompt's interpretation).
Status check_prompt(std::string_view prompt, const ScenarioIntent& intent, const KnownWord& known,
                    const PromptRules& rules);

// English words: a list of function words (articles, pronouns, prepositions, auxiliaries …) and
// every noun, verb, adjective and adverb WordNet knows (after its morphology).
KnownWord english_words(const WordNet& wordnet);

}  // namespace socsim::scenario
