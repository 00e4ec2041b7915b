#pragma once
// world.yaml (paper 001, Fig. 3): reading with errors that name line, column and field,
// and writing a World back so that reading the text gives the same World.
#include <string>
#include <string_view>
#include <vector>

#include "core/world/world_builder.hpp"
#include "core/world/yaml_reader.hpp"

namespace socsim::world {

// Parses, checks the document and builds the World. Every FieldError of the result carries
// the line and column of the field (or of the object that lacks it).
Result<World> world_from_yaml(std::string_view text, const BuildOptions& options = {},
                              const YamlLimits& limits = {});

// A world and what reading it assumed, each warning with its pointer, line and column: a zone
// region inferred and walls added to close it (WorldBuilder), and the '↳' marks with which a
// printed listing wraps long lines (Fig. 3 of paper 001 as printed) read as continuations.
struct WorldReading {
  World world;
  std::vector<FieldError> warnings;
};
Result<WorldReading> read_world_yaml(std::string_view text, const BuildOptions& options = {},
                                     const YamlLimits& limits = {});

// Stable text: one flow-style line per element, numbers in shortest round-trip form.
std::string world_to_yaml(const World& world);

}  // namespace socsim::world
