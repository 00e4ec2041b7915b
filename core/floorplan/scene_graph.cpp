#include "core/floorplan/scene_graph.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>

#include "core/floorplan/rooms.hpp"
#include "core/floorplan/schemas.hpp"
#include "core/knowledge/types.hpp"

namespace socsim::floorplan {
namespace {

struct ProgramRoom {
  std::string_view type;
  int count;
  std::string_view link;  // room type it opens onto; empty: the circulation room
  bool en_suite = false;  // each room after the first opens onto the one before (galleries)
};

struct Program {
  std::string_view domain;
  std::string_view circulation;
  std::string_view entrance;  // type of the room with the front door
  std::vector<ProgramRoom> rooms;
};

const std::vector<Program>& programs() {
  static const std::vector<Program> p = {
      {"residential",
       "hallway",
       "hallway",
       {{"living_room", 1, ""},
        {"kitchen", 1, "living_room"},
        {"bedroom", 2, ""},
        {"bathroom", 1, ""},
        {"storage", 1, ""}}},
      {"office",
       "corridor",
       "reception",
       {{"reception", 1, ""},
        {"open_office", 1, ""},
        {"meeting_room", 2, ""},
        {"kitchenette", 1, ""},
        {"toilet", 2, ""}}},
      {"hospital",
       "corridor",
       "lobby",
       {{"lobby", 1, ""},
        {"patient_room", 4, ""},
        {"nurse_station", 1, ""},
        {"treatment_room", 2, ""},
        {"toilet", 2, ""}}},
      {"canteen",
       "dining_hall",
       "dining_hall",
       {{"kitchen", 1, ""}, {"storage", 1, "kitchen"}, {"toilet", 2, ""}}},
      {"retail",
       "sales_floor",
       "sales_floor",
       {{"stock_room", 1, ""}, {"private_office", 1, ""}, {"toilet", 1, ""}}},
      {"warehouse",
       "warehouse_floor",
       "warehouse_floor",
       {{"loading_bay", 1, ""}, {"private_office", 1, ""}, {"break_room", 1, ""}, {"toilet", 1, ""}}},
      {"school",
       "corridor",
       "lobby",
       {{"lobby", 1, ""},
        {"classroom", 4, ""},
        {"staff_room", 1, ""},
        {"private_office", 1, ""},
        {"toilet", 2, ""}}},
      {"airport",
       "concourse",
       "security",
       {{"security", 1, ""}, {"gate_area", 2, ""}, {"cafe", 1, ""}, {"toilet", 2, ""}}},
      {"train_station",
       "concourse",
       "ticket_hall",
       {{"ticket_hall", 1, ""},
        {"platform", 2, ""},
        {"waiting_room", 1, ""},
        {"cafe", 1, ""},
        {"toilet", 2, ""},
        {"staff_room", 1, ""}}},
      {"hotel",
       "corridor",
       "lobby",
       {{"lobby", 1, ""},
        {"hotel_room", 8, ""},
        {"restaurant", 1, ""},
        {"kitchen", 1, "restaurant"},
        {"storage", 1, ""},
        {"staff_room", 1, ""},
        {"toilet", 2, ""}}},
      {"library",
       "reading_room",
       "lobby",
       {{"lobby", 1, ""},
        {"library_stacks", 2, ""},
        {"study_room", 3, ""},
        {"private_office", 1, ""},
        {"toilet", 2, ""}}},
      {"museum",
       "foyer",
       "foyer",
       {{"gallery", 5, "", true},
        {"cafe", 1, ""},
        {"shop_unit", 1, ""},
        {"storage", 1, ""},
        {"toilet", 2, ""}}},
      {"theatre",
       "foyer",
       "foyer",
       {{"auditorium", 2, ""}, {"backstage", 1, "auditorium"}, {"storage", 1, ""}, {"toilet", 2, ""}}},
      {"arena",
       "concourse",
       "concourse",
       {{"arena_floor", 1, ""},
        {"concession", 3, ""},
        {"locker_room", 2, ""},
        {"first_aid", 1, ""},
        {"storage", 1, ""},
        {"toilet", 4, ""}}},
      {"factory",
       "production_floor",
       "production_floor",
       {{"loading_bay", 1, ""},
        {"storage", 1, ""},
        {"private_office", 1, ""},
        {"break_room", 1, ""},
        {"locker_room", 1, ""},
        {"toilet", 2, ""}}},
      {"mall",
       "mall_concourse",
       "mall_concourse",
       {{"shop_unit", 8, ""}, {"food_court", 1, ""}, {"private_office", 1, ""}, {"toilet", 2, ""}}},
      {"supermarket",
       "sales_floor",
       "sales_floor",
       {{"stock_room", 1, ""},
        {"loading_bay", 1, "stock_room"},
        {"private_office", 1, ""},
        {"staff_room", 1, ""},
        {"toilet", 1, ""}}},
      {"restaurant",
       "restaurant",
       "restaurant",
       {{"kitchen", 1, ""}, {"storage", 1, "kitchen"}, {"toilet", 2, ""}}},
      {"university",
       "corridor",
       "lobby",
       {{"lobby", 1, ""},
        {"lecture_hall", 2, ""},
        {"seminar_room", 3, ""},
        {"private_office", 2, ""},
        {"cafe", 1, ""},
        {"toilet", 2, ""}}},
      {"gym",
       "corridor",
       "lobby",
       {{"lobby", 1, ""},
        {"sports_hall", 1, ""},
        {"fitness_room", 1, ""},
        {"changing_room", 2, ""},
        {"storage", 1, ""},
        {"toilet", 1, ""}}},
      {"care_home",
       "corridor",
       "lobby",
       {{"lobby", 1, ""},
        {"resident_room", 8, ""},
        {"day_room", 1, ""},
        {"nurse_station", 1, ""},
        {"kitchen", 1, ""},
        {"staff_room", 1, ""},
        {"toilet", 2, ""}}},
      {"community_hall",
       "main_hall",
       "main_hall",
       {{"kitchen", 1, ""}, {"meeting_room", 1, ""}, {"storage", 1, ""}, {"toilet", 2, ""}}},
  };
  return p;
}

const Program& program_for(std::string_view domain) {
  for (const auto& p : programs())
    if (p.domain == domain) return p;
  return programs().front();
}

// Room words of prompts: words (singular) → room type; count_only terms count only after a number.
struct Term {
  std::vector<std::string_view> words;
  std::string_view type;
  bool count_only = false;
};

const std::vector<Term>& terms() {
  static const std::vector<Term> t = {
      {{"patient", "room"}, "patient_room"},
      {{"patient", "bedroom"}, "patient_room"},
      {{"treatment", "room"}, "treatment_room"},
      {{"exam", "room"}, "treatment_room"},
      {{"examination", "room"}, "treatment_room"},
      {{"consultation", "room"}, "treatment_room"},
      {{"consulting", "room"}, "treatment_room"},
      {{"nurse", "station"}, "nurse_station"},
      {{"waiting", "room"}, "waiting_room"},
      {{"icu", "room"}, "icu_room"},
      {{"meeting", "room"}, "meeting_room"},
      {{"conference", "room"}, "meeting_room"},
      {{"private", "office"}, "private_office"},
      {{"open", "plan", "office"}, "open_office"},
      {{"open", "office"}, "open_office"},
      {{"living", "room"}, "living_room"},
      {{"dining", "room"}, "dining_room"},
      {{"storage", "room"}, "storage"},
      {{"store", "room"}, "storage"},
      {{"stock", "room"}, "stock_room"},
      {{"staff", "room"}, "staff_room"},
      {{"break", "room"}, "break_room"},
      {{"loading", "bay"}, "loading_bay"},
      {{"loading", "dock"}, "loading_bay"},
      {{"coffee", "shop"}, "cafe"},
      {{"security", "checkpoint"}, "security"},
      {{"bedroom"}, "bedroom"},
      {{"bathroom"}, "bathroom"},
      {{"toilet"}, "toilet"},
      {{"restroom"}, "toilet"},
      {{"washroom"}, "toilet"},
      {{"wc"}, "toilet"},
      {{"kitchenette"}, "kitchenette"},
      {{"kitchen"}, "kitchen"},
      {{"lounge"}, "living_room"},
      {{"study"}, "study"},
      {{"storeroom"}, "storage"},
      {{"stockroom"}, "stock_room"},
      {{"classroom"}, "classroom"},
      {{"cafe"}, "cafe"},
      {{"reception"}, "reception"},
      {{"lobby"}, "lobby"},
      {{"icu"}, "icu_room", true},
      {{"office"}, "private_office", true},
      {{"gate"}, "gate_area", true},
      {{"ward"}, "patient_room", true},
      {{"ticket", "hall"}, "ticket_hall"},
      {{"platform"}, "platform", true},
      {{"hotel", "room"}, "hotel_room"},
      {{"guest", "room"}, "hotel_room"},
      {{"room"}, "hotel_room", true},
      {{"restaurant"}, "restaurant"},
      {{"reading", "room"}, "reading_room"},
      {{"study", "room"}, "study_room"},
      {{"stack"}, "library_stacks"},
      {{"gallery"}, "gallery", true},
      {{"exhibition", "room"}, "gallery"},
      {{"foyer"}, "foyer"},
      {{"auditorium"}, "auditorium", true},
      {{"screen"}, "auditorium", true},
      {{"cinema", "hall"}, "auditorium"},
      {{"backstage"}, "backstage"},
      {{"concession", "stand"}, "concession"},
      {{"kiosk"}, "concession", true},
      {{"first", "aid", "room"}, "first_aid"},
      {{"lecture", "hall"}, "lecture_hall"},
      {{"lecture", "theatre"}, "lecture_hall"},
      {{"seminar", "room"}, "seminar_room"},
      {{"production", "floor"}, "production_floor"},
      {{"production", "hall"}, "production_floor"},
      {{"locker", "room"}, "locker_room"},
      {{"changing", "room"}, "changing_room"},
      {{"shop"}, "shop_unit", true},
      {{"store"}, "shop_unit", true},
      {{"food", "court"}, "food_court"},
      {{"sports", "hall"}, "sports_hall"},
      {{"fitness", "room"}, "fitness_room"},
      {{"resident", "room"}, "resident_room"},
      {{"day", "room"}, "day_room"},
      {{"main", "hall"}, "main_hall"},
  };
  return t;
}

// The same room word means different rooms in different buildings.
std::string_view localise(std::string_view domain, std::string_view type) {
  if (domain == "residential" && type == "toilet") return "bathroom";
  if (domain != "residential" && type == "bathroom") return "toilet";
  if (domain == "hospital" && type == "bedroom") return "patient_room";
  if ((domain == "hospital" || domain == "school" || domain == "airport") && type == "reception")
    return "lobby";
  if (domain == "office" && type == "lobby") return "reception";
  if ((domain == "retail" || domain == "supermarket") && type == "storage") return "stock_room";
  if ((domain == "care_home") && (type == "bedroom" || type == "patient_room" || type == "hotel_room"))
    return "resident_room";
  if (domain == "hotel" && type == "bedroom") return "hotel_room";
  // "twenty rooms": guest rooms in a hotel, residents' rooms in a care home, bedrooms at home.
  if (domain != "hotel" && type == "hotel_room")
    return domain == "care_home" ? "resident_room" : domain == "residential" ? "bedroom" : "";
  if ((domain == "hotel" || domain == "gym" || domain == "university" || domain == "care_home" ||
       domain == "library") &&
      type == "reception")
    return "lobby";
  if ((domain == "theatre" || domain == "museum") && (type == "lobby" || type == "reception")) return "foyer";
  if (domain != "mall" && domain != "museum" && type == "shop_unit") return "sales_floor";
  return type;
}

std::optional<int> number_word(std::string_view w) {
  static constexpr std::array<std::string_view, 21> kWords = {
      "zero",     "one",     "two",     "three",     "four",     "five",     "six",
      "seven",    "eight",   "nine",    "ten",       "eleven",   "twelve",   "thirteen",
      "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen", "twenty"};
  for (std::size_t i = 0; i < kWords.size(); ++i)
    if (w == kWords[i]) return static_cast<int>(i);
  if (w == "single") return 1;
  if (w == "couple" || w == "pair") return 2;
  if (!w.empty() && w.size() <= 4 &&
      std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::stoi(std::string(w));
  return std::nullopt;
}

std::string singular(std::string w) {
  if (w.size() > 4 && w.ends_with("ies")) return w.substr(0, w.size() - 3) + "y";
  if (w.size() > 3 && w.ends_with("s") && !w.ends_with("ss")) return w.substr(0, w.size() - 1);
  return w;
}

std::vector<std::string> words_of(std::string_view text) {
  std::vector<std::string> out;
  std::string cur;
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isalnum(c)) {
      cur.push_back(static_cast<char>(std::tolower(c)));
    } else if (!cur.empty()) {
      out.push_back(singular(cur));
      cur.clear();
    }
  }
  if (!cur.empty()) out.push_back(singular(cur));
  return out;
}

bool is_stop(std::string_view w) {
  return w == "and" || w == "with" || w == "or" || w == "plus" || w == "a" || w == "an" || w == "the" ||
         w == "for" || w == "in" || w == "has" || w == "have";
}
bool is_negation(std::string_view w) {
  return w == "no" || w == "not" || w == "without" || w == "non";
}

std::string room_name(std::string_view type, int index, int count) {
  if (count <= 1) return std::string(type);
  char buf[16];
  std::snprintf(buf, sizeof buf, "_%02d", index + 1);
  return std::string(type) + buf;
}

std::string default_entrance(const SceneGraph& g) {
  for (const auto& r : g.rooms)
    if (r.type == "lobby" || r.type == "reception" || r.type == "security") return r.name;
  for (const auto& r : g.rooms)
    if (is_circulation_type(r.type)) return r.name;
  return g.rooms.empty() ? "" : g.rooms.front().name;
}

}  // namespace

