// socsim-bench crowd: steps a walking crowd at 1 person/m² in a walled square (optionally with
// pillars and groups) and reports throughput; then checks the cell-list step against the O(N²)
// reference of the same forces at --reference-agents (default 2000) for 100 steps.
#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "core/common/rng.hpp"
#include "core/crowd/crowd_simulation.hpp"
#include "core/crowd/social_kernel.hpp"
#include "core/crowd/velocity_field.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/bench/bench.hpp"
#include "tests/bench/crowd_bench_scene.hpp"

namespace {

using socsim::crowd::CrowdSimulation;
using socsim::crowd::Vec2;

// Taking turns with another process (--turns IN,OUT: two named pipes; tests/bench/paired-crowd.sh):
// before each timed step wait for a byte on IN, after it send one on OUT. Two builds stepping in
// turns see the same machine at the same moments, so the ratio of their step times is steady to
// about 1 % where the machine's own speed wanders by 2x within minutes.
class Turns {
 public:
  explicit Turns(const std::string& spec) {
    if (spec.empty()) return;
    const auto comma = spec.find(',');
    if (comma == std::string::npos) throw std::invalid_argument("--turns IN,OUT: two named pipes");
    // Read-write opens do not block waiting for the other end (Linux).
    in_ = ::open(spec.substr(0, comma).c_str(), O_RDWR);
    out_ = ::open(spec.substr(comma + 1).c_str(), O_RDWR);
    if (in_ < 0 || out_ < 0) throw std::invalid_argument("--turns: cannot open " + spec);
  }
  ~Turns() {
    if (in_ >= 0) ::close(in_);
    if (out_ >= 0) ::close(out_);
  }
  Turns(const Turns&) = delete;
  Turns& operator=(const Turns&) = delete;
  [[nodiscard]] bool on() const { return in_ >= 0; }
  void wait() const {
    char byte = 0;
    if (in_ >= 0 && ::read(in_, &byte, 1) != 1) throw std::runtime_error("--turns: the other side went away");
  }
  void pass() const {
    const char byte = 1;
    if (out_ >= 0 && ::write(out_, &byte, 1) != 1) throw std::runtime_error("--turns: cannot pass the turn");
  }

