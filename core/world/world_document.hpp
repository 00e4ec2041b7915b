#pragma once
// The world document: the one structure behind world.yaml and the REST API's JSON
// (schemas/world.schema.json). Converts it to a WorldBuilder (typed, with JSON pointers on
// every bad field) and a World back to it.
#include "core/common/json_io.hpp"
#include "core/world/world_builder.hpp"

namespace socsim::world {

inline constexpr std::size_t kMaxWorldElements = 10'000;  // per list (zones, walls, …)
inline constexpr std::size_t kMaxPolygonPoints = 10'000;

// Reads the document form. Units are applied here (the builder works in metres and radians).
// Fails with kValidation and one FieldError per bad field (unknown keys, wrong types, …).
Result<WorldBuilder> builder_from_document(const Json& document);

// builder_from_document + build.
Result<World> world_from_document(const Json& document, const BuildOptions& options = {});

// The document form of a world, in metres and radians, walls written out.
Json world_to_document(const World& world);

// Kind of an ROI written without one: its name when that is a known kind (after dropping a
// trailing "_<digits>"), otherwise "area".
std::string infer_roi_kind(std::string_view name);

}  // namespace socsim::world
