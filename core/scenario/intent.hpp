#pragma once
// Prompt understanding for the offline generator: which Table II categories a prompt asks for
// (per clause, weighted), who takes part and how many ("two nurses", "about thirty visitors"),
// where ("near the elevator", resolved to the world's places by type and name) and when ("after
// 20 seconds", "for two minutes"), with every match recorded for provenance.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/scenario/lexicon.hpp"
#include "core/world/world.hpp"

namespace socsim::scenario {

struct CategoryScore {
  Category category = Category::kNormalOperation;
  double score = 0.0;
  std::vector<std::string> phrases;  // the lexicon phrases that matched
};

struct RoleMention {
  std::string role;                  // program role ("nurse")
  std::string phrase;                // as written ("nurses")
  std::optional<std::size_t> count;  // bound count, when the prompt gives one
  std::string count_phrase;          // "about thirty", "2", "a dozen"
  bool approximate = false;
  std::size_t clause = 0;
  std::size_t offset = 0;  // byte offset of the role word
};

struct PlaceMention {
  std::string phrase;                    // "the elevator", "reception desk"
  std::vector<std::string> words;        // content words ("elevator")
  const PlacePhrase* lexicon = nullptr;  // the lexicon entry it matched, if any
  std::string preposition;               // "near", "at", "" when mentioned without one
  std::size_t clause = 0;
  std::size_t offset = 0;
};

struct Timing {
  std::optional<double> start_after_s;  // "after 20 seconds", "at 30 s", "in a minute"
  std::optional<double> duration_s;     // "for two minutes", "lasting 90 s"
  std::vector<std::string> phrases;
};

// One clause of the prompt ("patients queue at the reception desk" / "staff chat near the corridor").
struct Clause {
  std::size_t index = 0;
  std::string text;
  std::vector<CategoryScore> categories;  // best first
  std::vector<RoleMention> roles;
  std::vector<PlaceMention> places;
};

struct Intent {
  std::string prompt;
  std::vector<CategoryScore> categories;  // whole prompt, best first; empty when nothing matched
  std::vector<Clause> clauses;
  std::optional<std::size_t> crowd_size;  // "a crowd of 200" without a role
  std::string crowd_phrase;
  std::size_t crowd_clause = 0;
  Timing timing;
};

// Never fails: an empty or unmatched prompt gives an Intent without categories.
Intent parse_intent(std::string_view prompt);
Json to_json(const Intent& intent);

// A place of the world a mention resolved to.
struct ResolvedPlace {
  enum class Kind { kRoi, kEntity, kDoor, kZone };
  std::string name;
  Kind kind = Kind::kRoi;
  std::string type;  // ROI kind, entity type, "door" or zone type
  double score = 0.0;
  std::string why;  // "entity type water_dispenser", "name word 'reception'" …
};
std::string_view to_string(ResolvedPlace::Kind kind);

// The best place of the world for a mention (lexicon types first, then words of names and types);
// nullopt when nothing in the world fits — the caller falls back and says so, it never invents a name.
std::optional<ResolvedPlace> resolve_place(const PlaceMention& mention, const world::World& world);
Json to_json(const ResolvedPlace& place);

}  // namespace socsim::scenario
