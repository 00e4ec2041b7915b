// socsim-bench household: configures N dynamic scenes (procedural houses of 4–10 rooms, 1–4
// residents drawn from the 50 built-in personas by the number of bedrooms, D days) with the
// offline generators, in parallel over houses (each house has its own seed, so the result does
// not depend on the thread count), and times P(o, t) queries on the indexed scenes.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include <unistd.h>

#include "core/common/rng.hpp"
#include "core/household/scene.hpp"
#include "tests/bench/bench.hpp"

namespace {

using namespace socsim;
using namespace socsim::household;

std::uint64_t splitmix64_copy(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t state = seed ^ (index * 0x9E3779B97F4A7C15ULL);
  return splitmix64(state);
}

double peak_rss_mb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

struct Totals {
  std::uint64_t events = 0, relocations = 0, residents = 0, rooms = 0, objects = 0, digest = 0;
  std::vector<double> query_us;
  int failures = 0;
};

int run_household(const bench::Args& a) {
  const auto houses = a.integer("houses", 1000);
  const auto days = static_cast<int>(a.integer("days", 5));
  const auto threads = static_cast<int>(std::max<std::int64_t>(1, a.integer("threads", 2)));
  const auto seed = static_cast<std::uint64_t>(a.integer("seed", 1));
  const std::string db = a.str("db", (std::filesystem::temp_directory_path() /
                                      ("socsim-bench-household-" + std::to_string(::getpid()) + ".db"))
                                         .string());

  const auto t0 = std::chrono::steady_clock::now();
  auto store = store::Store::open(db);
  if (!store) {
    std::cerr << store.error().message() << "\n";
    return 1;
  }
  auto knowledge = load_household_knowledge(**store);
  (*store)->close();
  if (!a.has("db"))
    std::filesystem::remove(db), std::filesystem::remove(db + "-wal"), std::filesystem::remove(db + "-shm");
  if (!knowledge) {
    std::cerr << knowledge.error().message() << "\n";
    return 1;
  }
  // The residents: scene-agnostic, generated once and shared by every scene (as the paper's 50).
  std::vector<std::shared_ptr<const ResidentProfile>> pool;
  auto vocab = ActivityVocabulary::initial(*knowledge);
  for (const auto& p : knowledge->personas) {
    auto r = make_resident_offline(p, *knowledge, {days, Weekday::kWednesday, seed}, vocab);
    if (!r) {
      std::cerr << p.name << ": " << r.error().message() << "\n";
      return 1;
    }
    pool.push_back(std::make_shared<const ResidentProfile>(std::move(*r)));
  }
  const double pool_s = bench::seconds_since(t0);

  const auto t1 = std::chrono::steady_clock::now();
  std::atomic<std::int64_t> next{0};
  std::mutex merge;
  Totals all;
  auto worker = [&] {
    Totals local;
    for (std::int64_t i; (i = next.fetch_add(1)) < houses;) {
      const std::uint64_t hs = splitmix64_copy(seed, static_cast<std::uint64_t>(i));
      Rng pick(hs, 7);
      const int rooms = static_cast<int>(pick.between(4, 10));
      auto house = generate_house({rooms, std::nullopt, hs}, *knowledge);
      if (!house) {
        ++local.failures;
        continue;
      }
      auto shared = std::make_shared<const House>(std::move(*house));
      auto scene = configure_scene(shared, pool, {0, hs}, *knowledge);
      if (!scene) {
        ++local.failures;
        continue;
      }
      local.events += scene->events().size();
      local.relocations += scene->relocations().size();
      local.residents += scene->residents().size();
      local.rooms += shared->rooms.size();
      local.objects += shared->objects.size();
      local.digest ^=
          fnv1a64(std::to_string(i) + ":" + std::to_string(scene->relocations().size()) + ":" +
                  std::to_string(scene->relocations().empty() ? 0 : scene->relocations().back().to));
      if (i % 50 == 0 && !shared->objects.empty()) {
        Rng q(hs, 9);
        constexpr int kQueries = 2000;
        std::vector<std::pair<int, Seconds>> probes(kQueries);
        for (auto& p : probes)
          p = {static_cast<int>(q.below(static_cast<std::uint32_t>(shared->objects.size()))),
               static_cast<Seconds>(q.below(static_cast<std::uint32_t>(scene->end())))};
        volatile int sink = 0;
        const auto tq = std::chrono::steady_clock::now();
        for (const auto& [o, t] : probes) sink = sink + scene->receptacle_at(o, t);
        local.query_us.push_back(bench::seconds_since(tq) * 1e6 / kQueries);
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    all.events += local.events;
    all.relocations += local.relocations;
    all.residents += local.residents;
    all.rooms += local.rooms;
    all.objects += local.objects;
    all.digest ^= local.digest;
    all.failures += local.failures;
    all.query_us.insert(all.query_us.end(), local.query_us.begin(), local.query_us.end());
  };
  std::vector<std::thread> pool_threads;
  for (int t = 0; t < threads; ++t) pool_threads.emplace_back(worker);
  for (auto& t : pool_threads) t.join();
  const double scenes_s = bench::seconds_since(t1);
  double q_mean = 0;
  for (double x : all.query_us) q_mean += x;
  if (!all.query_us.empty()) q_mean /= static_cast<double>(all.query_us.size());
  const double n = static_cast<double>(std::max<std::int64_t>(1, houses));
  bench::emit({{"bench", "household"},
               {"houses", houses},
               {"days", days},
               {"threads", threads},
               {"seed", seed},
               {"residents_pool_s", pool_s},
               {"scenes_s", scenes_s},
               {"total_s", bench::seconds_since(t0)},
               {"scenes_per_s", n / scenes_s},
               {"failures", all.failures},
               {"mean_rooms", static_cast<double>(all.rooms) / n},
               {"mean_residents", static_cast<double>(all.residents) / n},
               {"mean_objects", static_cast<double>(all.objects) / n},
               {"mean_events", static_cast<double>(all.events) / n},
               {"mean_relocations", static_cast<double>(all.relocations) / n},
               {"query_us_mean", q_mean},
               {"query_us_p99", all.query_us.empty() ? 0.0 : bench::percentile(all.query_us, 99)},
               {"peak_rss_mb", peak_rss_mb()},
               {"digest", all.digest}});
  return all.failures == 0 ? 0 : 1;
}

SOCSIM_BENCH("household",
             "dynamic household scenes: --houses N --days D [--threads T] [--seed S] [--db FILE]",
             run_household);

}  // namespace
