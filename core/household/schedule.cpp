#include "core/household/schedule.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"

namespace socsim::household {
namespace {

int round5(double minutes) {
  return static_cast<int>(std::lround(minutes / 5.0)) * 5;
}

Rng rng_for(std::uint64_t seed, const std::string& persona, std::string_view label, int day) {
  return Rng(seed ^ fnv1a64(persona), fnv1a64(label) + static_cast<std::uint64_t>(day + 10));
}

// ---------------------------------------------------------------------------------------------
// Offline day plan: sleep, work and outdoor habits as fixed blocks; the gaps are time at home.
// ---------------------------------------------------------------------------------------------

struct Fixed {
  int start = 0;  // minutes from 00:00 of the day that owns it (may pass 1440)
  int end = 0;
  BlockKind kind = BlockKind::kAway;
  std::string description;
};

// A recurring outdoor habit read from the persona's text.
struct Habit {
  std::vector<std::string_view> keywords;
  int min_age, max_age;
  std::uint8_t days;  // bit per weekday, Monday = bit 0
  double p;
  double window_lo, window_hi;  // start hours
  int min_minutes, max_minutes;
  std::string_view description;
  bool free_days_only;
};

constexpr std::uint8_t kWeekdays = 0x1f, kWeekend = 0x60, kEveryDay = 0x7f;
constexpr std::uint8_t day_bit(Weekday d) {
  return static_cast<std::uint8_t>(1u << static_cast<unsigned>(d));
}

const std::vector<Habit>& habits() {
  static const std::vector<Habit> h = {
      {{"runs", "running", "half marathon"},
       14,
       80,
       kEveryDay,
       0.8,
       5.5,
       7.5,
       30,
       60,
       "going for a run",
       false},
      {{"swim", "swims"}, 10, 90, kWeekdays, 0.8, 5.5, 7.0, 45, 60, "swimming laps at the pool", false},
      {{"dog", "beagle"}, 8, 95, kEveryDay, 0.95, 6.0, 8.5, 20, 40, "walking the dog", false},
      {{"dog", "beagle"}, 8, 95, kEveryDay, 0.8, 18.5, 21.0, 20, 35, "an evening walk with the dog", false},
      {{"church"}, 0, 120, day_bit(Weekday::kSunday), 0.95, 9.0, 10.5, 90, 150, "attending church", false},
      {{"choir"}, 0, 120, day_bit(Weekday::kThursday), 0.9, 18.5, 19.5, 100, 130, "choir rehearsal", false},
      {{"gym", "bouldering", "lifts weights", "climbs"},
       14,
       75,
       kWeekdays,
       0.45,
       17.5,
       20.0,
       60,
       120,
       "training at the gym",
       false},
      {{"fishing"},
       12,
       90,
       day_bit(Weekday::kSaturday),
       0.8,
       5.5,
       8.0,
       240,
       360,
       "fishing at the lake",
       false},
      {{"rugby"},
       10,
       60,
       day_bit(Weekday::kSunday),
       0.9,
       9.5,
       11.0,
       150,
       210,
       "playing rugby with the club",
       false},
      {{"tennis"}, 10, 85, day_bit(Weekday::kFriday), 0.9, 10.0, 16.0, 80, 110, "playing tennis", false},
      {{"football"}, 6, 16, kWeekdays, 0.5, 15.75, 17.0, 60, 90, "playing football in the park", false},
      {{"football on monday", "football on monday mornings"},
       17,
       70,
       day_bit(Weekday::kMonday),
       0.9,
       9.5,
       11.0,
       90,
       120,
       "playing football with friends",
       false},
      {{"basketball"}, 10, 18, kWeekdays, 0.5, 16.0, 18.0, 60, 120, "basketball practice", false},
      {{"basketball"},
       10,
       18,
       day_bit(Weekday::kSaturday),
       0.9,
       10.0,
       14.0,
       150,
       180,
       "a basketball game",
       false},
      {{"birdwatching"},
       10,
       95,
       kWeekend,
       0.8,
       6.0,
       9.0,
       150,
       240,
       "birdwatching in the nature reserve",
       false},
      {{"backgammon at the cafe", "cafe"},
       50,
       100,
       kEveryDay,
       0.5,
       15.0,
       17.0,
       90,
       150,
       "playing backgammon at the cafe",
       false},
      {{"walk", "long walk", "walks"},
       60,
       100,
       kEveryDay,
       0.8,
       9.5,
       16.0,
       45,
       90,
       "taking a long walk",
       false},
      {{"pram"}, 18, 90, kEveryDay, 0.9, 10.0, 15.0, 60, 90, "walking the baby in the pram", false},
      {{"twins"}, 18, 90, kEveryDay, 0.7, 9.5, 11.0, 60, 90, "at the playground with the twins", false},
      {{"weddings"},
       18,
       90,
       day_bit(Weekday::kSaturday),
       0.9,
       11.0,
       13.0,
       480,
       600,
       "photographing a wedding",
       false},
      {{"saturday mornings"},
       14,
       90,
       day_bit(Weekday::kSaturday),
       1.0,
       8.25,
       8.75,
       240,
       270,
       "working the Saturday shift",
       false},
      {{"evening classes"},
       18,
       90,
       day_bit(Weekday::kTuesday) | day_bit(Weekday::kThursday),
       0.95,
       17.5,
       18.0,
       110,
       130,
       "teaching an evening class",
       false},
      {{"thrifts", "thrift"}, 14, 90, kWeekend, 0.4, 11.0, 15.0, 90, 150, "thrift shopping", false},
      {{"ginger beer", "jazz records"},
       18,
       90,
       day_bit(Weekday::kSaturday),
       0.0,
       12.0,
       14.0,
       60,
       90,
       "record shopping",
       false},
  };
  return h;
}

struct PersonaContext {
  const Persona& persona;
  PersonaTraits traits;
  std::string id;
  int commute = 25;
  explicit PersonaContext(const Persona& p) : persona(p), traits(infer_traits(p)), id(persona_id(p)) {
    commute = 15 + static_cast<int>(fnv1a64(id + ":commute") % 26);
  }
  [[nodiscard]] bool day_sleeper() const { return traits.work == WorkPattern::kNightShift; }
  [[nodiscard]] bool works(Weekday d) const { return traits.work_days[static_cast<std::size_t>(d)]; }
  [[nodiscard]] bool works_away(Weekday d) const {
    if (!works(d)) return false;
    switch (traits.work) {
      case WorkPattern::kRemote:
      case WorkPattern::kFreelance:
        return false;
      case WorkPattern::kHybrid:
        return !traits.home_work_days[static_cast<std::size_t>(d)];
      default:
        return true;
    }
  }
  [[nodiscard]] bool works_home(Weekday d) const {
    return traits.work == WorkPattern::kJobSeeker ? !is_weekend(d) : works(d) && !works_away(d);
  }
};

class DayTimes {
 public:
  DayTimes(const PersonaContext& pc, std::uint64_t seed, Weekday first)
      : pc_(pc), seed_(seed), first_(first) {}

