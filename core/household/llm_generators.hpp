#pragma once
// LLM implementations of the household generators (paper 000 §IV, §VI-A), beside the offline
// ones: persona, day plan, minute-level schedule, activity database, hint and hint
// interpretation. Each goes through llm::StructuredGenerator with the artifact's JSON Schema and
// a semantic check, so only answers that fit the schedule/database invariants come back.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/household/activity_db.hpp"
#include "core/household/persona_generator.hpp"
#include "core/household/scene.hpp"
#include "core/household/schedule.hpp"
#include "core/llm/structured_generator.hpp"

namespace socsim::household {

// How the LLM is asked; shared by the generators of one job.
struct LlmSettings {
  llm::StructuredGenerator* generator = nullptr;  // required
  std::optional<std::string> model;               // per-request model name (checked by the client)
  double temperature = 0.7;
  std::optional<std::string> job_id;  // for the call log
  llm::CancelToken cancel;
};

// Personas from the LLM: each answer must be a valid persona inside the constraints and no
// near-duplicate of `existing` or of the ones before it.
Result<std::vector<Persona>> generate_personas_llm(const PersonaRequest& request,
                                                   std::span<const Persona> existing,
                                                   const LlmSettings& settings);

class LlmDayPlanner final : public DayPlanGenerator {
 public:
  LlmDayPlanner(const HouseholdKnowledge& knowledge, LlmSettings settings)
      : knowledge_(knowledge), settings_(std::move(settings)) {}
  Result<DayPlan> plan_day(const Persona& persona, const DayPlanContext& context) override;

 private:
  const HouseholdKnowledge& knowledge_;
  LlmSettings settings_;
};

// Minute level with the vocabulary's activities as the granularity reference; "leave home"
// blocks must come back whole, meals at plausible hours. New names grow the vocabulary.
class LlmDecomposer final : public ScheduleDecomposer {
 public:
  LlmDecomposer(const HouseholdKnowledge& knowledge, LlmSettings settings)
      : knowledge_(knowledge), settings_(std::move(settings)) {}
  Result<std::vector<ScheduleEntry>> decompose(const Persona& persona, const DayPlan& filtered_plan,
                                               ActivityVocabulary& vocabulary, std::uint64_t seed) override;

 private:
  const HouseholdKnowledge& knowledge_;
  LlmSettings settings_;
};

// p(l|a), p(o|a,l), p(r|o,a,l) in batches of activities, with the scene prior (room, object and
// receptacle types and which go together) in the prompt; validated by validate_activity_db.
class LlmActivityDatabaseGenerator final : public ActivityDatabaseGenerator {
 public:
  LlmActivityDatabaseGenerator(const HouseholdKnowledge& knowledge, LlmSettings settings,
                               std::size_t batch = 12)
      : knowledge_(knowledge), settings_(std::move(settings)), batch_(batch) {}
  Result<ActivityDatabase> generate(const Persona& persona, std::span<const std::string> primaries,
                                    std::uint64_t seed) override;

 private:
  const HouseholdKnowledge& knowledge_;
  LlmSettings settings_;
  std::size_t batch_;
};

// The resident answers from a coarse memory of their recent events (hour slots with activity
// and room names), as in the paper; the answer's activity must be one of the memory.
class LlmHintGenerator final : public HintGenerator {
 public:
  explicit LlmHintGenerator(LlmSettings settings) : settings_(std::move(settings)) {}
  Result<Hint> hint(const HintQuery& query) override;

 private:
  LlmSettings settings_;
};

class LlmHintInterpreter final : public HintInterpreter {
 public:
  explicit LlmHintInterpreter(LlmSettings settings) : settings_(std::move(settings)) {}
  Result<HintInterpretation> interpret(const HintInterpretationQuery& query) override;

 private:
  LlmSettings settings_;
};

// The resident's coarse memory of [t − lookback, t): one line per hour slot, e.g.
// "Wed 07:00-08:00: having breakfast (kitchen), getting dressed (bedroom)".
std::string coarse_memory(const DynamicScene& scene, int resident, Seconds t, Seconds lookback);

}  // namespace socsim::household
