#pragma once
// Hints as in paper 000 §VI-A: a resident answers from a coarse memory of its own day (hour
// blocks and the last few activities), never from where objects are; the answer may name a room,
// an activity or a time, is sometimes vague, and names a receptacle only when the activity would
// make a person remember it. The offline and the LLM hint generators take the same memory; the
// hint reader turns any answer's words into a distribution over a house's receptacles.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/household/knowledge.hpp"
#include "core/household/scene.hpp"

namespace socsim::household {

// One remembered activity: as the resident calls it, where (room index, −1 away) and when.
struct RememberedActivity {
  int event = -1;  // index into DynamicScene::events()
  std::string name, primary;
  ActivityRole role = ActivityRole::kLeisure;
  int room = -1;
  Seconds start = 0, end = 0;
};

// What a resident remembers of [time − lookback, time): per hour slot the one or two activities
// that filled most of it (short steps such as washing hands are forgotten), and every activity of
// the last `kRecentSpan` at minute resolution.
struct ResidentMemory {
  static constexpr Seconds kRecentSpan = 2 * 3600;
  int resident = 0;
  Seconds time = 0, lookback = kSecondsPerDay;
  Weekday first_day = Weekday::kWednesday;
  std::vector<std::pair<Seconds, std::vector<RememberedActivity>>> hours;  // slot start → activities
  std::vector<RememberedActivity> recent;                                  // by start time
  // Every distinct activity in the memory (hour blocks first, then recent ones), by event.
  [[nodiscard]] std::vector<const RememberedActivity*> activities() const;
};
ResidentMemory remember(const DynamicScene& scene, int resident, Seconds time,
                        Seconds lookback = kSecondsPerDay);
// The memory as the LLM hint prompt shows it ("Thu 07:00-08:00: having breakfast (kitchen)", then
// "Just now:" lines with minutes).
std::string memory_text(const ResidentMemory& memory, const House& house);

// Documented shares of the offline resident's answers (docs/household.md, "Hints").
struct HintStyle {
  double vague = 0.2;        // answers "not sure, maybe in the <room>" though it could say more
  double recall = 0.75;      // remembers an activity in which it really moved such an object as a use
  double memorable_p = 0.5;  // p(o|a,l) at or above which the object is central to the activity…
  Seconds memorable_within = 3 * 3600;  // …and recent enough that the resident remembers where it went
};

// The offline resident recalls its last use: going back from the newest remembered activity, each
// counts as a use with its judged p(o|a,l) (the resident's own activity database at the remembered
// room), or with `recall` besides when that activity really moved such an object (seeded by scene,
// resident, type and time); none: "No". A memorable activity that did move such an object names
// its receptacle; otherwise the answer names the activity, the time of day and the room, or (share
// `vague`) only a room, hedged.
Hint hint_from_memory(const DynamicScene& scene, const ResidentMemory& memory, std::string_view object_type,
                      const HintStyle& style = {});

// What a hint's words say, matched against the knowledge's room, receptacle and activity names.
struct HintReading {
  bool used = false;   // the resident says they used it (or thinks so)
  bool vague = false;  // hedged: "not sure", "maybe"
  std::optional<RoomType> room;
  std::string receptacle_type;             // "" when none is named
  const ActivitySpec* activity = nullptr;  // the curated activity named, by name or synonym
};
HintReading read_hint(std::string_view hint, const HouseholdKnowledge& knowledge);
// Several residents' answers, one a line, each optionally after "<name>: " (as the navigation
// benchmark asks every resident); one reading per non-empty line.
std::vector<HintReading> read_hints(std::string_view answers, const HouseholdKnowledge& knowledge);

// A receptacle as the reader sees it: its type and its room's type.
struct ReceptacleView {
  std::string_view type;
  RoomType room_type = RoomType::kLivingRoom;
};
// Turns a reading into one probability per receptacle, starting from `base` (e.g. a scene prior;
// uniform when empty): a named receptacle (in the named room) gets `trust` of the mass; else a
// named room and activity reweight `base` by the curated p(l|a) and p(r|o,a,l) of that activity
// and, for the room, keep `trust` (half of it when the answer is vague) inside rooms of that type.
// "No" or nothing understood gives `base` normalised. `activity_tables` false: the curated
// activity's p(l|a) and p(r|o,a,l) are not read (they are the scene generator's own tables): a
// named room's `trust` is spread evenly over that room's receptacles (the answer says nothing of
// which one; `base` ranks them in its 1 − trust share), and an answer naming only an activity gives
// `base`.
std::vector<double> hint_distribution(const HintReading& reading, std::string_view object_type,
                                      std::span<const ReceptacleView> receptacles,
                                      std::span<const double> base, double trust = 0.85,
                                      bool activity_tables = true);
// The answers of several residents combined: the mean of hint_distribution over the answers that
// say the object was used (the others know nothing of where it is); none such gives `base`.
std::vector<double> hint_distribution(std::span<const HintReading> readings, std::string_view object_type,
                                      std::span<const ReceptacleView> receptacles,
                                      std::span<const double> base, double trust = 0.85,
                                      bool activity_tables = true);

// The offline hint interpreter: read_hint + hint_distribution over the house's receptacles with
// the tidy-house contents as the base.
class OfflineHintInterpreter final : public HintInterpreter {
 public:
  explicit OfflineHintInterpreter(const HouseholdKnowledge& knowledge) : knowledge_(knowledge) {}
  Result<HintInterpretation> interpret(const HintInterpretationQuery& query) override;

 private:
  const HouseholdKnowledge& knowledge_;
};

}  // namespace socsim::household
