#include "core/scenario/program_llm.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/common/json_schema.hpp"
#include "core/geometry/planar.hpp"
#include "core/scenario/intent_check.hpp"
#include "core/scenario/lexicon.hpp"
#include "core/scenario/program_check.hpp"

namespace socsim::scenario {

const std::map<std::string, std::string>& embedded_scenario_schemas();

namespace {

const JsonSchema& answer_schema() {
  static const JsonSchema schema = [] {
    const auto& files = embedded_scenario_schemas();
    auto it = files.find("scenario_program.schema.json");
    if (it == files.end()) throw std::logic_error("scenario_program.schema.json is not embedded");
    auto parsed = parse_json_untrusted(it->second);
    if (!parsed)
      throw std::logic_error("embedded scenario_program.schema.json is not JSON: " +
                             parsed.error().message());
    auto compiled = JsonSchema::compile(std::move(*parsed));
    if (!compiled)
      throw std::logic_error("embedded scenario_program.schema.json: " + compiled.error().message());
    return std::move(*compiled);
  }();
  return schema;
}

std::string fixed1(double v) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);
  s << v;
  return s.str();
}

// Nodes every scenario may need, offered whatever the retrieval ranked first.
constexpr const char* kBaseNodes[] = {"RegularNav", "WaitAt", "Wander", "StopAndWait"};

std::string node_line(const knowledge::BehaviorNode& n) {
  std::string ports;
  for (const auto& p : n.ports) {
    if (!ports.empty()) ports += ", ";
    ports += p.name + ":" + p.type;
    if (p.default_value) ports += "=" + *p.default_value;
  }
  std::string line = "- " + n.name + " (" + std::string(knowledge::to_string(n.kind)) +
                     "; ports: " + (ports.empty() ? "none" : ports) + "): " + n.description;
  if (!n.when_to_use.empty()) line += " When to use: " + n.when_to_use;
  if (!n.example.empty()) line += " Example: " + n.example;
  return line;
}

// Program pointer → answer pointer (the compilation is one entry to one entry).
std::string answer_pointer(const std::string& p) {
  auto token = [&](std::size_t from) {
    const auto end = p.find('/', from);
    return std::pair{p.substr(from, end == std::string::npos ? std::string::npos : end - from), end};
  };
  if (p.rfind("/agents/", 0) == 0) {
    auto [index, end] = token(8);
    const std::string base = "/spotlight_agents/" + index;
    if (end == std::string::npos) return base;
    const std::string field = token(end + 1).first;
    if (field == "spawn") return base + "/spawn_roi";
    if (field == "behavior") return base + "/behavior_tree";
    if (field == "count" || field == "speed" || field == "group_id") return base + "/parameters/" + field;
    if (field == "role") return base + "/role";
    return base;
  }
  if (p.rfind("/ambient_groups/", 0) == 0) {
    auto [index, end] = token(16);
    const std::string base = "/ambient_groups/" + index;
    if (end == std::string::npos) return base;
    const std::string field = token(end + 1).first;
    if (field == "start") return base + "/start_roi";
    if (field == "goal") return base + "/goal_roi";
    if (field == "size" || field == "speed" || field == "role" || field == "description" || field == "name")
      return base + "/" + field;
    return base;
  }
  return "";
}

constexpr std::string_view kContradicts = "contradicts the prompt: ";

// The intent's contradictions with pointers into the answer and the words that say so.
std::vector<FieldError> answer_contradictions(const Json& program, const ScenarioIntent& intent,
                                              std::size_t bound) {
  std::vector<FieldError> out = intent_contradictions(program, intent, bound);
  for (FieldError& f : out) {
    f.pointer = answer_pointer(f.pointer);
    f.message = std::string(kContradicts) + f.message;
  }
  return out;
}

}  // namespace

std::string world_places_text(const world::World& world) {
  std::ostringstream out;
  for (const auto& z : world.zones())
    out << "zone " << z.name << " (" << z.type << ", " << fixed1(geometry::area(z.polygon)) << " m2)\n";
  for (const auto& d : world.doors()) {
    out << "door " << d.name << " (" << fixed1(d.width) << " m wide) between " << world.zone(d.zone).name
        << " and " << (d.other ? world.zone(*d.other).name : std::string("outside")) << "\n";
  }
  for (const auto& r : world.rois())
    out << "ROI " << r.name << " (" << r.kind << ", " << fixed1(geometry::area(r.polygon)) << " m2)\n";
  for (const auto& e : world.entities()) {
    out << "POI " << e.name << " (" << e.type << " in " << world.zone(e.zone).name;
    if (!e.affordances.empty()) {
      out << "; affords";
      for (const auto& a : e.affordances) out << " " << a;
    }
    out << ")\n";
  }
  return out.str();
}

