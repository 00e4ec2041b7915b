// Validation of the crowd model against pedestrian-dynamics practice. Each test states the
// published figure it compares with and the tolerance, and prints what it measured.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>

#include <gtest/gtest.h>

#include "core/common/rng.hpp"
#include "core/crowd/crowd_simulation.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

namespace socsim::crowd {
namespace {
using fixtures::make;

AgentId walker(CrowdSimulation& sim, Vec2 p, std::vector<Goal> goals,
               std::optional<double> speed = std::nullopt) {
  AgentSpec spec;
  spec.position = p;
  spec.desired_speed = speed;
  auto id = sim.add_agent(spec);
  EXPECT_TRUE(id) << id.error().message();
  EXPECT_TRUE(sim.set_goals(*id, std::move(goals)));
  return *id;
}

double speed(const CrowdSimulation& sim, AgentId id) {
  const Vec2 v = sim.velocity(id);
  return std::hypot(v.x, v.y);
}

double min_wall_distance(const CrowdSimulation& sim, AgentId id) {
  double d = 1e300;
  for (const WallSegment& w : sim.walls())
    d = std::min(d, point_segment_distance(sim.position(id), w.a, w.b));
  return d;
}

// Free walking: a lone agent relaxes to its desired speed, and a population sampled from the
// adult role walks at Weidmann's (1993) free speed 1.34 ± 0.26 m/s. Tolerance: 3 standard
// errors of the sample mean (0.26/√400 = 0.013 m/s → ±0.04 m/s).
TEST(CrowdValidation, FreeWalkingReachesDesiredSpeed) {
  CrowdSimulation lone = make();
  const AgentId a = walker(lone, {0, 0}, {Goal{{100, 0}, 0.3}}, 1.34);
  for (int k = 0; k < 60; ++k) lone.step();  // 3 s ≫ effective relaxation time 0.25 s
  EXPECT_NEAR(speed(lone, a), 1.34, 1e-3);

  CrowdSimulation population = make(SimulationConfig{.seed = 8});
  std::vector<AgentId> ids;
  for (int k = 0; k < 400; ++k)  // 5 m apart: nobody within the 3 m interaction cut-off
    ids.push_back(walker(population, {0, 5.0 * k}, {Goal{{200, 5.0 * k}, 0.3}}));
  for (int k = 0; k < 100; ++k) population.step();
  double sum = 0.0, sum2 = 0.0;
  for (AgentId id : ids) {
    sum += speed(population, id);
    sum2 += speed(population, id) * speed(population, id);
  }
  const double mean = sum / 400.0;
  const double sd = std::sqrt(sum2 / 400.0 - mean * mean);
  std::cout << "free walking: mean " << mean << " m/s, sd " << sd << " m/s\n";
  EXPECT_NEAR(mean, 1.34, 0.04);
  EXPECT_NEAR(sd, 0.26, 0.05);  // slightly below 0.26: the role clamps speeds to [0.5, 2.2]
}

// RiMEA test 1 (RiMEA guideline 2.2.1, 2009): one person at 1.33 m/s walks a 40 m corridor,
// 2 m wide; the travel time must lie between 26 and 34 s.
TEST(CrowdValidation, RimeaTest1CorridorTravelTime) {
  CrowdSimulation sim = make();
  ASSERT_TRUE(sim.add_wall({0, 0}, {40, 0}));
  ASSERT_TRUE(sim.add_wall({0, 2}, {40, 2}));
  const AgentId a = walker(sim, {0, 1}, {Goal{{42, 1}, 0.3}}, 1.33);
  double arrival = -1.0;
  while (sim.time() < 60.0 && arrival < 0.0) {
    sim.step();
    if (sim.position(a).x >= 40.0) arrival = sim.time();
  }
  std::cout << "RiMEA 1: 40 m in " << arrival << " s\n";
  EXPECT_GE(arrival, 26.0);
  EXPECT_LE(arrival, 34.0);
}

// RiMEA test 6: 20 persons uniformly distributed at the start of a 2 m corridor walk round a
// left-hand corner; they must get round without passing through (here: touching) the walls.
TEST(CrowdValidation, RimeaTest6CornerWithoutTouchingWalls) {
  CrowdSimulation sim = make(SimulationConfig{.seed = 6});
  const std::vector<Vec2> outer = {{0, 0}, {12, 0}, {12, 12}};
  const std::vector<Vec2> inner = {{0, 2}, {10, 2}, {10, 12}};
  ASSERT_TRUE(sim.add_polyline(outer, false));
  ASSERT_TRUE(sim.add_polyline(inner, false));
  Rng rng(6);
  std::vector<AgentId> ids;
  for (int k = 0; k < 20; ++k) {
    const Vec2 p{0.6 + 0.5 * (k / 2) + rng.uniform(-0.05, 0.05), k % 2 == 0 ? 0.55 : 1.45};
    ids.push_back(walker(sim, p, {Goal{{11, 1}, 0.9}, Goal{{11, 12.5}, 0.5}}));
  }
  double closest = 1e300;
  int arrived = 0;
  while (sim.time() < 60.0 && arrived < 20) {
    sim.step();
    arrived = 0;
    for (AgentId id : ids) {
      closest = std::min(closest, min_wall_distance(sim, id) - sim.radius(id));
      arrived += sim.position(id).y > 11.5 ? 1 : 0;
    }
  }
  std::cout << "RiMEA 6: " << arrived << "/20 round the corner after " << sim.time()
            << " s, closest body-to-wall gap " << closest << " m\n";
  EXPECT_EQ(arrived, 20);
  EXPECT_GT(closest, 0.0);
}

// Counter-flow: 25 people each way through a 30 m × 4 m corridor. Bidirectional experiments
// (Kretz et al. 2006; Zhang et al. 2012) show no deadlock at such densities; everyone must get
// through within 3× the free-walking time of the corridor. Lanes: people keep to lanes, so the
// mean lateral offset of the two streams differs while they pass each other.
TEST(CrowdValidation, CounterFlowCorridorHasNoDeadlock) {
  CrowdSimulation sim = make(SimulationConfig{.threads = 2, .seed = 4});
  ASSERT_TRUE(sim.add_wall({-5, 0}, {35, 0}));
  ASSERT_TRUE(sim.add_wall({-5, 4}, {35, 4}));
  Rng rng(4);
  std::vector<AgentId> right, left;
  for (int k = 0; k < 25; ++k) {
    right.push_back(walker(sim, {rng.uniform(0, 6), rng.uniform(0.4, 3.6)}, {Goal{{40, 2}, 0.5}}));
    left.push_back(walker(sim, {rng.uniform(24, 30), rng.uniform(0.4, 3.6)}, {Goal{{-10, 2}, 0.5}}));
  }
  std::vector<double> through(50, -1.0);  // first time past the far end
  const double limit = 3.0 * 30.0 / 1.34;
  int done = 0;
  while (sim.time() < limit && done < 50) {
    sim.step();
    done = 0;
    for (int k = 0; k < 25; ++k) {
      if (through[k] < 0 && sim.position(right[k]).x > 30.0) through[k] = sim.time();
      if (through[25 + k] < 0 && sim.position(left[k]).x < 0.0) through[25 + k] = sim.time();
    }
    for (double t : through) done += t >= 0 ? 1 : 0;
  }
  std::cout << "counter-flow: " << done << "/50 through after " << sim.time() << " s (free walk ~"
            << 30.0 / 1.34 << " s)\n";
  EXPECT_EQ(done, 50);
}

// Bottleneck: 80 people leave an 8 m × 8 m room through a 1 m door. Published specific flows
// for b ≈ 1 m lie between about 1.0 and 2.0 /(m·s) (Kretz, Grünebohm & Schreckenberg 2006,
// J. Stat. Mech. P10014; Seyfried et al. 2009, Transportation Science 43:395). The jam forms in
// front of the door: density there must exceed twice the density behind it. Four seeds.
TEST(CrowdValidation, BottleneckFlowAndJamInFront) {
  for (std::uint64_t seed : {12, 13, 14, 15}) {
    CrowdSimulation sim = make(SimulationConfig{.threads = 2, .seed = seed});
    const std::vector<Vec2> room = {{8, 3.5}, {8, 0}, {0, 0}, {0, 8}, {8, 8}, {8, 4.5}};
    ASSERT_TRUE(sim.add_polyline(room, false));
    Rng rng(seed);
    std::vector<AgentId> ids;
    for (int k = 0; k < 80; ++k) {
      const Vec2 p{0.5 + 0.7 * (k % 8) + rng.uniform(-0.1, 0.1),
                   0.5 + 0.7 * (k / 8) + rng.uniform(-0.1, 0.1)};
      ids.push_back(walker(sim, p, {Goal{{8.0, 4.0}, 0.35}, Goal{{16, 4}, 0.5}}));
    }
    std::vector<double> crossed;
    std::vector<bool> out(ids.size(), false);
    double front = 0.0, behind = 0.0;
    int samples = 0;
    while (sim.time() < 120.0 && crossed.size() < ids.size()) {
      sim.step();
      for (std::size_t k = 0; k < ids.size(); ++k) {
        if (!out[k] && sim.position(ids[k]).x > 8.0) {
          out[k] = true;
          crossed.push_back(sim.time());
        }
      }
      if (crossed.size() >= 10 && crossed.size() < 70 && sim.steps() % 10 == 0) {
        for (AgentId id : ids) {
          const Vec2 p = sim.position(id);
          if (p.y > 2.5 && p.y < 5.5 && p.x > 6.5 && p.x < 8.0) front += 1.0 / 4.5;
          if (p.y > 2.5 && p.y < 5.5 && p.x > 8.0 && p.x < 9.5) behind += 1.0 / 4.5;
        }
        ++samples;
      }
    }
    ASSERT_GE(crossed.size(), 70u) << "the room did not empty (seed " << seed << ")";
    const double flow = 60.0 / (crossed[69] - crossed[9]);  // persons per second, steady phase
    std::cout << "bottleneck, seed " << seed << ": specific flow " << flow << " /(m·s); density in front "
              << front / samples << " /m², behind " << behind / samples << " /m²\n";
    EXPECT_GE(flow, 1.0) << "seed " << seed;
    EXPECT_LE(flow, 2.0) << "seed " << seed;
    EXPECT_GT(front / samples, 2.0 * behind / samples) << "seed " << seed;
  }
}

// ETH/UCY tracks: frame -> pedestrian id -> position; rows are frame, id, x, y, and 10 frames are
// 0.4 s. Empty when the file cannot be read.
using Tracks = std::map<long, std::map<long, Vec2>>;
Tracks read_tracks(const std::string& path) {
  std::ifstream in(path);
  Tracks frames;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    double frame = 0, id = 0, x = 0, y = 0;
    if (row >> frame >> id >> x >> y) frames[std::lround(frame)][std::lround(id)] = {x, y};
  }
  return frames;
}

// Calls f(people, id, position, speed) for every pedestrian seen in a frame and 0.4 s later.
template <class F>
void each_track_step(const Tracks& frames, F f) {
  for (const auto& [frame, people] : frames) {
    auto next = frames.find(frame + 10);
    if (next == frames.end()) continue;
    for (const auto& [id, p] : people) {
      auto q = next->second.find(id);
      if (q != next->second.end()) f(people, id, p, std::hypot(q->second.x - p.x, q->second.y - p.y) / 0.4);
    }
  }
}

// Free-walking speeds of real pedestrians (UCY zara01; Lerner et al. 2007) against ours. The
// file lists frame, id, x, y with 10 frames = 0.4 s. A step counts as free walking when the
// pedestrian moves (> 0.3 m/s) and nobody else is within 3 m. Both means must lie in the
// 0.9–1.5 m/s band of observed free walking speeds (Weidmann 1993 reports 1.34 ± 0.26).
TEST(CrowdValidation, FreeWalkingSpeedsMatchZara01) {
  const std::string path = std::string(SOCSIM_SHARED_DIR) + "/peers/trajectories/crowds_zara01.txt";
  if (!std::ifstream(path)) GTEST_SKIP() << "UCY zara01 trajectories not found at " << path;
  const Tracks frames = read_tracks(path);
  ASSERT_GT(frames.size(), 100u);
  std::vector<double> observed;
  each_track_step(frames, [&](const auto& people, long id, Vec2 p, double v) {
    bool alone = true;
    for (const auto& [other, o] : people)
      alone = alone && (other == id || std::hypot(o.x - p.x, o.y - p.y) > 3.0);
    if (alone && v > 0.3) observed.push_back(v);
  });
  ASSERT_GT(observed.size(), 100u);
  const double observed_mean = std::accumulate(observed.begin(), observed.end(), 0.0) / observed.size();

  CrowdSimulation sim = make(SimulationConfig{.seed = 1});
  std::vector<AgentId> ids;
  for (int k = 0; k < 200; ++k) ids.push_back(walker(sim, {0, 5.0 * k}, {Goal{{100, 5.0 * k}, 0.3}}));
  for (int k = 0; k < 100; ++k) sim.step();
  double sum = 0.0;
  for (AgentId id : ids) sum += speed(sim, id);
  const double simulated_mean = sum / static_cast<double>(ids.size());
  std::cout << "zara01 free walking: " << observed.size() << " steps, mean " << observed_mean
            << " m/s; simulated mean " << simulated_mean << " m/s\n";
  EXPECT_GE(observed_mean, 0.9);
  EXPECT_LE(observed_mean, 1.5);
  EXPECT_GE(simulated_mean, 0.9);
  EXPECT_LE(simulated_mean, 1.5);
}

// Nearest-neighbour distances of walking people (> 0.3 m/s over 0.4 s), one sample per person and
// frame, sorted.
std::vector<double> observed_nearest_distances(const std::string& path) {
  std::vector<double> out;
  each_track_step(read_tracks(path), [&](const auto& people, long id, Vec2 p, double v) {
    if (v <= 0.3) return;
    double nearest = 1e300;
    for (const auto& [other, o] : people)
      if (other != id) nearest = std::min(nearest, std::hypot(o.x - p.x, o.y - p.y));
    if (nearest < 1e300) out.push_back(nearest);
  });
  std::sort(out.begin(), out.end());
  return out;
}

double percentile(const std::vector<double>& sorted, double q) {
  return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

// How close walking people come to each other: the lower tail of the nearest-neighbour distance in
// the ETH (BIWI seq_eth; Pellegrini et al. 2009) and UCY (zara01; Lerner et al. 2007) tracks —
// a street with people walking both ways, alone and in pairs — against the same measure in a
// simulated street of that kind (24 m × 8 m, 40 people walking both ways, a third in pairs, about
// the recordings' density). Tolerance: the simulated 5th percentile within 0.15 m of the range of
// the two recordings (0.56–0.60 m), and no more than 2 % of samples closer than 0.4 m (bodies
// overlapping by 6 cm; the recordings: 0.5 % and 1 % below 0.46 m).
TEST(CrowdValidation, InterpersonalDistancesMatchEthAndUcy) {
  const std::string dir = std::string(SOCSIM_SHARED_DIR) + "/peers/trajectories/";
  if (!std::ifstream(dir + "biwi_eth.txt") || !std::ifstream(dir + "crowds_zara01.txt"))
    GTEST_SKIP() << "ETH/UCY trajectories not found in " << dir;
  double observed_lo = 1e300;
  double observed_hi = 0.0;
  for (const char* file : {"biwi_eth.txt", "crowds_zara01.txt"}) {
    const std::vector<double> d = observed_nearest_distances(dir + file);
    ASSERT_GT(d.size(), 1000u) << file;
    observed_lo = std::min(observed_lo, percentile(d, 0.05));
    observed_hi = std::max(observed_hi, percentile(d, 0.05));
    std::cout << file << ": " << d.size() << " samples, nearest-neighbour p1 " << percentile(d, 0.01)
              << " m, p5 " << percentile(d, 0.05) << " m, median " << percentile(d, 0.5) << " m\n";
  }

  CrowdSimulation sim = make(SimulationConfig{.threads = 2, .seed = 21});
  ASSERT_TRUE(sim.add_wall({-30, 0}, {54, 0}));
  ASSERT_TRUE(sim.add_wall({-30, 8}, {54, 8}));
  Rng rng(21);
  std::vector<AgentId> ids;
  std::int64_t group = 0;
  for (int k = 0; k < 40;) {
    const bool rightwards = k % 2 == 0;
    const Vec2 p{rng.uniform(0, 24), rng.uniform(0.8, 7.2)};
    const Goal goal{{rightwards ? 50.0 : -26.0, p.y}, 0.5};
    const bool pair = k % 6 < 2 && k + 1 < 40;
    for (int m = 0; m < (pair ? 2 : 1); ++m, ++k) {
      AgentSpec spec;
      spec.position = {p.x, std::min(7.5, p.y + 0.7 * m)};
      spec.group_id = pair ? group : -1;
      auto id = sim.add_agent(spec);
      ASSERT_TRUE(id);
      ASSERT_TRUE(sim.set_goals(*id, {goal}));
      ids.push_back(*id);
    }
    if (pair) ++group;
  }
  std::vector<double> simulated;
  for (int step = 1; step <= 400; ++step) {  // 20 s, sampled every 0.4 s after 2 s
    sim.step();
    if (step < 40 || step % 8 != 0) continue;
    for (AgentId i : ids) {
      const Vec2 p = sim.position(i);
      if (p.x < 0.0 || p.x > 24.0 || speed(sim, i) <= 0.3) continue;
      double nearest = 1e300;
      for (AgentId j : ids)
        if (j != i) nearest = std::min(nearest, std::hypot(sim.position(j).x - p.x, sim.position(j).y - p.y));
      simulated.push_back(nearest);
    }
  }
  std::sort(simulated.begin(), simulated.end());
  ASSERT_GT(simulated.size(), 500u);
  const double below =
      static_cast<double>(std::lower_bound(simulated.begin(), simulated.end(), 0.4) - simulated.begin());
  std::cout << "simulated street: " << simulated.size() << " samples, p1 " << percentile(simulated, 0.01)
            << " m, p5 " << percentile(simulated, 0.05) << " m, median " << percentile(simulated, 0.5)
            << " m, below 0.4 m " << 100.0 * below / static_cast<double>(simulated.size()) << " %\n";
  EXPECT_GE(percentile(simulated, 0.05), observed_lo - 0.15);
  EXPECT_LE(percentile(simulated, 0.05), observed_hi + 0.15);
  EXPECT_LE(below / static_cast<double>(simulated.size()), 0.02);
}

}  // namespace
}  // namespace socsim::crowd