  [[nodiscard]] Weekday weekday(int d) const { return weekday_after(first_, d); }

  // Waking time of day d after a night in bed (minutes from 00:00 of d).
  [[nodiscard]] int wake(int d) const {
    Rng r = rng_for(seed_, pc_.id, "wake", d);
    const bool busy = pc_.works(weekday(d)) && !pc_.day_sleeper();
    const int base = busy ? pc_.traits.work_night.wake : pc_.traits.free_night.wake;
    return std::max(0, base + round5(std::clamp(r.normal(0.0, busy ? 5.0 : 15.0), -20.0, 30.0)));
  }
  // Bedtime in the evening of day d (minutes from 00:00 of d; ≥ 1440 after midnight).
  [[nodiscard]] int bed(int d) const {
    Rng r = rng_for(seed_, pc_.id, "bed", d);
    const bool busy_tomorrow = pc_.works(weekday(d + 1)) && !pc_.day_sleeper();
    int b = (busy_tomorrow ? pc_.traits.work_night.bed : pc_.traits.free_night.bed) +
            round5(std::clamp(r.normal(0.0, 12.0), -30.0, 40.0));
    return std::max(b, 18 * 60);
  }

  // Fixed blocks owned by day d.
  [[nodiscard]] std::vector<Fixed> fixed(int d) const {
    std::vector<Fixed> out;
    const Weekday wd = weekday(d);
    const auto& t = pc_.traits;
    Rng r = rng_for(seed_, pc_.id, "work", d);
    const int jitter_end = round5(std::clamp(r.normal(0.0, 8.0), -15.0, 25.0));
    int day_start = 0;  // first minute the person is up at home
    if (pc_.day_sleeper()) {
      const bool worked_last_night = pc_.works(weekday(d - 1));
      if (worked_last_night) {
        const int home_at = t.work_end - 1440 + pc_.commute + jitter_end;
        const int sleep_at = std::max(t.work_night.bed, home_at + 20);
        const int wake_at = std::max(t.work_night.wake + round5(r.normal(0.0, 10.0)), sleep_at + 300);
        out.push_back({sleep_at, wake_at, BlockKind::kSleep, "sleeping after the night shift"});
        day_start = wake_at;
      } else {
        day_start = wake(d);
      }
      if (pc_.works(wd)) {
        const int leave = t.work_start - pc_.commute;
        if (!worked_last_night && leave - 200 > day_start + 240)
          out.push_back({leave - 200, leave - 60, BlockKind::kNap, "napping before the night shift"});
        out.push_back({leave, t.work_end + pc_.commute + jitter_end, BlockKind::kAway, work_description()});
      } else {
        out.push_back({bed(d), 1440 + wake(d + 1), BlockKind::kSleep, "sleeping"});
      }
    } else {
      day_start = wake(d);
      if (pc_.works_away(wd)) {
        const int leave = std::max(t.work_start - pc_.commute, day_start + 30);
        out.push_back({leave, t.work_end + pc_.commute + jitter_end, BlockKind::kAway, work_description()});
        if (t.second_start >= 0)
          out.push_back({t.second_start - pc_.commute, t.second_end + pc_.commute, BlockKind::kAway,
                         work_description()});
      } else if (pc_.works_home(wd)) {
        const int start = std::max(t.work_start, day_start + 45);
        const int end = std::max(start + 120, t.work_end + jitter_end);
        out.push_back({start, end, BlockKind::kWorkAtHome, home_work_description()});
      }
      out.push_back({bed(d), 1440 + wake(d + 1), BlockKind::kSleep, "sleeping"});
      if (t.naps && !pc_.works_away(wd)) {
        Rng nr = rng_for(seed_, pc_.id, "nap", d);
        if (nr.chance(0.8)) {
          const int start = 13 * 60 + 30 + round5(nr.uniform(0, 60));
          const int len = round5(nr.uniform(30, pc_.persona.age < 6 ? 100 : 70));
          if (fits(out, start, start + len, day_start, 0))
            out.push_back({start, start + len, BlockKind::kNap, "an afternoon nap"});
        }
      }
    }
    place_habits(d, day_start, out);
    std::sort(out.begin(), out.end(), [](const Fixed& a, const Fixed& b) { return a.start < b.start; });
    return out;
  }

 private:
  static bool fits(const std::vector<Fixed>& blocks, int start, int end, int day_start, int margin) {
    if (start < day_start + margin) return false;
    for (const auto& b : blocks)
      if (start < b.end + margin && end + margin > b.start) return false;
    return true;
  }

  void place_habits(int d, int day_start, std::vector<Fixed>& out) const {
    const Weekday wd = weekday(d);
    Rng r = rng_for(seed_, pc_.id, "habits", d);
    const int age = pc_.persona.age;
    auto try_place = [&](double lo, double hi, int min_len, int max_len, std::string_view what) {
      for (int attempt = 0; attempt < 4; ++attempt) {
        const int start = round5(r.uniform(lo, hi) * 60.0);
        const int len = round5(r.uniform(min_len, max_len));
        if (fits(out, start, start + len, day_start, 30)) {
          out.push_back({start, start + len, BlockKind::kAway, std::string(what)});
          return true;
        }
      }
      return false;
    };
    for (const Habit& h : habits()) {
      if (age < h.min_age || age > h.max_age || (h.days & day_bit(wd)) == 0) continue;
      if (h.free_days_only && pc_.works(wd)) continue;
      if (!std::any_of(h.keywords.begin(), h.keywords.end(),
                       [&](std::string_view k) { return mentions(pc_.traits, k); }))
        continue;
      if (!r.chance(h.p)) continue;
      try_place(h.window_lo, h.window_hi, h.min_minutes, h.max_minutes, h.description);
    }
    if (age >= 16) {  // everyday errands
      const bool free = !pc_.works(wd);
      if (r.chance(free ? 0.45 : 0.25))
        try_place(free ? 9.5 : 17.5, free ? 17.0 : 19.0, 40, 90, "grocery shopping");
      if (wd == Weekday::kSaturday && r.chance(0.4))
        try_place(10.0, 16.0, 60, 150, "running errands in town");
      if (wd == Weekday::kSunday && r.chance(0.3)) try_place(12.0, 15.0, 150, 240, "visiting family");
      const bool weekend_night = wd == Weekday::kFriday || wd == Weekday::kSaturday;
      if (weekend_night && age <= 45 && pc_.traits.sociability >= 0.6 && r.chance(0.6))
        try_place(19.0, 20.5, 150, 220, "going out with friends");
      if (free && age >= 60 && pc_.traits.sociability >= 0.6 && r.chance(0.35))
        try_place(10.0, 15.0, 90, 150, "meeting friends in town");
    }
  }

