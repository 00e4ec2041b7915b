// socsim-bench navbench: the object-goal navigation benchmark (paper 000 §VI) on both splits —
// residents, scene-prior training houses, test scenes, tasks and all seven methods' episodes —
// timed per phase, with the table of each split. The full run of the paper is 50 + 50 scenes.
#include <filesystem>

#include <unistd.h>

#include "core/navbench/benchmark.hpp"
#include "core/store/store.hpp"
#include "tests/bench/bench.hpp"

namespace {

using namespace socsim;

int run_navbench(const bench::Args& a) {
  const auto scenes = static_cast<int>(a.integer("scenes", 50));
  const auto seed = static_cast<std::uint64_t>(a.integer("seed", 1));
  const auto threads = static_cast<int>(std::max<std::int64_t>(1, a.integer("threads", 2)));
  const auto training = static_cast<int>(a.integer("training-houses", 10000));
  const std::string db = a.str("db", (std::filesystem::temp_directory_path() /
                                      ("socsim-bench-navbench-" + std::to_string(::getpid()) + ".db"))
                                         .string());

  const auto t0 = std::chrono::steady_clock::now();
  auto store = store::Store::open(db);
  if (!store) {
    std::cerr << store.error().message() << "\n";
    return 1;
  }
  auto knowledge = navbench::load_benchmark_knowledge(**store);
  (*store)->close();
  if (!a.has("db"))
    std::filesystem::remove(db), std::filesystem::remove(db + "-wal"), std::filesystem::remove(db + "-shm");
  if (!knowledge) {
    std::cerr << knowledge.error().message() << "\n";
    return 1;
  }
  navbench::BenchmarkRequest request;
  request.scenes = scenes;
  request.seed = seed;
  request.training_houses = training;
  const auto t1 = std::chrono::steady_clock::now();
  auto pool = navbench::make_resident_pool(*knowledge, seed);
  const double pool_s = bench::seconds_since(t1);
  const auto t2 = std::chrono::steady_clock::now();
  auto counts = navbench::count_training_placements(*knowledge, training, request.training_seed, threads);
  const double training_s = bench::seconds_since(t2);
  if (!pool || !counts) {
    std::cerr << (!pool ? pool.error() : counts.error()).message() << "\n";
    return 1;
  }
  auto shared_counts = std::make_shared<const navbench::PlacementCounts>(std::move(*counts));
  nlohmann::json line = {{"bench", "navbench"},     {"scenes_per_split", scenes},  {"seed", seed},
                         {"threads", threads},      {"training_houses", training}, {"residents_s", pool_s},
                         {"training_s", training_s}};
  std::size_t tasks = 0;
  std::vector<std::string> tables;
  for (auto split : {navbench::Split::kNormal, navbench::Split::kHard}) {
    request.split = split;
    navbench::RunHooks hooks;
    hooks.threads = threads;
    auto result = navbench::run_benchmark(request, *knowledge, *pool, shared_counts, hooks);
    if (!result) {
      std::cerr << result.error().message() << "\n";
      return 1;
    }
    const std::string name(navbench::split_name(split));
    line[name + "_s"] = result->seconds;
    line[name] = navbench::to_json(*result);
    tasks += result->tasks.size();
    tables.push_back(navbench::format_table(*result));
  }
  line["tasks"] = tasks;
  line["total_s"] = bench::seconds_since(t0);
  for (const auto& t : tables) std::cerr << t << "\n";
  bench::emit(line);
  return 0;
}

SOCSIM_BENCH("navbench",
             "object-goal navigation benchmark, both splits: [--scenes 50] [--seed 1] [--threads 2] "
             "[--training-houses 10000] [--db FILE]",
             run_navbench);

}  // namespace
