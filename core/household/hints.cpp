#include "core/household/hints.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/common/rng.hpp"
#include "core/common/text.hpp"

namespace socsim::household {
namespace {

std::string room_phrase(RoomType t) {
  return object_words(room_type_name(t));
}

std::string time_of_day(Seconds when, Seconds now, Weekday first) {
  const Seconds day_now = now / kSecondsPerDay, day_then = when / kSecondsPerDay;
  const int hour = static_cast<int>((when % kSecondsPerDay) / 3600);
  const char* part = hour < 5 ? "night" : hour < 12 ? "morning" : hour < 17 ? "afternoon" : "evening";
  if (day_then == day_now) return hour < 5 ? "last night" : std::string("this ") + part;
  if (day_then == day_now - 1) return hour < 5 ? "the night before last" : std::string("yesterday ") + part;
  return "on " + std::string(weekday_name(weekday_after(first, static_cast<int>(day_then)))) + " " + part;
}

RememberedActivity remembered(const DynamicScene& scene, int idx) {
  const SceneEvent& e = scene.events()[static_cast<std::size_t>(idx)];
  const ScheduleEntry& en = scene.entry(e);
  return {idx, en.name, en.primary, en.role, e.room, e.start, e.end};
}

std::string item_text(const RememberedActivity& a, const House& h) {
  if (a.role == ActivityRole::kLeaveHome) return "leave home (away from home)";
  if (a.room < 0) return a.name;
  return a.name + " (" + room_phrase(h.rooms[static_cast<std::size_t>(a.room)].type) + ")";
}

// p(o|a,l) of the resident's own activity database at the remembered room's type.
double involvement(const ActivityDatabase& db, const RememberedActivity& a, RoomType room,
                   std::string_view type) {
  const ActivityPrior* prior = db.find(a.primary);
  if (!prior) return 0.0;
  for (const auto& loc : prior->locations) {
    if (loc.room != room) continue;
    for (const auto& o : loc.objects)
      if (o.type == type) return o.p;
  }
  return 0.0;
}

// Whether event `idx` moved an object of this type (when it ended).
bool moved_type(const DynamicScene& scene, int idx, std::string_view type) {
  const SceneEvent& e = scene.events()[static_cast<std::size_t>(idx)];
  const House& house = scene.house();
  for (const auto& r : scene.relocations_between(e.end, e.end + 1))
    if (r.event == idx &&
        house.entities[static_cast<std::size_t>(house.objects[static_cast<std::size_t>(r.object)])].type ==
            type)
      return true;
  return false;
}

// Finds `words` as whole words in `text` at or after `from`; npos when absent.
std::size_t find_words(std::string_view text, std::string_view words, std::size_t from = 0) {
  for (std::size_t at = text.find(words, from); at != std::string_view::npos; at = text.find(words, at + 1)) {
    const bool left = at == 0 || !std::isalpha(static_cast<unsigned char>(text[at - 1]));
    const std::size_t end = at + words.size();
    const bool right = end >= text.size() || !std::isalpha(static_cast<unsigned char>(text[end]));
    if (left && right) return at;
  }
  return std::string_view::npos;
}

}  // namespace

std::vector<const RememberedActivity*> ResidentMemory::activities() const {
  std::vector<const RememberedActivity*> out;
  std::set<int> seen;
  for (const auto& [slot, items] : hours)
    for (const auto& a : items)
      if (seen.insert(a.event).second) out.push_back(&a);
  for (const auto& a : recent)
    if (seen.insert(a.event).second) out.push_back(&a);
  return out;
}

ResidentMemory remember(const DynamicScene& scene, int resident, Seconds t, Seconds lookback) {
  ResidentMemory m;
  m.resident = resident;
  m.time = t;
  m.lookback = lookback;
  m.first_day = scene.first_day();
  const Seconds from = std::max<Seconds>(0, t - lookback);
  std::map<Seconds, std::vector<std::pair<Seconds, int>>> cover;  // slot → (seconds covered, event)
  for (int idx : scene.events_of(resident)) {
    const SceneEvent& e = scene.events()[static_cast<std::size_t>(idx)];
    if (e.end <= from || e.start >= t) continue;
    const Seconds a = std::max(e.start, from), b = std::min(e.end, t);
    for (Seconds slot = a / 3600; slot <= (b - 1) / 3600; ++slot) {
      const Seconds covered = std::min(b, (slot + 1) * 3600) - std::max(a, slot * 3600);
      cover[slot].emplace_back(covered, idx);
    }
    if (e.end > t - ResidentMemory::kRecentSpan) m.recent.push_back(remembered(scene, idx));
  }
  for (auto& [slot, items] : cover) {
    // What filled the hour: the longest one or two activities of at least a quarter of an hour.
    std::stable_sort(items.begin(), items.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    std::vector<RememberedActivity> kept;
    for (const auto& [covered, idx] : items) {
      if (kept.size() == 2 || (covered < 15 * 60 && !kept.empty())) break;
      kept.push_back(remembered(scene, idx));
    }
    m.hours.emplace_back(slot * 3600, std::move(kept));
  }
  return m;
}

std::string memory_text(const ResidentMemory& m, const House& h) {
  std::string out;
  for (const auto& [start, items] : m.hours) {
    const std::string end = format_clock(start + 3600, m.first_day).substr(4);
    out += format_clock(start, m.first_day) + "-" + (end == "00:00" ? "24:00" : end) + ": ";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + item_text(items[i], h);
    out += "\n";
  }
  if (!m.recent.empty()) {
    out += "Just now:\n";
    for (const auto& a : m.recent)
      out += "  " + format_clock(std::max(a.start, m.time - m.lookback), m.first_day).substr(4) + "-" +
             format_clock(std::min(a.end, m.time), m.first_day).substr(4) + " " + item_text(a, h) + "\n";
  }
  return out.empty() ? "(nothing remembered)\n" : out;
}

Hint hint_from_memory(const DynamicScene& scene, const ResidentMemory& m, std::string_view type,
                      const HintStyle& style) {
  Hint h;
  const House& house = scene.house();
  const ActivityDatabase& db = scene.residents()[static_cast<std::size_t>(m.resident)].profile->activity_db;
  // Newest first: asked "have you used it recently?", a person goes back from now to the last
  // time they remember using it.
  auto items = m.activities();
  std::stable_sort(items.begin(), items.end(),
                   [](const RememberedActivity* x, const RememberedActivity* y) { return x->end > y->end; });
  const std::string what = object_words(type);
  Rng rng = Rng(scene.seed(), 0x68696e74)
                .fork("hint|" + std::to_string(m.resident) + "|" + std::string(type) + "|" +
                      std::to_string(m.time));
  const RememberedActivity* last_use = nullptr;
  for (const RememberedActivity* a : items) {
    if (a->room < 0 || a->role == ActivityRole::kLeaveHome) continue;
    const RoomType room = house.rooms[static_cast<std::size_t>(a->room)].type;
    // Judged from the activity database, p(o|a,l); an activity in which the resident really moved
    // such an object is recalled as a use with probability `recall` besides.
    double q = involvement(db, *a, room, type);
    if (a->end <= m.time && moved_type(scene, a->event, type)) q = style.recall + (1.0 - style.recall) * q;
    if (q > 0.0 && rng.chance(q)) {
      last_use = a;
      break;
    }
  }
  if (!last_use) {
    h.text = "No, I don't think I've used the " + what + " recently.";
    return h;
  }
  const RememberedActivity& a = *last_use;
  const Room& room = house.rooms[static_cast<std::size_t>(a.room)];
  h.used = true;
  h.event = a.event;
  h.activity = a.name;
  h.when = std::min(a.end, m.time);
  h.room_id = room.id;
  const std::string in_room = room_phrase(room.type);
  if (rng.chance(style.vague)) {
    h.text = "I'm not sure. Maybe I had the " + what + " in the " + in_room + "?";
    return h;
  }
  // Did this activity really move such an object, and was it central enough to remember where?
  const SceneEvent& e = scene.events()[static_cast<std::size_t>(a.event)];
  const double p = involvement(db, a, room.type, type);
  if (p >= style.memorable_p && e.end <= m.time && m.time - e.end <= style.memorable_within) {
    for (const auto& r : scene.relocations_between(e.end, e.end + 1)) {
      const Entity& obj =
          house.entities[static_cast<std::size_t>(house.objects[static_cast<std::size_t>(r.object)])];
      if (r.event != a.event || obj.type != type) continue;
      const Entity& rec = house.entities[static_cast<std::size_t>(r.to)];
      h.object = r.object;
      h.receptacle_id = rec.id;
      h.text = "Yes, I used the " + what + " while " + a.name + " " +
               time_of_day(e.end, m.time, m.first_day) + " and left it on the " + object_words(rec.type) +
               " in the " + room_phrase(house.rooms[static_cast<std::size_t>(rec.room)].type) + ".";
      return h;
    }
  }
  h.text = "I think I had the " + what + " while " + a.name + " " + time_of_day(h.when, m.time, m.first_day) +
           ", in the " + in_room + ".";
  return h;
}

HintReading read_hint(std::string_view hint, const HouseholdKnowledge& k) {
  HintReading out;
  const std::string text = ascii_lower(hint);
  if (text.rfind("no", 0) == 0 && (text.size() == 2 || !std::isalpha(static_cast<unsigned char>(text[2]))))
    return out;
  out.used = true;
  out.vague = find_words(text, "not sure") != std::string::npos ||
              find_words(text, "maybe") != std::string::npos ||
              find_words(text, "might") != std::string::npos;
  std::size_t room_at = std::string::npos;
  for (RoomType t : kRoomTypes) {
    const std::string words = room_phrase(t);
    for (std::size_t at = find_words(text, words); at != std::string::npos;
         at = find_words(text, words, at + 1))
      if (room_at == std::string::npos || at > room_at) room_at = at, out.room = t;
  }
  // "on the <receptacle>": the longest receptacle type named after "on the".
  for (std::size_t on = text.find("on the "); on != std::string::npos; on = text.find("on the ", on + 1)) {
    const std::string_view rest = std::string_view(text).substr(on + 7);
    std::size_t best = 0;
    for (const auto& r : k.receptacles) {
      const std::string words = object_words(r.type);
      if (words.size() > best && rest.rfind(words, 0) == 0) best = words.size(), out.receptacle_type = r.type;
    }
  }
  // "while <activity>": the longest name or synonym of a curated activity.
  if (const auto w = text.find("while "); w != std::string::npos) {
    const std::string_view rest = std::string_view(text).substr(w + 6);
    std::size_t best = 0;
    for (const auto& a : k.activities) {
      auto consider = [&](const std::string& name) {
        const std::string n = ascii_lower(name);
        if (n.size() > best && rest.rfind(n, 0) == 0) best = n.size(), out.activity = &a;
      };
      consider(a.name);
      for (const auto& s : a.synonyms) consider(s);
    }
  }
  return out;
}

std::vector<HintReading> read_hints(std::string_view answers, const HouseholdKnowledge& k) {
  std::vector<HintReading> out;
  while (!answers.empty()) {
    const std::size_t nl = answers.find('\n');
    std::string_view line = answers.substr(0, nl);
    answers = nl == std::string_view::npos ? std::string_view{} : answers.substr(nl + 1);
    // "<name>: answer" — a name holds no sentence punctuation.
    if (const std::size_t colon = line.find(": ");
        colon != std::string_view::npos &&
        line.substr(0, colon).find_first_of(".,?!") == std::string_view::npos)
      line = line.substr(colon + 2);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front()))) line.remove_prefix(1);
    if (!line.empty()) out.push_back(read_hint(line, k));
  }
  return out;
}

