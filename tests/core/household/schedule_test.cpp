// Hierarchical schedules: every built-in persona gets five consistent days (no overlaps or gaps,
// sleep at night or by day after a night shift, meals at plausible hours), work days differ
// from days off, the same seed gives the same days, and generator answers of the wrong shape
// (as an LLM might give) are refused with a pointer.
#include "core/household/schedule.hpp"

#include <gtest/gtest.h>

#include <map>

#include "tests/core/household/household_fixture.hpp"

namespace socsim::household {
namespace {

using testing::knowledge;

Schedule make(const Persona& p, ScheduleRequest req = {}) {
  auto vocab = ActivityVocabulary::initial(knowledge());
  auto s = generate_schedule_offline(p, knowledge(), req, vocab);
  EXPECT_TRUE(s) << s.error().message();
  return *s;
}

const Persona& persona(std::string_view id) {
  const Persona* p = knowledge().persona(id);
  if (!p) throw std::runtime_error("no persona " + std::string(id));
  return *p;
}

int away_minutes(const Schedule& s, int day, int from, int to) {
  int total = 0;
  for (const auto& e : s.entries)
    if (e.role == ActivityRole::kLeaveHome)
      total += std::max(0, std::min(day * 1440 + to, e.end) - std::max(day * 1440 + from, e.start));
  return total;
}

TEST(Schedule, FiftyPersonasFiveDaysWithoutInconsistencies) {
  auto vocab = ActivityVocabulary::initial(knowledge());
  for (const auto& p : knowledge().personas) {
    auto s = generate_schedule_offline(p, knowledge(), {5, Weekday::kWednesday, 7}, vocab);
    ASSERT_TRUE(s) << p.name << ": " << s.error().message();
    EXPECT_EQ(s->plans.size(), 5u);
    for (const auto& issue : check_schedule(*s, p, knowledge()))
      ADD_FAILURE() << p.name << ": " << issue.kind << " at minute " << issue.minute << ": " << issue.detail;
    std::map<std::string, int> per_day;
    for (const auto& e : s->entries) ++per_day[std::to_string(e.start / 1440)];
    for (const auto& [day, n] : per_day) EXPECT_GE(n, 8) << p.name << " day " << day << " is too sparse";
  }
  EXPECT_GT(vocab.name_count(), vocab.primary_count()) << "synonyms appear and are merged";
}

TEST(Schedule, OtherSpansAndStartDaysAreConsistentToo) {
  for (const char* id : {"aiyana-redcloud", "ben-okafor", "hamid-rahimi", "mei-lin", "tevita-fifita"}) {
    for (ScheduleRequest req :
         {ScheduleRequest{1, Weekday::kSunday, 3}, ScheduleRequest{14, Weekday::kMonday, 11}}) {
      const auto s = make(persona(id), req);
      EXPECT_EQ(s.entries.back().end, req.days * 1440);
      for (const auto& issue : check_schedule(s, persona(id), knowledge()))
        ADD_FAILURE() << id << " (" << req.days << " days): " << issue.kind << " " << issue.detail;
    }
  }
}

TEST(Schedule, SameSeedSameDaysOtherSeedOtherDays) {
  const auto& p = persona("grace-whitfield");
  EXPECT_EQ(make(p, {5, Weekday::kWednesday, 42}), make(p, {5, Weekday::kWednesday, 42}));
  EXPECT_NE(make(p, {5, Weekday::kWednesday, 42}).entries, make(p, {5, Weekday::kWednesday, 43}).entries);
}

TEST(Schedule, WorkAndSchoolDaysDifferFromDaysOff) {
  int compared = 0;
  for (const auto& p : knowledge().personas) {
    const auto t = infer_traits(p);
    if (t.work != WorkPattern::kCommute && t.work != WorkPattern::kSchool && t.work != WorkPattern::kCollege)
      continue;
    const auto s = make(p, {7, Weekday::kMonday, 5});
    double work = 0, off = 0;
    int n_work = 0, n_off = 0;
    for (int d = 0; d < 7; ++d) {
      const bool busy = t.work_days[static_cast<std::size_t>(d)];
      (busy ? work : off) += away_minutes(s, d, 6 * 60, 20 * 60);
      (busy ? n_work : n_off) += 1;
    }
    if (n_work == 0 || n_off == 0) continue;
    const bool full_time = t.work_end - t.work_start >= 6 * 60;
    EXPECT_GT(work / n_work, off / n_off + (full_time ? 120 : 0))
        << p.name << " spends work days away longer than days off";
    ++compared;
  }
  EXPECT_GE(compared, 20);
}

TEST(Schedule, NightShiftWorkersSleepByDay) {
  for (const char* id : {"aiyana-redcloud", "oskar-lindqvist", "viktor-horvath"}) {
    const auto& p = persona(id);
    const auto t = infer_traits(p);
    ASSERT_EQ(t.work, WorkPattern::kNightShift) << id;
    const auto s = make(p, {7, Weekday::kMonday, 1});
    int day_sleeps = 0;
    for (int d = 1; d < 7; ++d) {
      if (!t.work_days[static_cast<std::size_t>(d - 1)]) continue;
      bool asleep_at_noon = false, away_at_3am = false;
      for (const auto& e : s.entries) {
        asleep_at_noon |=
            e.role == ActivityRole::kSleep && e.start <= d * 1440 + 720 && e.end > d * 1440 + 720;
        away_at_3am |=
            e.role == ActivityRole::kLeaveHome && e.start <= d * 1440 + 180 && e.end > d * 1440 + 180;
      }
      EXPECT_TRUE(asleep_at_noon) << id << " day " << d;
      EXPECT_TRUE(away_at_3am) << id << " day " << d;
      ++day_sleeps;
    }
    EXPECT_GE(day_sleeps, 3) << id;
  }
}

TEST(Schedule, ChildrenDoNotCookAndGoToBedEarly) {
  const auto& p = persona("tomas-ruiz");
  const auto s = make(p);
  for (const auto& e : s.entries) {
    EXPECT_NE(e.role, ActivityRole::kDinnerPrep) << e.name;
    EXPECT_NE(e.role, ActivityRole::kBreakfastPrep) << e.name;
    if (e.role == ActivityRole::kSleep && e.end - e.start > 300 && e.start > 0) {
      EXPECT_LT(e.start % 1440, 21 * 60) << "bedtime";
    }
  }
}

TEST(Schedule, CheckerFindsBrokenSchedules) {
  const auto& p = persona("amara-diallo");
  auto s = make(p);
  ASSERT_TRUE(check_schedule(s, p, knowledge()).empty());
  auto broken = s;
  broken.entries[3].end += 7;                         // overlaps the next one
  broken.entries.erase(broken.entries.begin() + 10);  // leaves a gap
  std::set<std::string> kinds;
  for (const auto& i : check_schedule(broken, p, knowledge())) kinds.insert(i.kind);
  EXPECT_TRUE(kinds.count("overlap"));
  EXPECT_TRUE(kinds.count("gap"));
  // Breakfast moved to 03:00 of day 2 and the night's sleep replaced by television.
  auto odd = s;
  const int dinner = knowledge().activity_index("having dinner");
  for (auto& e : odd.entries) {
    if (e.role == ActivityRole::kSleep && e.start < 2 * 1440 + 180 && e.end > 2 * 1440 + 180) {
      e.role = ActivityRole::kLeisure;
      e.primary = e.name = "watching TV";
    }
  }
  for (auto& e : odd.entries)
    if (e.start / 1440 == 1 && e.role == ActivityRole::kLeisure && e.start % 1440 < 23 * 60 &&
        e.start % 1440 > 21 * 60) {
      e.role = ActivityRole::kDinner;
      e.activity = dinner;
      break;
    }
  kinds.clear();
  for (const auto& i : check_schedule(odd, p, knowledge())) kinds.insert(i.kind);
  EXPECT_TRUE(kinds.count("sleep"));
}

TEST(Vocabulary, GrowsAndMergesSynonyms) {
  auto v = ActivityVocabulary::initial(knowledge());
  const std::size_t before = v.name_count();
  auto r = v.add("Eating Breakfast");
  EXPECT_EQ(r.primary, "having breakfast");
  EXPECT_FALSE(r.new_primary);
  r = v.add("reading books");
  EXPECT_EQ(r.primary, "reading a book");
  r = v.add("playing the violin");  // curated, not in the starting list
  EXPECT_EQ(r.primary, "practising the violin");
  EXPECT_TRUE(r.new_name);
  r = v.add("having a snack at night");  // unknown wording, close to a known activity
  EXPECT_EQ(r.primary, "having a snack");
  EXPECT_GE(r.activity, 0);
  r = v.add("assembling a drone");
  EXPECT_TRUE(r.new_primary);
  EXPECT_EQ(r.activity, -1);
  EXPECT_EQ(v.name_count(), before + 3) << "breakfast and books were in the starting list already";
  EXPECT_EQ(v.aliases().at("having a snack at night"), "having a snack");
  EXPECT_EQ(v.resolve("Assembling the drone")->primary, "assembling a drone");
}

// A generator that answers like a careless LLM.
class ScriptedPlanner : public DayPlanGenerator {
 public:
  explicit ScriptedPlanner(std::vector<PlanBlock> blocks) : blocks_(std::move(blocks)) {}
  Result<DayPlan> plan_day(const Persona&, const DayPlanContext& c) override {
    return DayPlan{c.day, c.weekday, blocks_};
  }
  std::vector<PlanBlock> blocks_;
};

TEST(Schedule, PlansOfTheWrongShapeAreRefused) {
  auto vocab = ActivityVocabulary::initial(knowledge());
  OfflineDecomposer decomposer(knowledge());
  ScriptedPlanner gap(
      {{0, 420, "sleeping", BlockKind::kSleep}, {480, 1440, "a day at home", BlockKind::kHome}});
  auto s = generate_schedule(persona("helen-park"), {1}, gap, decomposer, vocab);
  ASSERT_FALSE(s);
  ASSERT_FALSE(s.error().errors.empty());
  EXPECT_EQ(s.error().errors.front().pointer, "/blocks/1/start");

  ScriptedPlanner fine({{0, 420, "sleeping", BlockKind::kSleep},
                        {420, 540, "morning", BlockKind::kHome},
                        {540, 1020, "visiting the museum", BlockKind::kAway},
                        {1020, 1350, "evening", BlockKind::kHome},
                        {1350, 1440, "sleeping", BlockKind::kSleep}});
  s = generate_schedule(persona("helen-park"), {2}, fine, decomposer, vocab);
  ASSERT_TRUE(s) << s.error().message();
  EXPECT_TRUE(check_schedule(*s, persona("helen-park"), knowledge()).empty());
  EXPECT_EQ(leave_home_filter(s->plans[0]).blocks[2].description, "leave home");
  EXPECT_EQ(s->plans[0].blocks[2].description, "visiting the museum");
}

TEST(Schedule, DayPlansReadFromJsonWithPointers) {
  const auto plan = make(persona("kofi-mensah")).plans[1];
  auto back = day_plan_from_json(to_json(plan));
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(*back, plan);
  Json bad = to_json(plan);
  bad["blocks"][1]["start"] = "25:00";
  bad["blocks"][0]["kind"] = "party";
  auto r = day_plan_from_json(bad, "/plans/1");
  ASSERT_FALSE(r);
  std::set<std::string> ptrs;
  for (const auto& f : r.error().errors) ptrs.insert(f.pointer);
  EXPECT_TRUE(ptrs.count("/plans/1/blocks/1/start"));
  EXPECT_TRUE(ptrs.count("/plans/1/blocks/0/kind"));
}

}  // namespace
}  // namespace socsim::household
