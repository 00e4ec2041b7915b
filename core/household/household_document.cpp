#include "core/household/household_document.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"
#include "core/common/sha256.hpp"
#include "core/household/procthor.hpp"

namespace socsim::household {

Result<HouseholdRequest> household_request_from_json(const Json& json) {
  JsonChecker check;
  HouseholdRequest r;
  if (!json.is_object()) {
    check.add("",
              "must be an object with rooms or house, residents, days, start_weekday, seed and generator");
    return tl::unexpected(check.error("invalid household request"));
  }
  check.only_keys(json, "",
                  {"rooms", "house", "residents", "days", "start_weekday", "seed", "generator", "model"});
  const bool has_rooms = JsonChecker::given(json, "rooms"), has_house = JsonChecker::given(json, "house");
  if (has_rooms == has_house)
    check.add(has_rooms ? "/house" : "/rooms",
              has_rooms ? "give rooms or house, not both" : "give rooms (1-10) or a ProcTHOR house");
  if (auto v = check.integer(json, "", "rooms", false, 1, 10)) r.rooms = static_cast<int>(*v);
  if (has_house) {
    if (!json["house"].is_object())
      check.add("/house", "must be a ProcTHOR house object");
    else
      r.house = json["house"];
  }
  if (json.contains("residents")) {
    const Json& res = json["residents"];
    if (res.is_number_integer()) {
      const auto n = res.get<std::int64_t>();
      if (n < 0 || n > 4)
        check.add("/residents", "must be 0 (chosen by bedrooms) to 4");
      else
        r.resident_count = static_cast<int>(n);
    } else if (res.is_array()) {
      if (res.empty() || res.size() > 4) check.add("/residents", "must list 1 to 4 persona ids");
      for (std::size_t i = 0; i < res.size(); ++i) {
        if (!res[i].is_string() || res[i].get_ref<const std::string&>().empty() ||
            res[i].get_ref<const std::string&>().size() > 80)
          check.add("/residents/" + std::to_string(i), "must be a persona id");
        else if (std::find(r.resident_ids.begin(), r.resident_ids.end(), res[i].get<std::string>()) !=
                 r.resident_ids.end())
          check.add("/residents/" + std::to_string(i), "is listed twice");
        else
          r.resident_ids.push_back(res[i].get<std::string>());
      }
      r.resident_count = static_cast<int>(r.resident_ids.size());
    } else {
      check.add("/residents", "must be a count (0-4) or a list of persona ids");
    }
  }
  if (auto v = check.integer(json, "", "days", false, 1, 28)) r.days = static_cast<int>(*v);
  if (auto v = check.string(json, "", "start_weekday", false, 3, 12)) {
    if (auto wd = parse_weekday(*v))
      r.start_weekday = *wd;
    else
      check.add("/start_weekday", "must be a weekday name (Monday … Sunday)");
  }
  if (auto v = check.integer(json, "", "seed", false, 0, INT64_MAX)) r.seed = static_cast<std::uint64_t>(*v);
  if (auto v = check.string(json, "", "generator", false, 1, 20)) {
    if (*v != "offline" && *v != "llm")
      check.add("/generator", "must be offline or llm");
    else
      r.generator = *v;
  }
  if (auto v = check.string(json, "", "model", false, 1, 200)) r.model = *v;
  if (!check.ok()) return tl::unexpected(check.error("invalid household request"));
  return r;
}

Json to_json(const HouseholdRequest& r) {
  Json j = Json::object();
  if (r.house)
    j["house"] = *r.house;
  else
    j["rooms"] = r.rooms;
  if (!r.resident_ids.empty())
    j["residents"] = r.resident_ids;
  else
    j["residents"] = r.resident_count;
  j["days"] = r.days;
  j["start_weekday"] = weekday_name(r.start_weekday);
  j["seed"] = r.seed;
  j["generator"] = r.generator;
  if (r.model) j["model"] = *r.model;
  return j;
}

Result<House> household_house(const HouseholdRequest& r, const HouseholdKnowledge& knowledge) {
  if (r.house) {
    auto h = import_procthor(*r.house, knowledge, "house");
    if (!h) {
      auto e = h.error();
      e.under("/house");
      return tl::unexpected(e);
    }
    return h;
  }
  return generate_house({r.rooms, std::nullopt, r.seed}, knowledge);
}

std::string household_id(const HouseholdRequest& request, std::string_view salt) {
  return "hh_" + sha256_hex(canonical_json(to_json(request)) + "|" + std::string(salt)).substr(0, 20);
}

Result<HouseholdDocument> generate_household(const HouseholdRequest& request,
                                             const HouseholdKnowledge& knowledge,
                                             std::span<const Persona> personas, const ProfileGenerators& gens,
                                             const HouseholdProgress& progress, const std::string& id) {
  auto house = household_house(request, knowledge);
  if (!house) return tl::unexpected(house.error());
  const auto bedrooms = static_cast<int>(house->rooms_of(RoomType::kBedroom).size());
  const int most = std::min(4, bedrooms);
  if (most < 1)
    return fail(ErrorCode::kValidation, "the house has no bedroom",
                {FieldError{request.house ? "/house" : "/rooms", "needs at least one bedroom"}});

  Rng rng(request.seed, fnv1a64("household"));
  std::vector<Persona> chosen;
  if (!request.resident_ids.empty()) {
    if (static_cast<int>(request.resident_ids.size()) > most)
      return fail(ErrorCode::kValidation, "more residents than bedrooms",
                  {FieldError{"/residents",
                              "this house has room for " + std::to_string(most) + " (one bedroom each)"}});
    JsonChecker check;
    for (std::size_t i = 0; i < request.resident_ids.size(); ++i) {
      auto it = std::find_if(personas.begin(), personas.end(),
                             [&](const Persona& p) { return persona_id(p) == request.resident_ids[i]; });
      if (it == personas.end())
        check.add("/residents/" + std::to_string(i), "no persona '" + request.resident_ids[i] + "'");
      else
        chosen.push_back(*it);
    }
    if (!check.ok()) return tl::unexpected(check.error("unknown persona"));
  } else {
    if (request.resident_count > most)
      return fail(ErrorCode::kValidation, "more residents than bedrooms",
                  {FieldError{"/residents", "this house has room for 1 to " + std::to_string(most) +
                                                " (one bedroom each)"}});
    const int n =
        request.resident_count > 0 ? request.resident_count : static_cast<int>(rng.between(1, most));
    std::vector<const Persona*> pool;
    for (const auto& p : knowledge.personas) pool.push_back(&p);
    if (pool.empty()) return fail(ErrorCode::kValidation, "no personas to choose residents from");
    rng.shuffle(pool);
    for (int i = 0; i < n && i < static_cast<int>(pool.size()); ++i)
      chosen.push_back(*pool[static_cast<std::size_t>(i)]);
  }

  HouseholdDocument doc;
  doc.id = id;
  doc.request = request;
  doc.scene_seed = rng.next_u64() >> 1;
  OfflineDayPlanner offline_planner(knowledge);
  OfflineDecomposer offline_decomposer(knowledge);
  OfflineActivityDatabaseGenerator offline_db(knowledge);
  DayPlanGenerator& planner = gens.planner ? *gens.planner : offline_planner;
  ScheduleDecomposer& decomposer = gens.decomposer ? *gens.decomposer : offline_decomposer;
  ActivityDatabaseGenerator& dbgen = gens.activity_db ? *gens.activity_db : offline_db;
  auto vocabulary = ActivityVocabulary::initial(knowledge);
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (progress)
      progress(0.05 + 0.9 * static_cast<double>(i) / static_cast<double>(chosen.size()),
               "schedule of " + chosen[i].name);
    const ScheduleRequest sr{request.days, request.start_weekday,
                             request.seed ^ fnv1a64(persona_id(chosen[i]))};
    auto schedule = generate_schedule(chosen[i], sr, planner, decomposer, vocabulary);
    if (!schedule) return tl::unexpected(schedule.error());
    if (progress)
      progress(0.05 + 0.9 * (static_cast<double>(i) + 0.5) / static_cast<double>(chosen.size()),
               "activity database of " + chosen[i].name);
    auto db = dbgen.generate(chosen[i], primaries_of(*schedule), sr.seed);
    if (!db) return tl::unexpected(db.error());
    doc.residents.push_back(std::make_shared<const ResidentProfile>(
        ResidentProfile{chosen[i], std::move(*schedule), std::move(*db)}));
  }
  if (auto scene = instantiate_household(doc, knowledge); !scene) return tl::unexpected(scene.error());
  if (progress) progress(1.0, "scene configured");
  return doc;
}

