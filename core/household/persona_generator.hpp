#pragma once
// New personas on request (paper 000 §IV: "generate more"): offline, composed from curated parts
// (names by culture, occupations with their hours, household roles, traits, hobbies, thoughts —
// the household_persona_parts table of migration 0026), each checked to read back as intended
// and to be no near-duplicate of the existing ones.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/household/persona.hpp"

namespace socsim::household {

// Who lives with whom; shapes the lifestyle text and the age range.
enum class HouseholdRole : std::uint8_t { kSingle, kPartner, kParent, kChild, kGrandparent, kFlatmate };
std::string_view household_role_name(HouseholdRole role);  // "single", "partner", …
std::optional<HouseholdRole> parse_household_role(std::string_view name);

// The curated parts (one row of household_persona_parts each; see that migration for the fields).
// Text placeholders: {F} first name, {p}/{P} subject pronoun, {pp}/{PP} possessive, {po} object
// pronoun, {X} one of the occupation's variants.
struct CulturePart {
  std::vector<std::string> female, male, surnames;
};
struct OccupationPart {
  std::string key;
  std::vector<std::string> keywords;  // for the occupation constraint
  WorkPattern pattern = WorkPattern::kCommute;
  int min_age = 18, max_age = 70;
  std::vector<std::string> variants;  // {X}
  std::string text;
  int bed_lo = 0, bed_hi = 0, wake_lo = 0,
      wake_hi = 0;           // minutes after 00:00; bedtimes after midnight ≥ 1440
  bool day_sleeper = false;  // night shift: sleeps 8 am – 3 pm after a shift
  std::vector<std::string> thoughts;
  std::string habit;  // lifestyle phrase tied to the work ("" = none)
};
struct HobbyPart {
  std::string text;
  int min_age = 0, max_age = 0;
};
struct HouseholdRolePart {
  HouseholdRole role = HouseholdRole::kSingle;
  int min_age = 0, max_age = 0;
  std::vector<std::string> lines, thoughts;
};
struct PersonaParts {
  std::vector<CulturePart> cultures;
  std::vector<OccupationPart> occupations;
  OccupationPart fallback;  // a job the list does not know (its text is composed from the request)
  bool has_fallback = false;
  std::vector<HobbyPart> hobbies;
  std::vector<std::string> tidy_traits, messy_traits, social_traits, solitary_traits, other_traits;
  std::vector<std::string> tidy_habits, messy_habits;
  std::vector<HouseholdRolePart> roles;
};
// Adds one row (kind, name, JSON body); kStore naming the row when it is malformed.
Status add_persona_part(PersonaParts& parts, std::string_view kind, const std::string& name,
                        const Json& body);
// kStore naming what is missing (an empty or unmigrated table).
Status check_persona_parts(const PersonaParts& parts);

struct PersonaConstraints {
  std::optional<int> min_age, max_age;    // inclusive, 0 … 120
  std::optional<std::string> occupation;  // matched against the curated occupations ("nurse", "retired")
  std::optional<HouseholdRole> household_role;
  std::optional<std::string> gender;  // "female" | "male"
};

struct PersonaRequest {
  int count = 1;  // 1 … 200
  std::uint64_t seed = 0;
  PersonaConstraints constraints;
};

// Reads {count, seed, constraints: {min_age, max_age, occupation, household_role, gender}};
// every problem is named by JSON pointer below `pointer`.
Result<PersonaRequest> persona_request_from_json(const Json& json, const std::string& pointer = "");
Json to_json(const PersonaConstraints& constraints);

// The body of POST /api/v1/personas/generate: a PersonaRequest and how to make and keep them,
// {count, seed, constraints, generator: offline|llm, store: bool, model (llm only)}.
struct PersonaGenerateRequest {
  PersonaRequest personas;
  std::string generator = "offline";
  bool store = false;
  std::optional<std::string> model;
};
Result<PersonaGenerateRequest> persona_generate_request_from_json(const Json& json);

// Two personas are near-duplicates when they share an id (name), or have the same gender, ages
// within 5 years and mostly the same words in occupation, routine, lifestyle and personality.
double persona_similarity(const Persona& a, const Persona& b);  // content-word Jaccard, 0 … 1
bool near_duplicate(const Persona& a, const Persona& b);

// The occupations the offline generator knows (for messages and the API's documentation).
std::vector<std::string> known_occupations(const PersonaParts& parts);

// `count` personas fitting the constraints, none a near-duplicate of `existing` or of each other.
// Deterministic in the seed. kValidation naming /constraints/... when no persona can fit.
Result<std::vector<Persona>> generate_personas_offline(const PersonaRequest& request,
                                                       std::span<const Persona> existing,
                                                       const PersonaParts& parts);

}  // namespace socsim::household