  [[nodiscard]] std::string work_description() const {
    switch (pc_.traits.work) {
      case WorkPattern::kSchool:
        return "at school";
      case WorkPattern::kPreschool:
        return "at kindergarten";
      case WorkPattern::kCollege:
        return "classes and study on campus";
      case WorkPattern::kNightShift:
        return "working the night shift";
      default:
        break;
    }
    std::string occ = pc_.persona.occupation;
    for (std::string_view marker : {" is an ", " is a ", " works as an ", " works as a "}) {
      const auto pos = occ.find(marker);
      if (pos == std::string::npos) continue;
      std::string rest = occ.substr(pos + marker.size());
      for (std::string_view stop : {",", " who ", " and ", ".", ";", " with "}) {
        const auto s = rest.find(stop);
        if (s != std::string::npos) rest = rest.substr(0, s);
      }
      return "working as " + std::string(marker.substr(marker.size() - 3) == "an " ? "an " : "a ") + rest;
    }
    return "at work";
  }

  [[nodiscard]] std::string home_work_description() const {
    switch (pc_.traits.work) {
      case WorkPattern::kJobSeeker:
        return "looking for jobs from home";
      case WorkPattern::kFreelance:
        return "working on commissions at home";
      default:
        return "working from home";
    }
  }

  const PersonaContext& pc_;
  std::uint64_t seed_;
  Weekday first_;
};

std::string home_description(const PlanBlock& b, BlockKind prev, BlockKind next, bool weekend) {
  if (b.kind == BlockKind::kWorkAtHome) return b.description;
  if (prev == BlockKind::kSleep && next == BlockKind::kAway) return "getting ready for the day";
  if (prev == BlockKind::kSleep) return weekend ? "a slow morning at home" : "morning routine at home";
  if (next == BlockKind::kSleep && b.end - b.start <= 90) return "winding down for the night";
  if (prev == BlockKind::kAway && b.start >= 16 * 60) return "evening at home";
  if (b.start < 12 * 60) return "a morning at home";
  if (b.start < 17 * 60) return "an afternoon at home";
  return "evening at home";
}

// ---------------------------------------------------------------------------------------------
// Offline decomposition of a filtered plan into minute-level activities.
// ---------------------------------------------------------------------------------------------

struct Item {
  const ActivitySpec* spec = nullptr;
  int minutes = 0;
  int priority = 0;  // higher survives when time is short
};

class DayDecomposition {
 public:
  DayDecomposition(const HouseholdKnowledge& k, const PersonaContext& pc, const DayPlan& plan,
                   ActivityVocabulary& vocab, std::uint64_t seed)
      : k_(k), pc_(pc), plan_(plan), vocab_(vocab), rng_(rng_for(seed, pc.id, "decompose", plan.day)) {
    build_pool();
    morning_shower_ = rng_.chance(0.35 + 0.3 * pc_.traits.tidiness);
  }

  Result<std::vector<ScheduleEntry>> run() {
    const auto& blocks = plan_.blocks;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      const PlanBlock& b = blocks[i];
      const BlockKind prev = i > 0 ? blocks[i - 1].kind : BlockKind::kHome;
      const BlockKind next = i + 1 < blocks.size() ? blocks[i + 1].kind : BlockKind::kHome;
      const bool at_day_start = i == 0;
      switch (b.kind) {
        case BlockKind::kSleep:
          emit(find("sleeping"), b.start, b.end);
          break;
        case BlockKind::kNap:
          emit(find("taking a nap"), b.start, b.end);
          break;
        case BlockKind::kAway:
          emit(find("leave home"), b.start, b.end);
          break;
        case BlockKind::kHome:
        case BlockKind::kWorkAtHome:
          home_block(b, at_day_start ? BlockKind::kHome : prev,
                     i + 1 < blocks.size() ? next : BlockKind::kHome, at_day_start);
          break;
      }
    }
    return std::move(out_);
  }

 private:
  const ActivitySpec* find(std::string_view name) const {
    const ActivitySpec* a = k_.activity(name);
    return a;
  }

  bool eligible(const ActivitySpec& a) const {
    const int age = pc_.persona.age;
    if (age < a.min_age || age > a.max_age) return false;
    if (a.keywords.empty()) return true;
    return std::any_of(a.keywords.begin(), a.keywords.end(),
                       [&](const std::string& kw) { return mentions(pc_.traits, kw); });
  }
  const ActivitySpec* eligible_named(std::string_view name) const {
    const ActivitySpec* a = find(name);
    return a && eligible(*a) ? a : nullptr;
  }

  void build_pool() {
    const auto& t = pc_.traits;
    const bool student = t.work == WorkPattern::kSchool || t.work == WorkPattern::kCollege;
    const bool weekend = is_weekend(plan_.weekday);
    for (const auto& a : k_.activities) {
      if (!eligible(a)) continue;
      const bool matched = !a.keywords.empty();
      double w = a.weight * (matched ? 2.5 : 1.0);
      switch (a.role) {
        case ActivityRole::kLeisure:
          break;
        case ActivityRole::kHobby:
          w *= matched ? 1.4 : 0.6;
          break;
        case ActivityRole::kChore:
        case ActivityRole::kLaundry:
          if (t.child && a.name != "tidying the bedroom" && a.name != "tidying the living room") continue;
          w *= (0.5 + t.tidiness) * (weekend ? 1.5 : 1.0) * 0.8;
          break;
        case ActivityRole::kExercise:
          w *= 0.8;
          break;
        case ActivityRole::kSocialCall:
          w *= 0.5 + 0.5 * t.sociability;
          break;
        case ActivityRole::kSocial:
          w *= (weekend ? 1.0 : 0.3) * t.sociability;
          break;
        case ActivityRole::kStudy:
          w *= student ? (weekend ? 1.2 : 2.5) : 0.6;
          break;
        case ActivityRole::kWork:
          if (!matched) continue;
          w *= weekend ? 0.3 : 1.0;
          break;
        case ActivityRole::kChildcare:
          w *= 2.0;
          break;
        case ActivityRole::kSnack:
          w *= 0.6;
          break;
        case ActivityRole::kHotDrink:
          w *= t.child ? 0.0 : 0.3;
          break;
        default:
          continue;  // anchored roles are placed by rules, not as fillers
      }
      if (w > 0.0) pool_.push_back({&a, w});
    }
    for (const auto& a : k_.activities)
      if (a.role == ActivityRole::kWork && eligible(a))
        work_pool_.push_back({&a, a.keywords.empty() ? 1.0 : 2.5});
    if (t.work != WorkPattern::kRemote && t.work != WorkPattern::kHybrid)
      std::erase_if(work_pool_, [](const auto& p) { return p.first->name == "attending a video meeting"; });
    if (t.work == WorkPattern::kJobSeeker)
      std::erase_if(work_pool_, [](const auto& p) {
        return p.first->keywords.empty() && p.first->name != "answering work emails";
      });
  }