Result<DynamicScene> instantiate_household(const HouseholdDocument& doc,
                                           const HouseholdKnowledge& knowledge) {
  auto house = household_house(doc.request, knowledge);
  if (!house) return tl::unexpected(house.error());
  house->id = doc.id;
  auto shared = std::make_shared<const House>(std::move(*house));
  return configure_scene(shared, doc.residents, {static_cast<int>(doc.residents.size()), doc.scene_seed},
                         knowledge);
}

Json to_json(const HouseholdDocument& doc) {
  Json residents = Json::array();
  for (const auto& r : doc.residents) residents.push_back(to_json(*r));
  return {{"format", "socsim.household/1"},
          {"id", doc.id},
          {"request", to_json(doc.request)},
          {"scene_seed", doc.scene_seed},
          {"residents", residents}};
}

Result<HouseholdDocument> household_document_from_json(const Json& json,
                                                       const HouseholdKnowledge& knowledge) {
  if (!json.is_object() || json.value("format", "") != "socsim.household/1")
    return fail(ErrorCode::kValidation, "not a household document",
                {FieldError{"/format", "must be socsim.household/1"}});
  HouseholdDocument doc;
  doc.id = json.value("id", "");
  if (doc.id.rfind("hh_", 0) != 0)
    return fail(ErrorCode::kValidation, "invalid household document",
                {FieldError{"/id", "must start with hh_"}});
  auto request = household_request_from_json(json.value("request", Json::object()));
  if (!request) {
    auto e = request.error();
    e.under("/request");
    return tl::unexpected(e);
  }
  doc.request = std::move(*request);
  if (!json.contains("scene_seed") || !json["scene_seed"].is_number_unsigned())
    return fail(ErrorCode::kValidation, "invalid household document",
                {FieldError{"/scene_seed", "must be a non-negative integer"}});
  doc.scene_seed = json["scene_seed"].get<std::uint64_t>();
  if (!json.contains("residents") || !json["residents"].is_array() || json["residents"].empty())
    return fail(ErrorCode::kValidation, "invalid household document",
                {FieldError{"/residents", "must list the residents' profiles"}});
  for (std::size_t i = 0; i < json["residents"].size(); ++i) {
    auto p = resident_profile_from_json(json["residents"][i], knowledge, "/residents/" + std::to_string(i));
    if (!p) return tl::unexpected(p.error());
    doc.residents.push_back(std::make_shared<const ResidentProfile>(std::move(*p)));
  }
  return doc;
}

