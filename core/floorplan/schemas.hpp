#pragma once
// The floor-plan JSON Schemas compiled into the binary (schemas/floor_plan.schema.json for LLM
// answers, schemas/scene_graph.schema.json for generator input), compiled once on first use.
#include <string_view>

#include "core/common/json_schema.hpp"

namespace socsim::floorplan {

std::string_view floor_plan_schema_text();
std::string_view scene_graph_schema_text();

const JsonSchema& floor_plan_schema();
const JsonSchema& scene_graph_schema();

}  // namespace socsim::floorplan
