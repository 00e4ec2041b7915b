#pragma once
// Checks a scenario program (schemas/program.schema.json) against a world and the deployment's
// limits before anything runs, reporting every problem at once as a FieldError with a JSON
// pointer into the program: structure, unknown roles, places (with valid names listed), behaviour
// trees (unknown nodes and ports, bad literals), counts over the limits or beyond what a region
// holds — the text the LLM repair loop quotes back.
#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/scenario/program_offline.hpp"
#include "core/world/world.hpp"

namespace socsim::scenario {

// kValidation with one FieldError per problem; ok when ScenarioRunner::create accepts the program.
Status check_program(const Json& program, const world::World& world, const ScenarioLimits& limits);
// The same check, returning the program it parsed: generators hand this on, so that a request
// parses its program once and simulation runs exactly what was checked.
Result<crowd::Program> checked_program(const Json& program, const world::World& world,
                                       const ScenarioLimits& limits);

}  // namespace socsim::scenario