Status store_household(store::Store& store, const HouseholdDocument& doc, const Json& summary,
                       const std::string& author, const std::optional<std::string>& job_id) {
  const std::string body = to_json(doc).dump();
  return store.write([&](store::Database& db) -> Status {
    auto ins = db.prepare(
        "INSERT INTO households(id, job_id, author, generator, summary, document) VALUES (?, ?, ?, ?, ?, ?) "
        "ON CONFLICT(id) DO NOTHING");
    if (!ins) return tl::unexpected(ins.error());
    ins->bind(1, doc.id)
        .bind(2, job_id)
        .bind(3, author)
        .bind(4, doc.request.generator)
        .bind(5, summary.dump())
        .bind(6, body);
    return ins->run();
  });
}

Result<Json> load_household_document(store::Store& store, const std::string& id) {
  return store.read([&](store::Database& db) -> Result<Json> {
    auto st = db.prepare("SELECT document FROM households WHERE id = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id);
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) return fail(ErrorCode::kNotFound, "no household '" + id + "'");
    auto j = parse_json_untrusted(st->text(0));
    if (!j) return fail(ErrorCode::kStore, "household '" + id + "' is stored as invalid JSON");
    return std::move(*j);
  });
}

Result<std::vector<HouseholdRow>> list_households(store::Store& store, std::size_t limit,
                                                  const std::optional<std::string>& after_id) {
  return store.read([&](store::Database& db) -> Result<std::vector<HouseholdRow>> {
    if (after_id) {  // an id that is not there would silently give an empty page
      auto known = db.prepare("SELECT 1 FROM households WHERE id = ?");
      if (!known) return tl::unexpected(known.error());
      known->bind(1, *after_id);
      auto found = known->step();
      if (!found) return tl::unexpected(found.error());
      if (!*found) return fail(ErrorCode::kNotFound, "no household '" + *after_id + "' to continue after");
    }
    auto st = db.prepare(
        after_id ? "SELECT id, job_id, author, generator, summary, created_at FROM households WHERE rowid < "
                   "(SELECT rowid FROM households WHERE id = ?) ORDER BY rowid DESC LIMIT ?"
                 : "SELECT id, job_id, author, generator, summary, created_at FROM households ORDER BY rowid "
                   "DESC LIMIT ?");
    if (!st) return tl::unexpected(st.error());
    if (after_id)
      st->bind(1, *after_id).bind(2, static_cast<std::int64_t>(limit));
    else
      st->bind(1, static_cast<std::int64_t>(limit));
    std::vector<HouseholdRow> out;
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      HouseholdRow r;
      r.id = st->text(0);
      r.job_id = st->optional_text(1);
      r.author = st->text(2);
      r.generator = st->text(3);
      auto s = parse_json_untrusted(st->text(4));
      r.summary = s ? *s : Json::object();
      r.created_at = st->text(5);
      out.push_back(std::move(r));
    }
    return out;
  });
}

