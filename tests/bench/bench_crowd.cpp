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

#include "core/common/rng.hpp"
#include "core/crowd/crowd_simulation.hpp"
#include "core/crowd/velocity_field.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/bench/bench.hpp"
#include "tests/bench/crowd_bench_scene.hpp"

namespace {

using socsim::crowd::CrowdSimulation;
using socsim::crowd::Vec2;

// The scene (tests/bench/crowd_bench_scene.hpp): N agents on a jittered 1 m lattice, walking
// back and forth between two random goals; --walls, --groups as described there.
CrowdSimulation make_crowd(std::size_t n, unsigned threads, bool walls, bool groups, std::uint64_t seed) {
  return socsim::bench::crowd_bench_simulation(socsim::bench::crowd_bench_scene(n, walls, groups, seed),
                                               threads, seed);
}

SOCSIM_BENCH("crowd", "--agents N --steps S --threads T [--walls] [--groups] [--reference-agents M]",
             [](const socsim::bench::Args& a) {
               const auto n = static_cast<std::size_t>(a.integer("agents", 10000));
               const auto steps = a.integer("steps", 200);
               const auto threads = static_cast<unsigned>(a.integer("threads", 2));
               const bool walls = a.has("walls");
               const bool groups = a.has("groups");
               CrowdSimulation sim = make_crowd(n, threads, walls, groups, 42);
               for (int k = 0; k < 10; ++k) sim.step();  // leave the lattice start behind
               const std::clock_t cpu0 = std::clock();
               const auto t0 = std::chrono::steady_clock::now();
               for (std::int64_t k = 0; k < steps; ++k) sim.step();
               const double seconds = socsim::bench::seconds_since(t0);
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
                    {"agent_steps_per_s", static_cast<double>(n) * static_cast<double>(steps) / seconds},
                    {"ms_per_step", 1000.0 * seconds / static_cast<double>(steps)},
                    {"cpu_us_per_agent_step",
                     1e6 * cpu_seconds / (static_cast<double>(n) * static_cast<double>(steps))},
                    {"state_fnv1a", fnv}});

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
