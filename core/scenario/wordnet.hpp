#pragma once
// WordNet 3.0 (Princeton, Debian wordnet-base) as the open vocabulary of prompt understanding:
// noun lemmas, lexicographer files (noun.person, noun.artifact, noun.group …), hypernym chains and
// parts of speech. Thread-safe (the C library is not: one lock around it) and cached per word.
// The data is read at run time from WNSEARCHDIR, else /usr/share/wordnet; when it is missing,
// open() fails with a message naming the package and the directory instead of crashing.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::scenario {

// What WordNet says about one noun (lower case, spaces or underscores for collocations).
struct NounSense {
  std::string lexfile;                 // "noun.person", "noun.artifact" …
  std::vector<std::string> hypernyms;  // first word of every hypernym synset up the chain, nearest first
};

struct NounEntry {
  bool known = false;             // WordNet has it as a noun (possibly after morphology)
  std::string lemma;              // base form ("children" → "child"), spaces for collocations
  std::vector<NounSense> senses;  // most frequent first, at most kMaxSenses
  bool verb = false;              // the surface word or its lemma is also a verb
  bool adjective = false;         // … an adjective
  bool adverb = false;            // … an adverb
  static constexpr std::size_t kMaxSenses = 4;
};

class WordNet {
 public:
  // The process-wide instance; the first call loads the data. Error (kInternal) when the data
  // files are missing, naming the directory searched and the package that provides them.
  static Result<const WordNet*> open();

  // The entry lives as long as the instance (cached; safe to hold across calls and threads).
  [[nodiscard]] const NounEntry& noun(std::string_view word) const;
  [[nodiscard]] bool is_verb(std::string_view word) const;
  [[nodiscard]] bool is_adjective(std::string_view word) const;
  [[nodiscard]] bool is_adverb(std::string_view word) const;
  [[nodiscard]] const std::string& directory() const { return directory_; }

  WordNet(const WordNet&) = delete;
  WordNet& operator=(const WordNet&) = delete;
  ~WordNet();

 private:
  explicit WordNet(std::string directory);
  struct Cache;
  std::string directory_;
  std::unique_ptr<Cache> cache_;
};

// The directory WordNet's data is read from (WNSEARCHDIR when set, else /usr/share/wordnet).
std::string wordnet_directory();

}  // namespace socsim::scenario
