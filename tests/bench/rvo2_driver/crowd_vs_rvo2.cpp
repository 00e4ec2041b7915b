// socsim-crowd-vs-rvo2 crowd-vs-rvo2: socsim's step and RVO2's (ORCA) on the same scene in one
// process, alternating blocks of steps so both see the same machine load. The scene is
// tests/bench/crowd_bench_scene.hpp; the RVO2 side uses the same start positions, radii, desired
// speeds (as maxSpeed and preferred speed), walls and pillars (as RVO2 obstacles) and cyclic goals
// (reached within 0.5 m). docs/crowd.md ("Side by side with RVO2") lists every parameter.
#include <RVO.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <thread>
#include <vector>

#include "tests/bench/bench.hpp"
#include "tests/bench/crowd_bench_scene.hpp"

namespace {

using socsim::crowd::AgentId;
using socsim::crowd::CrowdSimulation;

struct Rvo2Parameters {
  float neighbor_dist = 3.0F;      // m, as socsim's neighbour cut-off
  std::size_t max_neighbors = 10;  // RVO2's examples
  float time_horizon = 2.0F;       // s
  float time_horizon_obst = 1.0F;  // s
};

// RVO2 with the scene of `sim` (same positions, radii, desired speeds, goals).
class Rvo2Crowd {
 public:
  Rvo2Crowd(const socsim::bench::CrowdBenchScene& scene, const CrowdSimulation& sim, const Rvo2Parameters& p,
            float dt)
      : goals_(scene.goals), current_(scene.goals.size(), 0) {
    rvo_.setTimeStep(dt);
    rvo_.setAgentDefaults(p.neighbor_dist, p.max_neighbors, p.time_horizon, p.time_horizon_obst, 0.23F,
                          1.34F);
    for (std::size_t k = 0; k < scene.outlines.size(); ++k) {
      std::vector<RVO::Vector2> vertices;
      for (const auto& v : scene.outlines[k])
        vertices.emplace_back(static_cast<float>(v.x), static_cast<float>(v.y));
      // RVO2: counter-clockwise = solid obstacle (the pillars); the boundary that encloses the
      // agents is given clockwise.
      if (k == 0) std::reverse(vertices.begin(), vertices.end());
      rvo_.addObstacle(vertices);
    }
    rvo_.processObstacles();
    for (std::size_t i = 0; i < scene.agents.size(); ++i) {
      const auto id = AgentId(static_cast<std::uint32_t>(i));
      const auto p0 = scene.agents[i].position;
      const std::size_t a = rvo_.addAgent(RVO::Vector2(static_cast<float>(p0.x), static_cast<float>(p0.y)));
      rvo_.setAgentRadius(a, static_cast<float>(sim.radius(id)));
      rvo_.setAgentMaxSpeed(a, static_cast<float>(sim.desired_speed(id)));
      speed_.push_back(static_cast<float>(sim.desired_speed(id)));
    }
  }

  // Preferred velocities towards the current goals (the next one once within its radius), as
  // RVO2's examples do before each doStep() (serially: an OpenMP loop here cost more in barrier
  // waits on the shared machine than the 10,000 subtractions it spreads).
  void set_preferred_velocities() {
    for (std::size_t i = 0; i < goals_.size(); ++i) {
      const RVO::Vector2 p = rvo_.getAgentPosition(i);
      auto goal = goals_[i][current_[i]];
      RVO::Vector2 d(static_cast<float>(goal.position.x) - p.x(),
                     static_cast<float>(goal.position.y) - p.y());
      if (RVO::abs(d) < static_cast<float>(goal.radius)) {
        current_[i] = (current_[i] + 1) % goals_[i].size();
        goal = goals_[i][current_[i]];
        d = RVO::Vector2(static_cast<float>(goal.position.x) - p.x(),
                         static_cast<float>(goal.position.y) - p.y());
      }
      const float len = RVO::abs(d);
      rvo_.setAgentPrefVelocity(i, len > 0.0F ? d * (speed_[i] / len) : RVO::Vector2());
    }
  }
  void step() { rvo_.doStep(); }
  [[nodiscard]] double mean_speed() const {
    double sum = 0.0;
    for (std::size_t i = 0; i < rvo_.getNumAgents(); ++i) sum += RVO::abs(rvo_.getAgentVelocity(i));
    return sum / static_cast<double>(rvo_.getNumAgents());
  }