namespace {

Json point_json(double x, double z) {
  return {{"x", std::round(x * 1000.0) / 1000.0}, {"z", std::round(z * 1000.0) / 1000.0}};
}

std::string room_id_of(const House& h, int room) {
  return room >= 0 ? h.rooms[static_cast<std::size_t>(room)].id : std::string();
}

}  // namespace

Json house_plan_json(const House& h, bool floors) {
  Json rooms = Json::array(), walls = Json::array(), doors = Json::array(), receptacles = Json::array();
  for (const auto& r : h.rooms) {
    Json floor = Json::array();
    for (const auto& p : r.floor) floor.push_back(point_json(p.x, p.z));
    rooms.push_back({{"id", r.id}, {"type", room_type_name(r.type)}, {"floor", floor}});
  }
  for (const auto& w : h.walls)
    if (!w.empty && w.room_id != "exterior")
      walls.push_back({{"id", w.id},
                       {"room", w.room_id},
                       {"a", point_json(w.a.x, w.a.z)},
                       {"b", point_json(w.b.x, w.b.z)}});
  for (const auto& d : h.doors) {
    auto wall = std::find_if(h.walls.begin(), h.walls.end(), [&](const Wall& w) { return w.id == d.wall0; });
    Json door = {{"id", d.id},
                 {"room0", d.room0},
                 {"room1", d.room1},
                 {"width", std::abs(d.hole_max.x - d.hole_min.x)}};
    if (wall != h.walls.end()) {
      const double dx = wall->b.x - wall->a.x, dz = wall->b.z - wall->a.z, len = std::hypot(dx, dz);
      if (len > 0) {
        const double along = (d.hole_min.x + d.hole_max.x) / 2.0;
        door["center"] = point_json(wall->a.x + dx / len * along, wall->a.z + dz / len * along);
        door["direction"] = point_json(dx / len, dz / len);
      }
    }
    doors.push_back(std::move(door));
  }
  for (int idx : h.receptacles) {
    const Entity& e = h.entities[static_cast<std::size_t>(idx)];
    if (e.synthetic && !floors) continue;
    Json r = {{"id", e.id},
              {"type", e.type},
              {"room", room_id_of(h, e.room)},
              {"position", point_json(e.position.x, e.position.z)},
              {"size", {{"x", e.size_x}, {"z", e.size_z}}},
              {"yaw", e.rotation.y}};
    if (e.synthetic) r["synthetic"] = true;
    receptacles.push_back(std::move(r));
  }
  // Windows (ProcTHOR form: a hole along wall0), as doors are given: centre, direction, width.
  Json windows = Json::array();
  for (const auto& win : h.windows) {
    if (!win.is_object() || !win.contains("wall0") || !win.contains("holePolygon") ||
        !win["wall0"].is_string())
      continue;
    const auto& hole = win["holePolygon"];
    if (!hole.is_array() || hole.size() < 2 || !hole[0].contains("x") || !hole[1].contains("x") ||
        !hole[0]["x"].is_number() || !hole[1]["x"].is_number())
      continue;
    const std::string wall_id = win["wall0"].get<std::string>();
    auto wall = std::find_if(h.walls.begin(), h.walls.end(), [&](const Wall& w) { return w.id == wall_id; });
    if (wall == h.walls.end()) continue;
    const double dx = wall->b.x - wall->a.x, dz = wall->b.z - wall->a.z, len = std::hypot(dx, dz);
    if (len <= 0) continue;
    const double x0 = hole[0]["x"].get<double>(), x1 = hole[1]["x"].get<double>(), along = (x0 + x1) / 2.0;
    windows.push_back({{"id", win.value("id", "")},
                       {"room", win.value("room0", "")},
                       {"center", point_json(wall->a.x + dx / len * along, wall->a.z + dz / len * along)},
                       {"direction", point_json(dx / len, dz / len)},
                       {"width", std::abs(x1 - x0)}});
  }
  return {{"id", h.id},     {"rooms", rooms},     {"walls", walls},
          {"doors", doors}, {"windows", windows}, {"receptacles", receptacles}};
}

