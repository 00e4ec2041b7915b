// `socsim navbench`: the object-goal navigation benchmark (paper 000 §VI) from the shell; prints
// the table in the shape of Table I and writes it as JSON with --out.
#include <iostream>

#include "core/navbench/benchmark.hpp"
#include "core/store/store.hpp"
#include "server/cli/cli.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

constexpr const char* kNavbenchUsage =
    "  navbench --split normal|hard --scenes 50 --seed S [--out FILE]   object-goal navigation benchmark "
    "(Table I shape)\n"
    "           [--tasks-per-scene 10] [--max-steps 200] [--training-houses 10000] [--threads 2] "
    "[--episodes]\n"
    "           [--markdown FILE]   the Table I layout with 95 % intervals and the paper's figures\n"
    "           [--houses FILE.jsonl]   test houses from ProcTHOR house JSON, one per line (scenes "
    "default to their number)\n";

// An integer option within [lo, hi]; prints the problem and returns nullopt when it is not one.
std::optional<std::int64_t> int_option(const CliArgs& a, const std::string& key, std::int64_t fallback,
                                       std::int64_t lo, std::int64_t hi) {
  auto v = a.opt(key);
  if (!v) return fallback;
  try {
    std::size_t used = 0;
    const long long n = std::stoll(*v, &used);
    if (used == v->size() && n >= lo && n <= hi) return n;
  } catch (const std::exception&) {
  }
  std::cerr << "socsim: " << key << " must be an integer between " << lo << " and " << hi << "\n";
  return std::nullopt;
}

int navbench_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  if (!a.words.empty() || !a.opt("--split")) {
    std::cerr << "usage:\n" << kNavbenchUsage;
    return 2;
  }
  navbench::BenchmarkRequest request;
  auto split = navbench::parse_split(*a.opt("--split"));
  if (!split) {
    std::cerr << "socsim: --split is normal or hard\n";
    return 2;
  }
  request.split = *split;
  const auto scenes = int_option(a, "--scenes", 50, 1, 500);
  const auto seed = int_option(a, "--seed", 0, 0, INT64_MAX);
  const auto tasks = int_option(a, "--tasks-per-scene", 10, 1, 50);
  const auto steps = int_option(a, "--max-steps", 200, 1, 5000);
  const auto training = int_option(a, "--training-houses", 10000, 1, 20000);
  const auto threads = int_option(a, "--threads", 2, 1, 64);
  if (!scenes || !seed || !tasks || !steps || !training || !threads) return 2;
  request.scenes = static_cast<int>(*scenes);
  request.seed = static_cast<std::uint64_t>(*seed);
  request.tasks_per_scene = static_cast<int>(*tasks);
  request.max_steps = static_cast<int>(*steps);
  request.training_houses = static_cast<int>(*training);

  auto store = store::Store::open(cli_db_path(a));
  if (!store) return cli_report(store.error());
  auto knowledge = navbench::load_benchmark_knowledge(**store);
  if (!knowledge) return cli_report(knowledge.error());
  if (auto file = a.opt("--houses")) {
    auto text = cli_read_file(*file);
    if (!text) return cli_report(text.error());
    auto houses = navbench::read_procthor_houses(*text, *knowledge);
    if (!houses) return cli_report(houses.error());
    request.houses = std::move(*houses);
    if (!a.opt("--scenes")) request.scenes = static_cast<int>(request.houses.size());
  }
  auto inputs = navbench::prepare_inputs(*knowledge, request, static_cast<int>(*threads));
  if (!inputs) return cli_report(inputs.error());
  navbench::RunHooks hooks;
  hooks.threads = static_cast<int>(*threads);
  hooks.progress = [](double fraction, const std::string& message) {
    std::cerr << "\r" << message << " (" << static_cast<int>(fraction * 100) << "%)" << std::flush;
  };
  auto result = navbench::run_benchmark(request, *knowledge, inputs->pool, inputs->counts, hooks);
  std::cerr << "\n";
  if (!result) return cli_report(result.error());
  std::cout << navbench::format_table(*result);
  if (auto md = a.opt("--markdown")) {
    if (auto s = cli_write_file(*md, navbench::format_markdown(*result)); !s) return cli_report(s.error());
  }
  if (auto out = a.opt("--out")) {
    if (auto s = cli_write_file(*out, navbench::to_json(*result, a.flag("--episodes")).dump(2) + "\n"); !s)
      return cli_report(s.error());
  }
  return 0;
}

}  // namespace

SOCSIM_COMMAND("navbench", kNavbenchUsage, navbench_command);

}  // namespace socsim::server
