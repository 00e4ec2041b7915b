#pragma once
// The curated household knowledge (personas, activity vocabulary with effects, receptacle and
// room programs), loaded once from the store's seed tables into plain structs that the pure
// generation functions take. Also stores posted personas.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/common/error.hpp"
#include "core/household/persona.hpp"
#include "core/household/persona_generator.hpp"
#include "core/household/types.hpp"
#include "core/store/store.hpp"

namespace socsim::household {

// An object an activity may involve, with its receptacle weights (un-normalised, > 0).
struct ObjectEffect {
  std::string type;
  double p = 0.0;  // p(o|a,l) before persona adjustments
  std::vector<std::pair<std::string, double>> receptacles;
};

// What an activity does to the house: where it happens and which objects it moves where.
struct ActivityEffects {
  std::array<double, kRoomTypeCount> rooms{};  // weights over room types (0 = never there)
  std::vector<ObjectEffect> objects;           // filtered per room by receptacle plausibility
};

// How an activity fits into a day.
enum class ActivityRole : std::uint8_t {
  kSleep,
  kNap,
  kWake,
  kMorningHygiene,
  kEveningHygiene,
  kDress,
  kToilet,
  kBreakfastPrep,
  kBreakfast,
  kLunchPrep,
  kLunch,
  kDinnerPrep,
  kDinner,
  kMealSetup,
  kSnack,
  kHotDrink,
  kDishCleanup,
  kChore,
  kLaundry,
  kArrive,
  kDepart,
  kBedtime,
  kLeisure,
  kHobby,
  kExercise,
  kWork,
  kStudy,
  kChildcare,
  kPet,
  kMedication,
  kSocialCall,
  kSocial,
  kPrayer,
  kLeaveHome,
};
std::optional<ActivityRole> parse_activity_role(std::string_view name);
std::string_view activity_role_name(ActivityRole role);
bool is_meal(ActivityRole role);

struct ActivitySpec {
  std::string name;  // primary name
  ActivityRole role = ActivityRole::kLeisure;
  std::vector<std::string> synonyms;
  int min_minutes = 5, max_minutes = 30;
  std::vector<std::pair<double, double>> windows;  // hours, end may pass 24
  std::vector<std::string> keywords;               // persona phrases that make it part of their life
  int min_age = 0, max_age = 200;
  double weight = 1.0;
  bool base = false;  // in the initial vocabulary (the paper's HOMER-like starting list)
  ActivityEffects effects;
  // True when the minute-of-day (0…1440, or later for windows passing midnight) is in a window.
  [[nodiscard]] bool in_window(int minute_of_day) const;
};

struct ReceptacleSpec {
  std::string type;
  std::vector<RoomType> rooms;
  double size_x = 1.0, size_z = 0.5, height = 0.8;
  bool middle = false;  // stands in the middle of the room (tables) rather than against a wall
  double mean_objects = 1.0;
  std::vector<std::pair<std::string, double>> contents;  // object type → weight (tidy-house placement)
  [[nodiscard]] bool allowed_in(RoomType room) const;
};

struct FurnitureRule {
  std::string type;
  double p = 1.0;
  int max_count = 1;
};

// A fixture the generator adds to a room: hung on a wall ("wall") or standing on a receptacle of
// the named type in the same room (a television on the TV stand).
struct FixtureRule {
  std::string type;
  double p = 1.0;
  int max_count = 1;
  std::string on = "wall";
};

struct RoomProgram {
  double min_area = 9.0, max_area = 16.0;
  std::vector<FurnitureRule> furniture;
  std::vector<FixtureRule> fixtures;
};

struct HouseholdKnowledge {
  std::vector<Persona> personas;  // built-in first, then posted ones
  std::vector<ActivitySpec> activities;
  std::vector<ReceptacleSpec> receptacles;
  std::array<RoomProgram, kRoomTypeCount> room_programs;
  std::vector<std::string> movable_types;  // sorted
  std::vector<std::string> fixture_types;  // sorted
  PersonaParts persona_parts;              // what new personas are composed from

  [[nodiscard]] const ActivitySpec* activity(std::string_view primary_name) const;
  [[nodiscard]] int activity_index(std::string_view primary_name) const;  // -1 when unknown
  [[nodiscard]] const ReceptacleSpec* receptacle(std::string_view type) const;
  [[nodiscard]] bool is_movable(std::string_view type) const;
  [[nodiscard]] bool is_fixture(std::string_view type) const;
  [[nodiscard]] const Persona* persona(std::string_view id) const;

  // Builds the lookup tables; call after filling the vectors by hand (tests do).
  void index();

 private:
  std::unordered_map<std::string, int> activity_by_name_;
  std::unordered_map<std::string, int> receptacle_by_type_;
  std::unordered_map<std::string, int> persona_by_id_;
};

// Reads every seed table (and posted personas) once.
Result<HouseholdKnowledge> load_household_knowledge(store::Store& store);
// Parses one activity row's JSON body (used by the loader and by tests of bad rows).
Result<ActivitySpec> activity_from_json(const std::string& name, const std::string& role, const Json& body);

// Stores a posted persona (validated by the caller with persona_from_json); kConflict when a
// built-in or another persona already has its id.
Status store_persona(store::Store& store, const Persona& persona);
Result<std::vector<Persona>> list_stored_personas(store::Store& store, bool include_builtin);

}  // namespace socsim::household
