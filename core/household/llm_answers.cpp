#include "core/household/llm_answers.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "core/common/json_check.hpp"

namespace socsim::household {

// Generated from schemas/{persona,schedule,activity_db,hint}.schema.json by core/household/CMakeLists.txt.
const std::map<std::string, std::string>& embedded_household_schemas();

namespace {

// Replaces every local "$ref" by the schema it points to, so an answer schema stands alone.
Json inline_refs(const Json& node, const Json& document, int depth = 0) {
  if (depth > 32) throw std::runtime_error("household schema: $ref nesting too deep");
  if (node.is_object()) {
    if (auto it = node.find("$ref"); it != node.end() && it->is_string()) {
      const std::string ref = it->get<std::string>();
      if (ref.rfind("#/", 0) != 0)
        throw std::runtime_error("household schema: only local $ref is supported: " + ref);
      return inline_refs(document.at(Json::json_pointer(ref.substr(1))), document, depth + 1);
    }
    Json out = Json::object();
    for (const auto& [k, v] : node.items())
      if (k != "$defs" && k != "$schema" && k != "$id") out[k] = inline_refs(v, document, depth + 1);
    return out;
  }
  if (node.is_array()) {
    Json out = Json::array();
    for (const auto& v : node) out.push_back(inline_refs(v, document, depth + 1));
    return out;
  }
  return node;
}

const std::map<std::string, JsonSchema, std::less<>>& answer_schemas() {
  static const std::map<std::string, JsonSchema, std::less<>> all = [] {
    const auto& files = embedded_household_schemas();
    auto doc = [&](const char* name) { return Json::parse(files.at(name)); };
    const Json persona = doc("persona.schema.json"), schedule = doc("schedule.schema.json"),
               db = doc("activity_db.schema.json"), hint = doc("hint.schema.json");
    const std::vector<std::pair<std::string, Json>> parts = {
        {"persona", inline_refs(persona, persona)},
        {"day_plan", inline_refs(schedule.at("/$defs/day_plan"_json_pointer), schedule)},
        {"activity_schedule", inline_refs(schedule.at("/$defs/day_activities"_json_pointer), schedule)},
        {"activity_database", inline_refs(db.at("/$defs/answer"_json_pointer), db)},
        {"hint", inline_refs(hint.at("/$defs/hint"_json_pointer), hint)},
        {"hint_interpretation", inline_refs(hint.at("/$defs/hint_interpretation"_json_pointer), hint)},
    };
    std::map<std::string, JsonSchema, std::less<>> out;
    for (const auto& [name, schema] : parts) {
      auto compiled = JsonSchema::compile(schema);
      if (!compiled)
        throw std::runtime_error("household answer schema '" + name + "': " + compiled.error().message());
      out.emplace(name, std::move(*compiled));
    }
    return out;
  }();
  return all;
}

std::string lower_trim(std::string_view s) {
  std::string out;
  for (char c : s) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  while (!out.empty() && (std::isspace(static_cast<unsigned char>(out.back())) || out.back() == '.'))
    out.pop_back();
  std::size_t i = 0;
  while (i < out.size() && std::isspace(static_cast<unsigned char>(out[i]))) ++i;
  return out.substr(i);
}

Status with_errors(const JsonChecker& check, const char* what) {
  if (check.ok()) return {};
  return tl::unexpected(check.error(what));
}

void copy_errors(JsonChecker& check, const Error& e) {
  if (e.errors.empty()) check.add("", e.detail);
  for (const auto& f : e.errors) check.add(f.pointer, f.message);
}

}  // namespace

int parse_clock(std::string_view text) {
  if (text.size() != 5 || text[2] != ':') return -1;
  for (std::size_t i : {0u, 1u, 3u, 4u})
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return -1;
  const int h = (text[0] - '0') * 10 + (text[1] - '0'), m = (text[3] - '0') * 10 + (text[4] - '0');
  if (h > 24 || m > 59 || (h == 24 && m != 0)) return -1;
  return h * 60 + m;
}

Result<const JsonSchema*> answer_schema(std::string_view artifact) {
  const auto& all = answer_schemas();
  auto it = all.find(artifact);
  if (it == all.end())
    return fail(ErrorCode::kInternal, "no answer schema for '" + std::string(artifact) + "'");
  return &it->second;
}

Status check_persona_answer(const Json& answer, const PersonaConstraints& c,
                            std::span<const Persona> existing) {
  JsonChecker check;
  auto p = persona_from_json(answer);
  if (!p) return tl::unexpected(p.error());
  if (c.min_age && p->age < *c.min_age) check.add("/age", "must be at least " + std::to_string(*c.min_age));
  if (c.max_age && p->age > *c.max_age) check.add("/age", "must be at most " + std::to_string(*c.max_age));
  if (c.gender && lower_trim(p->gender) != *c.gender) check.add("/gender", "must be " + *c.gender);
  if (c.occupation) {
    const std::string occ = lower_trim(p->occupation), want = lower_trim(*c.occupation);
    if (occ.find(want) == std::string::npos)
      check.add("/occupation", "must name the occupation '" + *c.occupation + "'");
  }
  for (const auto& q : existing)
    if (near_duplicate(*p, q)) {
      check.add("/name", persona_id(*p) == persona_id(q)
                             ? "'" + q.name + "' already exists: choose another name"
                             : "too similar to the existing persona '" + q.name +
                                   "': vary occupation, routine and lifestyle");
      break;
    }
  return with_errors(check, "persona does not fit");
}

Status check_day_plan_answer(const Json& answer, const DayPlanContext& ctx) {
  JsonChecker check;
  auto plan = day_plan_from_json(answer);
  if (!plan) return tl::unexpected(plan.error());
  if (plan->day != ctx.day) check.add("/day", "must be " + std::to_string(ctx.day));
  if (plan->weekday != ctx.weekday)
    check.add("/weekday", "must be " + std::string(weekday_name(ctx.weekday)));
  int sleep = 0;
  for (const auto& b : plan->blocks)
    if (b.kind == BlockKind::kSleep) sleep += b.end - b.start;
  if (sleep < 240) check.add("/blocks", "must include at least 4 hours of sleep (kind \"sleep\")");
  return with_errors(check, "day plan does not fit");
}

Status check_day_activities_answer(const Json& answer, const DayPlan& plan,
                                   const ActivityVocabulary& vocabulary,
                                   const HouseholdKnowledge& knowledge) {
  JsonChecker check;
  const Json* acts = check.array(answer, "", "activities", true, 300);
  if (!acts) return with_errors(check, "schedule does not fit");
  struct Item {
    int start, end;
    std::string name;
  };
  std::vector<Item> items;
  int cursor = 0;
  for (std::size_t i = 0; i < acts->size(); ++i) {
    const std::string ptr = "/activities/" + std::to_string(i);
    const Json& a = (*acts)[i];
    const int start = parse_clock(a.value("start", "")), end = parse_clock(a.value("end", ""));
    const std::string name = a.value("activity", "");
    if (start < 0) check.add(ptr + "/start", "must be HH:MM");
    if (end < 0) check.add(ptr + "/end", "must be HH:MM");
    if (start < 0 || end < 0) continue;
    if (start != cursor)
      check.add(ptr + "/start", "must be " + format_minutes(cursor) + " (no gaps or overlaps)");
    if (end <= start) check.add(ptr + "/end", "must be after start");
    cursor = std::max(cursor, end);
    items.push_back({start, end, lower_trim(name)});
    if (auto r = vocabulary.resolve(name); r && r->activity >= 0) {
      const ActivitySpec& spec = knowledge.activities[static_cast<std::size_t>(r->activity)];
      if (is_meal(spec.role) && !spec.in_window(start))
        check.add(ptr + "/start",
                  "'" + name + "' at " + format_minutes(start) + " is outside its plausible hours");
    }
  }
  if (check.ok() && cursor != 1440)
    check.add("/activities", "must end at 24:00, not " + format_minutes(cursor));
  for (const auto& b : plan.blocks) {
    if (b.kind != BlockKind::kAway) continue;
    const bool whole = std::any_of(items.begin(), items.end(), [&](const Item& it) {
      return it.name == "leave home" && it.start == b.start && it.end == b.end;
    });
    if (!whole)
      check.add("/activities", "the plan's 'leave home' block " + format_minutes(b.start) + "-" +
                                   format_minutes(b.end) +
                                   " must be one activity \"leave home\" with the same start and end");
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name != "leave home") continue;
    const bool planned = std::any_of(plan.blocks.begin(), plan.blocks.end(), [&](const PlanBlock& b) {
      return b.kind == BlockKind::kAway && b.start == items[i].start && b.end == items[i].end;
    });
    if (!planned)
      check.add("/activities/" + std::to_string(i) + "/activity",
                "\"leave home\" only for the plan's blocks away from home");
  }
  return with_errors(check, "schedule does not fit");
}

