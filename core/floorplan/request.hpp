#pragma once
// A request for a floor plan, as POST /api/v1/worlds and `socsim world generate` take it:
// {scene_graph | prompt, domain?, seed, generator: offline|llm, model?, jurisdiction?, requirements?}, read
// with a pointer for every bad field, and resolved into the scene graph to lay out.
#include <cstdint>
#include <optional>
#include <string>

#include "core/common/json_io.hpp"
#include "core/floorplan/scene_graph.hpp"
#include "core/world/requirements.hpp"

namespace socsim::floorplan {

struct FloorPlanRequest {
  std::optional<Json> scene_graph;  // as posted (checked when resolved)
  std::optional<std::string> prompt;
  std::optional<std::string> domain;
  std::uint64_t seed = 0;
  std::string generator = "offline";      // offline | llm
  std::optional<std::string> model;       // llm only
  std::string jurisdiction;               // restricts the code entries used; empty: all
  world::WorldRequirements requirements;  // what the world must hold (features, rooms, objects, people)
};

inline constexpr std::int64_t kMaxFloorPlanSeed = (std::int64_t{1} << 53) - 1;  // exact in JSON numbers

Result<FloorPlanRequest> floor_plan_request_from_json(const Json& body);

struct ResolvedSceneGraph {
  SceneGraph graph;
  Json
      classification;  // how the domain was found: {type, confidence, explanation, evidence} or {given: true}
};

// The scene graph (its pointers prefixed /scene_graph) or the prompt's programme; the request's
// domain wins over a classification, and must agree with a scene graph's own domain. The rooms
// the requirements name are added to a prompt's programme; a given scene graph must have them.
Result<ResolvedSceneGraph> resolve_scene_graph(const FloorPlanRequest& request);

}  // namespace socsim::floorplan
