#pragma once
// LLM scenario-program generator (paper 001 §III-G): the prompt, the world's places and the
// behaviour nodes retrieved for the prompt go into the scenario_program template; the answer
// (schemas/scenario_program.schema.json: spotlight agents with BT XML, ambient groups between
// ROIs) is compiled into a program (schemas/program.schema.json) and checked against the world,
// every problem quoted back with a pointer into the answer in bounded repair rounds.
#include <optional>
#include <string>

#include "core/knowledge/knowledge_base.hpp"
#include "core/llm/structured_generator.hpp"
#include "core/scenario/program_offline.hpp"
#include "core/world/world.hpp"

namespace socsim::scenario {

struct LlmProgramOptions {
  std::optional<std::string> model;
  double temperature = 0.2;
  std::optional<int> repair_rounds;
  std::optional<std::string> job_id;
  llm::CancelToken cancel;
  std::size_t retrieved_nodes = 14;  // behaviour nodes offered to the model
};

// The world as the prompt lists it: one line per zone, door, ROI and entity, by exact name.
std::string world_places_text(const world::World& world);

// Answer → program JSON (behaviour trees inline), before any world check.
Json program_from_answer(const Json& answer, const ProgramRequest& request);

// Compiles and checks an answer; errors point into the answer (/spotlight_agents/2/spawn_roi …).
Result<Json> checked_program_from_answer(const Json& answer, const world::World& world,
                                         const ProgramRequest& request, const ScenarioLimits& limits);

// kUpstream / kUpstreamTimeout naming the endpoint's failure; kValidation when the last answer
// still failed (errors[] point into it). The result's provenance holds the LLM calls and the
// retrieved nodes.
Result<GeneratedProgram> generate_program_llm(const llm::StructuredGenerator& generator,
                                              const world::World& world,
                                              const knowledge::KnowledgeBase& knowledge,
                                              const ProgramRequest& request, const ScenarioLimits& limits,
                                              const LlmProgramOptions& options = {});

}  // namespace socsim::scenario