 private:
  int in_ = -1;
  int out_ = -1;
};

// The scene (tests/bench/crowd_bench_scene.hpp): N agents on a jittered 1 m lattice, walking
// back and forth between two random goals; --walls, --groups as described there.
CrowdSimulation make_crowd(std::size_t n, unsigned threads, bool walls, bool groups, std::uint64_t seed,
                           bool pairs_once = true) {
  return socsim::bench::crowd_bench_simulation(socsim::bench::crowd_bench_scene(n, walls, groups, seed),
                                               threads, seed, pairs_once);
}

SOCSIM_BENCH(
    "crowd",
    "--agents N --steps S --threads T [--walls] [--groups] [--reference-agents M] [--agent-by-agent] "
    "[--turns IN,OUT]",
    [](const socsim::bench::Args& a) {
      const auto n = static_cast<std::size_t>(a.integer("agents", 10000));
      const auto steps = a.integer("steps", 200);
      const auto threads = static_cast<unsigned>(a.integer("threads", 2));
      const bool walls = a.has("walls");
      const bool groups = a.has("groups");
      // Each pair once (the default) or agent by agent: the same state_fnv1a.
      const bool pairs_once = !a.has("agent-by-agent");
      CrowdSimulation sim = make_crowd(n, threads, walls, groups, 42, pairs_once);
      for (int k = 0; k < 10; ++k) sim.step();  // leave the lattice start behind
      const Turns turns(a.str("turns", ""));
      std::vector<double> step_ms;  // with --turns: each step's time, for pairing
      double seconds = 0.0;
      const std::clock_t cpu0 = std::clock();
      if (turns.on()) {
        for (std::int64_t k = 0; k < steps; ++k) {
          turns.wait();
          const auto t1 = std::chrono::steady_clock::now();
          sim.step();
          step_ms.push_back(socsim::bench::ms_since(t1));
          turns.pass();
          seconds += step_ms.back() / 1000.0;
        }
      } else {
        const auto t0 = std::chrono::steady_clock::now();
        for (std::int64_t k = 0; k < steps; ++k) sim.step();
        seconds = socsim::bench::seconds_since(t0);
      }
      // CPU time of all threads: on a shared machine the wall clock also counts waiting.
      const double cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
      // FNV-1a over the bits of every position and velocity: equal between two builds
      // exactly when a change to the step left every result bit-identical.
      std::uint64_t fnv = 14695981039346656037ULL;
      for (std::uint32_t i = 0; i < n; ++i) {
        const Vec2 p = sim.position(socsim::crowd::AgentId(i));
        const Vec2 v = sim.velocity(socsim::crowd::AgentId(i));
        for (const double value : {p.x, p.y, v.x, v.y}) {
          auto bits = std::bit_cast<std::uint64_t>(value);
          for (int b = 0; b < 8; ++b, bits >>= 8) fnv = (fnv ^ (bits & 0xffU)) * 1099511628211ULL;
        }
      }
      socsim::bench::emit(
          {{"bench", "crowd"},
           {"agents", n},
           {"threads", threads},
           {"steps", steps},
           {"walls", walls},
           {"groups", groups},
           {"pairs_once", pairs_once},
           {"agent_steps_per_s", static_cast<double>(n) * static_cast<double>(steps) / seconds},
           {"ms_per_step", 1000.0 * seconds / static_cast<double>(steps)},
           {"cpu_us_per_agent_step",
            1e6 * cpu_seconds / (static_cast<double>(n) * static_cast<double>(steps))},
           {"state_fnv1a", fnv},
           {"step_ms", step_ms}});

      const auto m = static_cast<std::size_t>(a.integer("reference-agents", 2000));
      if (m == 0) return 0;
      CrowdSimulation grid = make_crowd(m, threads, walls, groups, 7);
      CrowdSimulation brute = make_crowd(m, threads, walls, groups, 7);
      double grid_s = 0.0;
      double brute_s = 0.0;
      for (int k = 0; k < 100; ++k) {
        auto t1 = std::chrono::steady_clock::now();
        grid.step();
        grid_s += socsim::bench::seconds_since(t1);
        t1 = std::chrono::steady_clock::now();
        brute.step_reference();
        brute_s += socsim::bench::seconds_since(t1);
      }
      double max_diff = 0.0;
      for (std::uint32_t i = 0; i < m; ++i) {
        const Vec2 p = grid.position(socsim::crowd::AgentId(i));
        const Vec2 q = brute.position(socsim::crowd::AgentId(i));
        max_diff = std::max(max_diff, std::hypot(p.x - q.x, p.y - q.y));
      }
      socsim::bench::emit({{"bench", "crowd_reference"},
                           {"agents", m},
                           {"threads", threads},
                           {"steps", 100},
                           {"walls", walls},
                           {"groups", groups},
                           {"grid_ms_per_step", 1000.0 * grid_s / 100.0},
                           {"brute_force_ms_per_step", 1000.0 * brute_s / 100.0},
                           {"speedup", brute_s / grid_s},
                           {"max_position_difference_m", max_diff},
                           {"agree_1e-4_m", max_diff <= 1e-4}});
      return 0;
    });

}  // namespace

// Velocity field of paper 001 Algorithm 1 at 256 × 256: the geodesic distance to the goal region
// (fast marching) plus the per-cell descent directions, on the example clinic (20 × 12 m, a
// routing grid of the same cell size). Also the cost of Algorithm 1's lookup per agent.
int crowd_field_bench(const socsim::bench::Args& a) {
  using namespace socsim;
  const auto size = static_cast<int>(a.integer("size", 256));
  const auto runs = static_cast<int>(a.integer("runs", 20));
  const std::string path =
      a.str("world", "schemas/examples/world_clinic.yaml");  // run from the repository root
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  auto world = world::world_from_yaml(text.str());
  if (!world) {
    std::cerr << world.error().message() << "\n";
    return 1;
  }
  const geometry::Box box = world->bounds();
  const double cell = std::max(box.width(), box.height()) / size;
  crowd::VelocityField::GeodesicSpec spec;
  spec.width = spec.height = size;
  spec.speed = 1.3;
  spec.variation = 0.2;
  spec.start = {geometry::Polygon{{{1, 7}, {9, 7}, {9, 11}, {1, 11}}, {}}};
  spec.goal = {geometry::Polygon{{{14, 1}, {19, 1}, {19, 5}, {14, 5}}, {}}};
  std::vector<double> grid_ms;
  std::vector<double> field_ms;
  std::vector<double> field_cpu_ms;
  int cells = 0;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const world::OccupancyGrid grid = world::OccupancyGrid::rasterise(*world, {cell, 0.15, 4'000'000});
    const auto t1 = std::chrono::steady_clock::now();
    const std::clock_t c1 = std::clock();
    auto f = crowd::VelocityField::from_geodesic(grid, box, spec);
    const std::clock_t c2 = std::clock();
    const auto t2 = std::chrono::steady_clock::now();
    field_cpu_ms.push_back(1000.0 * static_cast<double>(c2 - c1) / CLOCKS_PER_SEC);
    if (!f) {
      std::cerr << f.error().message() << "\n";
      return 1;
    }
    cells = grid.width() * grid.height();
    grid_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    field_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
  }
  // Algorithm 1 per agent: lookup + intermediate goal.
  auto f = crowd::VelocityField::from_geodesic(
      world::OccupancyGrid::rasterise(*world, {cell, 0.15, 4'000'000}), box, spec);
  socsim::Rng rng(1);
  std::vector<crowd::Vec2> points(100'000);
  for (auto& p : points) p = {rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y)};
  const auto t0 = std::chrono::steady_clock::now();
  double sink = 0.0;
  for (const auto& p : points) sink += crowd::velocity_field_goal(*f, p, 0.05, 0.5).x;
  const double lookup_ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() /
      static_cast<double>(points.size());
  socsim::bench::emit({{"bench", "crowd-field"},
                       {"size", size},
                       {"routing_cells", cells},
                       {"rasterise_ms_p50", socsim::bench::percentile(grid_ms, 50)},
                       {"field_ms_p50", socsim::bench::percentile(field_ms, 50)},
                       {"field_ms_p95", socsim::bench::percentile(field_ms, 95)},
                       {"field_cpu_ms_p50", socsim::bench::percentile(field_cpu_ms, 50)},
                       {"algorithm1_ns_per_agent", lookup_ns},
                       {"checksum", sink}});
  return 0;
}

