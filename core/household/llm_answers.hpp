#pragma once
// What an LLM answer for each household artifact must be: its JSON Schema (from the embedded
// household schemas, made self-contained) and the semantic rules a schema cannot say, each
// problem named by JSON pointer into the answer so a repair round can quote it.
#include <span>
#include <string>
#include <string_view>

#include "core/common/json_schema.hpp"
#include "core/household/persona_generator.hpp"
#include "core/household/scene.hpp"
#include "core/household/schedule.hpp"

namespace socsim::household {

// artifact: persona, day_plan, activity_schedule, activity_database, hint, hint_interpretation.
Result<const JsonSchema*> answer_schema(std::string_view artifact);

// Inside the constraints (age, gender) and no near-duplicate of `existing`.
Status check_persona_answer(const Json& answer, const PersonaConstraints& constraints,
                            std::span<const Persona> existing);
// A day plan of this day and weekday, tiling 00:00–24:00, with at least four hours of sleep.
Status check_day_plan_answer(const Json& answer, const DayPlanContext& context);
// Activities tiling 00:00–24:00; each "leave home" block of the plan exactly one "leave home"
// activity with its times and "leave home" nowhere else; curated meals inside their hours.
Status check_day_activities_answer(const Json& answer, const DayPlan& filtered_plan,
                                   const ActivityVocabulary& vocabulary, const HouseholdKnowledge& knowledge);
// Exactly the requested activities, each a valid database entry (sums, types, rooms).
Status check_activity_db_answer(const Json& answer, std::span<const std::string> requested,
                                const HouseholdKnowledge& knowledge);
// The activity is empty or one of the memory's (case-insensitive); used_recently agrees with it.
Status check_hint_answer(const Json& answer, std::span<const std::string> memory_activities);
// Known receptacle ids of the house, no repeats, probabilities summing to 1 (± 0.02).
Status check_hint_interpretation_answer(const Json& answer, const House& house);

// "HH:MM" (00:00 … 24:00) → minutes; -1 when malformed.
int parse_clock(std::string_view text);

}  // namespace socsim::household
