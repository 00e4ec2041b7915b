#pragma once
// Per-persona activity databases (paper 000 §IV-B): for each activity p(l|a) over room types
// (sums to 1), p(o|a,l) per object type and p(r|o,a,l) over receptacle types (sums to 1).
// Offline: the curated priors perturbed by the persona's traits with a seed; an LLM generator
// can implement the same interface. Every database is validated before use.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/household/knowledge.hpp"
#include "core/household/schedule.hpp"

namespace socsim::household {

struct ObjectPrior {
  std::string type;
  double p = 0.0;                                           // p(o|a,l)
  std::vector<std::pair<std::string, double>> receptacles;  // p(r|o,a,l), sums to 1
  friend bool operator==(const ObjectPrior&, const ObjectPrior&) = default;
};

struct LocationPrior {
  RoomType room = RoomType::kLivingRoom;
  double p = 0.0;  // p(l|a)
  std::vector<ObjectPrior> objects;
  friend bool operator==(const LocationPrior&, const LocationPrior&) = default;
};

struct ActivityPrior {
  std::string activity;                  // primary name
  std::vector<LocationPrior> locations;  // p sums to 1; empty for activities away from home
  friend bool operator==(const ActivityPrior&, const ActivityPrior&) = default;
};

struct ActivityDatabase {
  std::string persona_id;
  std::vector<ActivityPrior> activities;  // sorted by activity name
  [[nodiscard]] const ActivityPrior* find(std::string_view primary) const;
  friend bool operator==(const ActivityDatabase&, const ActivityDatabase&) = default;
};

class ActivityDatabaseGenerator {
 public:
  virtual ~ActivityDatabaseGenerator() = default;
  // One entry per primary activity named (the persona's schedule decides which).
  virtual Result<ActivityDatabase> generate(const Persona& persona, std::span<const std::string> primaries,
                                            std::uint64_t seed) = 0;
};

class OfflineActivityDatabaseGenerator final : public ActivityDatabaseGenerator {
 public:
  explicit OfflineActivityDatabaseGenerator(const HouseholdKnowledge& knowledge) : knowledge_(knowledge) {}
  Result<ActivityDatabase> generate(const Persona& persona, std::span<const std::string> primaries,
                                    std::uint64_t seed) override;

 private:
  const HouseholdKnowledge& knowledge_;
};

// The distinct primary activities of a schedule, sorted.
std::vector<std::string> primaries_of(const Schedule& schedule);

// Ranges, sums (±1e-6), known object and receptacle types, and receptacles that can stand in the
// room; every problem is reported with its JSON pointer (/activities/i/locations/j/…).
Status validate_activity_db(const ActivityDatabase& db, const HouseholdKnowledge& knowledge);

Json to_json(const ActivityDatabase& db);
// Reads and validates (for posted or LLM-written databases).
Result<ActivityDatabase> activity_db_from_json(const Json& json, const HouseholdKnowledge& knowledge);

}  // namespace socsim::household
