#include "core/floorplan/schemas.hpp"

#include <stdexcept>
#include <string>

namespace socsim::floorplan {
namespace {

JsonSchema compile_embedded(std::string_view text, const char* what) {
  auto parsed = parse_json_untrusted(text);
  if (!parsed)
    throw std::logic_error(std::string("embedded ") + what + " is not JSON: " + parsed.error().message());
  auto schema = JsonSchema::compile(std::move(*parsed));
  if (!schema)
    throw std::logic_error(std::string("embedded ") + what +
                           " does not compile: " + schema.error().message());
  return std::move(*schema);
}

}  // namespace

const JsonSchema& floor_plan_schema() {
  static const JsonSchema schema = compile_embedded(floor_plan_schema_text(), "floor_plan.schema.json");
  return schema;
}

const JsonSchema& scene_graph_schema() {
  static const JsonSchema schema = compile_embedded(scene_graph_schema_text(), "scene_graph.schema.json");
  return schema;
}

}  // namespace socsim::floorplan
