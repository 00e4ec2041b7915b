#pragma once
// LLM floor-plan generator (paper 001 §III-C): the scene graph and the building-code
// constraints retrieved for the domain go into the floor_plan prompt; the JSON polygons that
// come back (schemas/floor_plan.schema.json) are built into a World, furnished by room type and
// checked against the constraints; failures are quoted back in bounded repair rounds.
#include <optional>
#include <span>
#include <string>

#include "core/floorplan/offline.hpp"
#include "core/llm/structured_generator.hpp"

namespace socsim::floorplan {

struct LlmFloorPlanOptions {
  std::optional<std::string> model;
  std::int64_t seed = 0;
  double temperature = 0.2;
  std::optional<int> repair_rounds;   // default: the client's configuration
  std::optional<std::string> job_id;  // for the call log
  llm::CancelToken cancel;
  BuildOptions build;
};

// The prompt's variables: scene graph as JSON text, one describe() line per constraint.
llm::PromptVariables floor_plan_prompt_variables(std::string_view prompt, const SceneGraph& graph,
                                                 std::span<const knowledge::MergedConstraint> constraints);

// Builds, furnishes and checks an answer; the Status carries every problem with a pointer into
// the answer (/rooms/2/polygon, /doors/0/position …) — the semantic check of the repair loop.
Result<FloorPlan> floor_plan_from_answer(const Json& answer, const SceneGraph& graph,
                                         std::span<const knowledge::MergedConstraint> constraints,
                                         const BuildOptions& build = {});

// Errors: kUpstream / kUpstreamTimeout naming the endpoint's failure; kValidation when the last
// answer still failed (errors[] point into it).
Result<FloorPlan> generate_floor_plan_llm(const llm::StructuredGenerator& generator, std::string_view prompt,
                                          const SceneGraph& graph,
                                          std::span<const knowledge::MergedConstraint> constraints,
                                          const LlmFloorPlanOptions& options = {});

// A world as the answer the floor_plan prompt asks for (rooms with polygons, doors with rooms,
// position and width): for examples, tests and replaying a plan through the LLM path.
Json floor_plan_answer(const World& world);

}  // namespace socsim::floorplan
