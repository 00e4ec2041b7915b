#include "core/floorplan/llm.hpp"

#include <cstdio>
#include <map>
#include <set>

#include "core/common/rng.hpp"
#include "core/common/text.hpp"
#include "core/floorplan/furnish.hpp"
#include "core/floorplan/rooms.hpp"
#include "core/floorplan/schemas.hpp"

namespace socsim::floorplan {
namespace {

using knowledge::MergedConstraint;

// Builder pointers (/zones/3/polygon, /doors/1/pose) as pointers into the answer.
std::string answer_pointer(const std::string& p) {
  auto replace_prefix = [&](const std::string& from, const std::string& to) -> std::optional<std::string> {
    if (p.rfind(from, 0) != 0) return std::nullopt;
    return to + p.substr(from.size());
  };
  if (auto r = replace_prefix("/zones", "/rooms")) return *r;
  if (p.rfind("/doors/", 0) == 0) {
    std::string out = p;
    for (auto [from, to] : {std::pair{"/pose", "/position"}, std::pair{"/connects", "/rooms"}}) {
      const auto at = out.find(from);
      if (at != std::string::npos) out = out.substr(0, at) + to + out.substr(at + std::string(from).size());
    }
    return out;
  }
  return "";
}

}  // namespace

llm::PromptVariables floor_plan_prompt_variables(std::string_view prompt, const SceneGraph& graph,
                                                 std::span<const MergedConstraint> constraints) {
  std::string lines;
  for (const auto& c : constraints) lines += "- " + knowledge::describe(c) + "\n";
  if (lines.empty()) lines = "(no building-code constraints are stored for this building type)\n";
  return {{"prompt", prompt.empty() ? std::string("(none: lay out the scene graph)") : std::string(prompt)},
          {"building_type", graph.domain},
          {"scene_graph", to_json(graph).dump(2)},
          {"constraints", lines}};
}

Result<FloorPlan> floor_plan_from_answer(const Json& answer, const SceneGraph& graph,
                                         std::span<const MergedConstraint> constraints,
                                         const BuildOptions& build) {
  if (auto errors = floor_plan_schema().validate(answer, 50); !errors.empty())
    return fail(ErrorCode::kValidation, "the floor plan does not match its schema", std::move(errors));
  std::vector<FieldError> errors;
  std::vector<Zone> zones;
  std::map<std::string, std::size_t> room_index;
  const Json& rooms = answer.at("rooms");
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    Zone z;
    z.name = rooms[i].at("name").get<std::string>();
    z.type = canonical_room_type(rooms[i].at("type").get<std::string>());
    z.material = is_toilet_type(z.type) ? "ceramic_tile" : "painted_plaster";
    for (const auto& p : rooms[i].at("polygon"))
      z.polygon.outer.push_back({p[0].get<double>(), p[1].get<double>()});
    room_index.emplace(z.name, i);
    zones.push_back(std::move(z));
  }
  std::vector<DoorSpec> doors;
  std::set<std::pair<std::string, std::string>> connected;
  bool entrance = false;
  const Json& ds = answer.at("doors");
  for (std::size_t i = 0; i < ds.size(); ++i) {
    DoorSpec d;
    d.name = ds[i].at("name").get<std::string>();
    d.pose = {ds[i].at("position")[0].get<double>(), ds[i].at("position")[1].get<double>(), 0.0};
    d.width = ds[i].at("width").get<double>();
    for (const auto& r : ds[i].at("rooms")) d.connects.push_back(r.get<std::string>());
    if (d.connects.size() == 1) entrance = true;
    if (d.connects.size() == 2) connected.insert(std::minmax(d.connects[0], d.connects[1]));
    doors.push_back(std::move(d));
  }
  // The scene graph: every room present, every edge a door, a way in.
  for (std::size_t i = 0; i < graph.rooms.size(); ++i)
    if (!room_index.count(graph.rooms[i].name))
      errors.push_back({"/rooms", "room '" + graph.rooms[i].name + "' (" + graph.rooms[i].type +
                                      ") of the scene graph is missing"});
  for (const auto& [a, b] : graph.adjacency)
    if (room_index.count(a) && room_index.count(b) && !connected.count(std::minmax(a, b)))
      errors.push_back(
          {"/doors", "no door connects '" + a + "' and '" + b +
                         "': the scene graph says they are adjacent; give them a shared wall with a door"});
  if (!entrance)
    errors.push_back({"/doors", "no entrance: add a door with one room (the entrance room '" +
                                    graph.entrance + "') on an outer wall"});