  std::string phrase(const ActivitySpec& a) {
    std::vector<const std::string*> names = {&a.name};
    for (const auto& s : a.synonyms) names.push_back(&s);
    const std::uint64_t h = fnv1a64(pc_.id + "|" + a.name);
    std::size_t preferred =
        (h % 100) < 55 ? 0
                       : 1 + static_cast<std::size_t>((h >> 8) % std::max<std::size_t>(1, names.size() - 1));
    if (preferred >= names.size()) preferred = 0;
    if (names.size() > 1 && rng_.chance(0.15))
      preferred = rng_.below(static_cast<std::uint32_t>(names.size()));
    return *names[preferred];
  }

  void emit(const ActivitySpec* spec, int start, int end) {
    if (!spec || end <= start) return;
    if (!out_.empty() && out_.back().activity == k_.activity_index(spec->name) && out_.back().end == start &&
        (spec->role == ActivityRole::kSleep || spec->role == ActivityRole::kLeaveHome)) {
      out_.back().end = end;
      return;
    }
    ScheduleEntry e;
    e.start = start;
    e.end = end;
    e.name = spec->role == ActivityRole::kLeaveHome ? spec->name : phrase(*spec);
    auto res = vocab_.add(e.name);
    e.primary = res.primary;
    e.activity = res.activity;
    e.role = spec->role;
    out_.push_back(std::move(e));
    ++used_[spec];
  }

  int sample_minutes(const ActivitySpec& a) {
    return std::max(a.min_minutes, round5(rng_.uniform(a.min_minutes, a.max_minutes)));
  }

  void add(std::vector<Item>& items, const ActivitySpec* spec, int priority, double p = 1.0) {
    if (!spec || !rng_.chance(p)) return;
    items.push_back({spec, sample_minutes(*spec), priority});
  }

  static int total(const std::vector<Item>& items) {
    int s = 0;
    for (const auto& i : items) s += i.minutes;
    return s;
  }

  // Drops the least important items (priority < 3), then shortens the rest toward their typical
  // minimum and finally squeezes them, until the items fit in `budget` minutes.
  static void fit(std::vector<Item>& items, int budget) {
    while (total(items) > budget) {
      auto lowest = std::min_element(items.begin(), items.end(),
                                     [](const Item& a, const Item& b) { return a.priority < b.priority; });
      if (lowest == items.end() || lowest->priority >= 3) break;
      items.erase(lowest);
    }
    int excess = total(items) - budget;
    for (auto& it : items) {
      if (excess <= 0) break;
      const int cut = std::min(excess, it.minutes - it.spec->min_minutes);
      if (cut > 0) {
        it.minutes -= cut;
        excess -= cut;
      }
    }
    if (excess > 0) {
      while (!items.empty() && static_cast<int>(items.size()) > budget) items.erase(items.begin());
      if (items.empty()) return;
      const int n = static_cast<int>(items.size());
      for (auto& it : items) it.minutes = budget / n;
      items.back().minutes += budget - total(items);
    }
  }

  void home_block(const PlanBlock& b, BlockKind prev, BlockKind next, bool at_day_start) {
    const auto& t = pc_.traits;
    const int age = pc_.persona.age;
    const bool after_sleep = !at_day_start && prev == BlockKind::kSleep;
    const bool after_away = prev == BlockKind::kAway && !at_day_start;
    const bool before_sleep = next == BlockKind::kSleep;
    const bool before_away = next == BlockKind::kAway;
    std::vector<Item> front, back;

    if (after_sleep) {
      add(front, find("getting out of bed"), 3);
      add(front, find("using the toilet"), 1, 0.8);
      if (t.prayers_per_day > 0) add(front, eligible_named("praying"), 1, 0.9);
      if (morning_shower_ && !(age < 10)) add(front, find("taking a shower"), 1);
      for (const char* n : {"washing face", "shaving", "doing a skincare routine", "doing hair"})
        if (const auto* a = eligible_named(n)) add(front, a, 0, 0.35);
      if (age >= 3) add(front, find("getting dressed"), 2, is_weekend(plan_.weekday) ? 0.75 : 0.95);
      if (const auto* yoga = eligible_named("doing yoga");
          yoga && (mentions(t, "every morning") || mentions(t, "starts each day") || mentions(t, "daily")))
        add(front, yoga, 1, 0.8);
      if (const auto* st = eligible_named("stretching with a foam roller");
          st && mentions(t, "stretches every morning"))
        add(front, st, 1, 0.8);
      add(front, find("making the bed"), 0, t.child ? 0.3 : t.tidiness);
      // Breakfast only when it falls in its plausible hours and the morning is long enough.
      const ActivitySpec* breakfast = find("having breakfast");
      std::vector<Item> chain;
      if (!t.child && age >= 12) {
        add(chain, eligible_named(mentions(t, "tea") || mentions(t, "chai") ? "making tea" : "making coffee"),
            1, 0.55);
        add(chain, eligible_named("making breakfast"), 1, 0.6);
      }
      const int breakfast_at = b.start + total(front) + total(chain);
      if (breakfast && breakfast->in_window(breakfast_at % 1440) && b.end - breakfast_at >= 20) {
        front.insert(front.end(), chain.begin(), chain.end());
        add(front, breakfast, 2);
        had_.insert(ActivityRole::kBreakfast);
        if (const auto* med = eligible_named("taking medication")) add(front, med, 2);
        if (const auto* med = eligible_named("checking blood pressure")) add(front, med, 1, 0.7);
        add(front, eligible_named("washing dishes"), 0, 0.25 * t.tidiness);
      }
      add(front, find("brushing teeth"), 2, 0.9);
      if (const auto* pet = eligible_named("feeding the pet")) add(front, pet, 2);
    } else if (after_away) {
      add(front, find("coming home"), 3, 0.95);
      add(front, find("washing hands"), 0, 0.4);
    }

    if (before_away) {
      if (after_sleep || b.start < 11 * 60)
        if (const auto* lunch = eligible_named("packing a lunch box"); lunch && pc_.works_away(plan_.weekday))
          add(back, lunch, 0, 0.3);
      add(back, find("using the toilet"), 0, 0.3);
      add(back, find("getting ready to leave"), 3, 0.95);
    } else if (before_sleep) {
      if (age < 10)
        add(back, find("taking a bath"), 1, 0.7);
      else if (!morning_shower_)
        add(back, rng_.chance(0.2) ? eligible_named("taking a bath") : find("taking a shower"), 1, 0.65);
      if (const auto* d = eligible_named("doing a skincare routine")) add(back, d, 0, 0.3);
      if (const auto* j = eligible_named("writing in a journal")) add(back, j, 0, 0.6);
      add(back, find("brushing teeth"), 2, 0.95);
      if (const auto* story = eligible_named("reading a bedtime story")) add(back, story, 1, 0.8);
      add(back, find("getting ready for bed"), 3);
    }

    const int length = b.end - b.start;
    fit(front, length);
    fit(back, std::max(0, length - total(front)));
    int cursor = b.start;
    for (const auto& it : front) {
      emit(it.spec, cursor, cursor + it.minutes);
      cursor += it.minutes;
    }
    const int middle_end = b.end - total(back);
    middle(cursor, middle_end, b.kind == BlockKind::kWorkAtHome);
    cursor = middle_end;
    for (const auto& it : back) {
      emit(it.spec, cursor, cursor + it.minutes);
      cursor += it.minutes;
    }
  }