Status check_activity_db_answer(const Json& answer, std::span<const std::string> requested,
                                const HouseholdKnowledge& knowledge) {
  JsonChecker check;
  Json db = answer;
  db["persona_id"] = "answer";
  if (auto parsed = activity_db_from_json(db, knowledge); !parsed) copy_errors(check, parsed.error());
  std::set<std::string> wanted(requested.begin(), requested.end()), seen;
  if (const Json* acts =
          answer.contains("activities") && answer["activities"].is_array() ? &answer["activities"] : nullptr)
    for (std::size_t i = 0; i < acts->size(); ++i) {
      const std::string name = (*acts)[i].value("activity", "");
      const std::string ptr = "/activities/" + std::to_string(i) + "/activity";
      if (!wanted.count(name))
        check.add(ptr, "'" + name + "' was not asked for; use the names of the list exactly");
      else if (!seen.insert(name).second)
        check.add(ptr, "'" + name + "' is listed twice");
    }
  for (const auto& w : wanted)
    if (!seen.count(w)) check.add("/activities", "missing the activity '" + w + "'");
  return with_errors(check, "activity database does not fit");
}

Status check_hint_answer(const Json& answer, std::span<const std::string> memory) {
  JsonChecker check;
  const std::string activity = lower_trim(answer.value("activity", ""));
  const bool used = answer.value("used_recently", false);
  if (!activity.empty()) {
    const bool known = std::any_of(memory.begin(), memory.end(),
                                   [&](const std::string& m) { return lower_trim(m) == activity; });
    if (!known)
      check.add("/activity", "must be one of the activities in the memory, written as there, or empty");
  } else if (used) {
    check.add("/activity", "name the activity of the memory in which the object was used");
  }
  return with_errors(check, "hint does not fit");
}

Status check_hint_interpretation_answer(const Json& answer, const House& house) {
  JsonChecker check;
  std::set<std::string> ids, seen;
  for (int r : house.receptacles) ids.insert(house.entities[static_cast<std::size_t>(r)].id);
  double sum = 0.0;
  if (const Json* recs = check.array(answer, "", "receptacles", true, 500))
    for (std::size_t i = 0; i < recs->size(); ++i) {
      const std::string ptr = "/receptacles/" + std::to_string(i);
      const std::string id = (*recs)[i].value("receptacle_id", "");
      if (!ids.count(id))
        check.add(ptr + "/receptacle_id", "'" + id + "' is not a receptacle of this home");
      else if (!seen.insert(id).second)
        check.add(ptr + "/receptacle_id", "'" + id + "' is listed twice");
      sum += (*recs)[i].value("p", 0.0);
    }
  if (check.ok() && std::abs(sum - 1.0) > 0.02)
    check.add("/receptacles", "probabilities must sum to 1, not " + std::to_string(sum));
  return with_errors(check, "hint interpretation does not fit");
}

}  // namespace socsim::household