SOCSIM_BENCH("crowd-field", "--size 256 --runs 20 [--world schemas/examples/world_clinic.yaml]",
             crowd_field_bench);

// socsim-bench crowd-kernel: the pair kernel alone (social force, headway cap and side push in one
// pass, as the step calls it) on batches shaped like the crowd bench's — neighbours uniform in a
// 3 m disc, walking at 1.34 m/s in random directions, batches of 28–40 pairs padded to 8 — so a
// change to the kernel can be timed without the rest of the step's noise. Reports the best of
// --repeats timings in ns per pair: the dispatched kernel with and without the ahead terms, the
// portable loop (social force only), and the kernel of the step that computes each pair once.
int crowd_kernel_bench(const socsim::bench::Args& a) {
  using namespace socsim::crowd;
  const auto batches = static_cast<int>(a.integer("batches", 4096));
  const auto passes = static_cast<int>(a.integer("passes", 50));
  const auto repeats = static_cast<int>(a.integer("repeats", 5));
  socsim::Rng rng(7);
  std::vector<PairBatch> data(static_cast<std::size_t>(batches));
  std::vector<int> counts(static_cast<std::size_t>(batches));
  std::vector<AheadParams> ahead(static_cast<std::size_t>(batches));
  std::int64_t pairs_per_pass = 0;
  for (int k = 0; k < batches; ++k) {
    PairBatch& b = data[static_cast<std::size_t>(k)];
    b = PairBatch{};
    const int count = 28 + static_cast<int>(rng.uniform() * 13.0);
    const double heading = rng.uniform(-3.14159, 3.14159);
    const double vx = 1.34 * std::cos(heading);
    const double vy = 1.34 * std::sin(heading);
    for (int m = 0; m < count; ++m) {
      const double rr = 3.0 * std::sqrt(rng.uniform(0.01, 1.0));
      const double phi = rng.uniform(-3.14159, 3.14159);
      const double h = rng.uniform(-3.14159, 3.14159);
      b.dx[m] = static_cast<float>(rr * std::cos(phi));
      b.dy[m] = static_cast<float>(rr * std::sin(phi));
      b.dvx[m] = static_cast<float>(vx - 1.34 * std::cos(h));
      b.dvy[m] = static_cast<float>(vy - 1.34 * std::sin(h));
    }
    const int padded = (count + kBatchLanes - 1) / kBatchLanes * kBatchLanes;
    counts[static_cast<std::size_t>(k)] = padded;
    pairs_per_pass += count;
    ahead[static_cast<std::size_t>(k)] = {static_cast<float>(std::cos(heading)),
                                          static_cast<float>(std::sin(heading)),
                                          1.34f,
                                          0.1f,
                                          0.345f,
                                          0.36f,
                                          1.0f / 0.9f,
                                          0.5f,
                                          0.5f,
                                          0.1f,
                                          0.8f,
                                          1.0f / 1.5f};
  }
  const SocialParams params{2.0f, 0.35f, 1.0f / 0.35f, 2.0f, 3.0f, 2.1f};
  const auto time_kernel = [&](bool portable, bool with_ahead) {
    double best = 1e30;
    std::int64_t sink = 0;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int pass = 0; pass < passes; ++pass) {
        for (int k = 0; k < batches; ++k) {
          PairBatch& b = data[static_cast<std::size_t>(k)];
          const int n = counts[static_cast<std::size_t>(k)];
          if (portable) {
            social_kernel_portable(params, n, b.dx, b.dy, b.dvx, b.dvy, b.tie_x, b.tie_y, b.fx, b.fy);
            sink += b.fx[0];
          } else {
            const AheadParams* terms = with_ahead ? &ahead[static_cast<std::size_t>(k)] : nullptr;
            const BatchTotals t = social_kernel_with_ahead(params, terms, 1e30f, n, b.dx, b.dy, b.dvx, b.dvy,
                                                           b.tie_x, b.tie_y, b.fx, b.fy);
            sink += t.fx + t.ahead.side_push;
          }
        }
      }
      best = std::min(best, socsim::bench::seconds_since(t0));
    }
    return std::pair{best * 1e9 / static_cast<double>(pairs_per_pass * passes), sink};
  };
  const auto [fused_ns, fused_sink] = time_kernel(false, true);
  const auto [social_ns, social_sink] = time_kernel(false, false);
  const auto [portable_ns, portable_sink] = time_kernel(true, false);
  // The pair kernel of the step that computes each pair once: the same pairs, 48–56 to a batch
  // (several agents', as the step fills them), each lane with both agents' headings.
  std::vector<PairLanes> lanes;
  std::vector<int> lane_counts;
  std::int64_t lanes_per_pass = 0;
  {
    PairLanes cur{};
    int fill = 0;
    int target = 48;
    for (int k = 0; k < batches; ++k) {
      const PairBatch& b = data[static_cast<std::size_t>(k)];
      const AheadParams& h = ahead[static_cast<std::size_t>(k)];
      for (int m = 0; m < counts[static_cast<std::size_t>(k)] && b.dvx[m] != 0.0f; ++m) {
        const double other = rng.uniform(-3.14159, 3.14159);
        cur.dx[fill] = b.dx[m];
        cur.dy[fill] = b.dy[m];
        cur.dvx[fill] = b.dvx[m];
        cur.dvy[fill] = b.dvy[m];
        cur.ex_i[fill] = h.ex;
        cur.ey_i[fill] = h.ey;
        cur.along_i[fill] = 1.34f;
        cur.band_i[fill] = 0.345f;
        cur.ex_j[fill] = static_cast<float>(std::cos(other));
        cur.ey_j[fill] = static_cast<float>(std::sin(other));
        cur.along_j[fill] = 1.34f;
        cur.band_j[fill] = 0.345f;
        if (++fill == target) {
          lanes.push_back(cur);
          lane_counts.push_back(fill);
          lanes_per_pass += fill;
          cur = PairLanes{};
          fill = 0;
          target = 48 + static_cast<int>(rng.uniform() * 9.0);
        }
      }
    }
  }
  const PairAheadParams pair_ahead{0.1f, 0.36f, 1.0f / 0.9f, 0.5f, 0.5f, 0.1f, 0.8f, 1.0f / 1.5f};
  const int granule = pair_kernel_lanes();
  double pair_ns = 1e30;
  std::int64_t pair_sink = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int pass = 0; pass < passes; ++pass) {
      for (std::size_t k = 0; k < lanes.size(); ++k) {
        const int n = (lane_counts[k] + granule - 1) / granule * granule;
        pair_kernel(params, pair_ahead, n, lanes[k]);
        pair_sink += lanes[k].fx[0] + lanes[k].cap_j[0];
      }
    }
    pair_ns = std::min(pair_ns,
                       socsim::bench::seconds_since(t0) * 1e9 / static_cast<double>(lanes_per_pass * passes));
  }
  socsim::bench::emit({{"bench", "crowd-kernel"},
                       {"batches", batches},
                       {"pairs_per_batch_mean", static_cast<double>(pairs_per_pass) / batches},
                       {"fused_ns_per_pair", fused_ns},
                       {"social_only_ns_per_pair", social_ns},
                       {"portable_social_only_ns_per_pair", portable_ns},
                       // Per pair computed once: both agents' terms (two of the pairs above).
                       {"pairs_once_ns_per_pair", pair_ns},
                       {"checksum", fused_sink + social_sink + portable_sink + pair_sink}});
  return 0;
}

SOCSIM_BENCH("crowd-kernel", "[--batches 4096] [--passes 50] [--repeats 5]", crowd_kernel_bench);
