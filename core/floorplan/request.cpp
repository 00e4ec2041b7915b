#include "core/floorplan/request.hpp"

#include "core/common/json_check.hpp"
#include "core/floorplan/features.hpp"
#include "core/knowledge/types.hpp"

namespace socsim::floorplan {

Result<FloorPlanRequest> floor_plan_request_from_json(const Json& body) {
  JsonChecker c;
  FloorPlanRequest r;
  if (!body.is_object()) {
    c.add("", "must be an object with scene_graph or prompt");
    return tl::unexpected(c.error("the request is not an object"));
  }
  c.only_keys(
      body, "",
      {"scene_graph", "prompt", "domain", "seed", "generator", "model", "jurisdiction", "requirements"});
  if (const Json* g = c.object(body, "", "scene_graph", false)) r.scene_graph = *g;
  r.prompt = c.string(body, "", "prompt", false, 1, 4000);
  if (r.scene_graph && r.prompt) c.add("/prompt", "give either scene_graph or prompt, not both");
  // A scene_graph or prompt that is given but bad has its own error already; null counts as not given.
  if (!r.scene_graph && !r.prompt && !JsonChecker::given(body, "scene_graph") &&
      !JsonChecker::given(body, "prompt"))
    c.add("", "give scene_graph (rooms and adjacency) or prompt (a description of the building)");
  r.domain = c.string(body, "", "domain", false, 1, 32);
  if (r.domain && !knowledge::is_building_type(*r.domain)) {
    std::string all;
    for (auto t : knowledge::building_types()) all += (all.empty() ? "" : ", ") + std::string(t);
    c.add("/domain", "unknown building type '" + *r.domain + "'; one of " + all);
  }
  if (auto seed = c.integer(body, "", "seed", false, 0, kMaxFloorPlanSeed))
    r.seed = static_cast<std::uint64_t>(*seed);
  if (auto g = c.string(body, "", "generator", false)) {
    if (*g != "offline" && *g != "llm") c.add("/generator", "must be offline or llm");
    r.generator = *g;
  }
  r.model = c.string(body, "", "model", false, 1, 200);
  if (r.model && r.generator != "llm") c.add("/model", "a model is chosen only with generator llm");
  if (auto j = c.string(body, "", "jurisdiction", false, 0, 64)) r.jurisdiction = *j;
  std::vector<FieldError> errors = c.errors();
  if (const auto it = body.find("requirements"); it != body.end() && !it->is_null()) {
    auto req = world_requirements_from_json(*it, "/requirements");
    if (req)
      r.requirements = std::move(*req);
    else
      errors.insert(errors.end(), req.error().errors.begin(), req.error().errors.end());
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "the world request is invalid", std::move(errors));
  return r;
}

Result<ResolvedSceneGraph> resolve_scene_graph(const FloorPlanRequest& request) {
  ResolvedSceneGraph out;
  if (request.scene_graph) {
    auto g = scene_graph_from_json(*request.scene_graph, "/scene_graph");
    if (!g) return tl::unexpected(g.error());
    const bool had_domain = request.scene_graph->contains("domain");
    if (request.domain && had_domain && g->domain != *request.domain)
      return fail(ErrorCode::kValidation, "the domain and the scene graph's domain disagree",
                  {{"/domain", "is " + *request.domain + " but /scene_graph/domain is " + g->domain}});
    if (request.domain) g->domain = *request.domain;
    out.classification = had_domain || request.domain
                             ? Json{{"given", true}, {"type", g->domain}}
                             : Json{{"given", false}, {"type", g->domain}, {"from", "room names"}};
    out.graph = std::move(*g);
    if (auto s = apply_room_requirements(out.graph, request.requirements, true); !s)
      return tl::unexpected(s.error());
    return out;
  }
  if (!request.prompt)
    return fail(ErrorCode::kValidation, "the world request has neither scene_graph nor prompt",
                {{"", "give scene_graph or prompt"}});
  auto p = scene_graph_from_prompt(*request.prompt, request.domain);
  if (!p) return tl::unexpected(p.error());
  out.graph = std::move(p->graph);
  out.classification = knowledge::to_json(p->classification);
  out.classification["given"] = request.domain.has_value();
  Json counts = Json::object();
  for (const auto& [type, n] : p->counts) counts[type] = n;
  out.classification["room_counts"] = std::move(counts);
  std::vector<std::string> notes;
  if (auto s = apply_room_requirements(out.graph, request.requirements, false, &notes); !s)
    return tl::unexpected(s.error());
  if (!notes.empty()) out.classification["requirement_notes"] = notes;
  return out;
}

}  // namespace socsim::floorplan