std::vector<double> hint_distribution(std::span<const HintReading> readings, std::string_view object_type,
                                      std::span<const ReceptacleView> recs, std::span<const double> base,
                                      double trust, bool activity_tables) {
  std::vector<double> sum;
  int used = 0;
  for (const HintReading& r : readings) {
    if (!r.used) continue;
    const std::vector<double> p = hint_distribution(r, object_type, recs, base, trust, activity_tables);
    if (sum.empty()) sum.assign(p.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) sum[i] += p[i];
    ++used;
  }
  if (used == 0) return hint_distribution(HintReading{}, object_type, recs, base, trust, activity_tables);
  for (double& x : sum) x /= used;
  return sum;
}

std::vector<double> hint_distribution(const HintReading& reading, std::string_view object_type,
                                      std::span<const ReceptacleView> recs, std::span<const double> base_in,
                                      double trust, bool activity_tables) {
  const std::size_t n = recs.size();
  std::vector<double> base(n, 1.0);
  if (base_in.size() == n)
    for (std::size_t i = 0; i < n; ++i) base[i] = std::max(0.0, base_in[i]);
  auto normalise = [](std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    if (s > 0.0)
      for (double& x : v) x /= s;
    return s > 0.0;
  };
  if (!normalise(base)) base.assign(n, n ? 1.0 / static_cast<double>(n) : 0.0);
  if (!reading.used || n == 0) return base;
  std::vector<double> focus(n, 0.0);
  if (!reading.receptacle_type.empty()) {
    for (std::size_t i = 0; i < n; ++i)
      focus[i] =
          recs[i].type == reading.receptacle_type && (!reading.room || recs[i].room_type == *reading.room);
    if (!normalise(focus))  // the room named has none: trust the type alone
      for (std::size_t i = 0; i < n; ++i) focus[i] = recs[i].type == reading.receptacle_type;
  } else {
    const ObjectEffect* effect = nullptr;
    double rec_total = 0.0;
    const ActivitySpec* activity = activity_tables ? reading.activity : nullptr;
    if (activity)
      for (const auto& o : activity->effects.objects)
        if (o.type == object_type) {
          effect = &o;
          for (const auto& [r, x] : o.receptacles) rec_total += x;
        }
    for (std::size_t i = 0; i < n; ++i) {
      // Without the activity's tables the answer places the object in a room and says nothing of
      // which receptacle there: its share is spread evenly over the room's receptacles, and the
      // base's own view of them stays in the remaining 1 − trust (docs/navbench.md, "Hints and the
      // two planners").
      double x = activity_tables ? base[i] : 1.0;
      if (reading.room) x *= recs[i].room_type == *reading.room ? 1.0 : 0.0;
      if (activity) {
        x *= activity->effects.rooms[index_of(recs[i].room_type)] + 0.05;
        if (effect) {
          double r = 0.0;
          for (const auto& [type, weight] : effect->receptacles)
            if (type == recs[i].type) r = weight;
          x *= 0.1 + (rec_total > 0.0 ? r / rec_total : 0.0);
        }
      }
      focus[i] = x;
    }
    if (!reading.room && !activity) return base;
  }
  if (!normalise(focus)) return base;
  const double t = reading.vague ? trust / 2.0 : trust;
  std::vector<double> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = (1.0 - t) * base[i] + t * focus[i];
  return p;
}