  struct Anchor {
    int target = 0;
    std::vector<Item> chain;
    ActivityRole meal = ActivityRole::kSleep;  // kSleep: not a meal
  };

  static int minutes_before(const std::vector<Item>& chain, ActivityRole meal) {
    int m = 0;
    for (const auto& it : chain) {
      if (it.spec->role == meal) break;
      m += it.minutes;
    }
    return m;
  }

  std::vector<Anchor> anchors(int from, int to, bool work_block) {
    std::vector<Anchor> out;
    const auto& t = pc_.traits;
    const int age = pc_.persona.age;
    const std::uint64_t h = fnv1a64(pc_.id + ":meals");
    const int lunch_at = 12 * 60 + static_cast<int>(h % 7) * 10 - 20 + round5(rng_.normal(0, 10));
    int dinner_at = (age < 13 || age >= 65 ? 18 * 60 : 18 * 60 + 30 + static_cast<int>((h >> 8) % 7) * 10) +
                    round5(rng_.normal(0, 12));
    auto meal_chain = [&](const char* prep, const char* meal, double p_prep, ActivityRole role) {
      Anchor a;
      a.meal = role;
      if (!t.child && age >= 12) add(a.chain, eligible_named(prep), 1, p_prep);
      add(a.chain, eligible_named("setting the table"), 0, age < 13 ? 0.35 : 0.2);
      add(a.chain, find(meal), 2);
      if (role == ActivityRole::kDinner) {
        if (const auto* med = eligible_named("taking medication")) add(a.chain, med, 2);
      }
      if (age >= 6)
        add(a.chain, eligible_named(rng_.chance(0.5) ? "washing dishes" : "clearing the table"), 0,
            0.3 + 0.5 * t.tidiness);
      return a;
    };
    int lunch_when = lunch_at;
    if (lunch_when < from + 10 && from + 10 <= 14 * 60)
      lunch_when = from + 10;  // got up late or came home: eat soon
    lunch_when = std::min(lunch_when, to - 40);
    if (!had_.count(ActivityRole::kLunch) && lunch_when >= from && lunch_when >= 11 * 60 &&
        lunch_when + 20 <= to) {
      Anchor a = meal_chain("cooking lunch", "having lunch", 0.55, ActivityRole::kLunch);
      a.target = lunch_when - minutes_before(a.chain, ActivityRole::kLunch);
      out.push_back(std::move(a));
    }
    if (!had_.count(ActivityRole::kDinner) && !work_block) {
      if (dinner_at < from + 20 && from + 20 <= 21 * 60 + 15)
        dinner_at = from + 25;                                           // came home late: eat soon
      dinner_at = std::max(std::min(dinner_at, to - 50), 17 * 60 + 10);  // early to bed or out: eat earlier
      if (dinner_at >= from && dinner_at < to - 20 && dinner_at <= 21 * 60 + 30) {
        const bool feast =
            is_weekend(plan_.weekday) && eligible_named("cooking a family feast") && rng_.chance(0.5);
        Anchor a = meal_chain(feast ? "cooking a family feast" : "cooking dinner", "having dinner",
                              feast ? 1.0 : 0.85, ActivityRole::kDinner);
        a.target = std::max(from, dinner_at - minutes_before(a.chain, ActivityRole::kDinner));
        out.push_back(std::move(a));
      }
    }
    if (const auto* pet = eligible_named("feeding the pet"); pet && from <= 18 * 60 && to >= 17 * 60) {
      Anchor a;
      add(a.chain, pet, 2);
      a.target = std::max(from, 17 * 60 + round5(rng_.uniform(0, 90)));
      out.push_back(std::move(a));
    }
    if (t.prayers_per_day >= 5)
      for (int at : {13 * 60, 16 * 60 + 30, 18 * 60 + 45, 20 * 60 + 30})
        if (at >= from && at < to - 15) {
          Anchor a;
          add(a.chain, eligible_named("praying"), 2);
          a.target = at;
          out.push_back(std::move(a));
        }
    if (const auto* feed = eligible_named("feeding the children"))
      for (int at : {8 * 60, 12 * 60, 17 * 60 + 15})
        if (at >= from && at < to - 30) {
          Anchor a;
          add(a.chain, feed, 2);
          a.target = at;
          out.push_back(std::move(a));
        }
    if (const auto* bath = eligible_named("bathing the children");
        bath && 19 * 60 >= from && 19 * 60 < to - 30) {
      Anchor a;
      add(a.chain, bath, 2, 0.8);
      a.target = 19 * 60;
      out.push_back(std::move(a));
    }
    std::sort(out.begin(), out.end(), [](const Anchor& a, const Anchor& b) { return a.target < b.target; });
    return out;
  }

  void middle(int from, int to, bool work_block) {
    if (to <= from) return;
    int cursor = from;
    for (Anchor& a : anchors(from, to, work_block)) {
      if (a.chain.empty()) continue;
      const int len = total(a.chain);
      int start = std::max(cursor, std::min(a.target, to - len));
      if (start + len > to || start < cursor) {
        // Not enough room: keep only the main part (the meal or the one item).
        std::erase_if(a.chain, [](const Item& it) { return it.priority < 2; });
        const int l2 = total(a.chain);
        if (a.chain.empty() || cursor + l2 > to) continue;
        start = std::max(cursor, std::min(a.target, to - l2));
      }
      if (a.meal != ActivityRole::kSleep) {
        const ActivitySpec* meal = nullptr;
        for (const auto& it : a.chain)
          if (it.spec->role == a.meal) meal = it.spec;
        int meal_at = start;
        for (const auto& it : a.chain) {
          if (it.spec == meal) break;
          meal_at += it.minutes;
        }
        if (meal && !meal->in_window(meal_at % 1440)) continue;
        had_.insert(a.meal);
      }
      fill(cursor, start, work_block);
      cursor = start;
      for (const auto& it : a.chain) {
        emit(it.spec, cursor, cursor + it.minutes);
        cursor += it.minutes;
      }
    }
    fill(cursor, to, work_block);
  }

  int max_per_day(const ActivitySpec& a) const {
    switch (a.role) {
      case ActivityRole::kChore:
      case ActivityRole::kSocial:
      case ActivityRole::kExercise:
        return 1;
      case ActivityRole::kLaundry:
      case ActivityRole::kHobby:
      case ActivityRole::kStudy:
      case ActivityRole::kSocialCall:
        return 2;
      case ActivityRole::kWork:
        return 6;
      default:
        return 3;
    }
  }

