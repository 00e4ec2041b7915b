#include "core/world/requirements.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>

#include "core/common/json_check.hpp"

namespace socsim::world {
namespace {

using F = Feature;

constexpr std::array<FeatureInfo, 21> kFeatures = {{
    {F::kExit, "exit", "exits", 12},
    {F::kEntrance, "entrance", "entrances", 12},
    {F::kDoor, "door", "doors", 200},
    {F::kCounter, "counter", "counters", 30},
    {F::kCheckout, "checkout", "checkouts", 30},
    {F::kGate, "gate", "gates", 40},
    {F::kElevator, "elevator", "elevators", 12},
    {F::kStair, "stair", "stairs", 12},
    {F::kEscalator, "escalator", "escalators", 12},
    {F::kTable, "table", "tables", 200},
    {F::kSeat, "seat", "seats", 2000},
    {F::kDesk, "desk", "desks", 300},
    {F::kBed, "bed", "beds", 200},
    {F::kShelf, "shelf", "shelves", 300},
    {F::kRack, "rack", "racks", 300},
    {F::kScreen, "screen", "screens", 30},
    {F::kStage, "stage", "stages", 4},
    {F::kBar, "bar", "bars", 10},
    {F::kLocker, "locker", "lockers", 300},
    {F::kPlatform, "platform", "platforms", 12},
    {F::kToilet, "toilet", "toilets", 30},
}};

// Words (singular, lower case, single spaces) that name a feature besides its key.
constexpr std::array<std::pair<std::string_view, Feature>, 52> kSynonyms = {{
    {"emergency exit", F::kExit},
    {"fire exit", F::kExit},
    {"way out", F::kExit},
    {"exit door", F::kExit},
    {"egress", F::kExit},
    {"entry", F::kEntrance},
    {"main entrance", F::kEntrance},
    {"doorway", F::kDoor},
    {"reception desk", F::kCounter},
    {"reception counter", F::kCounter},
    {"information desk", F::kCounter},
    {"info desk", F::kCounter},
    {"help desk", F::kCounter},
    {"service counter", F::kCounter},
    {"serving counter", F::kCounter},
    {"food counter", F::kCounter},
    {"ticket counter", F::kCounter},
    {"check-in counter", F::kCounter},
    {"check-out", F::kCheckout},
    {"checkout counter", F::kCheckout},
    {"self checkout", F::kCheckout},
    {"till", F::kCheckout},
    {"cash register", F::kCheckout},
    {"register", F::kCheckout},
    {"turnstile", F::kGate},
    {"ticket gate", F::kGate},
    {"ticket barrier", F::kGate},
    {"fare gate", F::kGate},
    {"barrier", F::kGate},
    {"boarding gate", F::kGate},
    {"departure gate", F::kGate},
    {"lift", F::kElevator},
    {"staircase", F::kStair},
    {"stairway", F::kStair},
    {"stairwell", F::kStair},
    {"moving staircase", F::kEscalator},
    {"dining table", F::kTable},
    {"chair", F::kSeat},
    {"bench", F::kSeat},
    {"armchair", F::kSeat},
    {"stool", F::kSeat},
    {"sofa", F::kSeat},
    {"couch", F::kSeat},
    {"bookshelf", F::kShelf},
    {"bookcase", F::kShelf},
    {"bar counter", F::kBar},
    {"projection screen", F::kScreen},
    {"track", F::kPlatform},
    {"restroom", F::kToilet},
    {"lavatory", F::kToilet},
    {"wc", F::kToilet},
    {"washroom", F::kToilet},
}};

// Lower case, '-'/'_' as spaces, single spaces, the last word singular.
std::string normal_words(std::string_view words) {
  std::string out;
  for (const char c : words) {
    const auto u = static_cast<unsigned char>(c);
    const char l = (c == '_' || std::isspace(u)) ? ' ' : static_cast<char>(std::tolower(u));
    if (l == ' ' && (out.empty() || out.back() == ' ')) continue;
    out.push_back(l);
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::string singular_last(std::string s) {
  const std::size_t sp = s.rfind(' ');
  std::string last = sp == std::string::npos ? s : s.substr(sp + 1);
  const std::string head = sp == std::string::npos ? "" : s.substr(0, sp + 1);
  if (last == "shelves") return head + "shelf";
  if (last == "stairs" || last == "bus" || last == "wc" || last == "egress") return head + last;
  if (last.size() > 4 && last.ends_with("ches")) return head + last.substr(0, last.size() - 2);  // benches
  if (last.size() > 3 && last.ends_with("ies")) return head + last.substr(0, last.size() - 3) + "y";
  if (last.size() > 3 && last.ends_with("s") && !last.ends_with("ss")) last.pop_back();
  return head + last;
}

bool one_of(std::string_view s, std::initializer_list<std::string_view> options) {
  return std::find(options.begin(), options.end(), s) != options.end();
}

bool label_ok(const std::string& s) {
  return std::none_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; });
}

bool type_ok(const std::string& s) {
  return !s.empty() && s.size() <= 64 && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

}  // namespace

std::span<const FeatureInfo> features() {
  return kFeatures;
}

const FeatureInfo& info(Feature feature) {
  for (const auto& f : kFeatures)
    if (f.feature == feature) return f;
  return kFeatures[0];
}

std::string_view to_string(Feature feature) {
  return info(feature).key;
}

std::optional<Feature> feature_from_word(std::string_view words) {
  const std::string w = singular_last(normal_words(words));
  if (w.empty()) return std::nullopt;
  for (const auto& [phrase, f] : kSynonyms)
    if (w == phrase) return f;
  for (const auto& f : kFeatures)
    if (w == f.key || w == f.plural) return f.feature;
  if (w == "stair" || w == "step") return F::kStair;
  // "fire escape stairs", "north exit": the last word decides when it names a feature.
  const std::size_t sp = w.rfind(' ');
  if (sp != std::string::npos) return feature_from_word(std::string_view(w).substr(sp + 1));
  return std::nullopt;
}

std::string snake_case(std::string_view words) {
  // Accented Latin letters as their base letter ("café" → cafe); other non-ASCII is a separator.
  static constexpr std::pair<std::string_view, char> kAccents[] = {
      {"à", 'a'}, {"á", 'a'}, {"â", 'a'}, {"ä", 'a'}, {"ç", 'c'}, {"è", 'e'}, {"é", 'e'},
      {"ê", 'e'}, {"ë", 'e'}, {"í", 'i'}, {"î", 'i'}, {"ï", 'i'}, {"ñ", 'n'}, {"ó", 'o'},
      {"ô", 'o'}, {"ö", 'o'}, {"ú", 'u'}, {"û", 'u'}, {"ü", 'u'}, {"É", 'e'}};
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const char c = words[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) {
      bool mapped = false;
      for (const auto& [from, to] : kAccents) {
        if (words.substr(i, from.size()) == from) {
          out.push_back(to);
          i += from.size() - 1;
          mapped = true;
          break;
        }
      }
      if (!mapped && !out.empty() && out.back() != '_') out.push_back('_');
      continue;
    }
    if (std::isalnum(u)) {
      out.push_back(static_cast<char>(std::tolower(u)));
    } else if (!out.empty() && out.back() != '_') {
      out.push_back('_');
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

const FeatureCount* WorldRequirements::find(Feature feature) const {
  for (const auto& f : features)
    if (f.feature == feature) return &f;
  return nullptr;
}

Result<WorldRequirements> world_requirements_from_json(const Json& j, const std::string& pointer) {
  JsonChecker ck;
  WorldRequirements r;
  if (!j.is_object()) {
    ck.add(pointer, std::string("must be an object, not ") + j.type_name());
    return tl::unexpected(ck.error("the world requirements are not valid"));
  }
  ck.only_keys(j, pointer, {"features", "rooms", "objects", "occupants"});
  auto label = [&](const Json& obj, const std::string& ptr, const char* key, bool required) {
    auto s = ck.string(obj, ptr, key, required, required ? 1 : 0, 128);
    if (s && !label_ok(*s)) {
      ck.add(JsonChecker::child(ptr, key), "must not contain control characters");
      return std::optional<std::string>();
    }
    return s;
  };
  auto type_of = [&](const Json& obj, const std::string& ptr, const std::string& name) {
    auto t = label(obj, ptr, "type", false);
    if (!t || t->empty()) return snake_case(name);
    if (!type_ok(*t)) {
      ck.add(JsonChecker::child(ptr, "type"), "'" + *t + "' must be lower-case letters, digits and '_'");
      return std::string();
    }
    return *t;
  };

  if (const Json* list = ck.array(j, pointer, "features", false, kFeatures.size())) {
    const std::string base = JsonChecker::child(pointer, "features");
    std::map<Feature, std::string> seen;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Json& item = (*list)[i];
      const std::string ptr = JsonChecker::child(base, i);
      if (!item.is_object()) {
        ck.add(ptr, std::string("must be an object, not ") + item.type_name());
        continue;
      }
      ck.only_keys(item, ptr, {"feature", "count", "at_least", "words"});
      FeatureCount fc;
      auto name = ck.string(item, ptr, "feature", true, 1, 64);
      std::optional<Feature> f;
      if (name) {
        f = feature_from_word(*name);
        if (!f) {
          std::string known;
          for (const auto& k : kFeatures) known += (known.empty() ? "" : ", ") + std::string(k.key);
          ck.add(JsonChecker::child(ptr, "feature"),
                 "unknown feature '" + *name + "' (known: " + known + ")");
        } else if (auto [it, fresh] = seen.emplace(*f, ptr); !fresh) {
          ck.add(JsonChecker::child(ptr, "feature"),
                 "feature '" + std::string(to_string(*f)) + "' is already asked for at " + it->second);
        }
      }
      const int max = f ? info(*f).max_count : 2000;
      auto count = ck.integer(item, ptr, "count", true, 0, max);
      auto at_least = ck.boolean(item, ptr, "at_least", false);
      auto words = label(item, ptr, "words", false);
      if (!f || !count) continue;
      fc.feature = *f;
      fc.count = static_cast<int>(*count);
      fc.at_least = at_least.value_or(false);
      fc.words = words.value_or("");
      r.features.push_back(std::move(fc));
    }
  }
  if (const Json* list = ck.array(j, pointer, "rooms", false, kMaxNamedRooms)) {
    const std::string base = JsonChecker::child(pointer, "rooms");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Json& item = (*list)[i];
      const std::string ptr = JsonChecker::child(base, i);
      if (!item.is_object()) {
        ck.add(ptr, std::string("must be an object, not ") + item.type_name());
        continue;
      }
      ck.only_keys(item, ptr, {"name", "type", "count"});
      auto name = label(item, ptr, "name", true);
      auto count = ck.integer(item, ptr, "count", false, 1, kMaxNamedCount);
      if (!name) continue;
      if (snake_case(*name).empty()) {
        ck.add(JsonChecker::child(ptr, "name"), "must contain a letter or digit");
        continue;
      }
      std::string type = type_of(item, ptr, *name);
      r.rooms.push_back({*name, std::move(type), static_cast<int>(count.value_or(1))});
    }
  }
  if (const Json* list = ck.array(j, pointer, "objects", false, kMaxNamedObjects)) {
    const std::string base = JsonChecker::child(pointer, "objects");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Json& item = (*list)[i];
      const std::string ptr = JsonChecker::child(base, i);
      if (!item.is_object()) {
        ck.add(ptr, std::string("must be an object, not ") + item.type_name());
        continue;
      }
      ck.only_keys(item, ptr, {"name", "type", "count", "room"});
      auto name = label(item, ptr, "name", true);
      auto count = ck.integer(item, ptr, "count", false, 1, kMaxNamedCount);
      auto room = label(item, ptr, "room", false);
      if (!name) continue;
      if (snake_case(*name).empty()) {
        ck.add(JsonChecker::child(ptr, "name"), "must contain a letter or digit");
        continue;
      }
      std::string type = type_of(item, ptr, *name);
      r.objects.push_back({*name, std::move(type), static_cast<int>(count.value_or(1)), room.value_or("")});
    }
  }
  if (auto n = ck.integer(j, pointer, "occupants", false, 0, kMaxOccupants))
    r.occupants = static_cast<int>(*n);
  if (!ck.ok()) return tl::unexpected(ck.error("the world requirements are not valid"));
  return r;
}

Json to_json(const WorldRequirements& r) {
  Json out = Json::object();
  Json features = Json::array();
  for (const auto& f : r.features) {
    Json j{{"feature", std::string(to_string(f.feature))}, {"count", f.count}};
    if (f.at_least) j["at_least"] = true;
    if (!f.words.empty()) j["words"] = f.words;
    features.push_back(std::move(j));
  }
  out["features"] = std::move(features);
  Json rooms = Json::array();
  for (const auto& n : r.rooms) rooms.push_back(Json{{"name", n.name}, {"type", n.type}, {"count", n.count}});
  out["rooms"] = std::move(rooms);
  Json objects = Json::array();
  for (const auto& o : r.objects) {
    Json j{{"name", o.name}, {"type", o.type}, {"count", o.count}};
    if (!o.room.empty()) j["room"] = o.room;
    objects.push_back(std::move(j));
  }
  out["objects"] = std::move(objects);
  if (r.occupants) out["occupants"] = *r.occupants;
  return out;
}

bool entity_is(Feature feature, std::string_view t, std::span<const std::string> affordances) {
  auto has_aff = [&](std::string_view a) {
    return std::find(affordances.begin(), affordances.end(), a) != affordances.end();
  };
  const bool pays = has_aff("pay");
  const bool boards = has_aff("board");
  switch (feature) {
    case F::kCounter:
      return t == "counter" && !pays && !boards;
    case F::kCheckout:
      return (t == "counter" && pays) || t == "checkout";
    case F::kGate:
      return t == "ticket_gate" || boards;
    case F::kElevator:
      return t == "elevator";
    case F::kStair:
      return t == "stairs";
    case F::kEscalator:
      return t == "escalator";
    case F::kTable:
      return one_of(t, {"table", "dining_table", "meeting_table", "reading_table"});
    case F::kSeat:
      return one_of(t, {"chair", "seat", "bench", "sofa", "armchair", "stool"});
    case F::kDesk:
      return one_of(t, {"desk", "teacher_desk"});
    case F::kBed:
      return t == "bed" || t == "hospital_bed";
    case F::kShelf:
      return t == "shelf" || t == "bookshelf";
    case F::kRack:
      return t == "rack";
    case F::kScreen:
      return t == "screen" || t == "cinema_screen";
    case F::kStage:
      return t == "stage";
    case F::kBar:
      return t == "bar_counter";
    case F::kLocker:
      return t == "locker";
    default:
      return false;
  }
}

int count_feature(const World& world, Feature feature) {
  int n = 0;
  switch (feature) {
    case F::kExit:
    case F::kEntrance:
      for (const auto& d : world.doors()) n += !d.other;
      return n;
    case F::kDoor:
      return static_cast<int>(world.doors().size());
    case F::kPlatform:
    case F::kToilet:
      for (const auto& z : world.zones()) n += z.type == (feature == F::kPlatform ? "platform" : "toilet");
      return n;
    default:
      break;
  }
  for (const auto& e : world.entities()) n += entity_is(feature, e.type, e.affordances);
  return n;
}

}  // namespace socsim::world