Json objects_at_json(const DynamicScene& scene, Seconds t) {
  const House& h = scene.house();
  const std::vector<int> at = scene.placement_at(t);
  std::map<int, std::vector<std::size_t>> on;  // receptacle → objects on it, in object order
  for (std::size_t o = 0; o < at.size(); ++o) on[at[o]].push_back(o);
  Json objects = Json::array();
  for (std::size_t o = 0; o < at.size(); ++o) {
    const Entity& obj = h.entities[static_cast<std::size_t>(h.objects[o])];
    const Entity& rec = h.entities[static_cast<std::size_t>(at[o])];
    const auto& group = on[at[o]];
    const auto k = static_cast<std::size_t>(std::find(group.begin(), group.end(), o) - group.begin());
    // A small grid over the receptacle's footprint (synthetic floors: around the room's centre).
    const std::size_t cols = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(group.size())))));
    const double sx = std::max(0.2, rec.size_x) * 0.7, sz = std::max(0.2, rec.size_z) * 0.7;
    const double fx = cols > 1 ? (static_cast<double>(k % cols) / static_cast<double>(cols - 1) - 0.5) : 0.0;
    const double rows = std::ceil(static_cast<double>(group.size()) / static_cast<double>(cols));
    const double fz = rows > 1 ? (static_cast<double>(k / cols) / (rows - 1) - 0.5) : 0.0;
    const double yaw = rec.rotation.y * std::numbers::pi / 180.0;
    const double lx = fx * sx, lz = fz * sz;
    const double x = rec.position.x + lx * std::cos(yaw) + lz * std::sin(yaw),
                 z = rec.position.z - lx * std::sin(yaw) + lz * std::cos(yaw);
    objects.push_back({{"id", obj.id},
                       {"type", obj.type},
                       {"receptacle", rec.id},
                       {"receptacle_type", rec.type},
                       {"room", room_id_of(h, rec.room)},
                       {"position", point_json(x, z)}});
  }
  return {{"t", t}, {"clock", format_clock(t, scene.first_day())}, {"objects", objects}};
}