 private:
  RVO::RVOSimulator rvo_;
  std::vector<std::vector<socsim::crowd::Goal>> goals_;
  std::vector<std::size_t> current_;
  std::vector<float> speed_;
};

struct Timing {
  double wall_s = 0.0;
  double cpu_s = 0.0;
  template <class F>
  void add(F&& f) {
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    wall_s += socsim::bench::seconds_since(t0);
    cpu_s += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  }
};

int crowd_vs_rvo2(const socsim::bench::Args& a) {
  const auto n = static_cast<std::size_t>(a.integer("agents", 10000));
  const auto steps = a.integer("steps", 100);  // per block and engine
  const auto rounds = a.integer("rounds", 3);  // blocks per engine, alternating
  const auto threads = static_cast<unsigned>(a.integer("threads", 2));
  // Before each block of steps, untimed: the other engine's idle threads stop waiting actively
  // (socsim's pool after 1 ms, GOMP's default after its spin count), so neither engine's block
  // starts with the other's threads still spinning on the two cores.
  const auto settle = std::chrono::milliseconds(a.integer("settle-ms", 20));
  const bool walls = !a.has("no-walls");
  const bool groups = !a.has("no-groups");
  Rvo2Parameters p;
  p.neighbor_dist = static_cast<float>(a.number("neighbor-dist", p.neighbor_dist));
  p.max_neighbors =
      static_cast<std::size_t>(a.integer("max-neighbors", static_cast<std::int64_t>(p.max_neighbors)));
  p.time_horizon = static_cast<float>(a.number("time-horizon", p.time_horizon));
  p.time_horizon_obst = static_cast<float>(a.number("time-horizon-obst", p.time_horizon_obst));
  omp_set_num_threads(static_cast<int>(threads));

  const auto scene = socsim::bench::crowd_bench_scene(n, walls, groups, 42);
  CrowdSimulation sim = socsim::bench::crowd_bench_simulation(scene, threads, 42);
  Rvo2Crowd rvo(scene, sim, p, static_cast<float>(sim.config().dt));
  for (int k = 0; k < 10; ++k) {  // leave the lattice start behind, warm both
    sim.step();
    rvo.set_preferred_velocities();
    rvo.step();
  }
  Timing socsim_time;
  Timing rvo_total;                  // preferred velocities (+ doStep once the rounds are over)
  Timing rvo_step;                   // doStep alone
  std::vector<double> round_ratios;  // per round: RVO2's wall time / socsim's, the same load
  for (std::int64_t r = 0; r < rounds; ++r) {
    const double socsim_before = socsim_time.wall_s;
    const double rvo_before = rvo_total.wall_s + rvo_step.wall_s;
    std::this_thread::sleep_for(settle);
    socsim_time.add([&] {
      for (std::int64_t k = 0; k < steps; ++k) sim.step();
    });
    std::this_thread::sleep_for(settle);
    for (std::int64_t k = 0; k < steps; ++k) {
      rvo_total.add([&] { rvo.set_preferred_velocities(); });
      rvo_step.add([&] { rvo.step(); });
    }
    round_ratios.push_back((rvo_total.wall_s + rvo_step.wall_s - rvo_before) /
                           (socsim_time.wall_s - socsim_before));
  }
  rvo_total.wall_s += rvo_step.wall_s;
  rvo_total.cpu_s += rvo_step.cpu_s;
  double socsim_speed = 0.0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto v = sim.velocity(AgentId(i));
    socsim_speed += std::hypot(v.x, v.y);
  }
  const double agent_steps = static_cast<double>(n) * static_cast<double>(steps * rounds);
  const double socsim_rate = agent_steps / socsim_time.wall_s;
  const double rvo_rate = agent_steps / rvo_total.wall_s;
  const double rvo_step_rate = agent_steps / rvo_step.wall_s;
  socsim::bench::emit(
      {{"bench", "crowd-vs-rvo2"},
       {"agents", n},
       {"threads", threads},
       {"steps", steps * rounds},
       {"rounds", rounds},
       {"walls", walls},
       {"groups", groups},
       {"settle_ms", settle.count()},
       // GOMP busy-waits at RVO2's barriers unless told otherwise; on a loaded
       // machine that inflates RVO2's times (docs/crowd.md, "Side by side").
       {"omp_wait_policy", std::getenv("OMP_WAIT_POLICY") ? std::getenv("OMP_WAIT_POLICY") : "(default)"},
       {"rvo2",
        {{"neighbor_dist", p.neighbor_dist},
         {"max_neighbors", p.max_neighbors},
         {"time_horizon", p.time_horizon},
         {"time_horizon_obst", p.time_horizon_obst}}},
       {"socsim_agent_steps_per_s", socsim_rate},
       {"socsim_cpu_us_per_agent_step", 1e6 * socsim_time.cpu_s / agent_steps},
       {"rvo2_agent_steps_per_s", rvo_rate},
       {"rvo2_cpu_us_per_agent_step", 1e6 * rvo_total.cpu_s / agent_steps},
       {"rvo2_dostep_only_agent_steps_per_s", rvo_step_rate},
       {"ratio_wall", socsim_rate / rvo_rate},
       {"ratio_wall_vs_dostep_only", socsim_rate / rvo_step_rate},
       {"ratio_cpu", rvo_total.cpu_s / socsim_time.cpu_s},
       {"ratio_wall_per_round", round_ratios},
       {"ratio_wall_median_round", socsim::bench::percentile(round_ratios, 50)},
       {"socsim_mean_speed", socsim_speed / static_cast<double>(n)},
       {"rvo2_mean_speed", rvo.mean_speed()}});
  return 0;
}

SOCSIM_BENCH(
    "crowd-vs-rvo2",
    "--agents 10000 --steps 100 --rounds 3 --threads 2 [--no-walls] [--no-groups] [--neighbor-dist 3] "
    "[--max-neighbors 10] [--time-horizon 2] [--time-horizon-obst 1] [--settle-ms 20]",
    crowd_vs_rvo2);

}  // namespace