Json program_from_answer(const Json& answer, const ProgramRequest& request) {
  Json agents = Json::array();
  for (const auto& a : answer.value("spotlight_agents", Json::array())) {
    Json agent = {{"name", a.value("id", "")},
                  {"role", a.value("role", "adult")},
                  {"spawn", a.value("spawn_roi", "")},
                  {"behavior", {{"xml", a.value("behavior_tree", "")}}}};
    const Json params = a.value("parameters", Json::object());
    if (params.contains("count")) agent["count"] = params["count"];
    if (params.contains("speed")) agent["speed"] = params["speed"];
    if (params.contains("group_id")) agent["group_id"] = params["group_id"];
    if (params.contains("description")) agent["tags"] = Json::array({params["description"]});
    agents.push_back(std::move(agent));
  }
  Json groups = Json::array();
  for (const auto& g : answer.value("ambient_groups", Json::array())) {
    Json group = {{"name", g.value("name", "")},
                  {"description", g.value("description", "")},
                  {"start", Json::array({g.value("start_roi", "")})},
                  {"goal", Json::array({g.value("goal_roi", "")})},
                  {"size", g.value("size", 0)},
                  {"speed", g.value("speed", 1.34)},
                  {"variation", 0.15},
                  {"on_arrival", "exit"}};
    if (g.contains("role")) group["role"] = g["role"];
    groups.push_back(std::move(group));
  }
  // Roles the engine does not know take the lexicon's profile (nurse, visitor, …) or adult's.
  Json roles = Json::object();
  auto define = [&](const Json& entry) {
    const std::string role = entry.value("role", std::string("adult"));
    if (role.empty() || is_builtin_role(role) || roles.contains(role)) return;
    Json r = Json::object();
    if (auto p = role_profile(role))
      r = {{"speed", {{"mean", p->mean}, {"sd", p->sd}, {"min", p->min}, {"max", p->max}}},
           {"radius", p->radius}};
    roles[role] = std::move(r);
  };
  for (const auto& a : agents) define(a);
  for (const auto& g : groups) define(g);
  std::string name = request.prompt.substr(0, 200);
  return Json{{"version", 1},
              {"name", name},
              {"dt", 0.05},
              {"decision_period", 0.1},
              {"roles", std::move(roles)},
              {"agents", std::move(agents)},
              {"ambient_groups", std::move(groups)}};
}

namespace {

struct CheckedAnswer {
  Json program;
  crowd::Program checked;
};

Result<CheckedAnswer> check_answer(const Json& answer, const world::World& world,
                                   const ProgramRequest& request, const ScenarioLimits& limits) {
  // Unique ids, so that errors and trajectories name agents unambiguously.
  std::vector<FieldError> errors;
  std::set<std::string> ids;
  const Json agents = answer.value("spotlight_agents", Json::array());
  for (std::size_t i = 0; i < agents.size(); ++i)
    if (!ids.insert(agents[i].value("id", "")).second)
      errors.push_back({"/spotlight_agents/" + std::to_string(i) + "/id", "id is used by another agent"});
  Json program = program_from_answer(answer, request);
  auto checked = checked_program(program, world, limits);
  if (!checked) {
    for (auto e : checked.error().errors) {
      e.pointer = answer_pointer(e.pointer);
      errors.push_back(std::move(e));
    }
    if (errors.empty()) errors.push_back({"", checked.error().detail});
  }
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "the scenario program does not fit the world", std::move(errors));
  return CheckedAnswer{std::move(program), std::move(*checked)};
}

}  // namespace

Result<Json> checked_program_from_answer(const Json& answer, const world::World& world,
                                         const ProgramRequest& request, const ScenarioLimits& limits) {
  auto checked = check_answer(answer, world, request, limits);
  if (!checked) return tl::unexpected(checked.error());
  return std::move(checked->program);
}

