#pragma once
// The offline scenario-program generator (paper 001 §III-G without an LLM): the prompt's
// categories, roles, counts, places and timing (intent.hpp) are instantiated against the world's
// ROIs, POIs, doors and zones — spotlight agents with behaviour trees assembled from nodes the
// knowledge store returns for the category, ambient groups driven by velocity fields — with
// seeded variety and the limits of the deployment.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/crowd/program.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/world/world.hpp"

namespace socsim::scenario {

struct ScenarioLimits {
  std::size_t max_agents = 2000;
  std::size_t max_spotlight = 64;
  double max_duration_s = 600;
};

struct ProgramRequest {
  std::string prompt;
  std::uint64_t seed = 0;
  std::optional<std::size_t> agents;  // upper bound on the people in the scenario
  double duration_s = 60;
};

struct GeneratedProgram {
  Json program;                         // schemas/program.schema.json, trees inline
  crowd::Program checked;               // `program` parsed and passed by check_program(): what runs
  Json provenance;                      // categories, lexicon matches, places, knowledge hits, fallbacks …
  std::vector<std::string> categories;  // Table II category names, most weighted first
};

// Same world, knowledge, request and limits → identical program JSON. Errors: kBadRequest for an
// empty prompt (/prompt), kValidation for a duration or agent bound outside the limits
// (/duration_s, /agents), for a world without any zone (/world), and when the knowledge store lacks
// a behaviour node a category needs. The result passes check_program().
Result<GeneratedProgram> generate_program_offline(const world::World& world,
                                                  const knowledge::KnowledgeBase& knowledge,
                                                  const ProgramRequest& request,
                                                  const ScenarioLimits& limits);

}  // namespace socsim::scenario