SceneGraph room_program(std::string_view domain, const std::map<std::string, int>& counts) {
  const Program& p = program_for(domain);
  SceneGraph g;
  g.domain = std::string(p.domain);
  const std::string circulation(p.circulation);
  g.rooms.push_back({circulation, circulation, std::nullopt});
  std::vector<ProgramRoom> rooms = p.rooms;
  for (const auto& [type, n] : counts) {
    if (is_circulation_type(type)) continue;
    const std::string& wanted = type;  // clang 14 cannot capture structured bindings
    const bool known =
        std::any_of(rooms.begin(), rooms.end(), [&](const ProgramRoom& r) { return r.type == wanted; });
    if (!known) {
      const RoomType* rt = find_room_type(type);
      if (rt) rooms.push_back({rt->type, n, ""});
    }
  }
  std::map<std::string, std::string> first_of_type;
  for (const auto& r : rooms) {
    const auto it = counts.find(std::string(r.type));
    const int n = it != counts.end() ? it->second : r.count;
    std::string previous;
    for (int i = 0; i < n; ++i) {
      const std::string name = room_name(r.type, i, n);
      g.rooms.push_back({name, std::string(r.type), std::nullopt});
      first_of_type.emplace(std::string(r.type), name);
      const auto link = first_of_type.find(std::string(r.link));
      if (r.en_suite && !previous.empty())
        g.adjacency.emplace_back(previous, name);
      else
        g.adjacency.emplace_back(r.link.empty() || link == first_of_type.end() ? circulation : link->second,
                                 name);
      previous = name;
    }
    // Three or more rooms en suite make a circuit: the last opens back onto where the first does.
    if (r.en_suite && n >= 3) {
      const auto link = first_of_type.find(std::string(r.link));
      g.adjacency.emplace_back(r.link.empty() || link == first_of_type.end() ? circulation : link->second,
                               previous);
    }
  }
  const auto entrance = first_of_type.find(std::string(p.entrance));
  g.entrance = entrance != first_of_type.end() ? entrance->second : circulation;
  // A small home (up to two bedrooms, eight rooms) has no hallway: its rooms open onto the living
  // room, as in ProcTHOR's houses (the offline generator's home_open_plan family).
  const auto living = first_of_type.find("living_room");
  const int bedrooms = static_cast<int>(
      std::count_if(g.rooms.begin(), g.rooms.end(), [](const SceneRoom& r) { return r.type == "bedroom"; }));
  if (g.domain == "residential" && living != first_of_type.end() && bedrooms <= 2 && g.rooms.size() <= 9) {
    const std::string hub = living->second;
    g.rooms.erase(g.rooms.begin());  // the hallway
    std::vector<std::pair<std::string, std::string>> edges;
    for (auto [a, b] : g.adjacency) {
      if (a == circulation) a = hub;
      if (b == circulation) b = hub;
      if (a != b) edges.emplace_back(a, b);
    }
    g.adjacency = std::move(edges);
    g.entrance = hub;
  }
  return g;
}