  const ActivitySpec* choose(const std::vector<std::pair<const ActivitySpec*, double>>& pool, int at,
                             int remaining, const ActivitySpec* last) {
    std::vector<double> w;
    w.reserve(pool.size());
    const int minute = at % 1440;
    bool any = false;
    for (const auto& [a, weight] : pool) {
      double x = weight;
      if (a == last || !a->in_window(minute) || a->min_minutes > remaining)
        x = 0.0;
      else if (used_.count(a) && used_.at(a) >= max_per_day(*a))
        x = 0.0;
      if (a->role == ActivityRole::kNap)
        x *= pc_.traits.naps && minute >= 12 * 60 && minute <= 17 * 60 ? 3.0 : 0.0;
      any = any || x > 0.0;
      w.push_back(x);
    }
    if (!any) return nullptr;
    return pool[rng_.weighted(w)].first;
  }

  void fill(int from, int to, bool work_block) {
    const ActivitySpec* last = out_.empty() ? nullptr : k_.activity(out_.back().primary);
    int cursor = from;
    bool work_turn = true;
    while (to - cursor > 0) {
      const int remaining = to - cursor;
      const ActivitySpec* pick = nullptr;
      if (work_block && work_turn && !work_pool_.empty())
        pick = choose(work_pool_, cursor, remaining, nullptr);
      if (!pick && remaining >= 5) {
        pick = choose(pool_, cursor, remaining, last);
        if (work_block && pick && pick->max_minutes > 20 && pick->role != ActivityRole::kWork) {
          // Breaks during work are short.
          for (const char* n :
               {"making coffee", "browsing on the phone", "having a snack", "using the toilet"})
            if (const auto* brk = eligible_named(n); brk && brk->in_window(cursor % 1440)) {
              pick = brk;
              break;
            }
        }
      }
      if (!pick) {
        if (remaining < 10 && !out_.empty() && out_.back().end == cursor) {
          out_.back().end = to;  // too short for anything else: the previous activity runs on
          return;
        }
        // Nothing typical fits this hour: a quiet pause at home.
        pick = eligible_named(pc_.persona.age >= 11 && remaining <= 40 ? "browsing on the phone"
                                                                       : "relaxing on the sofa");
        if (!pick) pick = find("relaxing on the sofa");
        if (!pick) return;
        const int len = remaining < 55 ? remaining : 45;
        emit(pick, cursor, cursor + len);
        cursor += len;
        last = pick;
        continue;
      }
      int len = sample_minutes(*pick);
      if (len > remaining) len = remaining;
      if (remaining - len < 10) len = remaining;
      emit(pick, cursor, cursor + len);
      cursor += len;
      last = pick;
      work_turn = pick->role != ActivityRole::kWork;
    }
  }

  const HouseholdKnowledge& k_;
  const PersonaContext& pc_;
  const DayPlan& plan_;
  ActivityVocabulary& vocab_;
  Rng rng_;
  bool morning_shower_ = true;
  std::vector<std::pair<const ActivitySpec*, double>> pool_;
  std::vector<std::pair<const ActivitySpec*, double>> work_pool_;
  std::map<const ActivitySpec*, int> used_;
  std::set<ActivityRole> had_;
  std::vector<ScheduleEntry> out_;
};

}  // namespace

std::string_view block_kind_name(BlockKind kind) {
  switch (kind) {
    case BlockKind::kSleep:
      return "sleep";
    case BlockKind::kNap:
      return "nap";
    case BlockKind::kHome:
      return "home";
    case BlockKind::kWorkAtHome:
      return "work_at_home";
    case BlockKind::kAway:
      return "away";
  }
  return "home";
}

std::string format_minutes(int minutes_of_day) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d:%02d", minutes_of_day / 60, minutes_of_day % 60);
  return buf;
}

Result<DayPlan> OfflineDayPlanner::plan_day(const Persona& persona, const DayPlanContext& ctx) {
  const PersonaContext pc(persona);
  // The weekday of day 0 is what DayTimes counts from.
  const Weekday first = weekday_after(ctx.weekday, -ctx.day);
  const DayTimes times(pc, ctx.seed, first);
  std::vector<Fixed> blocks;
  for (const Fixed& f : times.fixed(ctx.day - 1))
    if (f.end > 1440) blocks.push_back({f.start - 1440, f.end - 1440, f.kind, f.description});
  for (const Fixed& f : times.fixed(ctx.day)) blocks.push_back(f);
  std::sort(blocks.begin(), blocks.end(), [](const Fixed& a, const Fixed& b) { return a.start < b.start; });

  DayPlan plan;
  plan.day = ctx.day;
  plan.weekday = ctx.weekday;
  int cursor = 0;
  auto push = [&](int s, int e, BlockKind kind, std::string desc) {
    s = std::max(s, 0);
    e = std::min(e, 1440);
    if (e <= s) return;
    if (!plan.blocks.empty() && plan.blocks.back().kind == kind && plan.blocks.back().end == s &&
        kind == BlockKind::kHome) {
      plan.blocks.back().end = e;
      return;
    }
    plan.blocks.push_back({s, e, std::move(desc), kind});
  };
  for (const Fixed& f : blocks) {
    const int s = std::max(f.start, cursor);
    if (f.end <= s) continue;
    if (s > cursor) push(cursor, s, BlockKind::kHome, "");
    push(s, f.end, f.kind, f.description);
    cursor = std::max(cursor, std::min(f.end, 1440));
    if (cursor >= 1440) break;
  }
  if (cursor < 1440) push(cursor, 1440, BlockKind::kHome, "");
  for (std::size_t i = 0; i < plan.blocks.size(); ++i) {
    PlanBlock& b = plan.blocks[i];
    if (b.kind != BlockKind::kHome) continue;
    const BlockKind prev = i > 0 ? plan.blocks[i - 1].kind : BlockKind::kHome;
    const BlockKind next = i + 1 < plan.blocks.size() ? plan.blocks[i + 1].kind : BlockKind::kSleep;
    b.description = home_description(b, prev, next, is_weekend(ctx.weekday));
  }
  return plan;
}

Result<std::vector<ScheduleEntry>> OfflineDecomposer::decompose(const Persona& persona, const DayPlan& plan,
                                                                ActivityVocabulary& vocabulary,
                                                                std::uint64_t seed) {
  const PersonaContext pc(persona);
  DayDecomposition d(knowledge_, pc, plan, vocabulary, seed);
  return d.run();
}

DayPlan leave_home_filter(const DayPlan& plan) {
  DayPlan out = plan;
  for (auto& b : out.blocks)
    if (b.kind == BlockKind::kAway) b.description = "leave home";
  return out;
}

Status validate_day_plan(const DayPlan& plan) {
  JsonChecker check;
  if (plan.blocks.empty()) check.add("/blocks", "must cover the day from 00:00 to 24:00");
  int cursor = 0;
  for (std::size_t i = 0; i < plan.blocks.size(); ++i) {
    const auto& b = plan.blocks[i];
    const std::string ptr = "/blocks/" + std::to_string(i);
    if (b.start != cursor)
      check.add(ptr + "/start", "must be " + format_minutes(cursor) + " (blocks are contiguous)");
    if (b.end <= b.start || b.end > 1440) check.add(ptr + "/end", "must be after start and at most 24:00");
    cursor = b.end;
  }
  if (!plan.blocks.empty() && cursor != 1440) check.add("/blocks", "must end at 24:00");
  if (!check.ok()) return tl::unexpected(check.error("invalid day plan for day " + std::to_string(plan.day)));
  return {};
}

