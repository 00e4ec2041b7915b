// socsim-bench scenario: text to scenario offline, as POST /api/v1/scenarios runs it — a floor plan
// from the prompt, the scenario program, the simulation logged at 10 Hz — for each of the seven
// Table II categories over several seeds. Prints per stage p50/p95 (ms) and scenarios per second.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/knowledge/knowledge_base.hpp"
#include "core/scenario/pipeline.hpp"
#include "core/store/store.hpp"
#include "tests/bench/bench.hpp"

namespace {

const std::vector<std::pair<std::string, std::string>> kPrompts = {
    {"queuing", "About twenty patients queue at the reception desk of a clinic"},
    {"emergency", "Fire alarm in the office: everyone evacuates"},
    {"coffee_break", "Staff take a coffee break around the coffee machine of the office"},
    {"reception", "Visitors check in at the front desk of the office and then leave"},
    {"bottleneck", "A crowd squeezes through the narrow door into the canteen"},
    {"social_party", "A birthday party at home: guests chat in the living room"},
    {"normal_operation", "Normal daily traffic in a hospital ward: nurses and visitors walk between rooms"},
};

int scenario_bench(const socsim::bench::Args& a) {
  using socsim::bench::percentile;
  const auto seeds = a.integer("seeds", 3);
  const double seconds = a.number("seconds", 30.0);
  const auto db = std::filesystem::temp_directory_path() /
                  ("socsim-bench-scenario-" + std::to_string(::getpid()) + ".db");
  auto store = socsim::store::Store::open(db.string());
  if (!store) {
    std::cerr << store.error().message() << "\n";
    return 1;
  }
  socsim::knowledge::KnowledgeBase kb(**store);
  socsim::scenario::ScenarioConfig config;
  std::vector<double> world_ms, program_ms, simulate_ms, total_ms, agents;
  std::size_t failures = 0;
  const auto all = std::chrono::steady_clock::now();
  for (const auto& [category, prompt] : kPrompts) {
    for (std::int64_t seed = 1; seed <= seeds; ++seed) {
      auto request = socsim::scenario::scenario_request_from_json(
          {{"prompt", prompt}, {"seed", seed}, {"duration_s", seconds}}, config);
      if (!request) return 1;
      // Stages timed through the pipeline's progress messages: world (< 0.1), program (< 0.2), simulation.
      auto t0 = std::chrono::steady_clock::now();
      double world_done = 0, program_done = 0;
      socsim::scenario::ScenarioServices s{
          kb, nullptr, config, std::nullopt, {}, [&](double f, const std::string&) {
            const double now = socsim::bench::seconds_since(t0) * 1e3;
            if (f >= 0.1 && world_done == 0) world_done = now;
            if (f >= 0.2 && program_done == 0) program_done = now;
          }};
      auto out = socsim::scenario::run_scenario(*request, std::nullopt, s);
      const double total = socsim::bench::seconds_since(t0) * 1e3;
      if (!out) {
        ++failures;
        std::cerr << category << " seed " << seed << ": " << out.error().message() << "\n";
        continue;
      }
      world_ms.push_back(world_done);
      program_ms.push_back(program_done - world_done);
      simulate_ms.push_back(total - program_done);
      total_ms.push_back(total);
      agents.push_back(static_cast<double>(out->log.agent_count()));
    }
  }
  const double wall = socsim::bench::seconds_since(all);
  (*store)->close();
  std::filesystem::remove(db);
  auto stage = [](const std::vector<double>& v) {
    return nlohmann::json{{"p50_ms", percentile(v, 50)}, {"p95_ms", percentile(v, 95)}};
  };
  socsim::bench::emit({{"bench", "scenario"},
                       {"scenarios", total_ms.size()},
                       {"failures", failures},
                       {"simulated_s", seconds},
                       {"agents_p50", percentile(agents, 50)},
                       {"world", stage(world_ms)},
                       {"program", stage(program_ms)},
                       {"simulate", stage(simulate_ms)},
                       {"total", stage(total_ms)},
                       {"scenarios_per_s", static_cast<double>(total_ms.size()) / wall}});
  return failures == 0 ? 0 : 1;
}

}  // namespace

SOCSIM_BENCH("scenario", "text to scenario offline: --seeds 3 --seconds 30 (7 categories × seeds)",
             scenario_bench);
