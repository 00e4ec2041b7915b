#pragma once
// New personas on request (paper 000 §IV: "generate more"): offline, composed from curated parts
// (names by culture, occupations with their hours, household roles, traits, hobbies, thoughts),
// each checked to read back as intended and to be no near-duplicate of the existing ones.
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
std::vector<std::string> known_occupations();

// `count` personas fitting the constraints, none a near-duplicate of `existing` or of each other.
// Deterministic in the seed. kValidation naming /constraints/... when no persona can fit.
Result<std::vector<Persona>> generate_personas_offline(const PersonaRequest& request,
                                                       std::span<const Persona> existing);

}  // namespace socsim::household