Result<Schedule> generate_schedule(const Persona& persona, const ScheduleRequest& request,
                                   DayPlanGenerator& planner, ScheduleDecomposer& decomposer,
                                   ActivityVocabulary& vocabulary) {
  if (request.days < 1 || request.days > 366)
    return fail(ErrorCode::kValidation, "days must be between 1 and 366",
                {FieldError{"/days", "must be between 1 and 366", {}, 0, 0}});
  Schedule s;
  s.persona_id = persona_id(persona);
  s.first_day = request.first_day;
  s.days = request.days;
  for (int d = 0; d < request.days; ++d) {
    DayPlanContext ctx{d, weekday_after(request.first_day, d), request.seed,
                       s.plans.empty() ? nullptr : &s.plans.back()};
    auto plan = planner.plan_day(persona, ctx);
    if (!plan) return tl::unexpected(plan.error());
    if (auto v = validate_day_plan(*plan); !v) return tl::unexpected(v.error());
    const DayPlan filtered = leave_home_filter(*plan);
    auto entries = decomposer.decompose(persona, filtered, vocabulary, request.seed);
    if (!entries) return tl::unexpected(entries.error());
    int cursor = 0;
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const auto& e = (*entries)[i];
      if (e.start != cursor || e.end <= e.start || e.end > 1440)
        return fail(
            ErrorCode::kValidation, "the schedule of day " + std::to_string(d) + " is not contiguous",
            {FieldError{"/entries/" + std::to_string(i),
                        "starts at " + format_minutes(e.start) + ", expected " + format_minutes(cursor),
                        {},
                        0,
                        0}});
      cursor = e.end;
    }
    if (cursor != 1440)
      return fail(ErrorCode::kValidation,
                  "the schedule of day " + std::to_string(d) + " does not reach 24:00",
                  {FieldError{"/entries", "ends at " + format_minutes(cursor), {}, 0, 0}});
    for (auto e : *entries) {
      e.start += d * 1440;
      e.end += d * 1440;
      if (!s.entries.empty() && s.entries.back().end == e.start && s.entries.back().primary == e.primary &&
          (e.role == ActivityRole::kSleep || e.role == ActivityRole::kLeaveHome)) {
        s.entries.back().end = e.end;  // sleep and time away that run past midnight are one activity
        continue;
      }
      s.entries.push_back(std::move(e));
    }
    s.plans.push_back(std::move(*plan));
  }
  return s;
}

Result<Schedule> generate_schedule_offline(const Persona& persona, const HouseholdKnowledge& knowledge,
                                           const ScheduleRequest& request, ActivityVocabulary& vocabulary) {
  OfflineDayPlanner planner(knowledge);
  OfflineDecomposer decomposer(knowledge);
  return generate_schedule(persona, request, planner, decomposer, vocabulary);
}

std::vector<ScheduleIssue> check_schedule(const Schedule& s, const Persona& persona,
                                          const HouseholdKnowledge& knowledge) {
  std::vector<ScheduleIssue> issues;
  const int span = s.days * 1440;
  if (s.entries.empty()) {
    issues.push_back({"coverage", 0, "no activities"});
    return issues;
  }
  if (s.entries.front().start != 0)
    issues.push_back({"coverage", s.entries.front().start, "does not start at 00:00 of day 0"});
  if (s.entries.back().end != span)
    issues.push_back({"coverage", s.entries.back().end, "does not end at 24:00 of the last day"});
  for (std::size_t i = 0; i < s.entries.size(); ++i) {
    const auto& e = s.entries[i];
    if (e.end <= e.start)
      issues.push_back({"duration", e.start, "'" + e.name + "' has no positive duration"});
    if (i + 1 < s.entries.size()) {
      const auto& n = s.entries[i + 1];
      if (n.start < e.end)
        issues.push_back({"overlap", n.start, "'" + n.name + "' starts before '" + e.name + "' ends"});
      if (n.start > e.end)
        issues.push_back({"gap", e.end, "nothing scheduled until " + std::to_string(n.start)});
    }
  }
  const PersonaTraits traits = infer_traits(persona);
  const bool day_sleeper = traits.work == WorkPattern::kNightShift;
  auto overlap = [&](int a, int b, ActivityRole role, int min_len) {
    int total = 0;
    for (const auto& e : s.entries)
      if (e.role == role && e.end - e.start >= min_len)
        total += std::max(0, std::min(b, e.end) - std::max(a, e.start));
    return total;
  };
  for (int d = 1; d < s.days; ++d) {
    const int night = overlap(d * 1440 + 60, d * 1440 + 300, ActivityRole::kSleep, 180);
    const bool worked_night =
        day_sleeper && traits.work_days[static_cast<std::size_t>(weekday_after(s.first_day, d - 1))];
    if (worked_night) {
      const int by_day = overlap(d * 1440 + 300, d * 1440 + 1080, ActivityRole::kSleep, 240);
      if (by_day < 240) issues.push_back({"sleep", d * 1440, "no day sleep after the night shift"});
    } else if (night < 90) {
      issues.push_back({"sleep", d * 1440 + 60, "not asleep between 01:00 and 05:00"});
    }
  }
  std::vector<int> meals(static_cast<std::size_t>(s.days), 0),
      home_awake(static_cast<std::size_t>(s.days), 0);
  for (const auto& e : s.entries) {
    const auto day = static_cast<std::size_t>(e.start / 1440);
    if (is_meal(e.role)) {
      ++meals[day];
      const ActivitySpec* spec =
          e.activity >= 0 ? &knowledge.activities[static_cast<std::size_t>(e.activity)] : nullptr;
      if (spec && !spec->in_window(e.start % 1440))
        issues.push_back(
            {"meal", e.start,
             "'" + e.name + "' at " + format_minutes(e.start % 1440) + " is outside its plausible hours"});
    }
    if (e.role != ActivityRole::kSleep && e.role != ActivityRole::kNap && e.role != ActivityRole::kLeaveHome)
      for (std::size_t d = 0; d < meals.size(); ++d) {
        const int a = static_cast<int>(d) * 1440 + 360, b = static_cast<int>(d) * 1440 + 1320;
        home_awake[d] += std::max(0, std::min(b, e.end) - std::max(a, e.start));
      }
  }
  for (std::size_t d = 0; d < meals.size(); ++d)
    if (home_awake[d] >= 240 && meals[d] == 0)
      issues.push_back(
          {"meal", static_cast<int>(d) * 1440,
           "no meal at home on a day with " + std::to_string(home_awake[d] / 60) + " waking hours at home"});
  return issues;
}