Result<HintInterpretation> OfflineHintInterpreter::interpret(const HintInterpretationQuery& q) {
  if (!q.house) return fail(ErrorCode::kValidation, "no house to interpret the hint in");
  const House& h = *q.house;
  std::vector<ReceptacleView> views;
  std::vector<double> base;
  for (int r : h.receptacles) {
    const Entity& e = h.entities[static_cast<std::size_t>(r)];
    const RoomType room =
        e.room >= 0 ? h.rooms[static_cast<std::size_t>(e.room)].type : RoomType::kLivingRoom;
    views.push_back({e.type, room});
    // Base: where a tidy house keeps this type (the receptacle's contents weight), a little everywhere.
    double x = 0.02;
    if (const ReceptacleSpec* spec = knowledge_.receptacle(e.type))
      for (const auto& [o, weight] : spec->contents)
        if (o == q.object) x += weight;
    base.push_back(x);
  }
  const HintReading reading = read_hint(q.hint, knowledge_);
  const std::vector<double> p = hint_distribution(reading, q.object, views, base);
  HintInterpretation out;
  if (reading.activity) out.activity = reading.activity->name;
  if (reading.room) out.room = std::string(room_type_name(*reading.room));
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] > 0.0) out.receptacles.emplace_back(h.receptacles[i], p[i]);
  return out;
}

}  // namespace socsim::household
