#pragma once
// What a prompt asks a world to hold, typed: counts of features ("three exits", "two
// checkouts"), rooms and areas it names ("a waiting room"), objects it names ("a music
// system"), and how many people will be in it. The prompt reader fills it; floor-plan
// generators honour it; count_feature() says how many of a feature a world has.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/world/world.hpp"

namespace socsim::world {

enum class Feature {
  kExit,       // doors to the outside
  kEntrance,   // doors to the outside (a plan has as many as the larger of exits and entrances)
  kDoor,       // every door
  kCounter,    // service counters: reception, serving, information (not check-outs)
  kCheckout,   // check-outs (counters where people pay)
  kGate,       // ticket gates, boarding gates
  kElevator,   // lift doors
  kStair,      // stairs (a stair core on a single-storey plan)
  kEscalator,  // escalators
  kTable,      // tables people sit at (dining, meeting, café, library)
  kSeat,       // chairs, seats, benches, sofas
  kDesk,       // desks
  kBed,        // beds
  kShelf,      // shelves (shops, libraries, stores)
  kRack,       // storage racks
  kScreen,     // screens (cinema, lecture, departure boards)
  kStage,      // stages
  kBar,        // bar counters
  kLocker,     // lockers
  kPlatform,   // railway platforms (zones)
  kToilet,     // toilets (rooms)
};

struct FeatureInfo {
  Feature feature;
  std::string_view key;     // JSON name, singular: "exit", "checkout"
  std::string_view plural;  // "exits"
  int max_count;            // the largest count a request may ask for
};
std::span<const FeatureInfo> features();
const FeatureInfo& info(Feature feature);
std::string_view to_string(Feature feature);
// The feature a word or phrase names, singular or plural, with a few synonyms ("fire exit",
// "till", "turnstile", "lift", "staircase", "bench"); nullopt for other words.
std::optional<Feature> feature_from_word(std::string_view words);

struct FeatureCount {
  Feature feature = Feature::kExit;
  int count = 0;
  bool at_least = false;  // "at least three exits"; otherwise exactly `count`
  std::string words;      // as the prompt said it ("emergency exits"), for messages; may be empty
  friend bool operator==(const FeatureCount&, const FeatureCount&) = default;
};

// A room or area the prompt names. `type` is a room type ("waiting_room") or an ROI kind
// ("queue_lane") as far as the reader knows it; empty lets the generator decide by the name.
struct NamedRoom {
  std::string name;  // as written: "waiting room", "maternity ward"
  std::string type;
  int count = 1;
  friend bool operator==(const NamedRoom&, const NamedRoom&) = default;
};

// An object the prompt names ("music system", "coffee machine"): placed as an entity of
// `type` (default: the name in snake case), in the named room when one is given.
struct NamedObject {
  std::string name;
  std::string type;
  int count = 1;
  std::string room;  // a room name or type of the plan; empty: wherever it fits best
  friend bool operator==(const NamedObject&, const NamedObject&) = default;
};

struct WorldRequirements {
  std::vector<FeatureCount> features;  // one entry per feature
  std::vector<NamedRoom> rooms;
  std::vector<NamedObject> objects;
  std::optional<int> occupants;  // people the scenario puts in the building at once
  [[nodiscard]] bool empty() const {
    return features.empty() && rooms.empty() && objects.empty() && !occupants;
  }
  [[nodiscard]] const FeatureCount* find(Feature feature) const;
  friend bool operator==(const WorldRequirements&, const WorldRequirements&) = default;
};

inline constexpr std::size_t kMaxNamedRooms = 60;
inline constexpr std::size_t kMaxNamedObjects = 60;
inline constexpr int kMaxNamedCount = 30;
inline constexpr int kMaxOccupants = 100'000;

// {features: [{feature, count, at_least?, words?}], rooms: [{name, type?, count?}],
//  objects: [{name, type?, count?, room?}], occupants?}. kValidation with one FieldError per bad
// field, each pointer prefixed by `pointer` (e.g. "/requirements").
Result<WorldRequirements> world_requirements_from_json(const Json& j, const std::string& pointer = "");
Json to_json(const WorldRequirements& requirements);

// An object or room name in the form entity and zone types use: lower case, words joined by '_'.
std::string snake_case(std::string_view words);

// How many of a feature the world has (see Feature for what counts).
int count_feature(const World& world, Feature feature);
// Whether an entity of this type and these affordances is one of a feature (not for the
// features that are doors or zones: exits, entrances, doors, platforms, toilets).
bool entity_is(Feature feature, std::string_view type, std::span<const std::string> affordances);

}  // namespace socsim::world
