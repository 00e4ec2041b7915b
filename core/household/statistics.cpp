#include "core/household/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/common/rng.hpp"

namespace socsim::household {
namespace {

struct MeanSd {
  double mean = 0, sd = 0;
};
MeanSd mean_sd(const std::vector<double>& v) {
  MeanSd m;
  if (v.empty()) return m;
  for (double x : v) m.mean += x;
  m.mean /= static_cast<double>(v.size());
  if (v.size() < 2) return m;
  double ss = 0;
  for (double x : v) ss += (x - m.mean) * (x - m.mean);
  m.sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
  return m;
}
double round2(double x) {
  return std::round(x * 100.0) / 100.0;
}

}  // namespace

Json paper_statistics() {
  return {{"personas", 50},
          {"age", {{"mean", 35.8}, {"sd", 12.13}}},
          {"activities", {{"names", 564}, {"primaries", 448}}},
          {"objects_per_event", {{"mean", 5.50}, {"sd", 4.58}}},
          {"days", 5}};
}

Json dynamic_thor_statistics() {
  // Measured on the paper authors' released schedules (../shared/peers/dsg/character_schedules.csv:
  // 50 characters × 5 days, 06:00–22:00, no sleep rows); counts only.
  return {{"per_persona_day", {{"mean", 20.14}, {"sd", 5.90}}},
          {"median_minutes", 20.0},
          {"leave_home_share", 0.055},
          {"primaries", 572}};
}

Json day_statistics(std::span<const ResidentProfile> residents) {
  // Waking activities only, as DynamicTHOR lists them: sleep entries are left out.
  std::vector<double> per_day, minutes;
  std::size_t entries = 0, leave = 0;
  for (const auto& r : residents) {
    std::vector<double> days(static_cast<std::size_t>(std::max(0, r.schedule.days)), 0.0);
    for (const auto& e : r.schedule.entries) {
      if (e.role == ActivityRole::kSleep) continue;
      const auto day = static_cast<std::size_t>(std::max(0, e.start) / 1440);
      if (day < days.size()) days[day] += 1.0;
      minutes.push_back(e.end - e.start);
      ++entries;
      leave += e.role == ActivityRole::kLeaveHome;
    }
    per_day.insert(per_day.end(), days.begin(), days.end());
  }
  const auto pd = mean_sd(per_day);
  double median = 0;
  if (!minutes.empty()) {
    std::sort(minutes.begin(), minutes.end());
    const std::size_t m = minutes.size() / 2;
    median = minutes.size() % 2 ? minutes[m] : (minutes[m - 1] + minutes[m]) / 2;
  }
  return {{"per_persona_day", {{"mean", round2(pd.mean)}, {"sd", round2(pd.sd)}}},
          {"median_minutes", round2(median)},
          {"leave_home_share", std::round(1000.0 * static_cast<double>(leave) /
                                          static_cast<double>(std::max<std::size_t>(1, entries))) /
                                   1000.0},
          {"dynamic_thor", dynamic_thor_statistics()}};
}

Json statistics_report(std::span<const ResidentProfile> residents, std::uint64_t seed) {
  std::vector<double> ages, per_persona_names, per_persona_primaries, per_event;
  std::set<std::string> names, primaries;
  std::map<int, int> distribution;
  std::map<std::string, std::set<std::string>> receptacles_of;
  std::size_t events = 0;
  Rng rng(seed, fnv1a64("statistics"));
  for (const auto& r : residents) {
    ages.push_back(r.persona.age);
    std::set<std::string> mine, mine_primary;
    for (const auto& e : r.schedule.entries) {
      names.insert(e.name);
      primaries.insert(e.primary);
      mine.insert(e.name);
      mine_primary.insert(e.primary);
      if (e.role == ActivityRole::kLeaveHome) continue;  // not an indoor event
      const ActivityPrior* prior = r.activity_db.find(e.primary);
      int count = 0;
      if (prior && !prior->locations.empty()) {
        std::vector<double> w;
        for (const auto& l : prior->locations) w.push_back(l.p);
        const auto& loc = prior->locations[rng.weighted(w)];
        for (const auto& o : loc.objects) count += o.p > 0.0;
      }
      per_event.push_back(count);
      ++distribution[count];
      ++events;
    }
    per_persona_names.push_back(static_cast<double>(mine.size()));
    per_persona_primaries.push_back(static_cast<double>(mine_primary.size()));
    for (const auto& a : r.activity_db.activities)
      for (const auto& l : a.locations)
        for (const auto& o : l.objects)
          for (const auto& [rt, p] : o.receptacles)
            if (p > 0.0) receptacles_of[o.type].insert(rt);
  }
  const auto age = mean_sd(ages), ope = mean_sd(per_event), ppn = mean_sd(per_persona_names),
             ppp = mean_sd(per_persona_primaries);
  Json dist = Json::object();
  for (const auto& [k, v] : distribution)
    dist[std::to_string(k)] = round2(100.0 * v / static_cast<double>(std::max<std::size_t>(1, events)));
  Json by_count = Json::object();
  Json per_type = Json::object();
  std::map<std::size_t, int> hist;
  for (const auto& [type, recs] : receptacles_of) {
    ++hist[recs.size()];
    per_type[type] = Json(std::vector<std::string>(recs.begin(), recs.end()));
  }
  for (const auto& [k, v] : hist) by_count[std::to_string(k)] = v;
  return {
      {"personas", residents.size()},
      {"days", residents.empty() ? 0 : residents.front().schedule.days},
      {"age", {{"mean", round2(age.mean)}, {"sd", round2(age.sd)}}},
      {"activities",
       {{"names", names.size()},
        {"primaries", primaries.size()},
        {"per_persona_names", {{"mean", round2(ppn.mean)}, {"sd", round2(ppn.sd)}}},
        {"per_persona_primaries", {{"mean", round2(ppp.mean)}, {"sd", round2(ppp.sd)}}}}},
      {"objects_per_event",
       {{"events", events}, {"mean", round2(ope.mean)}, {"sd", round2(ope.sd)}, {"percent_by_count", dist}}},
      {"days_of_activities", day_statistics(residents)},
      {"receptacle_types_per_object_type",
       {{"object_types", receptacles_of.size()}, {"histogram", by_count}, {"by_type", per_type}}},
      {"paper", paper_statistics()}};
}

}  // namespace socsim::household