Result<PromptSceneGraph> scene_graph_from_prompt(std::string_view prompt, std::optional<std::string> domain) {
  if (prompt.find_first_not_of(" \t\r\n") == std::string_view::npos)
    return fail(ErrorCode::kValidation, "describe the building", {{"/prompt", "must not be empty"}});
  if (prompt.size() > 4000)
    return fail(ErrorCode::kValidation, "prompt too long", {{"/prompt", "at most 4000 bytes"}});
  PromptSceneGraph out;
  out.classification = knowledge::classify_building_type(prompt);
  if (domain && !knowledge::is_building_type(*domain)) {
    std::string all;
    for (auto t : knowledge::building_types()) all += (all.empty() ? "" : ", ") + std::string(t);
    return fail(ErrorCode::kValidation, "unknown domain '" + *domain + "'", {{"/domain", "one of " + all}});
  }
  const std::string d = domain ? *domain : out.classification.type;

  const auto words = words_of(prompt);
  std::map<std::string, int> counts;
  std::set<std::string> counted;  // types given a number: the first number wins
  for (std::size_t i = 0; i < words.size();) {
    const Term* match = nullptr;
    for (const auto& t : terms()) {
      if (i + t.words.size() > words.size()) continue;
      bool ok = true;
      for (std::size_t k = 0; k < t.words.size() && ok; ++k) ok = words[i + k] == t.words[k];
      if (ok && (!match || t.words.size() > match->words.size())) match = &t;
    }
    if (!match) {
      ++i;
      continue;
    }
    std::optional<int> n;
    bool negated = false;
    for (std::size_t back = 1; back <= 3 && back <= i; ++back) {
      const std::string& w = words[i - back];
      if (is_negation(w)) negated = true;
      if (n || negated) break;
      if (auto v = number_word(w)) {
        n = v;
        continue;
      }
      if (is_stop(w)) {
        if (back + 1 <= i && is_negation(words[i - back - 1])) negated = true;
        break;
      }
    }
    const std::string type(localise(d, match->type));
    i += match->words.size();
    if (type.empty()) continue;  // a word that names no room in this kind of building
    if (negated || (match->count_only && !n)) continue;
    if (n) {
      if (*n > kMaxRoomsPerType)
        return fail(ErrorCode::kValidation, "too many rooms of one type",
                    {{"/prompt", "asks for " + std::to_string(*n) + " rooms of type " + type + "; at most " +
                                     std::to_string(kMaxRoomsPerType)}});
      if (counted.insert(type).second) counts[type] = *n;
    } else if (!counts.count(type)) {
      counts[type] = -1;  // mentioned without a number: present at least once
    }
  }
  // Mentioned without a number: the program's own count, or one room when the program has none.
  const SceneGraph base = room_program(d, {});
  for (auto it = counts.begin(); it != counts.end();) {
    if (it->second >= 0) {
      ++it;
      continue;
    }
    const auto n = std::count_if(base.rooms.begin(), base.rooms.end(),
                                 [&](const SceneRoom& r) { return r.type == it->first; });
    if (n > 0) {
      it = counts.erase(it);
    } else {
      it->second = 1;
      ++it;
    }
  }
  out.counts = counts;
  out.graph = room_program(d, counts);
  if (out.graph.rooms.size() > kMaxSceneRooms)
    return fail(ErrorCode::kValidation, "too many rooms",
                {{"/prompt", "describes " + std::to_string(out.graph.rooms.size()) + " rooms; at most " +
                                 std::to_string(kMaxSceneRooms)}});
  return out;
}

