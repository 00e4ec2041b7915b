// The offline decomposition of a filtered day plan into minute-level activities.
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
          w *= (0.5 + t.tidiness) * (weekend ? 1.5 : 1.0) * 0.5;
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
          w *= t.child ? 0.0 : 0.2;
          break;
        default:
          continue;  // anchored roles are placed by rules, not as fillers
      }
      // People spend free time in few, longer activities (DynamicTHOR: ~20 waking activities a
      // day, median 20 min): favour activities that can last.
      w *= std::max(5, a.max_minutes) / 30.0;
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
        (spec->role == ActivityRole::kSleep || spec->role == ActivityRole::kLeaveHome ||
         spec->role == ActivityRole::kWork)) {  // one work session runs on, not two
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
      add(front, find("getting out of bed"), 3, 0.5);
      add(front, find("using the toilet"), 1, 0.25);
      if (t.prayers_per_day > 0) add(front, eligible_named("praying"), 1, 0.9);
      if (morning_shower_ && !(age < 10)) add(front, find("taking a shower"), 1);
      for (const char* n : {"washing face", "shaving", "doing a skincare routine", "doing hair"})
        if (const auto* a = eligible_named(n)) add(front, a, 0, 0.2);
      if (age >= 3) add(front, find("getting dressed"), 2, is_weekend(plan_.weekday) ? 0.75 : 0.95);
      if (const auto* yoga = eligible_named("doing yoga");
          yoga && (mentions(t, "every morning") || mentions(t, "starts each day") || mentions(t, "daily")))
        add(front, yoga, 1, 0.8);
      if (const auto* st = eligible_named("stretching with a foam roller");
          st && mentions(t, "stretches every morning"))
        add(front, st, 1, 0.8);
      add(front, find("making the bed"), 0, t.child ? 0.2 : 0.6 * t.tidiness);
      // Breakfast only when it falls in its plausible hours and the morning is long enough.
      const ActivitySpec* breakfast = find("having breakfast");
      std::vector<Item> chain;
      if (!t.child && age >= 12) {
        add(chain, eligible_named(mentions(t, "tea") || mentions(t, "chai") ? "making tea" : "making coffee"),
            1, 0.4);
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
      add(front, find("brushing teeth"), 2, 0.5);
      if (const auto* pet = eligible_named("feeding the pet")) add(front, pet, 2);
    } else if (after_away) {
      add(front, find("coming home"), 3, 0.7);
      add(front, find("washing hands"), 0, 0.2);
    }

    if (before_away) {
      if (after_sleep || b.start < 11 * 60)
        if (const auto* lunch = eligible_named("packing a lunch box"); lunch && pc_.works_away(plan_.weekday))
          add(back, lunch, 0, 0.3);
      add(back, find("using the toilet"), 0, 0.15);
      add(back, find("getting ready to leave"), 3, 0.7);
    } else if (before_sleep) {
      if (age < 10)
        add(back, find("taking a bath"), 1, 0.7);
      else if (!morning_shower_)
        add(back, rng_.chance(0.2) ? eligible_named("taking a bath") : find("taking a shower"), 1, 0.65);
      if (const auto* d = eligible_named("doing a skincare routine")) add(back, d, 0, 0.15);
      if (const auto* j = eligible_named("writing in a journal")) add(back, j, 0, 0.4);
      add(back, find("brushing teeth"), 2, 0.45);
      if (const auto* story = eligible_named("reading a bedtime story")) add(back, story, 1, 0.8);
      add(back, find("getting ready for bed"), 3, 0.7);
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
      add(a.chain, eligible_named("setting the table"), 0, age < 13 ? 0.2 : 0.1);
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
      // Fillers last between their typical and their longest length.
      int len =
          std::max(pick->min_minutes,
                   round5(rng_.uniform((pick->min_minutes + pick->max_minutes) / 2.0, pick->max_minutes)));
      if (len > remaining) len = remaining;
      if (remaining - len < 10) len = remaining;
      emit(pick, cursor, cursor + len);
      cursor += len;
      last = pick;
      // A break after about every other work session, not after each.
      work_turn = pick->role != ActivityRole::kWork || rng_.chance(0.5);
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

Result<std::vector<ScheduleEntry>> OfflineDecomposer::decompose(const Persona& persona, const DayPlan& plan,
                                                                ActivityVocabulary& vocabulary,
                                                                std::uint64_t seed) {
  const PersonaContext pc(persona);
  DayDecomposition d(knowledge_, pc, plan, vocabulary, seed);
  return d.run();
}

}  // namespace socsim::household
