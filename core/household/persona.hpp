#pragma once
// Residents' personas with the 8 fields of paper 000 (Fig. 2a): validated reading from JSON
// (errors name the field by JSON pointer), and the traits the offline generators read from the
// free text (sleep times, work pattern and days, tidiness, interests).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/household/types.hpp"

namespace socsim::household {

struct Persona {
  std::string name;
  int age = 0;
  std::string gender;
  std::string routine;
  std::vector<std::string> personality;
  std::string occupation;
  std::string thoughts;
  std::string lifestyle;
  friend bool operator==(const Persona&, const Persona&) = default;
};

// Reads a persona; every bad or missing field is reported with its JSON pointer below `pointer`.
Result<Persona> persona_from_json(const Json& json, const std::string& pointer = "");
Json to_json(const Persona& persona);
// Stable id from the name: "Margit Halvorsen" → "margit-halvorsen".
std::string persona_id(const Persona& persona);

enum class WorkPattern : std::uint8_t {
  kCommute,       // works away from home in the day
  kRemote,        // works at home on work days
  kHybrid,        // some work days at home, the others away
  kNightShift,    // works through the night, sleeps by day
  kEveningShift,  // works afternoon to late night
  kSplitShift,    // two blocks away with a break at home
  kCollege,       // university classes away on weekdays, study at home
  kSchool,        // school child
  kPreschool,     // kindergarten or at home, naps
  kRetired,
  kHomemaker,  // stay-at-home parent or homemaker
  kFreelance,  // works at home, irregular
  kJobSeeker,
};
std::string_view work_pattern_name(WorkPattern pattern);
std::optional<WorkPattern> parse_work_pattern(std::string_view name);  // "night_shift" → kNightShift

// Minutes after 00:00; bedtimes after midnight are ≥ 1440.
struct SleepTimes {
  int bed = 23 * 60;
  int wake = 7 * 60;
};

struct PersonaTraits {
  WorkPattern work = WorkPattern::kCommute;
  std::array<bool, 7> work_days{};         // Monday first
  std::array<bool, 7> home_work_days{};    // hybrid: days worked at home
  int work_start = 9 * 60;                 // minutes after 00:00 of the work day
  int work_end = 17 * 60;                  // may pass 1440 (night and evening shifts)
  int second_start = -1, second_end = -1;  // split shift
  SleepTimes work_night;                   // before a work/school day (or, day sleepers: the day sleep)
  SleepTimes free_night;                   // before a free day
  bool naps = false;
  bool child = false;     // under 13: does not cook
  double tidiness = 0.5;  // 0 messy … 1 meticulous
  double sociability = 0.5;
  int prayers_per_day = 0;
  std::string text;  // lower-case fields, for keyword matching
};

// Reads the traits from the persona's text (deterministic; no randomness).
PersonaTraits infer_traits(const Persona& persona);
// Whole-word, case-insensitive phrase match in the persona's text (plus its gender).
bool mentions(const PersonaTraits& traits, std::string_view phrase);

}  // namespace socsim::household
