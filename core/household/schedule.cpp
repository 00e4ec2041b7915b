#include "core/household/schedule.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"

#include "core/household/schedule_offline.hpp"

// The offline planner and decomposer are in day_planner.cpp and day_decomposer.cpp.
namespace socsim::household {
using namespace offline;

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
                {FieldError{"/days", "must be between 1 and 366"}});
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
                        "starts at " + format_minutes(e.start) + ", expected " + format_minutes(cursor)}});
      cursor = e.end;
    }
    if (cursor != 1440)
      return fail(ErrorCode::kValidation,
                  "the schedule of day " + std::to_string(d) + " does not reach 24:00",
                  {FieldError{"/entries", "ends at " + format_minutes(cursor)}});
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
    e.under(pointer);
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
