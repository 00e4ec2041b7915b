#pragma once
// What a prompt says, typed (schemas/intent.schema.json): the venue, the groups of people (role as
// written and normalised, a count that is exact / approximate / a range / unspecified, what they
// do, where, whether they move together), what the world must hold (counted features, named rooms
// and objects), exclusivity ("only", "except", "nobody else"), density words, robots and warnings
// for words it could not use. Every element keeps the byte span of the words it came from.
//
// Open vocabulary: nouns are classified with WordNet (wordnet.hpp) — a person (noun.person or a
// hypernym chain through person), a venue (a hypernym among the known building kinds), a room or
// area, an object (artifact) — and people are mapped to the nearest known role while keeping the
// user's word. Structure comes from a chunker over WordNet parts of speech: quantities and
// determiners attach to the noun phrase they precede, collectives ("a queue of 8 patients"),
// products ("two classes of 25 pupils each", "each with a queue of five", "one parent per child"),
// anaphora ("fourteen of them"), negation ("no visitors", "without any staff") and exceptions.
// Deterministic: the same prompt gives the same intent.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/scenario/lexicon.hpp"
#include "core/scenario/quantity.hpp"

namespace socsim::scenario {

struct VenueIntent {
  std::string type;  // venue kind: hospital, train_station, library, care_home … (see venue_types())
  std::string building_type;  // the nearest building type the world generator knows today
  std::string words;          // as written ("central train station")
  std::string why;            // "venue word 'station' after 'train'", "WordNet: motel → hotel"
  Span span;
};

struct PeopleGroup {
  std::string role;             // as written, singular, lower case: "security guard", "librarian"
  std::string normalized_role;  // nearest known role: nurse, doctor, worker, security, adult …
  std::string program_role;     // identifier for the scenario program ("security_guard", "adult")
  Count count;
  std::optional<Category> category;  // what they do, from their sentence (Table II)
  std::string activity;              // the verb as written ("queue", "chat"), "" when none
  std::string place;                 // place phrase as written ("at the reception desk"), "" when none
  Span place_span;
  bool together = false;  // "walk together", "a group of 15 tourists", "a family of four"
  std::string why;        // how the role was recognised
  Span span;              // the role words (with their count)
  std::size_t sentence = 0;
};

struct Feature {
  std::string name;  // as written, singular ("emergency exit", "checkout")
  std::string head;  // its last word ("exit")
  Count count;       // exact when said ("three exits", "the only open checkout"), else unspecified
  Span span;
};

struct NamedThing {
  std::string name;  // "waiting room", "music system"
  Span span;
};

struct WorldRequirements {
  std::vector<Feature> features;    // doors, exits, gates, counters, checkouts, tables, elevators …
  std::vector<NamedThing> rooms;    // rooms and areas named ("maternity ward", "staff room")
  std::vector<NamedThing> objects;  // other things named where people are ("music system")
};

struct Exclusivity {
  bool exclusive = false;            // nobody but the groups named
  std::vector<std::string> phrases;  // "only", "except for", "nobody else", "empty" …
  std::vector<Span> spans;
  std::vector<std::string> excluded_roles;  // "no visitors", "without any staff"
};

struct DensityWord {
  std::string word;   // "busy", "quiet", "crowded"
  std::string level;  // "high" or "low"
  Span span;
};

struct RobotMention {
  std::string words;  // "delivery robot"
  Count count;
  Span span;
};

struct IntentWarning {
  std::string message;
  Span span;
};

struct CategoryMention {
  Category category = Category::kNormalOperation;
  double score = 0.0;
  std::vector<std::string> phrases;
};

struct ScenarioIntent {
  std::string prompt;
  std::optional<VenueIntent> venue;
  std::vector<PeopleGroup> groups;
  WorldRequirements world;
  Exclusivity exclusivity;
  // The prompt asks for people beyond its groups ("lots of other people", "passers-by", or a
  // density word such as "busy" when no group has a count); `background_words` says which.
  bool background = false;
  std::vector<std::string> background_words;
  std::vector<DensityWord> density;
  std::vector<RobotMention> robots;
  std::vector<CategoryMention> categories;  // whole prompt, best first
  std::vector<IntentWarning> warnings;

  [[nodiscard]] Count total() const;  // sum of the groups (unspecified if one is)
};

// Errors: kInternal when WordNet's data is missing (the message says where it looked and which
// package provides it). Any text is accepted; a prompt without people gives no groups.
Result<ScenarioIntent> interpret_prompt(std::string_view prompt);

Json to_json(const ScenarioIntent& intent);
Json to_json(const Count& count);

// The venue kinds the reader knows (the building types of the worlds issue), and for each the
// nearest of knowledge::building_types() until the world generator has it.
std::vector<std::string_view> venue_types();
std::string_view nearest_building_type(std::string_view venue_type);

}  // namespace socsim::scenario
