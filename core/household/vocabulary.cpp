#include "core/household/vocabulary.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace socsim::household {
namespace {

const std::set<std::string, std::less<>>& stop_words() {
  static const std::set<std::string, std::less<>> words = {
      "a",   "an", "the",  "my", "his", "her", "their", "our", "some", "of",
      "for", "to", "with", "on", "in",  "at",  "up",    "out", "and"};
  return words;
}

std::string stem(std::string w) {
  if (w.size() > 4 && w.compare(w.size() - 3, 3, "ies") == 0) return w.substr(0, w.size() - 3) + "y";
  if (w.size() > 4 && w.compare(w.size() - 2, 2, "es") == 0 &&
      (w[w.size() - 3] == 's' || w[w.size() - 3] == 'h'))
    return w.substr(0, w.size() - 2);
  if (w.size() > 3 && w.back() == 's' && w[w.size() - 2] != 's') return w.substr(0, w.size() - 1);
  return w;
}

std::vector<std::string> words_of(std::string_view name) {
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty() && !stop_words().count(cur)) out.push_back(stem(cur));
    cur.clear();
  };
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u))
      cur += static_cast<char>(std::tolower(u));
    else if (c == '\'')
      continue;
    else
      flush();
  }
  flush();
  return out;
}

// Content words without the -ing verb form, for the fuzzy comparison.
std::set<std::string> content_set(std::string_view name) {
  std::set<std::string> s;
  for (std::string w : words_of(name)) {
    if (w.size() > 5 && w.compare(w.size() - 3, 3, "ing") == 0) w = w.substr(0, w.size() - 3);
    s.insert(w);
  }
  return s;
}

double jaccard(const std::set<std::string>& a, const std::set<std::string>& b) {
  if (a.empty() || b.empty()) return 0.0;
  std::size_t common = 0;
  for (const auto& w : a) common += b.count(w);
  return static_cast<double>(common) / static_cast<double>(a.size() + b.size() - common);
}

}  // namespace

std::string ActivityVocabulary::normalise(std::string_view name) {
  std::string key;
  for (const auto& w : words_of(name)) key += (key.empty() ? "" : " ") + w;
  return key;
}

ActivityVocabulary ActivityVocabulary::initial(const HouseholdKnowledge& knowledge) {
  ActivityVocabulary v(&knowledge);
  for (std::size_t i = 0; i < knowledge.activities.size(); ++i) {
    const auto& a = knowledge.activities[i];
    v.curated_keys_[normalise(a.name)] = a.name;
    for (const auto& s : a.synonyms) v.curated_keys_.emplace(normalise(s), a.name);
    if (!a.base) continue;
    v.entries_[normalise(a.name)] = {a.name, a.name, static_cast<int>(i)};
    for (const auto& s : a.synonyms)
      v.entries_.emplace(normalise(s), VocabularyEntry{s, a.name, static_cast<int>(i)});
  }
  return v;
}

std::optional<ActivityVocabulary::Resolution> ActivityVocabulary::match(const std::string& key) const {
  if (auto it = entries_.find(key); it != entries_.end())
    return Resolution{it->second.primary, it->second.activity, false, false};
  if (auto it = curated_keys_.find(key); it != curated_keys_.end())
    return Resolution{it->second, knowledge_->activity_index(it->second), true, false};
  return std::nullopt;
}

std::optional<ActivityVocabulary::Resolution> ActivityVocabulary::resolve(std::string_view name) const {
  return match(normalise(name));
}

ActivityVocabulary::Resolution ActivityVocabulary::add(std::string_view name) {
  const std::string key = normalise(name);
  if (auto r = match(key)) {
    if (r->new_name) entries_[key] = {std::string(name), r->primary, r->activity};
    return *r;
  }
  // Unknown wording: merge into the closest primary (known to the vocabulary or curated).
  const auto words = content_set(name);
  double best = 0.0;
  std::string best_primary;
  int best_activity = -1;
  auto consider = [&](const std::string& candidate, const std::string& primary, int activity) {
    const double j = jaccard(words, content_set(candidate));
    if (j > best || (j == best && j > 0.0 && primary < best_primary)) {
      best = j;
      best_primary = primary;
      best_activity = activity;
    }
  };
  for (const auto& [k, e] : entries_) consider(e.name, e.primary, e.activity);
  for (const auto& [k, primary] : curated_keys_) consider(k, primary, knowledge_->activity_index(primary));
  Resolution r;
  r.new_name = true;
  if (best >= 0.6) {
    r.primary = best_primary;
    r.activity = best_activity;
  } else {
    r.primary = std::string(name);
    r.activity = -1;
    r.new_primary = true;
  }
  entries_[key] = {std::string(name), r.primary, r.activity};
  return r;
}

std::size_t ActivityVocabulary::primary_count() const {
  std::set<std::string> primaries;
  for (const auto& [k, e] : entries_) primaries.insert(e.primary);
  return primaries.size();
}

std::vector<VocabularyEntry> ActivityVocabulary::entries() const {
  std::vector<VocabularyEntry> out;
  for (const auto& [k, e] : entries_) out.push_back(e);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

std::map<std::string, std::string> ActivityVocabulary::aliases() const {
  std::map<std::string, std::string> out;
  for (const auto& [k, e] : entries_)
    if (e.name != e.primary) out[e.name] = e.primary;
  return out;
}

}  // namespace socsim::household
