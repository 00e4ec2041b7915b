#include "core/household/llm_generators.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "core/common/rng.hpp"
#include "core/household/hints.hpp"
#include "core/household/llm_answers.hpp"

namespace socsim::household {
namespace {

Result<Json> ask(const LlmSettings& s, const std::string& artifact, llm::PromptVariables variables,
                 llm::SemanticCheck check, std::int64_t seed) {
  if (!s.generator) return fail(ErrorCode::kInternal, "LLM generator used without a StructuredGenerator");
  auto schema = answer_schema(artifact);
  if (!schema) return tl::unexpected(schema.error());
  llm::GenerationRequest r;
  r.artifact = artifact;
  r.variables = std::move(variables);
  r.schema = *schema;
  r.check = std::move(check);
  r.model = s.model;
  r.temperature = s.temperature;
  r.seed = seed;
  r.job_id = s.job_id;
  r.cancel = s.cancel;
  auto g = s.generator->generate(r);
  if (!g) return tl::unexpected(g.error());
  return std::move(g->value);
}

std::int64_t mix(std::uint64_t seed, std::string_view label) {
  std::uint64_t state = seed ^ fnv1a64(label);
  return static_cast<std::int64_t>(splitmix64(state) >> 1);
}

std::string persona_text(const Persona& p) {
  std::string traits;
  for (const auto& t : p.personality) traits += (traits.empty() ? "" : ", ") + t;
  return "Name: " + p.name + "\nAge: " + std::to_string(p.age) + "\nGender: " + p.gender +
         "\nOccupation: " + p.occupation + "\nRoutine: " + p.routine + "\nPersonality: " + traits +
         "\nThoughts: " + p.thoughts + "\nLifestyle: " + p.lifestyle;
}

std::string plan_text(const DayPlan& plan) {
  std::string out;
  for (const auto& b : plan.blocks)
    out += format_minutes(b.start) + "-" + format_minutes(b.end) + " " +
           std::string(block_kind_name(b.kind)) + ": " + b.description + "\n";
  return out;
}

std::string lower_trimmed(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
  return out;
}

std::string room_words(RoomType t) {
  switch (t) {
    case RoomType::kBedroom:
      return "bedroom";
    case RoomType::kBathroom:
      return "bathroom";
    case RoomType::kLivingRoom:
      return "living room";
    case RoomType::kKitchen:
      return "kitchen";
  }
  return "room";
}

// Room types with the receptacles that may stand there, and object types with the receptacle
// types they may be put on (from the curated effects and furnishing tables).
std::string scene_prior_text(const HouseholdKnowledge& k) {
  std::string out = "Room types: Bedroom, Bathroom, LivingRoom, Kitchen.\nReceptacle types per room type:\n";
  for (RoomType rt : kRoomTypes) {
    out += "- " + std::string(room_type_name(rt)) + ":";
    bool first = true;
    for (const auto& r : k.receptacles)
      if (r.allowed_in(rt)) out += std::string(first ? " " : ", ") + r.type, first = false;
    out += "\n";
  }
  std::map<std::string, std::set<std::string>> fits;
  for (const auto& a : k.activities)
    for (const auto& o : a.effects.objects)
      for (const auto& [r, w] : o.receptacles)
        if (w > 0 && k.receptacle(r)) fits[o.type].insert(r);
  for (const auto& r : k.receptacles)
    for (const auto& [o, w] : r.contents)
      if (w > 0) fits[o].insert(r.type);
  out += "Object types and the receptacle types they can be put on:\n";
  for (const auto& [o, rs] : fits) {
    if (!k.is_movable(o)) continue;
    out += "- " + o + ":";
    bool first = true;
    for (const auto& r : rs) out += std::string(first ? " " : ", ") + r, first = false;
    out += "\n";
  }
  return out;
}

}  // namespace

Result<std::vector<Persona>> generate_personas_llm(const PersonaRequest& request,
                                                   std::span<const Persona> existing,
                                                   const LlmSettings& settings) {
  if (request.count < 1 || request.count > 200)
    return fail(ErrorCode::kValidation, "count must be between 1 and 200",
                {FieldError{"/count", "must be between 1 and 200"}});
  const auto& c = request.constraints;
  std::string guidance;
  if (c.min_age || c.max_age)
    guidance += "age between " + std::to_string(c.min_age.value_or(0)) + " and " +
                std::to_string(c.max_age.value_or(120)) + "; ";
  if (c.gender) guidance += "gender " + *c.gender + "; ";
  if (c.occupation) guidance += "occupation: " + *c.occupation + "; ";
  if (c.household_role)
    guidance += "role in the household: " + std::string(household_role_name(*c.household_role)) + "; ";
  if (guidance.empty()) guidance = "anyone who could plausibly live in an ordinary home";
  std::vector<Persona> taken(existing.begin(), existing.end()), out;
  for (int i = 0; i < request.count; ++i) {
    if (settings.cancel.cancelled()) return fail(ErrorCode::kUpstream, "request cancelled");
    std::string summaries;
    const std::size_t from =
        taken.size() > 60 ? taken.size() - 60 : 0;  // the most recent ones keep the prompt short
    for (std::size_t k = from; k < taken.size(); ++k)
      summaries += "- " + taken[k].name + ", " + std::to_string(taken[k].age) + ", " +
                   taken[k].occupation.substr(0, 100) + "\n";
    if (summaries.empty()) summaries = "(none yet)\n";
    auto answer = ask(
        settings, "persona", {{"guidance", guidance}, {"existing_personas", summaries}},
        [&](const Json& j) { return check_persona_answer(j, c, taken); },
        mix(request.seed, "persona:" + std::to_string(i)));
    if (!answer) return tl::unexpected(answer.error());
    auto p = persona_from_json(*answer);
    if (!p) return tl::unexpected(p.error());
    taken.push_back(*p);
    out.push_back(std::move(*p));
  }
  return out;
}

Result<DayPlan> LlmDayPlanner::plan_day(const Persona& persona, const DayPlanContext& ctx) {
  std::string day = std::string(weekday_name(ctx.weekday)) + ", day " + std::to_string(ctx.day) +
                    " of the schedule (answer with \"day\": " + std::to_string(ctx.day) +
                    " and \"weekday\": \"" + std::string(weekday_name(ctx.weekday)) + "\").";
  if (ctx.previous) day += "\nThe day before went like this:\n" + plan_text(*ctx.previous);
  (void)knowledge_;
  auto answer = ask(
      settings_, "day_plan", {{"persona", persona_text(persona)}, {"day", day}},
      [&](const Json& j) { return check_day_plan_answer(j, ctx); },
      mix(ctx.seed, persona_id(persona) + ":plan:" + std::to_string(ctx.day)));
  if (!answer) return tl::unexpected(answer.error());
  return day_plan_from_json(*answer);
}

Result<std::vector<ScheduleEntry>> LlmDecomposer::decompose(const Persona& persona, const DayPlan& plan,
                                                            ActivityVocabulary& vocabulary,
                                                            std::uint64_t seed) {
  std::set<std::string> names;
  for (const auto& e : vocabulary.entries()) names.insert(e.primary);
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  const std::string day = std::string(weekday_name(plan.weekday)) + " (day " + std::to_string(plan.day) + ")";
  auto answer = ask(
      settings_, "activity_schedule",
      {{"persona", persona_text(persona)},
       {"day", day},
       {"day_plan", plan_text(plan)},
       {"activity_list", list}},
      [&](const Json& j) { return check_day_activities_answer(j, plan, vocabulary, knowledge_); },
      mix(seed, persona_id(persona) + ":schedule:" + std::to_string(plan.day)));
  if (!answer) return tl::unexpected(answer.error());
  std::vector<ScheduleEntry> out;
  for (const auto& a : (*answer)["activities"]) {
    ScheduleEntry e;
    e.start = parse_clock(a["start"].get<std::string>());
    e.end = parse_clock(a["end"].get<std::string>());
    const std::string name = a["activity"].get<std::string>();
    const bool away = lower_trimmed(name) == "leave home";
    e.name = away ? "leave home" : name;
    const auto r = vocabulary.add(e.name);
    e.primary = r.primary;
    e.activity = r.activity;
    if (away) {
      e.role = ActivityRole::kLeaveHome;
    } else if (r.activity >= 0) {
      e.role = knowledge_.activities[static_cast<std::size_t>(r.activity)].role;
    } else {
      // A new activity takes its role from the kind of plan block it sits in.
      e.role = ActivityRole::kLeisure;
      for (const auto& b : plan.blocks)
        if (e.start >= b.start && e.start < b.end)
          e.role = b.kind == BlockKind::kSleep        ? ActivityRole::kSleep
                   : b.kind == BlockKind::kNap        ? ActivityRole::kNap
                   : b.kind == BlockKind::kWorkAtHome ? ActivityRole::kWork
                                                      : ActivityRole::kLeisure;
    }
    if (!out.empty() && out.back().primary == e.primary && out.back().end == e.start &&
        (e.role == ActivityRole::kSleep || e.role == ActivityRole::kLeaveHome)) {
      out.back().end = e.end;
      continue;
    }
    out.push_back(std::move(e));
  }
  return out;
}

Result<ActivityDatabase> LlmActivityDatabaseGenerator::generate(const Persona& persona,
                                                                std::span<const std::string> primaries,
                                                                std::uint64_t seed) {
  ActivityDatabase db;
  db.persona_id = persona_id(persona);
  std::vector<std::string> ask_for;
  for (const auto& p : primaries) {
    const ActivitySpec* spec = knowledge_.activity(p);
    if (spec && spec->role == ActivityRole::kLeaveHome)
      db.activities.push_back({p, {}});  // away: nothing moves at home
    else
      ask_for.push_back(p);
  }
  const std::string prior = scene_prior_text(knowledge_);
  const std::size_t batch = std::max<std::size_t>(1, batch_);
  for (std::size_t from = 0; from < ask_for.size(); from += batch) {
    const std::span<const std::string> part(ask_for.data() + from, std::min(batch, ask_for.size() - from));
    std::string list;
    for (const auto& a : part) list += "- " + a + "\n";
    auto answer = ask(
        settings_, "activity_database",
        {{"persona", persona_text(persona)}, {"activities", list}, {"scene_prior", prior}},
        [&](const Json& j) { return check_activity_db_answer(j, part, knowledge_); },
        mix(seed, db.persona_id + ":db:" + std::to_string(from)));
    if (!answer) return tl::unexpected(answer.error());
    Json full = *answer;
    full["persona_id"] = db.persona_id;
    auto parsed = activity_db_from_json(full, knowledge_);
    if (!parsed) return tl::unexpected(parsed.error());
    for (auto& a : parsed->activities) db.activities.push_back(std::move(a));
  }
  std::sort(db.activities.begin(), db.activities.end(),
            [](const ActivityPrior& a, const ActivityPrior& b) { return a.activity < b.activity; });
  if (auto v = validate_activity_db(db, knowledge_); !v) return tl::unexpected(v.error());
  return db;
}

std::string coarse_memory(const DynamicScene& scene, int resident, Seconds t, Seconds lookback) {
  return memory_text(remember(scene, resident, t, lookback), scene.house());
}

Result<Hint> LlmHintGenerator::hint(const HintQuery& q) {
  if (!q.scene || q.resident < 0 || q.resident >= static_cast<int>(q.scene->residents().size()))
    return fail(ErrorCode::kValidation, "no such resident",
                {FieldError{"/resident", "must name a resident of the scene"}});
  const DynamicScene& scene = *q.scene;
  const House& h = scene.house();
  std::string type = q.object;
  for (int o : h.objects)
    if (h.entities[static_cast<std::size_t>(o)].id == q.object)
      type = h.entities[static_cast<std::size_t>(o)].type;
  // The same memory the offline resident answers from; the answer must name one of its activities.
  const ResidentMemory memory = remember(scene, q.resident, q.time, q.lookback);
  std::vector<std::string> remembered;
  for (const RememberedActivity* a : memory.activities()) remembered.push_back(a->name);
  const Persona& persona = scene.residents()[static_cast<std::size_t>(q.resident)].profile->persona;
  auto answer = ask(
      settings_, "hint",
      {{"persona", persona_text(persona)},
       {"object", object_words(type)},
       {"current_time", format_clock(q.time, scene.first_day())},
       {"memory", memory_text(memory, h)}},
      [&](const Json& j) { return check_hint_answer(j, remembered); },
      mix(scene.seed(),
          "hint:" + std::to_string(q.resident) + ":" + q.object + ":" + std::to_string(q.time)));
  if (!answer) return tl::unexpected(answer.error());
  Hint out;
  out.used = (*answer)["used_recently"].get<bool>();
  out.text = (*answer)["hint"].get<std::string>();
  out.activity = (*answer)["activity"].get<std::string>();
  // The event the answer refers to: the resident's latest event of that activity before t.
  const auto events = scene.events_of(q.resident);
  for (auto it = events.rbegin(); it != events.rend() && !out.activity.empty(); ++it) {
    const SceneEvent& e = scene.events()[static_cast<std::size_t>(*it)];
    if (e.start >= q.time || e.end <= q.time - q.lookback ||
        lower_trimmed(scene.entry(e).name) != lower_trimmed(out.activity))
      continue;
    out.event = *it;
    out.when = e.end;
    if (e.room >= 0) out.room_id = h.rooms[static_cast<std::size_t>(e.room)].id;
    for (const auto& r : scene.relocations_between(e.end, e.end + 1))
      if (r.event == *it &&
          h.entities[static_cast<std::size_t>(h.objects[static_cast<std::size_t>(r.object)])].type == type) {
        out.object = r.object;
        out.receptacle_id = h.entities[static_cast<std::size_t>(r.to)].id;
      }
    break;
  }
  return out;
}

Result<HintInterpretation> LlmHintInterpreter::interpret(const HintInterpretationQuery& q) {
  if (!q.house) return fail(ErrorCode::kValidation, "no house to interpret the hint in");
  const House& h = *q.house;
  std::string lines;
  for (int r : h.receptacles) {
    const Entity& e = h.entities[static_cast<std::size_t>(r)];
    const std::string room = e.room >= 0
                                 ? h.rooms[static_cast<std::size_t>(e.room)].id + " (" +
                                       room_words(h.rooms[static_cast<std::size_t>(e.room)].type) + ")"
                                 : "-";
    lines += e.id + " | " + e.type + " | " + room + "\n";
  }
  auto answer = ask(
      settings_, "hint_interpretation",
      {{"object", object_words(q.object)},
       {"hint", q.hint},
       {"current_time", format_clock(q.time, q.first_day)},
       {"receptacles", lines}},
      [&](const Json& j) { return check_hint_interpretation_answer(j, h); },
      mix(static_cast<std::uint64_t>(q.time), "interpret:" + q.object + ":" + q.hint));
  if (!answer) return tl::unexpected(answer.error());
  HintInterpretation out;
  out.activity = (*answer)["event"]["activity"].get<std::string>();
  out.room = (*answer)["event"]["room"].get<std::string>();
  std::map<std::string, int> by_id;
  for (int r : h.receptacles) by_id[h.entities[static_cast<std::size_t>(r)].id] = r;
  double sum = 0.0;
  for (const auto& r : (*answer)["receptacles"]) sum += r["p"].get<double>();
  for (const auto& r : (*answer)["receptacles"])
    out.receptacles.emplace_back(by_id.at(r["receptacle_id"].get<std::string>()),
                                 sum > 0 ? r["p"].get<double>() / sum : 0.0);
  return out;
}

}  // namespace socsim::household