Result<SceneGraph> scene_graph_from_json(const Json& j, const std::string& pointer) {
  std::vector<FieldError> errors = scene_graph_schema().validate(j, 50);
  for (auto& e : errors) e.pointer = pointer + e.pointer;
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "the scene graph does not match its schema", std::move(errors));

  SceneGraph g;
  std::map<std::string, std::size_t> index;
  const Json& rooms = j.at("rooms");
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    SceneRoom r;
    r.name = rooms[i].at("name").get<std::string>();
    r.type = canonical_room_type(rooms[i].at("type").get<std::string>());
    if (rooms[i].contains("area")) r.area = rooms[i].at("area").get<double>();
    const std::string ptr = pointer + "/rooms/" + std::to_string(i);
    if (auto [it, fresh] = index.emplace(r.name, i); !fresh)
      errors.push_back({ptr + "/name", "duplicate room name '" + r.name + "' (already " + pointer +
                                           "/rooms/" + std::to_string(it->second) + ")"});
    g.rooms.push_back(std::move(r));
  }
  std::vector<std::vector<std::size_t>> neighbours(g.rooms.size());
  std::set<std::pair<std::string, std::string>> seen;
  if (j.contains("adjacency")) {
    const Json& edges = j.at("adjacency");
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const std::string ptr = pointer + "/adjacency/" + std::to_string(i);
      const std::string a = edges[i][0].get<std::string>();
      const std::string b = edges[i][1].get<std::string>();
      bool ok = true;
      for (int k = 0; k < 2; ++k) {
        const std::string& n = k == 0 ? a : b;
        if (!index.count(n)) {
          errors.push_back({ptr + "/" + std::to_string(k), "no room is named '" + n + "'"});
          ok = false;
        }
      }
      if (!ok) continue;
      if (a == b) {
        errors.push_back({ptr, "an edge must join two different rooms (both are '" + a + "')"});
        continue;
      }
      if (!seen.insert(std::minmax(a, b)).second) {
        errors.push_back({ptr, "duplicate edge between '" + a + "' and '" + b + "'"});
        continue;
      }
      g.adjacency.emplace_back(a, b);
      neighbours[index[a]].push_back(index[b]);
      neighbours[index[b]].push_back(index[a]);
    }
  }
  if (j.contains("entrance")) {
    g.entrance = j.at("entrance").get<std::string>();
    if (!index.count(g.entrance))
      errors.push_back({pointer + "/entrance", "no room is named '" + g.entrance + "'"});
  }
  if (errors.empty() && g.rooms.size() > 1) {
    std::vector<bool> reached(g.rooms.size(), false);
    std::vector<std::size_t> stack{0};
    reached[0] = true;
    while (!stack.empty()) {
      const std::size_t r = stack.back();
      stack.pop_back();
      for (auto n : neighbours[r])
        if (!reached[n]) {
          reached[n] = true;
          stack.push_back(n);
        }
    }
    for (std::size_t i = 0; i < g.rooms.size(); ++i)
      if (!reached[i])
        errors.push_back({pointer + "/rooms/" + std::to_string(i),
                          "room '" + g.rooms[i].name + "' is not connected to '" + g.rooms[0].name +
                              "' by any chain of adjacency edges, so it could not be reached"});
  }
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "the scene graph is inconsistent", std::move(errors));

  if (j.contains("domain")) {
    g.domain = j.at("domain").get<std::string>();
  } else {
    std::vector<std::string> names;
    for (const auto& r : g.rooms) names.push_back(r.name + " " + r.type);
    g.domain = knowledge::classify_building_type(names).type;
  }
  if (g.entrance.empty()) g.entrance = default_entrance(g);
  return g;
}

Json to_json(const SceneGraph& g) {
  Json rooms = Json::array();
  for (const auto& r : g.rooms) {
    Json room = {{"name", r.name}, {"type", r.type}};
    if (r.area) room["area"] = *r.area;
    rooms.push_back(std::move(room));
  }
  Json edges = Json::array();
  for (const auto& [a, b] : g.adjacency) edges.push_back(Json::array({a, b}));
  return Json{{"domain", g.domain},
              {"rooms", std::move(rooms)},
              {"adjacency", std::move(edges)},
              {"entrance", g.entrance}};
}

}  // namespace socsim::floorplan
