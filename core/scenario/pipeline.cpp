#include "core/scenario/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "core/common/json_check.hpp"
#include "core/common/sha256.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/floorplan/llm.hpp"
#include "core/floorplan/request.hpp"
#include "core/floorplan/rooms.hpp"
#include "core/scenario/intent_check.hpp"
#include "core/scenario/intent_world.hpp"
#include "core/scenario/offline_tree.hpp"
#include "core/scenario/program_llm.hpp"
#include "core/scenario/scenario_intent.hpp"
#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"

namespace socsim::scenario {
namespace {

constexpr std::int64_t kMaxSeed = (std::int64_t{1} << 53) - 1;  // exact in JSON numbers
constexpr std::size_t kPerAgentMetricsUpTo = 200;

std::string short_title(const std::string& prompt) {
  std::string t = prompt.substr(0, 120);
  if (prompt.size() > 120) {
    // Cut at a word boundary and never inside a UTF-8 sequence.
    auto cut = t.find_last_of(' ');
    if (cut != std::string::npos && cut > 40) t.resize(cut);
    while (!t.empty() && (static_cast<unsigned char>(t.back()) & 0xC0) == 0x80) t.pop_back();
    if (!t.empty() && (static_cast<unsigned char>(t.back()) & 0x80)) t.pop_back();
    t += "…";
  }
  return t;
}

std::string hex_of_values(std::span<const crowd::Vec2> values) {
  std::string bytes;
  bytes.reserve(values.size() * 16);
  for (const auto& v : values) {
    char b[16];
    std::memcpy(b, &v.x, 8);
    std::memcpy(b + 8, &v.y, 8);
    bytes.append(b, 16);
  }
  return sha256_hex(bytes);
}

// Aggregates for the card: the whole crowd, per role, and per agent for small scenarios.
Json metrics_json(const crowd::RunMetrics& m) {
  struct Sum {
    std::size_t n = 0, reached = 0;
    double time_to_goal = 0, path = 0, min_dist = 1e9, intimate = 0, personal = 0, not_moving = 0, speed = 0;
    std::uint64_t collisions = 0;
    void add(const crowd::AgentMetrics& a) {
      ++n;
      if (a.time_to_reach_goal) {
        ++reached;
        time_to_goal += *a.time_to_reach_goal;
      }
      path += a.path_length;
      min_dist = std::min(min_dist, a.minimum_distance_to_people);
      intimate += a.intimate_space_intrusions;
      personal += a.personal_space_intrusions;
      not_moving += a.time_not_moving;
      speed += a.avg_linear_speed;
      collisions += a.collisions;
    }
    [[nodiscard]] Json json() const {
      const double k = n ? 1.0 / static_cast<double>(n) : 0.0;
      return Json{{"agents", n},
                  {"goal_reached", reached},
                  {"mean_time_to_reach_goal",
                   reached ? Json(time_to_goal / static_cast<double>(reached)) : Json(nullptr)},
                  {"mean_path_length", path * k},
                  {"minimum_distance_to_people", n ? Json(min_dist) : Json(nullptr)},
                  {"mean_intimate_space_intrusions", intimate * k},
                  {"mean_personal_space_intrusions", personal * k},
                  {"mean_time_not_moving", not_moving * k},
                  {"mean_linear_speed", speed * k},
                  {"collisions", collisions}};
    }
  };
  Sum all;
  std::map<std::string, Sum> by_role;
  for (const auto& a : m.agents) {
    all.add(a);
    by_role[a.role].add(a);
  }
  Json roles = Json::object();
  for (const auto& [role, s] : by_role) roles[role] = s.json();
  Json j = {{"duration", m.duration},         {"frames", m.frames},
            {"frame_period", m.frame_period}, {"avg_pedestrian_velocity", m.avg_pedestrian_velocity},
            {"summary", all.json()},          {"by_role", std::move(roles)}};
  if (m.agents.size() <= kPerAgentMetricsUpTo) {
    Json agents = Json::array();
    for (const auto& a : m.agents) agents.push_back(crowd::to_json(a));
    j["agents"] = std::move(agents);
  }
  if (m.robot) j["robot"] = crowd::to_json(*m.robot);
  return j;
}

std::string describe_program(const Json& program) {
  std::map<std::string, std::size_t> roles;
  std::size_t spotlight = 0, ambient = 0;
  for (const auto& a : program.value("agents", Json::array())) {
    const auto n = a.value("count", std::size_t{1});
    spotlight += n;
    roles[a.value("role", std::string("adult"))] += n;
  }
  const auto groups = program.value("ambient_groups", Json::array());
  for (const auto& g : groups) ambient += g.value("size", std::size_t{0});
  std::string text = std::to_string(spotlight) + " spotlight agent" + (spotlight == 1 ? "" : "s");
  if (!roles.empty()) {
    text += " (";
    bool first = true;
    for (const auto& [role, n] : roles) {
      text += (first ? "" : ", ") + std::to_string(n) + " " + role;
      first = false;
    }
    text += ")";
  }
  text += " and " + std::to_string(ambient) + " ambient pedestrians in " + std::to_string(groups.size()) +
          " group" + (groups.size() == 1 ? "" : "s");
  for (const auto& g : groups)
    if (!g.value("description", std::string()).empty()) text += "; " + g.value("description", std::string());
  return text + ".";
}

// Floor area a generated plan gives each person the prompt counts, over its rooms with a typical
// size: the offline planner places at most 0.8 people per m² of a room's floor 0.35 m in from its
// walls (about 70 % of a generated room's area), and an activity fills its own rooms first.
constexpr double kAreaPerNamedPerson = 2.3;

// How much the rooms of a prompt's programme must grow, all by one factor, to hold the people the
// prompt counts ("2,000 fans", "600 shoppers"); 1 when their typical sizes hold them. Toilets and
// corridors (sized by the generator) do not count.
double growth_for_people(const floorplan::SceneGraph& graph, std::size_t people, double& typical) {
  typical = 0.0;
  for (const floorplan::SceneRoom& r : graph.rooms) {
    const auto* type = floorplan::find_room_type(r.type);
    if (floorplan::is_toilet_type(r.type) || (!r.area && (!type || type->area_hi <= 0))) continue;
    typical += r.area ? *r.area : (type->area_lo + type->area_hi) / 2.0;
  }
  const double needed = static_cast<double>(people) * kAreaPerNamedPerson;
  return typical > 0.0 && typical < needed ? needed / typical : 1.0;
}

// The programme with those rooms grown by `factor` (they keep their proportions, the generator
// its layout rules).
floorplan::SceneGraph grown(floorplan::SceneGraph graph, double factor) {
  constexpr double kMaxRoomArea = 5000.0;  // schemas/scene_graph.schema.json
  if (factor <= 1.0) return graph;
  for (floorplan::SceneRoom& r : graph.rooms) {
    const auto* type = floorplan::find_room_type(r.type);
    if (floorplan::is_toilet_type(r.type) || (!r.area && (!type || type->area_hi <= 0))) continue;
    const double a = r.area ? *r.area : (type->area_lo + type->area_hi) / 2.0;
    r.area = std::min(kMaxRoomArea, std::round(a * factor));
  }
  return graph;
}

}  // namespace

Result<ScenarioRequest> scenario_request_from_json(const Json& body, const ScenarioConfig& config) {
  JsonChecker c;
  if (!body.is_object())
    return fail(ErrorCode::kValidation, "the request must be a JSON object", {{"", "expected an object"}});
  c.only_keys(body, "",
              {"prompt", "world", "world_id", "scene_graph", "domain", "seed", "generator", "model",
               "duration_s", "agents", "title", "tags"});
  ScenarioRequest r;
  r.prompt = c.string(body, "", "prompt", true, 1, config.max_prompt_bytes).value_or("");
  int sources = 0;
  if (body.contains("world")) {
    ++sources;
    if (!body["world"].is_object() && !body["world"].is_string())
      c.add("/world", "must be a world document (object) or world.yaml text (string)");
    else
      r.world = body["world"];
  }
  if (auto id = c.string(body, "", "world_id", false, 1, 64)) {
    ++sources;
    r.world_id = *id;
  }
  if (const Json* g = c.object(body, "", "scene_graph", false)) {
    ++sources;
    r.scene_graph = *g;
  }
  if (sources > 1) c.add("", "give at most one of world, world_id and scene_graph");
  if (auto d = c.string(body, "", "domain", false, 1, 64)) {
    if (!knowledge::is_building_type(*d))
      c.add("/domain", "not a building type: '" + *d + "'");
    else
      r.domain = *d;
  }
  r.seed = static_cast<std::uint64_t>(c.integer(body, "", "seed", false, 0, kMaxSeed).value_or(0));
  r.generator = c.string(body, "", "generator", false, 1, 16).value_or("offline");
  if (r.generator != "offline" && r.generator != "llm") c.add("/generator", "must be 'offline' or 'llm'");
  if (auto m = c.string(body, "", "model", false, 1, 128)) {
    if (r.generator != "llm") c.add("/model", "a model is only used with generator 'llm'");
    r.model = *m;
  }
  r.duration_s = c.number(body, "", "duration_s", false, 1.0, config.limits.max_duration_s)
                     .value_or(std::min(60.0, config.limits.max_duration_s));
  if (auto n = c.integer(body, "", "agents", false, 1, static_cast<std::int64_t>(config.limits.max_agents)))
    r.agents = static_cast<std::size_t>(*n);
  r.title = c.string(body, "", "title", false, 0, 200).value_or("");
  if (const Json* tags = c.array(body, "", "tags", false, 32)) {
    for (std::size_t i = 0; i < tags->size(); ++i) {
      const Json& t = (*tags)[i];
      if (!t.is_string() || t.get<std::string>().empty() || t.get<std::string>().size() > 64)
        c.add("/tags/" + std::to_string(i), "must be a string of 1 to 64 bytes");
      else
        r.tags.push_back(t.get<std::string>());
    }
  }
  if (!c.ok()) return tl::unexpected(c.error("the scenario request is not valid"));
  return r;
}

Result<ScenarioWorld> world_for_request(const ScenarioRequest& request,
                                        const knowledge::KnowledgeBase& knowledge,
                                        const llm::StructuredGenerator* llm,
                                        const std::optional<std::string>& job_id,
                                        const llm::CancelToken& cancel) {
  Json fp = {{"seed", request.seed}, {"generator", request.generator}};
  if (request.scene_graph)
    fp["scene_graph"] = *request.scene_graph;
  else
    fp["prompt"] = request.prompt;
  // The venue the prompt names ("train station", "library") decides the building type, by the
  // nearest type the floor-plan generator knows; a given domain or scene graph wins.
  Json venue = nullptr;
  auto intent = interpret_prompt(request.prompt);
  if (!intent) return tl::unexpected(intent.error());
  if (request.domain) {
    fp["domain"] = *request.domain;
  } else if (!request.scene_graph) {
    if (intent->venue) {
      fp["domain"] = intent->venue->building_type;
      venue = Json{{"type", intent->venue->type},
                   {"building_type", intent->venue->building_type},
                   {"words", intent->venue->words},
                   {"why", intent->venue->why}};
    }
  }
  if (request.model) fp["model"] = *request.model;
  auto fpr = floorplan::floor_plan_request_from_json(fp);
  if (!fpr) return tl::unexpected(fpr.error());
  // What the prompt asks the world to hold (counted features, named rooms and objects, its people).
  const world::WorldRequirements requirements = world_requirements(*intent);
  // The generator builds them (core/floorplan): a counted exit is a minimum the building code may
  // raise for the occupant load (docs/worlds.md, "Exits asked for and exits required").
  fpr->requirements = requirements;
  auto resolved = floorplan::resolve_scene_graph(*fpr);
  Json programme_fallback = nullptr;
  if (!resolved && resolved.error().code == ErrorCode::kValidation && !request.scene_graph && fpr->domain) {
    // The floor-plan reader refused the prompt's rooms (it read "35 office workers" as 35
    // offices, more than a plan holds): the building type's usual programme still gives a world.
    programme_fallback =
        Json{{"why", resolved.error().message()}, {"programme", "the usual rooms of a " + *fpr->domain}};
    resolved = floorplan::ResolvedSceneGraph{floorplan::room_program(*fpr->domain),
                                             Json{{"given", false}, {"type", *fpr->domain}}};
  }
  if (!resolved) return tl::unexpected(resolved.error());
  // A plan laid out from the prompt grows to hold the people it counts. The building code check of
  // the offline generator may refuse a grown plan (exit width for its occupant load): then it
  // grows less, and at worst keeps its typical sizes (the program notes who did not fit).
  // (No more than the agents a scenario may hold: a crowd beyond them is scaled down anyway.)
  const std::size_t people =
      std::min(people_named(*intent), request.agents.value_or(ScenarioLimits{}.max_agents));
  double typical_area = 0.0;
  const double growth = request.scene_graph ? 1.0 : growth_for_people(resolved->graph, people, typical_area);
  Json sized = nullptr;
  auto constraints = knowledge.constraints_for(resolved->graph.domain);
  if (!constraints) return tl::unexpected(constraints.error());
  Result<floorplan::FloorPlan> plan = fail(ErrorCode::kInternal, "no floor plan");
  if (request.generator == "llm" && llm) {
    floorplan::LlmFloorPlanOptions o;
    o.model = request.model;
    o.seed = static_cast<std::int64_t>(request.seed);
    o.job_id = job_id;
    o.cancel = cancel;
    plan = floorplan::generate_floor_plan_llm(*llm, request.prompt, resolved->graph, *constraints, o);
  } else {
    floorplan::OfflineOptions o;
    o.seed = request.seed;
    o.requirements = fpr->requirements;
    std::vector<double> factors{growth};
    if (growth > 1.0) factors.insert(factors.end(), {std::sqrt(growth), 1.0});
    std::string refused;  // why the larger plan was not built
    for (const double f : factors) {
      // A grown plan the code check refuses is refused at every attempt (its exits do not grow
      // with it): two attempts tell, and large plans are slow to build.
      floorplan::OfflineOptions attempt = o;
      if (f > 1.0) attempt.max_attempts = std::min(o.max_attempts, 2);
      plan = floorplan::generate_floor_plan(grown(resolved->graph, f), *constraints, attempt);
      if (growth > 1.0)
        sized =
            Json{{"people", people},
                 {"typical_area_m2", std::round(typical_area)},
                 {"factor_wanted", std::round(growth * 100.0) / 100.0},
                 {"factor", std::round(f * 100.0) / 100.0},
                 {"why", "rooms grown to hold the " + std::to_string(people) + " people the prompt counts (" +
                             format_number(kAreaPerNamedPerson) + " m² of room each)" +
                             (refused.empty() ? "" : "; less than wanted: " + refused)}};
      if (plan || plan.error().code != ErrorCode::kValidation) break;
      refused = "the larger plan failed the generator's code check (" + plan.error().message() + ")";
    }
  }
  if (!plan) return tl::unexpected(plan.error());
  plan->provenance["classification"] = resolved->classification;
  plan->provenance["compliance_passed"] = plan->compliance.passed;
  if (!venue.is_null()) plan->provenance["venue"] = venue;
  if (!sized.is_null()) plan->provenance["sized_for_people"] = sized;
  if (!programme_fallback.is_null()) plan->provenance["programme_fallback"] = programme_fallback;
  plan->provenance["intent_requirements"] =
      Json{{"requirements", world::to_json(requirements)}, {"passed_to_generator", true}};
  return ScenarioWorld{std::move(plan->world), resolved->graph.domain, std::move(plan->provenance),
                       requirements};
}

Result<SimulationOutput> simulate_program(const world::World& world, const Json& program_json,
                                          std::uint64_t seed, double duration_s, double frame_interval,
                                          const ProgressFn& progress, const llm::CancelToken& cancel) {
  auto program = crowd::program_from_json(program_json);
  if (!program) return tl::unexpected(program.error());
  return simulate_program(world, *program, seed, duration_s, frame_interval, progress, cancel);
}

Result<SimulationOutput> simulate_program(const world::World& world, const crowd::Program& program,
                                          std::uint64_t seed, double duration_s, double frame_interval,
                                          const ProgressFn& progress, const llm::CancelToken& cancel) {
  crowd::RunnerOptions options;
  options.seed = seed;
  options.threads = 1;
  auto runner = crowd::ScenarioRunner::create(&world, program, options);
  if (!runner) return tl::unexpected(runner.error());
  auto& r = **runner;
  const double dt = program.dt;
  const auto every = static_cast<std::uint64_t>(std::max(1.0, std::round(frame_interval / dt)));
  const auto total = static_cast<std::uint64_t>(std::ceil(duration_s / dt - 1e-9));
  TrajectoryRecorder recorder(static_cast<double>(every) * dt);
  {
    const auto states = r.states();
    recorder.add(r.time(), states);
  }
  const std::uint64_t report_every = std::max<std::uint64_t>(1, total / 50);
  for (std::uint64_t k = 1; k <= total; ++k) {
    r.step();
    if (k % every == 0) {
      const auto states = r.states();
      recorder.add(r.time(), states);
    }
    if (k % report_every == 0) {
      if (cancel.cancelled()) return fail(ErrorCode::kCancelled, "the simulation was cancelled");
      if (progress)
        progress(static_cast<double>(k) / static_cast<double>(total),
                 "simulating: " + std::to_string(static_cast<int>(r.time())) + " of " +
                     std::to_string(static_cast<int>(duration_s)) + " s");
    }
  }
  SimulationOutput out;
  out.log = std::move(recorder).finish();
  out.metrics = metrics_json(r.metrics());
  out.runtime_errors = r.errors();
  out.velocity_fields = Json::array();
  for (const auto& g : program.ambient_groups) {
    const auto* entry = r.environment().velocity_field(g.name);
    if (!entry) continue;
    const auto& f = entry->field;
    out.velocity_fields.push_back(
        {{"group", g.name},
         {"width", f.width()},
         {"height", f.height()},
         {"bounds", {f.bounds().min.x, f.bounds().min.y, f.bounds().max.x, f.bounds().max.y}},
         {"source", g.field ? "supplied" : "geodesic"},
         {"variation", g.variation},
         {"sha256", hex_of_values(f.values())}});
  }
  return out;
}

Result<ScenarioOutcome> run_scenario(const ScenarioRequest& request, std::optional<ScenarioWorld> world,
                                     const ScenarioServices& s) {
  auto report = [&](double f, const std::string& m) {
    if (s.progress) s.progress(f, m);
  };
  if (request.generator == "llm" && !s.llm)
    return fail(ErrorCode::kValidation,
                "no LLM endpoint is configured, so only the offline generator is available",
                {{"/generator", "must be offline on this server"}});
  if (!world) {
    report(0.02,
           "laying out a floor plan from the " + std::string(request.scene_graph ? "scene graph" : "prompt"));
    auto made = world_for_request(request, s.knowledge, s.llm, s.job_id, s.cancel);
    if (!made) return tl::unexpected(made.error());
    world = std::move(*made);
  }
  if (s.cancel.cancelled()) return fail(ErrorCode::kCancelled, "the scenario was cancelled");

  // What the prompt says: the card stores it, and the program is read against it.
  auto understood = interpret_prompt(request.prompt);
  if (!understood) return tl::unexpected(understood.error());
  const ScenarioIntent& intent = *understood;

  report(0.1, "writing the scenario program (" + request.generator + ")");
  ProgramRequest pr;
  pr.prompt = request.prompt;
  pr.seed = request.seed;
  pr.agents = request.agents;
  pr.duration_s = request.duration_s;
  Result<GeneratedProgram> generated = fail(ErrorCode::kInternal, "no program");
  if (request.generator == "llm") {
    LlmProgramOptions o;
    o.model = request.model;
    o.job_id = s.job_id;
    o.cancel = s.cancel;
    generated = generate_program_llm(*s.llm, world->world, s.knowledge, pr, s.config.limits, o);
  } else {
    generated = generate_program_offline(world->world, s.knowledge, pr, s.config.limits);
  }
  if (!generated) return tl::unexpected(generated.error());
  // Both generators return their program checked against this world (check_program) and parsed.

  report(0.2, "simulating " + std::to_string(static_cast<int>(request.duration_s)) + " s");
  auto sim = simulate_program(
      world->world, generated->checked, request.seed, request.duration_s, s.config.frame_interval,
      [&](double f, const std::string& m) { report(0.2 + 0.75 * f, m); }, s.cancel);
  if (!sim) return tl::unexpected(sim.error());

  ScenarioOutcome out;
  auto& c = out.card;
  c.title = request.title.empty() ? short_title(request.prompt) : request.title;
  c.description = describe_program(generated->program);
  // Every group the prompt did not name is listed with the reason it is there.
  const Json added = generated->provenance.contains("added_groups")
                         ? generated->provenance["added_groups"]
                         : added_groups(generated->program, intent, generated->categories, world->domain);
  for (const Json& g : added)
    c.description += " Added: " + std::to_string(g.value("count", 0)) + " " + g.value("role", std::string()) +
                     " (" + g.value("why", std::string()) + ").";
  // People the prompt asked for that the program could not hold (the agents cap, the building) are
  // said on the card.
  for (const auto& note : generated->provenance.value("notes", Json::array())) {
    if (!note.is_string()) continue;
    const std::string n = note.get<std::string>();
    if (n.find("fit") != std::string::npos || n.find("scaled down") != std::string::npos ||
        n.find("left out") != std::string::npos || n.find("cut in proportion") != std::string::npos)
      c.description += " " + n + ".";
  }
  c.prompt = request.prompt;
  c.intent = to_json(intent);
  c.seed = request.seed;
  c.generator.name = request.generator;
  if (request.generator == "llm") {
    const Json llm_prov = generated->provenance.value("llm", Json::object());
    if (llm_prov.contains("model") && llm_prov["model"].is_string())
      c.generator.model = llm_prov["model"].get<std::string>();
  }
  c.domain = world->domain.empty() ? std::optional<std::string>() : world->domain;
  std::vector<std::string> tags = request.tags;
  tags.push_back("scenario");
  for (const auto& cat : generated->categories) tags.push_back(cat);
  if (!world->domain.empty()) tags.push_back(world->domain);
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  if (tags.size() > 32) tags.resize(32);
  c.tags = std::move(tags);
  c.world = world::world_to_document(world->world);
  c.program = generated->program;
  c.metrics = sim->metrics;
  const std::string sha = sim->log.sha256();
  c.trajectory_log = {{"uri", "/api/v1/trajectories/" + sha},
                      {"format", kTrajectoryFormat},
                      {"frames", sim->log.frame_count()},
                      {"rate_hz", 1.0 / sim->log.frame_interval()},
                      {"agents", sim->log.agent_count()},
                      {"duration_s", request.duration_s},
                      {"sha256", sha}};
  c.provenance = {
      {"program", generated->provenance},
      {"world", world->provenance},
      {"categories", generated->categories},
      {"velocity_fields", sim->velocity_fields},
      {"simulation",
       {{"duration_s", request.duration_s}, {"threads", 1}, {"dt", generated->program.value("dt", 0.05)}}},
      {"runtime_errors", sim->runtime_errors}};
  if (request.world_id) c.provenance["world_id"] = *request.world_id;
  out.world_name = world->world.name();
  out.log = std::move(sim->log);
  report(1.0, "done");
  return out;
}

Result<SimulationOutput> replay_card(const cards::CardContent& card, const ProgressFn& progress,
                                     const llm::CancelToken& cancel) {
  if (!card.world.is_object() || !card.program.is_object() || !card.trajectory_log.is_object())
    return fail(ErrorCode::kValidation, "the card has no world, program or trajectory log to replay",
                {{"/trajectory_log", "a scenario card made by POST /api/v1/scenarios is needed"}});
  auto world = world::world_from_document(card.world);
  if (!world) return tl::unexpected(world.error());
  const double duration = card.trajectory_log.value("duration_s", 0.0);
  const double rate = card.trajectory_log.value("rate_hz", 10.0);
  const double interval = rate > 0 ? 1.0 / rate : 0.0;
  if (!(duration > 0) || !(interval > 0))
    return fail(ErrorCode::kValidation, "the card's trajectory log names no duration",
                {{"/trajectory_log/duration_s", "must be a positive number"}});
  return simulate_program(*world, card.program, card.seed, duration, interval, progress, cancel);
}

}  // namespace socsim::scenario
