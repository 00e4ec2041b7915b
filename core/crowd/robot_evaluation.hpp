#pragma once
// Evaluation of the built-in robot planners over scenarios × seeds (issue 19, docs/cosim.md
// "Evaluation jobs"): every episode runs in-process with a planner of robot_planners.hpp, and its
// metrics (docs/metrics.md) are summarised per scenario × planner (means over seeds) and per planner
// (means over scenarios with 95 % Student-t intervals). No I/O; same inputs → same table bytes.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/crowd/episode.hpp"
#include "core/crowd/episode_metrics.hpp"

namespace socsim::crowd {

struct EvaluationScenario {
  std::string id;                             // the card id
  std::shared_ptr<const world::World> world;  // may be null
  std::shared_ptr<const Program> program;
};

struct EvaluationPlan {
  std::vector<EvaluationScenario> scenarios;
  std::vector<std::uint64_t> seeds;
  std::vector<std::string> planners;       // labels as requested ("builtin:orca")
  std::vector<std::string> planner_names;  // make_planner() names, parallel to planners
  std::vector<RobotSpec> robots;           // empty: each program's robot
  EpisodeOptions episode;
};

struct EvaluationEpisode {
  std::size_t scenario = 0, planner = 0, seed = 0;  // indices into the plan
  std::uint64_t steps = 0;
  RobotEpisodeMetrics metrics;  // the (first) robot's
};

struct EvaluationHooks {
  std::function<void(std::size_t done, std::size_t total)> progress;
  std::function<bool()> cancelled;
};

// One episode of a planner until every robot's outcome is decided.
Result<EvaluationEpisode> run_planner_episode(const EvaluationPlan& plan, std::size_t scenario,
                                              std::size_t planner, std::size_t seed);
// Every scenario × planner × seed, in that order. kCancelled when hooks.cancelled() says so.
Result<std::vector<EvaluationEpisode>> run_evaluation(const EvaluationPlan& plan,
                                                      const EvaluationHooks& hooks = {});

// The results table: {interval, metrics, cells: [{card, planner, episodes, outcomes, mean}],
// planners: [{planner, episodes, cards, metrics: {name: {mean, ci95, n}}}], ranking, summary}.
Json evaluation_table(const EvaluationPlan& plan, std::span<const EvaluationEpisode> episodes);

// t_{0.975, df}: the two-sided 95 % quantile of Student's t distribution.
double student_t_975(std::size_t df);

}  // namespace socsim::crowd
