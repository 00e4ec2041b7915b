#pragma once
// The scene of `socsim-bench crowd` and of the RVO2 side-by-side driver (tests/bench/rvo2_driver):
// N agents on a jittered 1 m lattice in a square of side ceil(sqrt(N)) m, each walking back and
// forth between two random goals; optionally a wall round the square with a 0.5 m pillar every
// 8 m, and about a third of the agents in groups of 2–4 sharing their goals. docs/crowd.md
// ("Benchmark") states the scene in full; both engines are built from this one description.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/common/rng.hpp"
#include "core/crowd/crowd_simulation.hpp"

namespace socsim::bench {

struct CrowdBenchScene {
  std::vector<std::vector<crowd::Vec2>> outlines;  // closed polylines: the boundary, then pillars
  std::vector<crowd::AgentSpec> agents;
  std::vector<std::vector<crowd::Goal>> goals;  // per agent, visited cyclically
};

inline CrowdBenchScene crowd_bench_scene(std::size_t n, bool walls, bool groups, std::uint64_t seed) {
  using crowd::Goal;
  using crowd::Vec2;
  CrowdBenchScene scene;
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double size = static_cast<double>(side);
  Rng rng(seed);
  if (walls) {
    scene.outlines.push_back(
        {{-0.5, -0.5}, {size + 0.5, -0.5}, {size + 0.5, size + 0.5}, {-0.5, size + 0.5}});
    for (double px = 4.0; px < size - 2.0; px += 8.0) {
      for (double py = 4.0; py < size - 2.0; py += 8.0) {
        scene.outlines.push_back(
            {{px - 0.25, py - 0.25}, {px + 0.25, py - 0.25}, {px + 0.25, py + 0.25}, {px - 0.25, py + 0.25}});
      }
    }
  }
  std::int64_t group = -1;
  int left_in_group = 0;
  std::vector<Goal> goals;
  for (std::size_t k = 0; k < n; ++k) {
    crowd::AgentSpec spec;
    const double gx = static_cast<double>(k % side);
    const double gy = static_cast<double>(k / side);
    spec.position = {gx + 0.5 + rng.uniform(-0.2, 0.2), gy + 0.5 + rng.uniform(-0.2, 0.2)};
    if (walls && std::fmod(spec.position.x, 8.0) > 3.0 && std::fmod(spec.position.x, 8.0) < 5.0 &&
        std::fmod(spec.position.y, 8.0) > 3.0 && std::fmod(spec.position.y, 8.0) < 5.0)
      spec.position.x += 1.5;  // keep clear of the pillars
    spec.position.x = std::min(spec.position.x, size - 0.1);
    const bool new_goals = !groups || left_in_group == 0;
    if (groups) {
      if (left_in_group == 0) {
        if (rng.chance(0.33)) {
          ++group;
          left_in_group = static_cast<int>(rng.between(2, 4));
        }
      }
      if (left_in_group > 0) {
        spec.group_id = group;
        --left_in_group;
      }
    }
    if (new_goals || goals.empty())
      goals = {Goal{{rng.uniform(1.0, size - 1.0), rng.uniform(1.0, size - 1.0)}, 0.5},
               Goal{{rng.uniform(1.0, size - 1.0), rng.uniform(1.0, size - 1.0)}, 0.5}};
    scene.agents.push_back(spec);
    scene.goals.push_back(goals);
  }
  return scene;
}

// The socsim simulation of a scene (desired speeds sampled from the adult role with `seed`);
// pairs_once = false: agent by agent (SimulationConfig::pairs_once, the same bits).
inline crowd::CrowdSimulation crowd_bench_simulation(const CrowdBenchScene& scene, unsigned threads,
                                                     std::uint64_t seed, bool pairs_once = true) {
  crowd::SimulationConfig config;
  config.threads = threads;
  config.seed = seed;
  config.pairs_once = pairs_once;
  auto sim = crowd::CrowdSimulation::create(config);
  if (!sim) throw std::runtime_error(sim.error().message());
  for (const auto& outline : scene.outlines) (void)sim->add_polyline(outline, true);
  for (std::size_t k = 0; k < scene.agents.size(); ++k) {
    auto id = sim->add_agent(scene.agents[k]);
    if (!id) throw std::runtime_error(id.error().message());
    (void)sim->set_goals(*id, scene.goals[k], true);
  }
  return std::move(*sim);
}

}  // namespace socsim::bench