  // Geometry first (so that problems point at rooms and doors), then the furnished world.
  WorldBuilder bare;
  bare.set_name(graph.domain + "_plan");
  for (const auto& z : zones) bare.add_zone(z);
  for (const auto& d : doors) bare.add_door(d);
  auto checked = bare.build(build);
  if (!checked) {
    for (const auto& e : checked.error().errors) errors.push_back({answer_pointer(e.pointer), e.message});
  }
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "the floor plan is not a valid world", std::move(errors));

  WorldBuilder builder = bare;
  Rng rng(0x464c4f4f52ULL);  // furnishing of an LLM plan depends on its geometry only
  const PlanRequirement plan = plan_requirement(constraints, graph.domain);
  Furnishing f = furnish(zones, doors, furnishing_rules(constraints, plan), rng);
  for (auto& r : f.rois) builder.add_roi(std::move(r));
  for (auto& e : f.entities) builder.add_entity(std::move(e));
  auto world = builder.build(build);
  if (!world)
    world = std::move(checked);  // furnishing never makes a valid plan invalid; keep the bare one if it did

  ComplianceReport report = check_compliance(*world, graph.domain, constraints);
  for (const auto* c : report.failures()) {
    std::string where;
    if (auto it = room_index.find(c->element); it != room_index.end())
      where = "/rooms/" + std::to_string(it->second);
    for (std::size_t i = 0; i < doors.size() && where.empty(); ++i)
      if (doors[i].name == c->element) where = "/doors/" + std::to_string(i) + "/width";
    const std::string bound = c->type == "max" ? "at most " : "at least ";
    errors.push_back({where, c->name + " (" + c->ref_id + (c->section.empty() ? "" : ", " + c->section) +
                                 "): " + c->element + " has " +
                                 (c->value ? compact_number(*c->value) : std::string("none")) + " " +
                                 c->unit + ", must be " + bound + compact_number(c->required) + " " +
                                 c->unit + " — " + c->detail});
  }
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "the floor plan breaks building-code constraints", std::move(errors));
  return FloorPlan{std::move(*world), std::move(report), graph, Json::object()};
}

Result<FloorPlan> generate_floor_plan_llm(const llm::StructuredGenerator& generator, std::string_view prompt,
                                          const SceneGraph& graph,
                                          std::span<const MergedConstraint> constraints,
                                          const LlmFloorPlanOptions& options) {
  llm::GenerationRequest r;
  r.artifact = "floor_plan";
  r.variables = floor_plan_prompt_variables(prompt, graph, constraints);
  r.schema = &floor_plan_schema();
  r.check = [&](const Json& answer) -> Status {
    auto plan = floor_plan_from_answer(answer, graph, constraints, options.build);
    if (!plan) return tl::unexpected(plan.error());
    return {};
  };
  r.model = options.model;
  r.temperature = options.temperature;
  r.seed = options.seed;
  r.job_id = options.job_id;
  r.repair_rounds = options.repair_rounds;
  r.cancel = options.cancel;
  auto g = generator.generate(r);
  if (!g) return tl::unexpected(g.error());
  auto plan = floor_plan_from_answer(g->value, graph, constraints, options.build);
  if (!plan) return tl::unexpected(plan.error());
  plan->provenance = {{"generator", "llm"},
                      {"seed", options.seed},
                      {"domain", graph.domain},
                      {"llm", g->provenance()},
                      {"knowledge", knowledge_provenance(constraints)}};
  return plan;
}

Json floor_plan_answer(const World& world) {
  Json rooms = Json::array();
  for (const auto& z : world.zones()) {
    Json poly = Json::array();
    for (const auto& p : z.polygon.outer) poly.push_back({p.x, p.y});
    rooms.push_back({{"name", z.name}, {"type", z.type}, {"polygon", std::move(poly)}});
  }
  Json doors = Json::array();
  for (const auto& d : world.doors()) {
    Json names = Json::array({world.zone(d.zone).name});
    if (d.other) names.push_back(world.zone(*d.other).name);
    doors.push_back({{"name", d.name},
                     {"rooms", std::move(names)},
                     {"position", {d.pose.x, d.pose.y}},
                     {"width", d.width}});
  }
  return {{"rooms", std::move(rooms)}, {"doors", std::move(doors)}};
}

}  // namespace socsim::floorplan
