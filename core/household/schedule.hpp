#pragma once
// Hierarchical activity schedules (paper 000 §IV-A): an hour-level general plan per day from the
// persona and the weekday → outdoor parts replaced by "leave home" → minute-level indoor
// activities from the growing vocabulary. Generators sit behind interfaces so that an LLM
// implementation can stand beside the offline one; the orchestration and checks are shared.
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/household/knowledge.hpp"
#include "core/household/persona.hpp"
#include "core/household/vocabulary.hpp"

namespace socsim::household {

enum class BlockKind : std::uint8_t { kSleep, kNap, kHome, kWorkAtHome, kAway };
std::string_view block_kind_name(BlockKind kind);

// One block of the general plan, in minutes from 00:00 of its day (0 ≤ start < end ≤ 1440).
struct PlanBlock {
  int start = 0;
  int end = 0;
  std::string description;  // "working at the audit firm", "a slow morning at home", "leave home"
  BlockKind kind = BlockKind::kHome;
  friend bool operator==(const PlanBlock&, const PlanBlock&) = default;
};

// The hour-level plan of one day: contiguous blocks covering [0, 1440).
struct DayPlan {
  int day = 0;
  Weekday weekday = Weekday::kWednesday;
  std::vector<PlanBlock> blocks;
  friend bool operator==(const DayPlan&, const DayPlan&) = default;
};

// One minute-level activity; minutes from 00:00 of the schedule's first day.
struct ScheduleEntry {
  int start = 0;
  int end = 0;
  std::string name;     // as written ("eating breakfast")
  std::string primary;  // after synonym merging ("having breakfast")
  int activity = -1;    // index into HouseholdKnowledge::activities, -1 when not curated
  ActivityRole role = ActivityRole::kLeisure;
  friend bool operator==(const ScheduleEntry&, const ScheduleEntry&) = default;
};

struct Schedule {
  std::string persona_id;
  Weekday first_day = Weekday::kWednesday;
  int days = 5;
  std::vector<DayPlan> plans;          // general plans as generated (before filtering)
  std::vector<ScheduleEntry> entries;  // contiguous, covering [0, days·1440)
  friend bool operator==(const Schedule&, const Schedule&) = default;
};

struct ScheduleRequest {
  int days = 5;                             // 1 … 366
  Weekday first_day = Weekday::kWednesday;  // the paper's span is Wednesday to Sunday
  std::uint64_t seed = 0;
};

struct DayPlanContext {
  int day = 0;
  Weekday weekday = Weekday::kWednesday;
  std::uint64_t seed = 0;
  const DayPlan* previous = nullptr;  // the plan of the day before, when there is one
};

// Writes the hour-level plan of one day. Offline: rules over the persona's traits; LLM: a prompt
// with the persona (and the previous day) answered as JSON in DayPlan's shape.
class DayPlanGenerator {
 public:
  virtual ~DayPlanGenerator() = default;
  virtual Result<DayPlan> plan_day(const Persona& persona, const DayPlanContext& context) = 0;
};

// Turns one filtered plan into minute-level activities covering [0, 1440) of that day
// (day-local minutes); names go through the vocabulary, which grows.
class ScheduleDecomposer {
 public:
  virtual ~ScheduleDecomposer() = default;
  virtual Result<std::vector<ScheduleEntry>> decompose(const Persona& persona, const DayPlan& filtered_plan,
                                                       ActivityVocabulary& vocabulary,
                                                       std::uint64_t seed) = 0;
};

class OfflineDayPlanner final : public DayPlanGenerator {
 public:
  explicit OfflineDayPlanner(const HouseholdKnowledge& knowledge) : knowledge_(knowledge) {}
  Result<DayPlan> plan_day(const Persona& persona, const DayPlanContext& context) override;

 private:
  [[maybe_unused]] const HouseholdKnowledge& knowledge_;  // the offline plans need none yet (clang warns)
};

class OfflineDecomposer final : public ScheduleDecomposer {
 public:
  explicit OfflineDecomposer(const HouseholdKnowledge& knowledge) : knowledge_(knowledge) {}
  Result<std::vector<ScheduleEntry>> decompose(const Persona& persona, const DayPlan& filtered_plan,
                                               ActivityVocabulary& vocabulary, std::uint64_t seed) override;

 private:
  const HouseholdKnowledge& knowledge_;
};

// The paper's filter: every away block becomes "leave home".
DayPlan leave_home_filter(const DayPlan& plan);

// Checks a plan's shape (contiguous blocks over the whole day); errors name /blocks/i.
Status validate_day_plan(const DayPlan& plan);

// Plans each day, filters, decomposes, and joins the days (activities that run past midnight,
// like sleep, become one entry). Any generator answer that breaks the shape is an error.
Result<Schedule> generate_schedule(const Persona& persona, const ScheduleRequest& request,
                                   DayPlanGenerator& planner, ScheduleDecomposer& decomposer,
                                   ActivityVocabulary& vocabulary);
Result<Schedule> generate_schedule_offline(const Persona& persona, const HouseholdKnowledge& knowledge,
                                           const ScheduleRequest& request, ActivityVocabulary& vocabulary);

// A consistency problem found in a schedule.
struct ScheduleIssue {
  std::string kind;  // overlap | gap | coverage | sleep | meal | duration
  int minute = 0;    // where, in schedule minutes
  std::string detail;
};
// Overlaps, gaps, coverage of [0, days·1440), a night's sleep (day sleepers: a day sleep after
// a night shift), meals only at plausible hours and at least one meal on every day at home.
std::vector<ScheduleIssue> check_schedule(const Schedule& schedule, const Persona& persona,
                                          const HouseholdKnowledge& knowledge);

Json to_json(const Schedule& schedule);
Json to_json(const DayPlan& plan);
Result<DayPlan> day_plan_from_json(const Json& json, const std::string& pointer = "");
// Reads a schedule written by to_json (stored households); entries must tile [0, days·86400)
// in whole minutes, roles must be known; errors are named by JSON pointer below `pointer`.
Result<Schedule> schedule_from_json(const Json& json, const HouseholdKnowledge& knowledge,
                                    const std::string& pointer = "");
std::string format_minutes(int minutes_of_day);  // "07:30"

}  // namespace socsim::household
