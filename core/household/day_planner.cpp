// The offline day plan: sleep, work and outdoor habits (a curated habit table) as fixed blocks
// around a persona's working pattern; the gaps are time at home.
#include "core/household/schedule.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "core/household/schedule_offline.hpp"

namespace socsim::household {
namespace {
using namespace offline;

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

}  // namespace

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

}  // namespace socsim::household
