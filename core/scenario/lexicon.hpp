#pragma once
// The curated vocabulary the offline scenario generator reads prompts with: phrases of the seven
// scenario categories of paper 001 Table II (with weights), role words and their crowd
// parameters, count words ("a dozen", "thirty"), place phrases and the node queries per category.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace socsim::scenario {

enum class Category {
  kEmergency,
  kQueuing,
  kSocialParty,
  kCoffeeBreak,
  kReception,
  kBottleneck,
  kNormalOperation
};

std::span<const Category> all_categories();
std::string_view to_string(Category c);  // "emergency", "queuing", "social_party", …
std::optional<Category> category_from_string(std::string_view s);

// A prompt word: lower-cased text, its byte offset in the prompt and the clause it belongs to
// (clauses end at , ; . : ! ? and at "while", "whereas", "meanwhile", "then").
struct Token {
  std::string text;
  std::size_t offset = 0;
  std::size_t clause = 0;
  bool number = false;  // all digits (a decimal point allowed)
};
std::vector<Token> tokenize(std::string_view prompt);

struct CategoryPhrase {
  std::string_view phrase;  // space-separated words, matched on whole tokens
  Category category;
  double weight;
};
std::span<const CategoryPhrase> category_phrases();

// A role word ("nurses") and the program role it stands for ("nurse").
struct RoleWord {
  std::string_view phrase;
  std::string_view role;
};
std::span<const RoleWord> role_words();

// Crowd parameters of a role the built-in RoleTable lacks (nurse, visitor, …): desired speed
// Normal(mean, sd) clamped to [min, max] and body radius. nullopt for the built-in roles
// (adult, elderly, staff, jogger, stroller_pusher) and unknown names.
struct RoleProfile {
  std::string_view role;
  double mean, sd, min, max, radius;
};
std::optional<RoleProfile> role_profile(std::string_view role);
bool is_builtin_role(std::string_view role);

// Count words: "two" → 2, "a dozen" → 12, "a few" → 3, "several" → 5 (approximate ones flagged).
struct CountWord {
  std::string_view phrase;
  double value;
  bool approximate;
  bool multiplier;  // "hundred", "dozen": multiplies a preceding number ("two hundred")
};
std::span<const CountWord> count_words();
// Phrases that mark the following count as approximate ("about", "around", "up to" …).
std::span<const std::string_view> approximation_phrases();

// A place phrase of prompts and what it may resolve to in a world, strongest first: entity
// types, ROI kinds, zone types, doors (exterior = doors to the outside), and name words.
struct PlacePhrase {
  std::string_view phrase;
  std::vector<std::string_view> entity_types;
  std::vector<std::string_view> roi_kinds;
  std::vector<std::string_view> zone_types;
  bool doors = false;
  bool exterior = false;
  std::vector<std::string_view> name_words;
};
std::span<const PlacePhrase> place_phrases();
// Prepositions that introduce a place ("at", "near", "in front of" …), longest first.
std::span<const std::string_view> place_prepositions();

// The knowledge-store query used to retrieve behaviour nodes for a category, and the nodes its
// behaviour trees are assembled from.
std::string_view node_query(Category c);
std::span<const std::string_view> category_nodes(Category c);

}  // namespace socsim::scenario
