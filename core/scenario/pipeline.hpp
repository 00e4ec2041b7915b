#pragma once
// Text to scenario, end to end (paper 001 Fig. 1): a request {prompt, world | scene graph,
// seed, generator} → a world (given, or laid out from the prompt) → a scenario program (offline
// or LLM, checked against the world) → a simulation at fixed dt, sampled at 10 Hz into a
// trajectory log → the content of a scenario card that replays bit for bit.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/cards/card.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/llm/cancel_token.hpp"
#include "core/llm/structured_generator.hpp"
#include "core/scenario/program_offline.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/world/requirements.hpp"
#include "core/world/world.hpp"

namespace socsim::scenario {

// POST /api/v1/scenarios and `socsim scenario generate`.
struct ScenarioRequest {
  std::string prompt;
  std::optional<Json> world;  // a world document (object) or world.yaml text (string)
  std::optional<std::string> world_id;
  std::optional<Json> scene_graph;
  std::optional<std::string> domain;
  std::uint64_t seed = 0;
  std::string generator = "offline";  // offline | llm
  std::optional<std::string> model;
  double duration_s = 60.0;
  std::optional<std::size_t> agents;  // upper bound on the people in the scenario
  std::string title;
  std::vector<std::string> tags;
};

struct ScenarioConfig {
  ScenarioLimits limits;
  std::size_t max_prompt_bytes = 4000;
  double frame_interval = 0.1;  // s between logged frames (10 Hz)
};

// Every bad field reported at once with its pointer; at most one of world, world_id, scene_graph.
Result<ScenarioRequest> scenario_request_from_json(const Json& body, const ScenarioConfig& config);

using ProgressFn = std::function<void(double fraction, const std::string& message)>;

struct ScenarioWorld {
  world::World world;
  std::string domain;
  Json provenance = Json::object();  // how it was made (given, generated offline or by the LLM)
  // What the prompt asked the world to hold (scenario::world_requirements); empty for given worlds.
  world::WorldRequirements requirements = {};
};

// The world of a request that carries none: a floor plan from the scene graph or the prompt
// (offline by default, the LLM when the request's generator is llm and `llm` is set).
Result<ScenarioWorld> world_for_request(const ScenarioRequest& request,
                                        const knowledge::KnowledgeBase& knowledge,
                                        const llm::StructuredGenerator* llm,
                                        const std::optional<std::string>& job_id,
                                        const llm::CancelToken& cancel);

struct SimulationOutput {
  TrajectoryLog log;
  Json metrics;          // crowd::RunMetrics as JSON
  Json velocity_fields;  // [{group, width, height, bounds, sha256}]
  std::vector<std::string> runtime_errors;
};

// Runs a checked program for duration_s (one thread: the card's promise is per build, not per
// machine's core count) and logs a frame every `frame_interval`. kCancelled when cancelled.
Result<SimulationOutput> simulate_program(const world::World& world, const crowd::Program& program,
                                          std::uint64_t seed, double duration_s, double frame_interval,
                                          const ProgressFn& progress = {},
                                          const llm::CancelToken& cancel = {});
// The same for a program as JSON (a stored card's), parsed here.
Result<SimulationOutput> simulate_program(const world::World& world, const Json& program, std::uint64_t seed,
                                          double duration_s, double frame_interval,
                                          const ProgressFn& progress = {},
                                          const llm::CancelToken& cancel = {});

struct ScenarioOutcome {
  cards::CardContent card;
  TrajectoryLog log;
  std::string world_name;
};

struct ScenarioServices {
  const knowledge::KnowledgeBase& knowledge;
  const llm::StructuredGenerator* llm = nullptr;  // null: offline only
  ScenarioConfig config;
  std::optional<std::string> job_id;
  llm::CancelToken cancel;
  ProgressFn progress;
};

// The whole pipeline. `world` is the resolved world when the request named one (inline or by
// id); otherwise it is laid out from the request.
Result<ScenarioOutcome> run_scenario(const ScenarioRequest& request, std::optional<ScenarioWorld> world,
                                     const ScenarioServices& services);

// Re-runs a card's program in its world with its seed and duration: the same build gives the
// same log (compare sha256() with the card's trajectory_log.sha256).
Result<SimulationOutput> replay_card(const cards::CardContent& card, const ProgressFn& progress = {},
                                     const llm::CancelToken& cancel = {});

}  // namespace socsim::scenario
