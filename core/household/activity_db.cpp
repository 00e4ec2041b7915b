#include "core/household/activity_db.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"

namespace socsim::household {
namespace {

bool is_storage(std::string_view r) {
  for (std::string_view s : {"ShelvingUnit", "Dresser", "Fridge", "TowelHolder", "HandTowelHolder",
                             "ToiletPaperHanger", "LaundryHamper", "Sink", "GarbageCan", "StoveBurner"})
    if (r == s) return true;
  return false;
}

// Curated activity used for a primary: itself, or the one sharing most words with it.
const ActivitySpec* curated_for(const HouseholdKnowledge& k, const std::string& primary) {
  if (const auto* a = k.activity(primary)) return a;
  auto words = [](std::string_view s) {
    std::set<std::string> w;
    std::string cur;
    for (char c : std::string(s) + " ") {
      if (std::isalpha(static_cast<unsigned char>(c)))
        cur += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      else {
        if (cur.size() > 3) w.insert(cur);
        cur.clear();
      }
    }
    return w;
  };
  const auto target = words(primary);
  const ActivitySpec* best = nullptr;
  double best_score = 0.0;
  for (const auto& a : k.activities) {
    if (a.role == ActivityRole::kLeaveHome) continue;
    const auto w = words(a.name);
    std::size_t common = 0;
    for (const auto& x : target) common += w.count(x);
    const double score =
        common == 0 ? 0.0
                    : static_cast<double>(common) / static_cast<double>(target.size() + w.size() - common);
    if (score > best_score) {
      best_score = score;
      best = &a;
    }
  }
  return best;
}

}  // namespace

const ActivityPrior* ActivityDatabase::find(std::string_view primary) const {
  auto it = std::lower_bound(activities.begin(), activities.end(), primary,
                             [](const ActivityPrior& a, std::string_view n) { return a.activity < n; });
  return it != activities.end() && it->activity == primary ? &*it : nullptr;
}

std::vector<std::string> primaries_of(const Schedule& schedule) {
  std::set<std::string> s;
  for (const auto& e : schedule.entries) s.insert(e.primary);
  return {s.begin(), s.end()};
}

Result<ActivityDatabase> OfflineActivityDatabaseGenerator::generate(const Persona& persona,
                                                                    std::span<const std::string> primaries,
                                                                    std::uint64_t seed) {
  const PersonaTraits traits = infer_traits(persona);
  ActivityDatabase db;
  db.persona_id = persona_id(persona);
  const Rng base(seed ^ fnv1a64(db.persona_id), fnv1a64("activity-db"));
  std::set<std::string> names(primaries.begin(), primaries.end());
  for (const auto& name : names) {
    ActivityPrior prior;
    prior.activity = name;
    const ActivitySpec* spec = curated_for(knowledge_, name);
    Rng rng = base.fork(name);
    if (spec && spec->role == ActivityRole::kLeaveHome) {
      db.activities.push_back(std::move(prior));
      continue;
    }
    std::array<double, kRoomTypeCount> rooms{};
    if (spec) {
      for (RoomType t : kRoomTypes) {
        const double w = spec->effects.rooms[index_of(t)];
        double f = std::exp(rng.normal(0.0, 0.2));
        if (traits.child && t == RoomType::kBedroom) f *= 1.3;
        rooms[index_of(t)] = w * f;
      }
    } else {
      rooms.fill(1.0);
    }
    double total = 0.0;
    for (double w : rooms) total += w;
    if (total <= 0.0) {
      db.activities.push_back(std::move(prior));
      continue;
    }
    const double storage = 0.6 + 0.8 * traits.tidiness, dropping = 1.4 - 0.8 * traits.tidiness;
    for (RoomType t : kRoomTypes) {
      const double p_room = rooms[index_of(t)] / total;
      if (p_room <= 0.0) continue;
      LocationPrior loc;
      loc.room = t;
      loc.p = p_room;
      if (spec)
        for (const auto& o : spec->effects.objects) {
          ObjectPrior op;
          op.type = o.type;
          op.p = std::clamp(o.p * std::exp(rng.normal(0.0, 0.25)), 0.02, 0.98);
          double sum = 0.0;
          for (const auto& [r, w] : o.receptacles) {
            const auto* rs = knowledge_.receptacle(r);
            const double noise = std::exp(rng.normal(0.0, 0.3));
            if (!rs || !rs->allowed_in(t)) continue;
            const double x = w * noise * (is_storage(r) ? storage : dropping);
            op.receptacles.emplace_back(r, x);
            sum += x;
          }
          if (op.receptacles.empty()) continue;
          for (auto& [r, w] : op.receptacles) w /= sum;
          loc.objects.push_back(std::move(op));
        }
      prior.locations.push_back(std::move(loc));
    }
    // Renormalise after dropping nothing (rooms with p = 0 are simply absent).
    db.activities.push_back(std::move(prior));
  }
  std::sort(db.activities.begin(), db.activities.end(),
            [](const auto& a, const auto& b) { return a.activity < b.activity; });
  if (auto v = validate_activity_db(db, knowledge_); !v) return tl::unexpected(v.error());
  return db;
}

namespace {
Status validate_impl(const ActivityDatabase& db, const HouseholdKnowledge& k, bool require_sorted) {
  JsonChecker check;
  for (std::size_t i = 0; i < db.activities.size(); ++i) {
    const auto& a = db.activities[i];
    const std::string pa = "/activities/" + std::to_string(i);
    if (a.activity.empty()) check.add(pa + "/activity", "must not be empty");
    if (require_sorted && i > 0 && !(db.activities[i - 1].activity < a.activity))
      check.add(pa + "/activity", "activities must be unique and sorted");
    if (!require_sorted)
      for (std::size_t j = 0; j < i; ++j)
        if (db.activities[j].activity == a.activity) check.add(pa + "/activity", "activity listed twice");
    if (a.locations.empty()) continue;
    double sum = 0.0;
    std::set<RoomType> seen;
    for (std::size_t j = 0; j < a.locations.size(); ++j) {
      const auto& l = a.locations[j];
      const std::string pl = pa + "/locations/" + std::to_string(j);
      if (!(l.p > 0.0 && l.p <= 1.0)) check.add(pl + "/p", "p(l|a) must be in (0, 1]");
      if (!seen.insert(l.room).second) check.add(pl + "/room", "room type listed twice");
      sum += l.p;
      for (std::size_t m = 0; m < l.objects.size(); ++m) {
        const auto& o = l.objects[m];
        const std::string po = pl + "/objects/" + std::to_string(m);
        if (!k.is_movable(o.type)) check.add(po + "/type", "unknown movable object type '" + o.type + "'");
        if (!(o.p >= 0.0 && o.p <= 1.0)) check.add(po + "/p", "p(o|a,l) must be in [0, 1]");
        double rs = 0.0;
        for (std::size_t n = 0; n < o.receptacles.size(); ++n) {
          const auto& [r, p] = o.receptacles[n];
          const std::string pr = po + "/receptacles/" + std::to_string(n);
          const auto* spec = k.receptacle(r);
          if (!spec)
            check.add(pr, "unknown receptacle type '" + r + "'");
          else if (!spec->allowed_in(l.room))
            check.add(pr, "'" + r + "' does not stand in a " + std::string(room_type_name(l.room)));
          if (!(p >= 0.0 && p <= 1.0)) check.add(pr, "p(r|o,a,l) must be in [0, 1]");
          rs += p;
        }
        if (o.receptacles.empty() || std::abs(rs - 1.0) > 1e-6)
          check.add(po + "/receptacles", "p(r|o,a,l) must sum to 1 (sums to " + std::to_string(rs) + ")");
      }
    }
    if (std::abs(sum - 1.0) > 1e-6)
      check.add(pa + "/locations", "p(l|a) must sum to 1 (sums to " + std::to_string(sum) + ")");
  }
  if (!check.ok())
    return tl::unexpected(check.error("invalid activity database for '" + db.persona_id + "'"));
  return {};
}
}  // namespace

Status validate_activity_db(const ActivityDatabase& db, const HouseholdKnowledge& k) {
  return validate_impl(db, k, true);
}

Json to_json(const ActivityDatabase& db) {
  Json acts = Json::array();
  for (const auto& a : db.activities) {
    Json locs = Json::array();
    for (const auto& l : a.locations) {
      Json objs = Json::array();
      for (const auto& o : l.objects) {
        Json rec = Json::object();
        for (const auto& [r, p] : o.receptacles) rec[r] = p;
        objs.push_back({{"type", o.type}, {"p", o.p}, {"receptacles", rec}});
      }
      locs.push_back({{"room", room_type_name(l.room)}, {"p", l.p}, {"objects", objs}});
    }
    acts.push_back({{"activity", a.activity}, {"locations", locs}});
  }
  return {{"persona_id", db.persona_id}, {"activities", acts}};
}

Result<ActivityDatabase> activity_db_from_json(const Json& json, const HouseholdKnowledge& k) {
  JsonChecker check;
  ActivityDatabase db;
  if (auto id = check.string(json, "", "persona_id", true, 1, 80)) db.persona_id = *id;
  if (const Json* acts = check.array(json, "", "activities", true, 2000))
    for (std::size_t i = 0; i < acts->size(); ++i) {
      const Json& a = (*acts)[i];
      const std::string pa = "/activities/" + std::to_string(i);
      ActivityPrior ap;
      if (auto n = check.string(a, pa, "activity", true, 1, 120)) ap.activity = *n;
      if (const Json* locs = check.array(a, pa, "locations", true, 8))
        for (std::size_t j = 0; j < locs->size(); ++j) {
          const Json& l = (*locs)[j];
          const std::string pl = pa + "/locations/" + std::to_string(j);
          LocationPrior lp;
          if (auto r = check.string(l, pl, "room", true, 1, 20)) {
            if (auto rt = parse_room_type(*r))
              lp.room = *rt;
            else
              check.add(pl + "/room", "must be Bedroom, Bathroom, LivingRoom or Kitchen");
          }
          if (auto p = check.number(l, pl, "p", true, 0.0, 1.0)) lp.p = *p;
          if (const Json* objs = check.array(l, pl, "objects", true, 200))
            for (std::size_t m = 0; m < objs->size(); ++m) {
              const Json& o = (*objs)[m];
              const std::string po = pl + "/objects/" + std::to_string(m);
              ObjectPrior op;
              if (auto t = check.string(o, po, "type", true, 1, 60)) op.type = *t;
              if (auto p = check.number(o, po, "p", true, 0.0, 1.0)) op.p = *p;
              if (const Json* rec = check.object(o, po, "receptacles", true))
                for (const auto& [r, p] : rec->items()) {
                  if (!p.is_number())
                    check.add(po + "/receptacles/" + json_pointer_token(r), "must be a number");
                  else
                    op.receptacles.emplace_back(r, p.get<double>());
                }
              lp.objects.push_back(std::move(op));
            }
          ap.locations.push_back(std::move(lp));
        }
      db.activities.push_back(std::move(ap));
    }
  if (!check.ok()) return tl::unexpected(check.error("invalid activity database"));
  if (auto v = validate_impl(db, k, false); !v) return tl::unexpected(v.error());  // pointers in input order
  std::sort(db.activities.begin(), db.activities.end(),
            [](const auto& a, const auto& b) { return a.activity < b.activity; });
  return db;
}

}  // namespace socsim::household