Json to_json(const DayPlan& plan) {
  Json blocks = Json::array();
  for (const auto& b : plan.blocks)
    blocks.push_back({{"start", format_minutes(b.start)},
                      {"end", format_minutes(b.end)},
                      {"kind", block_kind_name(b.kind)},
                      {"description", b.description}});
  return {{"day", plan.day}, {"weekday", weekday_name(plan.weekday)}, {"blocks", blocks}};
}

Json to_json(const Schedule& s) {
  Json entries = Json::array();
  for (const auto& e : s.entries)
    entries.push_back(
        {{"start", e.start * 60},
         {"end", e.end * 60},
         {"day", e.start / 1440},
         {"clock", format_minutes(e.start % 1440) + "-" +
                       format_minutes(e.end % 1440 == 0 && e.end > e.start ? 1440 : e.end % 1440)},
         {"activity", e.name},
         {"primary", e.primary},
         {"role", activity_role_name(e.role)}});
  Json plans = Json::array();
  for (const auto& p : s.plans) plans.push_back(to_json(p));
  return {{"persona_id", s.persona_id},
          {"first_day", weekday_name(s.first_day)},
          {"days", s.days},
          {"plans", plans},
          {"entries", entries}};
}

Result<DayPlan> day_plan_from_json(const Json& json, const std::string& pointer) {
  JsonChecker check;
  DayPlan plan;
  if (!json.is_object()) {
    check.add(pointer, "must be an object with day, weekday and blocks");
    return tl::unexpected(check.error("invalid day plan"));
  }
  if (auto d = check.integer(json, pointer, "day", true, 0, 365)) plan.day = static_cast<int>(*d);
  if (auto w = check.string(json, pointer, "weekday", true, 3, 12)) {
    if (auto wd = parse_weekday(*w))
      plan.weekday = *wd;
    else
      check.add(JsonChecker::child(pointer, "weekday"), "must be a weekday name");
  }
  auto parse_clock = [&](const Json& obj, const std::string& ptr, std::string_view key) -> int {
    auto s = check.string(obj, ptr, key, true, 4, 5);
    if (!s) return -1;
    int h = -1, m = -1;
    if (std::sscanf(s->c_str(), "%d:%d", &h, &m) != 2 || h < 0 || h > 24 || m < 0 || m > 59 ||
        (h == 24 && m != 0)) {
      check.add(JsonChecker::child(ptr, key), "must be HH:MM between 00:00 and 24:00");
      return -1;
    }
    return h * 60 + m;
  };
  if (const Json* blocks = check.array(json, pointer, "blocks", true, 200))
    for (std::size_t i = 0; i < blocks->size(); ++i) {
      const std::string ptr = JsonChecker::child(JsonChecker::child(pointer, "blocks"), i);
      const Json& b = (*blocks)[i];
      PlanBlock pb;
      pb.start = parse_clock(b, ptr, "start");
      pb.end = parse_clock(b, ptr, "end");
      if (auto d = check.string(b, ptr, "description", true, 1, 200)) pb.description = *d;
      if (auto k = check.string(b, ptr, "kind", true, 1, 20)) {
        bool ok = false;
        for (BlockKind kind :
             {BlockKind::kSleep, BlockKind::kNap, BlockKind::kHome, BlockKind::kWorkAtHome, BlockKind::kAway})
          if (block_kind_name(kind) == *k) {
            pb.kind = kind;
            ok = true;
          }
        if (!ok)
          check.add(JsonChecker::child(ptr, "kind"), "must be one of sleep, nap, home, work_at_home, away");
      }
      plan.blocks.push_back(std::move(pb));
    }
  if (!check.ok()) return tl::unexpected(check.error("invalid day plan"));
  if (auto v = validate_day_plan(plan); !v) {
    auto e = v.error();
    for (auto& f : e.errors) f.pointer = pointer + f.pointer;
    return tl::unexpected(e);
  }
  return plan;
}

Result<Schedule> schedule_from_json(const Json& json, const HouseholdKnowledge& knowledge,
                                    const std::string& pointer) {
  JsonChecker check;
  Schedule s;
  if (!json.is_object()) {
    check.add(pointer, "must be an object with persona_id, first_day, days, plans and entries");
    return tl::unexpected(check.error("invalid schedule"));
  }
  if (auto v = check.string(json, pointer, "persona_id", true, 1, 80)) s.persona_id = *v;
  if (auto v = check.string(json, pointer, "first_day", true, 3, 12)) {
    if (auto wd = parse_weekday(*v))
      s.first_day = *wd;
    else
      check.add(JsonChecker::child(pointer, "first_day"), "must be a weekday name");
  }
  if (auto v = check.integer(json, pointer, "days", true, 1, 366)) s.days = static_cast<int>(*v);
  if (const Json* plans = check.array(json, pointer, "plans", true, 366))
    for (std::size_t i = 0; i < plans->size(); ++i) {
      auto plan =
          day_plan_from_json((*plans)[i], JsonChecker::child(JsonChecker::child(pointer, "plans"), i));
      if (!plan) {
        for (const auto& f : plan.error().errors) check.add(f.pointer, f.message);
        continue;
      }
      s.plans.push_back(std::move(*plan));
    }
  int cursor = 0;
  if (const Json* entries = check.array(json, pointer, "entries", true, 200000))
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const Json& e = (*entries)[i];
      const std::string ptr = JsonChecker::child(JsonChecker::child(pointer, "entries"), i);
      ScheduleEntry en;
      auto start = check.integer(e, ptr, "start", true, 0, 366LL * 86400);
      auto end = check.integer(e, ptr, "end", true, 1, 366LL * 86400);
      if (start && end) {
        if (*start % 60 != 0 || *end % 60 != 0) check.add(ptr, "start and end must be whole minutes");
        en.start = static_cast<int>(*start / 60);
        en.end = static_cast<int>(*end / 60);
        if (en.start != cursor)
          check.add(JsonChecker::child(ptr, "start"),
                    "must be " + std::to_string(cursor * 60) + " (entries are contiguous)");
        if (en.end <= en.start) check.add(JsonChecker::child(ptr, "end"), "must be after start");
        cursor = en.end;
      }
      if (auto v = check.string(e, ptr, "activity", true, 1, 120)) en.name = *v;
      if (auto v = check.string(e, ptr, "primary", true, 1, 120)) en.primary = *v;
      if (auto v = check.string(e, ptr, "role", true, 1, 40)) {
        if (auto role = parse_activity_role(*v))
          en.role = *role;
        else
          check.add(JsonChecker::child(ptr, "role"), "unknown activity role");
      }
      en.activity = knowledge.activity_index(en.primary);
      s.entries.push_back(std::move(en));
    }
  if (check.ok() && cursor != s.days * 1440)
    check.add(JsonChecker::child(pointer, "entries"),
              "must end at " + std::to_string(s.days * 86400) + " (the end of the last day)");
  if (!check.ok()) return tl::unexpected(check.error("invalid schedule"));
  return s;
}

}  // namespace socsim::household
