// socsim-bench prompts: every prompt of tests/fixtures/prompts/everyday.jsonl through interpretation,
// scored fact by fact against what a reader expects (tests/core/scenario/prompt_facts.hpp). Prints
// one line per fact kind with its adherence, the overall figure, the interpretation time per prompt
// (p50/p95 ms), and with --failures every fact that did not hold; --prompt TEXT prints one interpretation.
#include <string>
#include <vector>

#include "tests/bench/bench.hpp"
#include "tests/core/scenario/prompt_facts.hpp"

namespace {

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
  return 0;
}

}  // namespace

SOCSIM_BENCH("prompts", "prompt understanding against tests/fixtures/prompts: adherence per fact kind",
             prompts_bench);