Json event_json(const DynamicScene& scene, int index) {
  const House& h = scene.house();
  const SceneEvent& e = scene.events()[static_cast<std::size_t>(index)];
  const ScheduleEntry& en = scene.entry(e);
  Json moves = Json::array();
  for (const auto& r : scene.relocations_between(e.end, e.end + 1))
    if (r.event == index)
      moves.push_back(
          {{"object", h.entities[static_cast<std::size_t>(h.objects[static_cast<std::size_t>(r.object)])].id},
           {"from", h.entities[static_cast<std::size_t>(r.from)].id},
           {"to", h.entities[static_cast<std::size_t>(r.to)].id}});
  return {{"index", index},
          {"resident", e.resident},
          {"start", e.start},
          {"end", e.end},
          {"clock",
           format_clock(e.start, scene.first_day()) + "-" + format_clock(e.end, scene.first_day()).substr(4)},
          {"activity", en.name},
          {"primary", en.primary},
          {"role", activity_role_name(en.role)},
          {"room", e.room >= 0 ? Json(room_id_of(h, e.room)) : Json(nullptr)},
          {"relocations", moves}};
}

Json household_summary_json(const HouseholdDocument& doc, const DynamicScene& scene) {
  const House& h = scene.house();
  Json residents = Json::array(), schedules = Json::array();
  for (std::size_t i = 0; i < scene.residents().size(); ++i) {
    const Resident& r = scene.residents()[i];
    const Persona& p = r.profile->persona;
    residents.push_back({{"index", i},
                         {"persona_id", persona_id(p)},
                         {"name", p.name},
                         {"age", p.age},
                         {"gender", p.gender},
                         {"occupation", p.occupation},
                         {"bedroom", r.bedroom >= 0 ? Json(room_id_of(h, r.bedroom)) : Json(nullptr)},
                         {"bathroom", r.bathroom >= 0 ? Json(room_id_of(h, r.bathroom)) : Json(nullptr)},
                         {"events", scene.events_of(static_cast<int>(i)).size()}});
    Json entries = Json::array();
    for (const auto& e : r.profile->schedule.entries)
      entries.push_back({{"start", e.start * Seconds{60}},
                         {"end", e.end * Seconds{60}},
                         {"activity", e.name},
                         {"primary", e.primary},
                         {"role", activity_role_name(e.role)}});
    schedules.push_back({{"resident", i}, {"entries", entries}});
  }
  return {{"id", doc.id},
          {"request",
           [&] {
             Json r = to_json(doc.request);
             if (r.contains("house")) r["house"] = "(ProcTHOR house)";
             return r;
           }()},
          {"first_day", weekday_name(scene.first_day())},
          {"days", doc.request.days},
          {"end", scene.end()},
          {"rooms", h.rooms.size()},
          {"receptacles", h.receptacles.size()},
          {"objects", h.objects.size()},
          {"events", scene.events().size()},
          {"relocations", scene.relocations().size()},
          {"residents", residents},
          {"schedules", schedules}};
}

}  // namespace socsim::household