Result<GeneratedProgram> generate_program_llm(const llm::StructuredGenerator& generator,
                                              const world::World& world,
                                              const knowledge::KnowledgeBase& knowledge,
                                              const ProgramRequest& request, const ScenarioLimits& limits,
                                              const LlmProgramOptions& options) {
  auto hits = knowledge.search(request.prompt, knowledge::Kind::kBehaviorNode, options.retrieved_nodes);
  if (!hits) return tl::unexpected(hits.error());
  std::vector<knowledge::BehaviorNode> nodes;
  std::set<std::string> seen;
  Json retrieved = Json::array();
  for (const auto& h : hits->hits) {
    const auto& node = std::get<knowledge::BehaviorNode>(h.entry);
    if (seen.insert(node.name).second) nodes.push_back(node);
    retrieved.push_back(knowledge::to_json(h.provenance));
  }
  for (const char* base : kBaseNodes) {
    if (seen.count(base)) continue;
    if (auto node = knowledge.behavior_node(base)) {
      seen.insert(node->name);
      nodes.push_back(std::move(*node));
    }
  }
  std::string node_text;
  for (const auto& n : nodes) node_text += node_line(n) + "\n";

  const std::size_t max_agents =
      request.agents ? std::min(*request.agents, limits.max_agents) : limits.max_agents;
  const std::string limits_text = "at most " + std::to_string(max_agents) +
                                  " people in total (spotlight counts plus ambient group sizes), at most " +
                                  std::to_string(limits.max_spotlight) +
                                  " spotlight agents; the scenario runs for " + fixed1(request.duration_s) +
                                  " s";

  llm::GenerationRequest r;
  r.artifact = "scenario_program";
  r.variables = {{"prompt", request.prompt},
                 {"world", world_places_text(world)},
                 {"behavior_nodes", node_text},
                 {"limits", limits_text}};
  r.schema = &answer_schema();
  // The prompt's explicit facts (who, how many; nobody else when it names who is there) are
  // checked like the world's places: a contradiction is quoted back in the repair round.
  auto intent = interpret_prompt(request.prompt);
  if (!intent) return tl::unexpected(intent.error());
  const std::size_t bound = std::min(limits.max_agents, request.agents.value_or(limits.max_agents));
  std::vector<FieldError> contradictions;                  // of the last answer that fitted the world
  std::optional<std::pair<Json, CheckedAnswer>> accepted;  // the last answer that passed, checked
  r.check = [&](const Json& answer) -> Status {
    auto program = check_answer(answer, world, request, limits);
    if (!program) return tl::unexpected(program.error());
    contradictions = answer_contradictions(program->program, *intent, bound);
    if (!contradictions.empty())
      return fail(ErrorCode::kValidation, "the scenario program contradicts the prompt", contradictions);
    accepted.emplace(answer, std::move(*program));
    return {};
  };
  r.model = options.model;
  r.temperature = options.temperature;
  r.seed = static_cast<std::int64_t>(request.seed & ((std::uint64_t{1} << 53) - 1));
  r.job_id = options.job_id;
  r.repair_rounds = options.repair_rounds;
  r.cancel = options.cancel;
  auto g = generator.generate(r);
  if (!g) {
    Error e = g.error();
    if (e.code == ErrorCode::kValidation && !contradictions.empty() &&
        std::any_of(e.errors.begin(), e.errors.end(),
                    [&](const FieldError& f) { return f.message.find(kContradicts) != std::string::npos; }))
      e.detail = "the LLM's scenario program still contradicts the prompt after its repair: " + e.detail;
    return tl::unexpected(std::move(e));
  }
  // The answer the generator returns is the one its check accepted last (checked again only if not).
  if (!accepted || accepted->first != g->value) {
    auto program = check_answer(g->value, world, request, limits);
    if (!program) return tl::unexpected(program.error());
    accepted.emplace(g->value, std::move(*program));
  }
  GeneratedProgram out;
  out.program = std::move(accepted->second.program);
  out.checked = std::move(accepted->second.checked);
  out.provenance = {{"generator", "llm"},
                    {"llm", g->provenance()},
                    {"answer", g->value},
                    {"intent_check", {{"contradictions", 0}, {"bound", bound}}},
                    {"knowledge", std::move(retrieved)},
                    {"offered_nodes", Json(std::vector<std::string>(seen.begin(), seen.end()))}};
  return out;
}

}  // namespace socsim::scenario
