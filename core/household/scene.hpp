#pragma once
// Dynamic scenes (paper 000 §III, §IV-C): a house, residents (persona + schedule + activity
// database, scene-agnostic and shareable), the events E of their indoor activities and the object
// configuration P(o, t). Configuration samples each event's room, objects and target receptacles
// from the resident's database normalised by what this house has. Queries are answered from
// indexes (binary search per object), never by replaying events. Times are seconds from 00:00 of
// the first day.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/household/activity_db.hpp"
#include "core/household/house.hpp"
#include "core/household/schedule.hpp"

namespace socsim::household {

// A resident independent of any house: reusable across scenes, like the paper's 50 characters.
struct ResidentProfile {
  Persona persona;
  Schedule schedule;
  ActivityDatabase activity_db;
};

// Offline pipeline for one persona: schedule (growing `vocabulary`) then its activity database.
Result<ResidentProfile> make_resident_offline(const Persona& persona, const HouseholdKnowledge& knowledge,
                                              const ScheduleRequest& request, ActivityVocabulary& vocabulary);

struct Resident {
  std::shared_ptr<const ResidentProfile> profile;
  int bedroom = -1;   // room index; the resident always uses it when an activity goes to a bedroom
  int bathroom = -1;  // own, or shared when there are fewer bathrooms than residents
};

struct SceneEvent {
  int resident = 0;
  int entry = 0;  // index into the resident's schedule entries
  Seconds start = 0, end = 0;
  int room = -1;  // room index, -1 when away or nowhere to go in this house
  std::uint32_t first_relocation = 0, relocation_count = 0;  // into relocations() in event order
};

struct Relocation {
  Seconds time = 0;      // the end of the event that moved the object
  int object = 0;        // index into House::objects
  int from = 0, to = 0;  // receptacle entity indices
  int event = 0;         // index into events()
};

// What a resident answers when asked whether they used an object recently.
struct Hint {
  bool used = false;
  int object = -1;  // index into House::objects when used
  int event = -1;
  std::string activity;  // as the resident calls it
  std::string room_id, receptacle_id;
  Seconds when = 0;
  std::string text;
};

struct SceneRequest {
  int residents = 0;  // 0: between 1 and min(4, bedrooms), at random
  std::uint64_t seed = 0;
};

class DynamicScene {
 public:
  [[nodiscard]] const House& house() const { return *house_; }
  [[nodiscard]] const std::vector<Resident>& residents() const { return residents_; }
  [[nodiscard]] const std::vector<SceneEvent>& events() const { return events_; }            // by start time
  [[nodiscard]] const std::vector<Relocation>& relocations() const { return relocations_; }  // by time
  [[nodiscard]] Seconds end() const { return end_; }
  [[nodiscard]] Weekday first_day() const { return first_day_; }
  [[nodiscard]] std::uint64_t seed() const { return seed_; }
  [[nodiscard]] const ScheduleEntry& entry(const SceneEvent& e) const;

  // P(o, t): the receptacle entity object o rests on at time t (moves at t count).
  [[nodiscard]] int receptacle_at(int object, Seconds t) const;
  [[nodiscard]] std::vector<int> placement_at(Seconds t) const;
  // Relocations with t1 ≤ time < t2.
  [[nodiscard]] std::span<const Relocation> relocations_between(Seconds t1, Seconds t2) const;
  // Events overlapping [t1, t2), in start order.
  [[nodiscard]] std::vector<int> events_between(Seconds t1, Seconds t2) const;
  [[nodiscard]] std::span<const int> events_of(int resident) const;
  // Offline hint: the resident's own most recent use of an object of this type (or this object
  // id) within `lookback` before t.
  [[nodiscard]] Hint hint(int resident, std::string_view object_type_or_id, Seconds t,
                          Seconds lookback = kSecondsPerDay) const;

  [[nodiscard]] Json to_json() const;

 private:
  friend Result<DynamicScene> configure_scene(std::shared_ptr<const House>,
                                              std::span<const std::shared_ptr<const ResidentProfile>>,
                                              const SceneRequest&, const HouseholdKnowledge&);
  std::shared_ptr<const House> house_;
  std::vector<Resident> residents_;
  std::vector<SceneEvent> events_;
  std::vector<Relocation> relocations_;           // sorted by (time, processing order)
  std::vector<std::uint32_t> event_relocations_;  // indices into relocations_, grouped by event
  std::vector<std::uint32_t> object_offsets_;     // CSR over House::objects
  std::vector<Seconds> object_times_;
  std::vector<int> object_receptacles_;
  std::vector<std::vector<int>> resident_events_;
  Seconds end_ = 0;
  Weekday first_day_ = Weekday::kWednesday;
  std::uint64_t seed_ = 0;
};

// Samples residents from `pool` by the number of bedrooms, assigns bedrooms and bathrooms, and
// samples every event's effects. All profiles must cover the same days.
Result<DynamicScene> configure_scene(std::shared_ptr<const House> house,
                                     std::span<const std::shared_ptr<const ResidentProfile>> pool,
                                     const SceneRequest& request, const HouseholdKnowledge& knowledge);

// The hint a resident gives; offline answers from the scene's events, an LLM one from a coarse
// schedule given as memory.
struct HintQuery {
  const DynamicScene* scene = nullptr;
  int resident = 0;
  std::string object;  // type ("Mug") or object id
  Seconds time = 0;
  Seconds lookback = kSecondsPerDay;
};
class HintGenerator {
 public:
  virtual ~HintGenerator() = default;
  virtual Result<Hint> hint(const HintQuery& query) = 0;
};
class OfflineHintGenerator final : public HintGenerator {
 public:
  Result<Hint> hint(const HintQuery& query) override;
};

// A hint read as where the object is now (paper 000 §VI-A(c)): the event it refers to and the
// probability of each receptacle of the house (entity indices; they sum to 1).
struct HintInterpretation {
  std::string activity, room;
  std::vector<std::pair<int, double>> receptacles;
};
struct HintInterpretationQuery {
  const House* house = nullptr;
  std::string object;  // type, e.g. "Mug"
  std::string hint;    // what the resident said
  Seconds time = 0;
  Weekday first_day = Weekday::kWednesday;
};
class HintInterpreter {
 public:
  virtual ~HintInterpreter() = default;
  virtual Result<HintInterpretation> interpret(const HintInterpretationQuery& query) = 0;
};

// A resident profile as JSON ({persona, schedule, activity_db}) and back, validated.
Json to_json(const ResidentProfile& profile);
Result<ResidentProfile> resident_profile_from_json(const Json& json, const HouseholdKnowledge& knowledge,
                                                   const std::string& pointer = "");

// "RemoteControl" → "remote control".
std::string object_words(std::string_view type);

}  // namespace socsim::household
