#pragma once
// The activity vocabulary that schedules draw on and grow (paper 000 §IV-A): it starts from the
// curated base list, admits new activities as schedules use them, and merges synonyms so that
// they share one primary activity and its effects.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/household/knowledge.hpp"

namespace socsim::household {

struct VocabularyEntry {
  std::string name;     // as written in schedules
  std::string primary;  // the activity it merges into
  int activity = -1;    // index into HouseholdKnowledge::activities; -1 for a primary without curated effects
};

class ActivityVocabulary {
 public:
  // The starting list: the curated activities marked `base`, with their synonyms.
  static ActivityVocabulary initial(const HouseholdKnowledge& knowledge);

  struct Resolution {
    std::string primary;
    int activity = -1;
    bool new_name = false;     // the name was not in the vocabulary before
    bool new_primary = false;  // …and it became a primary of its own
  };
  // Adds a name as a schedule uses it. A name of a curated activity (primary or synonym, after
  // normalising case, articles and plurals) joins under that activity. Any other name merges into
  // the known primary whose content words it shares most (Jaccard ≥ 0.6), else it becomes a new
  // primary without curated effects.
  Resolution add(std::string_view name);
  // Looks a name up without adding it.
  [[nodiscard]] std::optional<Resolution> resolve(std::string_view name) const;

  [[nodiscard]] std::size_t name_count() const { return entries_.size(); }
  [[nodiscard]] std::size_t primary_count() const;
  [[nodiscard]] std::vector<VocabularyEntry> entries() const;  // sorted by name
  // name → primary for every name that is not itself a primary (like DynamicTHOR's activity_alias).
  [[nodiscard]] std::map<std::string, std::string> aliases() const;

  // Normalised key: lower case, articles and possessives dropped, simple plurals folded.
  static std::string normalise(std::string_view name);

 private:
  explicit ActivityVocabulary(const HouseholdKnowledge* k) : knowledge_(k) {}
  [[nodiscard]] std::optional<Resolution> match(const std::string& key) const;
  const HouseholdKnowledge* knowledge_;
  std::unordered_map<std::string, VocabularyEntry> entries_;   // by normalised key
  std::unordered_map<std::string, std::string> curated_keys_;  // normalised key → curated primary
};

}  // namespace socsim::household
