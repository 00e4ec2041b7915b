#include "core/household/scene.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <numeric>

#include "core/common/rng.hpp"
#include "core/household/hints.hpp"

namespace socsim::household {
namespace {

std::string spaced_lower(std::string_view camel) {
  std::string out;
  for (std::size_t i = 0; i < camel.size(); ++i) {
    const char c = camel[i];
    if (std::isupper(static_cast<unsigned char>(c)) && i > 0 &&
        (std::islower(static_cast<unsigned char>(camel[i - 1])) ||
         (i + 1 < camel.size() && std::islower(static_cast<unsigned char>(camel[i + 1])))))
      out += ' ';
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

}  // namespace

std::string object_words(std::string_view type) {
  return spaced_lower(type);
}

Result<ResidentProfile> make_resident_offline(const Persona& persona, const HouseholdKnowledge& knowledge,
                                              const ScheduleRequest& request,
                                              ActivityVocabulary& vocabulary) {
  auto schedule = generate_schedule_offline(persona, knowledge, request, vocabulary);
  if (!schedule) return tl::unexpected(schedule.error());
  OfflineActivityDatabaseGenerator gen(knowledge);
  const auto primaries = primaries_of(*schedule);
  auto db = gen.generate(persona, primaries, request.seed);
  if (!db) return tl::unexpected(db.error());
  return ResidentProfile{persona, std::move(*schedule), std::move(*db)};
}

const ScheduleEntry& DynamicScene::entry(const SceneEvent& e) const {
  return residents_[static_cast<std::size_t>(e.resident)]
      .profile->schedule.entries[static_cast<std::size_t>(e.entry)];
}

int DynamicScene::receptacle_at(int object, Seconds t) const {
  const auto o = static_cast<std::size_t>(object);
  const auto begin = object_times_.begin() + object_offsets_[o];
  const auto end = object_times_.begin() + object_offsets_[o + 1];
  const auto it = std::upper_bound(begin, end, t);
  if (it == begin) return house_->entities[static_cast<std::size_t>(house_->objects[o])].parent;
  return object_receptacles_[static_cast<std::size_t>(it - object_times_.begin() - 1)];
}

std::vector<int> DynamicScene::placement_at(Seconds t) const {
  std::vector<int> out(house_->objects.size());
  for (std::size_t o = 0; o < out.size(); ++o) out[o] = receptacle_at(static_cast<int>(o), t);
  return out;
}

std::span<const Relocation> DynamicScene::relocations_between(Seconds t1, Seconds t2) const {
  auto lo = std::lower_bound(relocations_.begin(), relocations_.end(), t1,
                             [](const Relocation& r, Seconds t) { return r.time < t; });
  auto hi =
      std::lower_bound(lo, relocations_.end(), t2, [](const Relocation& r, Seconds t) { return r.time < t; });
  if (t2 <= t1) hi = lo;
  return {relocations_.data() + (lo - relocations_.begin()), static_cast<std::size_t>(hi - lo)};
}

std::vector<int> DynamicScene::events_between(Seconds t1, Seconds t2) const {
  std::vector<int> out;
  const auto last = std::lower_bound(events_.begin(), events_.end(), t2,
                                     [](const SceneEvent& e, Seconds t) { return e.start < t; });
  for (auto it = events_.begin(); it != last; ++it)
    if (it->end > t1) out.push_back(static_cast<int>(it - events_.begin()));
  return out;
}

std::span<const int> DynamicScene::events_of(int resident) const {
  const auto& v = resident_events_[static_cast<std::size_t>(resident)];
  return {v.data(), v.size()};
}

Hint DynamicScene::hint(int resident, std::string_view object, Seconds t, Seconds lookback) const {
  std::string type(object);
  if (object.find('|') != std::string_view::npos)
    for (int o : house_->objects)
      if (house_->entities[static_cast<std::size_t>(o)].id == object)
        type = house_->entities[static_cast<std::size_t>(o)].type;
  return hint_from_memory(*this, remember(*this, resident, t, lookback), type);
}

Result<Hint> OfflineHintGenerator::hint(const HintQuery& q) {
  if (!q.scene) return fail(ErrorCode::kValidation, "a hint needs a scene");
  if (q.resident < 0 || q.resident >= static_cast<int>(q.scene->residents().size()))
    return fail(ErrorCode::kValidation, "no such resident",
                {FieldError{"/resident", "must name a resident of the scene"}});
  return q.scene->hint(q.resident, q.object, q.time, q.lookback);
}

Result<DynamicScene> configure_scene(std::shared_ptr<const House> house,
                                     std::span<const std::shared_ptr<const ResidentProfile>> pool,
                                     const SceneRequest& request, const HouseholdKnowledge& knowledge) {
  if (!house || house->rooms.empty()) return fail(ErrorCode::kValidation, "a scene needs a house with rooms");
  if (pool.empty()) return fail(ErrorCode::kValidation, "no residents to choose from");
  const House& h = *house;
  Rng rng(request.seed, fnv1a64("scene"));
  const auto bedrooms = h.rooms_of(RoomType::kBedroom);
  const auto bathrooms = h.rooms_of(RoomType::kBathroom);
  const int most =
      std::max(1, std::min<int>({4, static_cast<int>(bedrooms.size()), static_cast<int>(pool.size())}));
  if (request.residents < 0 || request.residents > most)
    return fail(ErrorCode::kValidation, "this house has room for 1 to " + std::to_string(most) + " residents",
                {FieldError{"/residents",
                            "must be between 1 and " + std::to_string(most) + " (one bedroom each), or 0"}});
  const int n = request.residents > 0 ? request.residents : static_cast<int>(rng.between(1, most));

  DynamicScene s;
  s.house_ = house;
  s.seed_ = request.seed;
  std::vector<std::size_t> order(pool.size());
  std::iota(order.begin(), order.end(), 0);
  rng.shuffle(order);
  auto beds = bedrooms, baths = bathrooms;
  rng.shuffle(beds);
  rng.shuffle(baths);
  for (int i = 0; i < n; ++i) {
    Resident r;
    r.profile = pool[order[static_cast<std::size_t>(i)]];
    if (!r.profile) return fail(ErrorCode::kValidation, "empty resident profile");
    if (static_cast<std::size_t>(i) < beds.size()) r.bedroom = beds[static_cast<std::size_t>(i)];
    if (!baths.empty()) r.bathroom = baths[static_cast<std::size_t>(i) % baths.size()];
    s.residents_.push_back(std::move(r));
  }
  const Schedule& first = s.residents_[0].profile->schedule;
  s.first_day_ = first.first_day;
  s.end_ = static_cast<Seconds>(first.days) * kSecondsPerDay;
  for (const auto& r : s.residents_)
    if (r.profile->schedule.days != first.days || r.profile->schedule.first_day != first.first_day)
      return fail(ErrorCode::kValidation, "residents' schedules cover different days");

  // What this house offers: room types, receptacles per room and type, objects per type.
  std::array<bool, kRoomTypeCount> has_type{};
  for (const auto& room : h.rooms) has_type[index_of(room.type)] = true;
  std::vector<std::map<std::string, std::vector<int>, std::less<>>> receptacles_in(h.rooms.size());
  for (int idx : h.receptacles) {
    const Entity& e = h.entities[static_cast<std::size_t>(idx)];
    if (e.room >= 0 && !e.synthetic) receptacles_in[static_cast<std::size_t>(e.room)][e.type].push_back(idx);
  }
  std::map<std::string, std::vector<int>, std::less<>> objects_of;
  for (std::size_t o = 0; o < h.objects.size(); ++o)
    objects_of[h.entities[static_cast<std::size_t>(h.objects[o])].type].push_back(static_cast<int>(o));
  std::vector<int> current(h.objects.size());
  for (std::size_t o = 0; o < h.objects.size(); ++o)
    current[o] = h.entities[static_cast<std::size_t>(h.objects[o])].parent;
  std::vector<int> owner_of_room(h.rooms.size(), -1);
  for (std::size_t r = 0; r < s.residents_.size(); ++r)
    if (s.residents_[r].bedroom >= 0)
      owner_of_room[static_cast<std::size_t>(s.residents_[r].bedroom)] = static_cast<int>(r);

  // Events of all residents, processed in the order their effects happen (their end).
  for (std::size_t r = 0; r < s.residents_.size(); ++r) {
    const auto& entries = s.residents_[r].profile->schedule.entries;
    for (std::size_t e = 0; e < entries.size(); ++e)
      s.events_.push_back({static_cast<int>(r), static_cast<int>(e), entries[e].start * Seconds{60},
                           entries[e].end * Seconds{60}, -1, 0, 0});
  }
  std::stable_sort(s.events_.begin(), s.events_.end(), [](const SceneEvent& a, const SceneEvent& b) {
    return a.start != b.start ? a.start < b.start : a.resident < b.resident;
  });
  std::vector<std::size_t> by_end(s.events_.size());
  std::iota(by_end.begin(), by_end.end(), 0);
  std::stable_sort(by_end.begin(), by_end.end(), [&](std::size_t a, std::size_t b) {
    const auto& x = s.events_[a];
    const auto& y = s.events_[b];
    return x.end != y.end ? x.end < y.end : a < b;
  });

  std::vector<double> w;
  std::vector<std::vector<std::uint32_t>> per_event(s.events_.size());
  for (std::size_t idx : by_end) {
    SceneEvent& ev = s.events_[idx];
    const Resident& res = s.residents_[static_cast<std::size_t>(ev.resident)];
    const ScheduleEntry& en = res.profile->schedule.entries[static_cast<std::size_t>(ev.entry)];
    const ActivityPrior* prior = res.profile->activity_db.find(en.primary);
    if (!prior || prior->locations.empty()) continue;
    Rng er = rng.fork("event:" + std::to_string(ev.resident) + ":" + std::to_string(ev.entry));
    // 1. Location: p(l|a) over the room types this house has.
    w.clear();
    for (const auto& loc : prior->locations) w.push_back(has_type[index_of(loc.room)] ? loc.p : 0.0);
    if (std::all_of(w.begin(), w.end(), [](double x) { return x <= 0.0; })) continue;
    const LocationPrior& loc = prior->locations[er.weighted(w)];
    int room = -1;
    if (loc.room == RoomType::kBedroom && res.bedroom >= 0)
      room = res.bedroom;
    else if (loc.room == RoomType::kBathroom && res.bathroom >= 0)
      room = res.bathroom;
    else {
      const auto candidates = h.rooms_of(loc.room);
      room = candidates[er.below(static_cast<std::uint32_t>(candidates.size()))];
    }
    ev.room = room;
    const auto& here = receptacles_in[static_cast<std::size_t>(room)];
    // 2. Objects involved, 3. their target receptacles (normalised by what this room has).
    for (const auto& op : loc.objects) {
      if (!er.chance(op.p)) continue;
      auto found = objects_of.find(op.type);
      if (found == objects_of.end()) continue;
      w.clear();
      for (const auto& [rt, p] : op.receptacles) w.push_back(here.count(rt) ? p : 0.0);
      if (std::all_of(w.begin(), w.end(), [](double x) { return x <= 0.0; })) continue;
      const auto& target_type = op.receptacles[er.weighted(w)].first;
      const auto& instances = here.find(target_type)->second;
      const int target = instances[er.below(static_cast<std::uint32_t>(instances.size()))];
      // Which instance of the object type: nearby ones first, others' bedrooms last.
      w.clear();
      for (int o : found->second) {
        const int at_room = h.entities[static_cast<std::size_t>(current[static_cast<std::size_t>(o)])].room;
        const int owner = at_room >= 0 ? owner_of_room[static_cast<std::size_t>(at_room)] : -1;
        w.push_back(at_room == room ? 3.0 : (owner >= 0 && owner != ev.resident) ? 0.2 : 1.0);
      }
      const int object = found->second[er.weighted(w)];
      if (current[static_cast<std::size_t>(object)] == target) continue;
      per_event[idx].push_back(static_cast<std::uint32_t>(s.relocations_.size()));
      s.relocations_.push_back(
          {ev.end, object, current[static_cast<std::size_t>(object)], target, static_cast<int>(idx)});
      current[static_cast<std::size_t>(object)] = target;
    }
  }
  // Indexes: relocations by event, by object (CSR), events by resident.
  for (std::size_t e = 0; e < s.events_.size(); ++e) {
    s.events_[e].first_relocation = static_cast<std::uint32_t>(s.event_relocations_.size());
    s.events_[e].relocation_count = static_cast<std::uint32_t>(per_event[e].size());
    s.event_relocations_.insert(s.event_relocations_.end(), per_event[e].begin(), per_event[e].end());
  }
  s.object_offsets_.assign(h.objects.size() + 1, 0);
  for (const auto& r : s.relocations_) ++s.object_offsets_[static_cast<std::size_t>(r.object) + 1];
  for (std::size_t o = 0; o < h.objects.size(); ++o) s.object_offsets_[o + 1] += s.object_offsets_[o];
  s.object_times_.resize(s.relocations_.size());
  s.object_receptacles_.resize(s.relocations_.size());
  std::vector<std::uint32_t> fill(s.object_offsets_.begin(), s.object_offsets_.end() - 1);
  for (const auto& r : s.relocations_) {
    const auto at = fill[static_cast<std::size_t>(r.object)]++;
    s.object_times_[at] = r.time;
    s.object_receptacles_[at] = r.to;
  }
  s.resident_events_.assign(s.residents_.size(), {});
  for (std::size_t e = 0; e < s.events_.size(); ++e)
    s.resident_events_[static_cast<std::size_t>(s.events_[e].resident)].push_back(static_cast<int>(e));
  (void)knowledge;
  return s;
}

Json DynamicScene::to_json() const {
  const House& h = *house_;
  Json residents = Json::array();
  for (const auto& r : residents_)
    residents.push_back(
        {{"persona_id", persona_id(r.profile->persona)},
         {"name", r.profile->persona.name},
         {"bedroom", r.bedroom >= 0 ? Json(h.rooms[static_cast<std::size_t>(r.bedroom)].id) : Json()},
         {"bathroom", r.bathroom >= 0 ? Json(h.rooms[static_cast<std::size_t>(r.bathroom)].id) : Json()}});
  Json events = Json::array();
  for (const auto& e : events_) {
    Json moves = Json::array();
    for (std::uint32_t k = e.first_relocation; k < e.first_relocation + e.relocation_count; ++k) {
      const auto& r = relocations_[event_relocations_[k]];
      moves.push_back(
          {{"object", h.entities[static_cast<std::size_t>(h.objects[static_cast<std::size_t>(r.object)])].id},
           {"receptacle", h.entities[static_cast<std::size_t>(r.to)].id}});
    }
    const auto& en = entry(e);
    events.push_back({{"resident", e.resident},
                      {"start", e.start},
                      {"end", e.end},
                      {"activity", en.name},
                      {"primary", en.primary},
                      {"room", e.room >= 0 ? Json(h.rooms[static_cast<std::size_t>(e.room)].id) : Json()},
                      {"relocations", moves}});
  }
  Json initial = Json::object();
  for (int o : h.objects) {
    const Entity& e = h.entities[static_cast<std::size_t>(o)];
    initial[e.id] = h.entities[static_cast<std::size_t>(e.parent)].id;
  }
  return {{"house_id", h.id},   {"seed", seed_},   {"first_day", weekday_name(first_day_)},
          {"start", 0},         {"end", end_},     {"residents", residents},
          {"initial", initial}, {"events", events}};
}

Json to_json(const ResidentProfile& profile) {
  return {{"persona", to_json(profile.persona)},
          {"schedule", to_json(profile.schedule)},
          {"activity_db", to_json(profile.activity_db)}};
}

Result<ResidentProfile> resident_profile_from_json(const Json& json, const HouseholdKnowledge& knowledge,
                                                   const std::string& pointer) {
  if (!json.is_object() || !json.contains("persona") || !json.contains("schedule") ||
      !json.contains("activity_db"))
    return fail(ErrorCode::kValidation, "invalid resident profile",
                {FieldError{pointer, "must have persona, schedule and activity_db"}});
  auto persona = persona_from_json(json["persona"], pointer + "/persona");
  if (!persona) return tl::unexpected(persona.error());
  auto schedule = schedule_from_json(json["schedule"], knowledge, pointer + "/schedule");
  if (!schedule) return tl::unexpected(schedule.error());
  auto db = activity_db_from_json(json["activity_db"], knowledge);
  if (!db) {
    auto e = db.error();
    e.under(pointer + "/activity_db");
    return tl::unexpected(e);
  }
  return ResidentProfile{std::move(*persona), std::move(*schedule), std::move(*db)};
}

}  // namespace socsim::household
