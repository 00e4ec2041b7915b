#include "core/household/knowledge.hpp"

#include <algorithm>

#include "core/common/json_check.hpp"

namespace socsim::household {
namespace {

constexpr std::array<std::pair<ActivityRole, std::string_view>, 34> kRoleNames = {{
    {ActivityRole::kSleep, "sleep"},
    {ActivityRole::kNap, "nap"},
    {ActivityRole::kWake, "wake"},
    {ActivityRole::kMorningHygiene, "morning_hygiene"},
    {ActivityRole::kEveningHygiene, "evening_hygiene"},
    {ActivityRole::kDress, "dress"},
    {ActivityRole::kToilet, "toilet"},
    {ActivityRole::kBreakfastPrep, "breakfast_prep"},
    {ActivityRole::kBreakfast, "breakfast"},
    {ActivityRole::kLunchPrep, "lunch_prep"},
    {ActivityRole::kLunch, "lunch"},
    {ActivityRole::kDinnerPrep, "dinner_prep"},
    {ActivityRole::kDinner, "dinner"},
    {ActivityRole::kMealSetup, "meal_setup"},
    {ActivityRole::kSnack, "snack"},
    {ActivityRole::kHotDrink, "hot_drink"},
    {ActivityRole::kDishCleanup, "dish_cleanup"},
    {ActivityRole::kChore, "chore"},
    {ActivityRole::kLaundry, "laundry"},
    {ActivityRole::kArrive, "arrive"},
    {ActivityRole::kDepart, "depart"},
    {ActivityRole::kBedtime, "bedtime"},
    {ActivityRole::kLeisure, "leisure"},
    {ActivityRole::kHobby, "hobby"},
    {ActivityRole::kExercise, "exercise"},
    {ActivityRole::kWork, "work"},
    {ActivityRole::kStudy, "study"},
    {ActivityRole::kChildcare, "childcare"},
    {ActivityRole::kPet, "pet"},
    {ActivityRole::kMedication, "medication"},
    {ActivityRole::kSocialCall, "social_call"},
    {ActivityRole::kSocial, "social"},
    {ActivityRole::kPrayer, "prayer"},
    {ActivityRole::kLeaveHome, "leave_home"},
}};

Result<std::vector<std::pair<std::string, double>>> weight_map(const Json& obj, const std::string& ptr,
                                                               JsonChecker& check) {
  std::vector<std::pair<std::string, double>> out;
  if (!obj.is_object()) {
    check.add(ptr, "must be an object of weights");
    return out;
  }
  for (const auto& [k, v] : obj.items()) {
    if (!v.is_number() || v.get<double>() < 0.0)
      check.add(JsonChecker::child(ptr, k), "must be a non-negative number");
    else if (v.get<double>() > 0.0)
      out.emplace_back(k, v.get<double>());
  }
  return out;
}

template <class F>
Status for_rows(store::Database& db, const char* sql, F&& fn) {
  auto st = db.prepare(sql);
  if (!st) return tl::unexpected(st.error());
  for (;;) {
    auto more = st->step();
    if (!more) return tl::unexpected(more.error());
    if (!*more) return {};
    if (auto s = fn(*st); !s) return s;
  }
}

Result<Json> parse_body(const std::string& text, const std::string& what) {
  auto j = parse_json_untrusted(text);
  if (!j) return fail(ErrorCode::kStore, "seed row " + what + " holds invalid JSON: " + j.error().detail);
  return *j;
}

}  // namespace

std::optional<ActivityRole> parse_activity_role(std::string_view name) {
  for (const auto& [role, n] : kRoleNames)
    if (n == name) return role;
  return std::nullopt;
}

std::string_view activity_role_name(ActivityRole role) {
  for (const auto& [r, n] : kRoleNames)
    if (r == role) return n;
  return "leisure";
}

bool is_meal(ActivityRole role) {
  return role == ActivityRole::kBreakfast || role == ActivityRole::kLunch || role == ActivityRole::kDinner;
}

bool ActivitySpec::in_window(int minute_of_day) const {
  for (const auto& [a, b] : windows) {
    const double lo = a * 60.0, hi = b * 60.0;
    for (int shift : {0, 1440})
      if (minute_of_day + shift >= lo && minute_of_day + shift <= hi) return true;
  }
  return false;
}

bool ReceptacleSpec::allowed_in(RoomType room) const {
  return std::find(rooms.begin(), rooms.end(), room) != rooms.end();
}

const ActivitySpec* HouseholdKnowledge::activity(std::string_view primary_name) const {
  const int i = activity_index(primary_name);
  return i < 0 ? nullptr : &activities[static_cast<std::size_t>(i)];
}

int HouseholdKnowledge::activity_index(std::string_view primary_name) const {
  auto it = activity_by_name_.find(std::string(primary_name));
  return it == activity_by_name_.end() ? -1 : it->second;
}

const ReceptacleSpec* HouseholdKnowledge::receptacle(std::string_view type) const {
  auto it = receptacle_by_type_.find(std::string(type));
  return it == receptacle_by_type_.end() ? nullptr : &receptacles[static_cast<std::size_t>(it->second)];
}

bool HouseholdKnowledge::is_movable(std::string_view type) const {
  return std::binary_search(movable_types.begin(), movable_types.end(), type);
}
bool HouseholdKnowledge::is_fixture(std::string_view type) const {
  return std::binary_search(fixture_types.begin(), fixture_types.end(), type);
}

const Persona* HouseholdKnowledge::persona(std::string_view id) const {
  auto it = persona_by_id_.find(std::string(id));
  return it == persona_by_id_.end() ? nullptr : &personas[static_cast<std::size_t>(it->second)];
}

void HouseholdKnowledge::index() {
  activity_by_name_.clear();
  receptacle_by_type_.clear();
  persona_by_id_.clear();
  for (std::size_t i = 0; i < activities.size(); ++i)
    activity_by_name_[activities[i].name] = static_cast<int>(i);
  for (std::size_t i = 0; i < receptacles.size(); ++i)
    receptacle_by_type_[receptacles[i].type] = static_cast<int>(i);
  for (std::size_t i = 0; i < personas.size(); ++i)
    persona_by_id_.emplace(persona_id(personas[i]), static_cast<int>(i));
  std::sort(movable_types.begin(), movable_types.end());
  std::sort(fixture_types.begin(), fixture_types.end());
}

Result<ActivitySpec> activity_from_json(const std::string& name, const std::string& role, const Json& body) {
  JsonChecker check;
  ActivitySpec a;
  a.name = name;
  if (auto r = parse_activity_role(role))
    a.role = *r;
  else
    check.add("/role", "unknown activity role '" + role + "'");
  if (const Json* syn = check.array(body, "", "synonyms", true))
    for (std::size_t i = 0; i < syn->size(); ++i) {
      if ((*syn)[i].is_string())
        a.synonyms.push_back((*syn)[i].get<std::string>());
      else
        check.add("/synonyms/" + std::to_string(i), "must be a string");
    }
  if (const Json* d = check.array(body, "", "duration", true)) {
    if (d->size() != 2 || !(*d)[0].is_number_integer() || !(*d)[1].is_number_integer() ||
        (*d)[0].get<int>() < 1 || (*d)[1].get<int>() < (*d)[0].get<int>())
      check.add("/duration", "must be [min, max] minutes with 1 ≤ min ≤ max");
    else {
      a.min_minutes = (*d)[0].get<int>();
      a.max_minutes = (*d)[1].get<int>();
    }
  }
  if (const Json* w = check.array(body, "", "windows", true))
    for (std::size_t i = 0; i < w->size(); ++i) {
      const Json& win = (*w)[i];
      if (!win.is_array() || win.size() != 2 || !win[0].is_number() || !win[1].is_number() ||
          win[1].get<double>() <= win[0].get<double>() || win[0].get<double>() < 0 ||
          win[1].get<double>() > 48)
        check.add("/windows/" + std::to_string(i), "must be [start hour, end hour] with start < end ≤ 48");
      else
        a.windows.emplace_back(win[0].get<double>(), win[1].get<double>());
    }
  if (const Json* k = check.array(body, "", "keywords", false))
    for (const auto& s : *k)
      if (s.is_string()) a.keywords.push_back(s.get<std::string>());
  if (auto v = check.integer(body, "", "min_age", false, 0, 120)) a.min_age = static_cast<int>(*v);
  if (auto v = check.integer(body, "", "max_age", false, 0, 200)) a.max_age = static_cast<int>(*v);
  if (auto v = check.number(body, "", "weight", false, 0.0, 100.0)) a.weight = *v;
  if (auto v = check.boolean(body, "", "base", false)) a.base = *v;
  if (const Json* eff = check.object(body, "", "effects", true)) {
    if (const Json* rooms = check.object(*eff, "/effects", "rooms", true)) {
      for (const auto& [room, w] : rooms->items()) {
        auto rt = parse_room_type(room);
        if (!rt)
          check.add("/effects/rooms/" + json_pointer_token(room), "unknown room type");
        else if (!w.is_number() || w.get<double>() < 0)
          check.add("/effects/rooms/" + json_pointer_token(room), "must be ≥ 0");
        else
          a.effects.rooms[index_of(*rt)] = w.get<double>();
      }
    }
    if (const Json* objs = check.array(*eff, "/effects", "objects", true))
      for (std::size_t i = 0; i < objs->size(); ++i) {
        const std::string ptr = "/effects/objects/" + std::to_string(i);
        const Json& o = (*objs)[i];
        ObjectEffect e;
        if (auto t = check.string(o, ptr, "type", true, 1, 60)) e.type = *t;
        if (auto p = check.number(o, ptr, "p", true, 0.0, 1.0)) e.p = *p;
        if (const Json* r = check.object(o, ptr, "receptacles", true)) {
          auto m = weight_map(*r, ptr + "/receptacles", check);
          if (m) e.receptacles = std::move(*m);
          if (e.receptacles.empty())
            check.add(ptr + "/receptacles", "must name at least one receptacle with weight > 0");
        }
        a.effects.objects.push_back(std::move(e));
      }
  }
  if (!check.ok()) return tl::unexpected(check.error("invalid activity '" + name + "'"));
  return a;
}

Result<HouseholdKnowledge> load_household_knowledge(store::Store& store) {
  return store.read([](store::Database& db) -> Result<HouseholdKnowledge> {
    HouseholdKnowledge k;
    auto s = for_rows(db, "SELECT id, body FROM household_personas ORDER BY builtin DESC, rowid",
                      [&](store::Statement& st) -> Status {
                        auto body = parse_body(st.text(1), "household_personas/" + st.text(0));
                        if (!body) return tl::unexpected(body.error());
                        auto p = persona_from_json(*body);
                        if (!p)
                          return fail(ErrorCode::kStore, "stored persona '" + st.text(0) +
                                                             "' is invalid: " + p.error().message());
                        k.personas.push_back(std::move(*p));
                        return {};
                      });
    if (!s) return tl::unexpected(s.error());
    s = for_rows(db, "SELECT name, role, body FROM household_activities ORDER BY name",
                 [&](store::Statement& st) -> Status {
                   auto body = parse_body(st.text(2), "household_activities/" + st.text(0));
                   if (!body) return tl::unexpected(body.error());
                   auto a = activity_from_json(st.text(0), st.text(1), *body);
                   if (!a) return fail(ErrorCode::kStore, a.error().message());
                   k.activities.push_back(std::move(*a));
                   return {};
                 });
    if (!s) return tl::unexpected(s.error());
    s = for_rows(db, "SELECT type, kind FROM household_object_types ORDER BY type",
                 [&](store::Statement& st) -> Status {
                   (st.text(1) == "movable" ? k.movable_types : k.fixture_types).push_back(st.text(0));
                   return {};
                 });
    if (!s) return tl::unexpected(s.error());
    s = for_rows(db, "SELECT type, body FROM household_receptacle_types ORDER BY type",
                 [&](store::Statement& st) -> Status {
                   auto body = parse_body(st.text(1), "household_receptacle_types/" + st.text(0));
                   if (!body) return tl::unexpected(body.error());
                   ReceptacleSpec r;
                   r.type = st.text(0);
                   const Json& b = *body;
                   try {
                     for (const auto& room : b.at("rooms"))
                       if (auto rt = parse_room_type(room.get<std::string>())) r.rooms.push_back(*rt);
                     r.size_x = b.at("size").at(0).get<double>();
                     r.size_z = b.at("size").at(1).get<double>();
                     r.height = b.at("height").get<double>();
                     r.middle = b.at("placement").get<std::string>() == "middle";
                     r.mean_objects = b.at("mean_objects").get<double>();
                     for (const auto& [obj, w] : b.at("contents").items())
                       r.contents.emplace_back(obj, w.get<double>());
                   } catch (const Json::exception& e) {
                     return fail(ErrorCode::kStore,
                                 "receptacle type '" + r.type + "' has a malformed body: " + e.what());
                   }
                   k.receptacles.push_back(std::move(r));
                   return {};
                 });
    if (!s) return tl::unexpected(s.error());
    s = for_rows(
        db, "SELECT room_type, body FROM household_room_programs", [&](store::Statement& st) -> Status {
          auto rt = parse_room_type(st.text(0));
          auto body = parse_body(st.text(1), "household_room_programs/" + st.text(0));
          if (!body) return tl::unexpected(body.error());
          if (!rt)
            return fail(ErrorCode::kStore, "unknown room type in household_room_programs: " + st.text(0));
          RoomProgram prog;
          try {
            prog.min_area = body->at("area").at(0).get<double>();
            prog.max_area = body->at("area").at(1).get<double>();
            for (const auto& f : body->at("furniture"))
              prog.furniture.push_back(
                  {f.at("type").get<std::string>(), f.at("p").get<double>(), f.at("max").get<int>()});
            if (body->contains("fixtures"))
              for (const auto& f : body->at("fixtures"))
                prog.fixtures.push_back({f.at("type").get<std::string>(), f.at("p").get<double>(),
                                         f.at("max").get<int>(), f.at("on").get<std::string>()});
          } catch (const Json::exception& e) {
            return fail(ErrorCode::kStore, "room program '" + st.text(0) + "' is malformed: " + e.what());
          }
          k.room_programs[index_of(*rt)] = std::move(prog);
          return {};
        });
    if (!s) return tl::unexpected(s.error());
    s = for_rows(db, "SELECT kind, name, body FROM household_persona_parts ORDER BY position",
                 [&](store::Statement& st) -> Status {
                   auto body = parse_body(st.text(2), "household_persona_parts/" + st.text(1));
                   if (!body) return tl::unexpected(body.error());
                   return add_persona_part(k.persona_parts, st.text(0), st.text(1), *body);
                 });
    if (!s) return tl::unexpected(s.error());
    if (s = check_persona_parts(k.persona_parts); !s) return tl::unexpected(s.error());
    if (k.activities.empty() || k.receptacles.empty())
      return fail(ErrorCode::kStore,
                  "household knowledge tables are empty: the store is missing migrations 0020–0023");
    k.index();
    for (std::size_t r = 0; r < kRoomTypeCount; ++r)
      for (const auto& f : k.room_programs[r].fixtures)
        if (!k.is_fixture(f.type) || (f.on != "wall" && !k.receptacle(f.on)))
          return fail(ErrorCode::kStore, "room program fixture '" + f.type + "' on '" + f.on +
                                             "' is not a fixture type on a wall or a known receptacle");
    return k;
  });
}

Status store_persona(store::Store& store, const Persona& persona) {
  const std::string id = persona_id(persona);
  const std::string body = to_json(persona).dump();
  return store.write([&](store::Database& db) -> Status {
    auto check = db.prepare("SELECT builtin FROM household_personas WHERE id = ?");
    if (!check) return tl::unexpected(check.error());
    check->bind(1, id);
    auto row = check->step();
    if (!row) return tl::unexpected(row.error());
    if (*row)
      return fail(ErrorCode::kConflict, "a persona with id '" + id + "' already exists",
                  {FieldError{"/name", "another persona has this name"}});
    auto ins = db.prepare("INSERT INTO household_personas(id, builtin, body) VALUES (?, 0, ?)");
    if (!ins) return tl::unexpected(ins.error());
    ins->bind(1, id).bind(2, body);
    return ins->run();
  });
}

Result<std::vector<Persona>> list_stored_personas(store::Store& store, bool include_builtin) {
  return store.read([&](store::Database& db) -> Result<std::vector<Persona>> {
    std::vector<Persona> out;
    auto s =
        for_rows(db,
                 include_builtin ? "SELECT id, body FROM household_personas ORDER BY builtin DESC, rowid"
                                 : "SELECT id, body FROM household_personas WHERE builtin = 0 ORDER BY rowid",
                 [&](store::Statement& st) -> Status {
                   auto body = parse_body(st.text(1), "household_personas/" + st.text(0));
                   if (!body) return tl::unexpected(body.error());
                   auto p = persona_from_json(*body);
                   if (!p) return fail(ErrorCode::kStore, p.error().message());
                   out.push_back(std::move(*p));
                   return {};
                 });
    if (!s) return tl::unexpected(s.error());
    return out;
  });
}

}  // namespace socsim::household
