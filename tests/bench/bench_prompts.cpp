// socsim-bench prompts: every prompt of tests/fixtures/prompts/everyday.jsonl through interpretation,
// scored fact by fact against what a reader expects (tests/core/scenario/prompt_facts.hpp). Prints
// one line per fact kind with its adherence, the overall figure, the interpretation time per prompt
// (p50/p95 ms), and with --failures every fact that did not hold; --prompt TEXT prints one interpretation;
// --scenario also generates each offline scenario program and checks the people in it.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/knowledge/knowledge_base.hpp"
#include "core/scenario/pipeline.hpp"
#include "core/store/store.hpp"
#include "tests/bench/bench.hpp"
#include "tests/core/scenario/prompt_facts.hpp"

namespace {

// --scenario: each prompt through the offline generator as POST /api/v1/scenarios runs it (a floor
// plan from the prompt, then the program; no simulation: the program fixes who is there), and the
// program's people per role checked against the facts.
int scenario_stage(const socsim::bench::Args& a,
                   const std::vector<socsim::scenario::facts::Prompt>& prompts) {
  namespace facts = socsim::scenario::facts;
  const auto db =
      std::filesystem::temp_directory_path() / ("socsim-bench-prompts-" + std::to_string(::getpid()) + ".db");
  auto store = socsim::store::Store::open(db.string());
  if (!store) {
    std::cerr << store.error().message() << "\n";
    return 1;
  }
  socsim::knowledge::KnowledgeBase kb(**store);
  socsim::scenario::ScenarioConfig config;
  facts::Tally tally;
  std::vector<double> ms;
  for (const auto& p : prompts) {
    const auto t0 = std::chrono::steady_clock::now();
    auto request = socsim::scenario::scenario_request_from_json(
        {{"prompt", p.prompt}, {"seed", a.integer("seed", 1)}}, config);
    if (!request) return 1;
    auto world = socsim::scenario::world_for_request(*request, kb, nullptr, std::nullopt, {});
    if (!world) {
      facts::score_program(p, false, {}, tally, "world: " + world.error().message());
      continue;
    }
    socsim::scenario::ProgramRequest pr;
    pr.prompt = p.prompt;
    pr.seed = request->seed;
    pr.duration_s = request->duration_s;
    auto program = socsim::scenario::generate_program_offline(world->world, kb, pr, config.limits);
    ms.push_back(socsim::bench::seconds_since(t0) * 1e3);
    if (!program) {
      facts::score_program(p, false, {}, tally, "program: " + program.error().message());
      continue;
    }
    facts::score_program(p, true, program->program, tally);
    if (a.has("notes")) socsim::bench::emit({{"id", p.id}, {"notes", program->provenance["notes"]}});
  }
  (*store)->close();
  std::filesystem::remove(db);
  for (const auto& [kind, v] : tally.kinds)
    socsim::bench::emit({{"stage", "scenario"},
                         {"fact", kind},
                         {"held", v.first},
                         {"checked", v.second},
                         {"adherence", static_cast<double>(v.first) / v.second}});
  const auto all = tally.all();
  socsim::bench::emit({{"stage", "scenario"},
                       {"fact", "all"},
                       {"prompts", prompts.size()},
                       {"held", all.first},
                       {"checked", all.second},
                       {"adherence", static_cast<double>(all.first) / all.second},
                       {"p50_ms", socsim::bench::percentile(ms, 50)},
                       {"p95_ms", socsim::bench::percentile(ms, 95)}});
  if (a.has("failures"))
    for (const auto& f : tally.failures) std::cout << "  " << f << "\n";
  return 0;
}

int prompts_bench(const socsim::bench::Args& a) {
  namespace facts = socsim::scenario::facts;
  if (a.has("prompt")) {  // one prompt: its interpretation as JSON
    auto intent = socsim::scenario::interpret_prompt(a.str("prompt", ""));
    if (!intent) {
      std::cerr << intent.error().message() << "\n";
      return 1;
    }
    std::cout << socsim::scenario::to_json(*intent).dump(2) << "\n";
    return 0;
  }
  const std::string path = a.str("fixtures", "tests/fixtures/prompts/everyday.jsonl");
  const auto prompts = facts::load(path);
  if (prompts.empty()) {
    std::cerr << "no prompts in " << path << " (run from the source tree or pass --fixtures)\n";
    return 1;
  }
  facts::Tally tally;
  std::vector<double> ms;
  // --warm: read every prompt once first, so the times are those of a running server whose WordNet
  // cache holds the words (the first reading of a word costs lookups in WordNet's files).
  if (a.has("warm"))
    for (const auto& p : prompts) (void)socsim::scenario::interpret_prompt(p.prompt);
  for (const auto& p : prompts) {
    const auto t0 = std::chrono::steady_clock::now();
    auto intent = socsim::scenario::interpret_prompt(p.prompt);
    ms.push_back(socsim::bench::seconds_since(t0) * 1e3);
    if (!intent) {
      std::cerr << intent.error().message() << "\n";
      return 1;
    }
    facts::score_intent(p, *intent, tally);
    if (a.has("dump")) socsim::bench::emit({{"id", p.id}, {"intent", socsim::scenario::to_json(*intent)}});
  }
  for (const auto& [kind, v] : tally.kinds)
    socsim::bench::emit({{"stage", "intent"},
                         {"fact", kind},
                         {"held", v.first},
                         {"checked", v.second},
                         {"adherence", static_cast<double>(v.first) / v.second}});
  const auto all = tally.all();
  socsim::bench::emit({{"stage", "intent"},
                       {"fact", "all"},
                       {"prompts", prompts.size()},
                       {"held", all.first},
                       {"checked", all.second},
                       {"adherence", static_cast<double>(all.first) / all.second},
                       {"p50_ms", socsim::bench::percentile(ms, 50)},
                       {"p95_ms", socsim::bench::percentile(ms, 95)}});
  if (a.has("failures"))
    for (const auto& f : tally.failures) std::cout << "  " << f << "\n";
  if (a.has("scenario")) return scenario_stage(a, prompts);
  return 0;
}

}  // namespace

SOCSIM_BENCH("prompts", "prompt understanding against tests/fixtures/prompts: adherence per fact kind",
             prompts_bench);
