// Validation of collective flow in a ring corridor (the geometry of the classic single- and
// multi-lane experiments; the straight periodic corridor is in validation/crowd_acceptance_test), steered
// through the behaviour layer (BtEnvironment) as scenario agents are: the speed–density relation against
// Weidmann's fundamental diagram, and lane formation in counter-flow, measured with Rex & Löwen's lane order
// parameter. Each test prints what it measured.
#include <cmath>
#include <iostream>
#include <numbers>

#include <gtest/gtest.h>

#include "core/common/rng.hpp"
#include "core/crowd/bt_environment.hpp"

namespace socsim::crowd {
namespace {

constexpr double kPi = std::numbers::pi;
// Ring corridors 2.5 m wide: inner radius 5 m (39 m long on the centre line) for the fundamental
// diagram, 6 m (45.6 m) for counter-flow.
constexpr double kWidth = 2.5;
double ring_area(double inner) {
  return kPi * ((inner + kWidth) * (inner + kWidth) - inner * inner);
}

// Weidmann (1993): v(ρ) = 1.34 · (1 − exp(−1.913 · (1/ρ − 1/5.4))).
double weidmann(double density) {
  return 1.34 * (1.0 - std::exp(-1.913 * (1.0 / density - 1.0 / 5.4)));
}

struct Ring {
  double inner = 5.0;
  CrowdSimulation sim;
  std::vector<AgentId> ids;
  std::vector<int> direction;  // +1 counter-clockwise, −1 clockwise
  std::unique_ptr<BtEnvironment> env;
};

Ring make_ring(double inner, std::size_t n, double share_clockwise, std::uint64_t seed) {
  auto created = CrowdSimulation::create(SimulationConfig{.threads = 2, .seed = seed});
  EXPECT_TRUE(created);
  Ring ring{inner, std::move(*created), {}, {}, nullptr};
  for (double r : {inner, inner + kWidth}) {
    std::vector<Vec2> circle;
    for (int k = 0; k < 96; ++k)
      circle.push_back({r * std::cos(2 * kPi * k / 96), r * std::sin(2 * kPi * k / 96)});
    EXPECT_TRUE(ring.sim.add_polyline(circle, true));
  }
  // Jittered placement on five circles 0.45 m apart, evenly spread along each.
  Rng rng(seed);
  const std::vector<double> lanes = {inner + 0.35, inner + 0.8, inner + 1.25, inner + 1.7, inner + 2.15};
  double total_length = 0.0;
  for (double r : lanes) total_length += 2 * kPi * r;
  std::size_t placed = 0;
  for (std::size_t l = 0; l < lanes.size(); ++l) {
    const double r = lanes[l];
    const auto count = l + 1 == lanes.size()
                           ? n - placed
                           : static_cast<std::size_t>(std::round(n * 2 * kPi * r / total_length));
    for (std::size_t k = 0; k < count; ++k) {
      const double a = 2 * kPi * (k + rng.uniform(-0.2, 0.2)) / static_cast<double>(count);
      const double rr = r + rng.uniform(-0.08, 0.08);
      AgentSpec spec;
      spec.position = {rr * std::cos(a), rr * std::sin(a)};
      auto id = ring.sim.add_agent(spec);
      EXPECT_TRUE(id) << id.error().message();
      ring.ids.push_back(*id);
      ring.direction.push_back(rng.chance(share_clockwise) ? -1 : 1);
    }
    placed += count;
  }
  ring.env = std::make_unique<BtEnvironment>(ring.sim, nullptr);
  return ring;
}

// Every agent heads for a point 1.5 m ahead along its own circle (the corridor's axis).
void steer(Ring& ring) {
  ring.env->begin_tick(ring.sim.time());
  for (std::size_t i = 0; i < ring.ids.size(); ++i) {
    const AgentId id = ring.ids[i];
    const Vec2 p = ring.sim.position(id);
    const double r = std::clamp(std::hypot(p.x, p.y), ring.inner + 0.3, ring.inner + kWidth - 0.3);
    const double a = std::atan2(p.y, p.x) + ring.direction[i] * 1.5 / r;
    ring.env->move_to(id, {r * std::cos(a), r * std::sin(a)}, 0.1, ring.env->base_speed(id),
                      Activity::kWalking, Routing::kDirect);
  }
  ring.env->apply();
}

double tangential_speed(const Ring& ring, std::size_t i) {
  const Vec2 p = ring.sim.position(ring.ids[i]);
  const Vec2 v = ring.sim.velocity(ring.ids[i]);
  const double r = std::hypot(p.x, p.y);
  return ring.direction[i] * (-p.y * v.x + p.x * v.y) / r;
}

// Weidmann's fundamental diagram (speed against density, pedestrians in corridors) at 0.5–4
// persons/m² in the ring, averaged over the whole ring. The model is calibrated on the straight
// periodic corridor of tests/core/crowd/validation (RiMEA 4's set-up, measured in a 2 × 2 m area:
// within ±15 % of Weidmann at 1, 2 and 3 /m²); this ring is narrower (2.5 m) and curved, and there
// the model is slow in free flow: faster walkers rarely overtake (someone within 1.5 radii of the
// walking line counts as ahead) and platoons form behind slow ones. Stated tolerance: 0.35 m/s at
// 0.5 and 1 /m², 0.2 m/s from 2 /m² on, and speeds must fall with density.
// Measured (seeds as below): 1.01, 0.76, 0.42, 0.25, 0.17 m/s against 1.30, 1.06, 0.61, 0.33, 0.16
// (before issue 22: 1.13, 0.95, 0.71, 0.42, 0.22).
TEST(CrowdFlowValidation, SpeedDensityFollowsWeidmann) {
  double previous = 10.0;
  for (double density : {0.5, 1.0, 2.0, 3.0, 4.0}) {
    const auto n = static_cast<std::size_t>(std::round(density * ring_area(5.0)));
    Ring ring = make_ring(5.0, n, 0.0, 100 + static_cast<std::uint64_t>(density * 10));
    double sum = 0.0;
    std::size_t samples = 0;
    for (int k = 0; k < 400; ++k) {  // 8 s to settle, 12 s measured
      if (k % 2 == 0) steer(ring);
      ring.sim.step();
      if (k >= 160 && k % 10 == 0) {
        for (std::size_t i = 0; i < n; ++i) sum += tangential_speed(ring, i);
        samples += n;
      }
    }
    const double speed = sum / static_cast<double>(samples);
    std::cout << "density " << density << " /m²: " << speed << " m/s (Weidmann " << weidmann(density)
              << ")\n";
    EXPECT_NEAR(speed, weidmann(density), density < 2.0 ? 0.35 : 0.2) << "density " << density;
    EXPECT_LT(speed, previous);
    previous = speed;
  }
}

// Rex & Löwen (2007) lane order parameter: φ_i = ((n_same − n_opposite)/(n_same + n_opposite))²
// over the agents in a lane-shaped neighbourhood of i (within 0.3 m across the corridor and 5 m
// along it); φ = mean over agents with neighbours. Mixed crowds give small φ, lanes φ → 1.
double lane_order(const Ring& ring) {
  double sum = 0.0;
  std::size_t counted = 0;
  for (std::size_t i = 0; i < ring.ids.size(); ++i) {
    const Vec2 p = ring.sim.position(ring.ids[i]);
    const double ri = std::hypot(p.x, p.y);
    const double ai = std::atan2(p.y, p.x);
    int same = 0;
    int other = 0;
    for (std::size_t j = 0; j < ring.ids.size(); ++j) {
      if (j == i) continue;
      const Vec2 q = ring.sim.position(ring.ids[j]);
      const double rj = std::hypot(q.x, q.y);
      const double along = std::abs(std::remainder(std::atan2(q.y, q.x) - ai, 2 * kPi)) * (ri + rj) / 2;
      if (std::abs(rj - ri) > 0.3 || along > 5.0) continue;
      (ring.direction[j] == ring.direction[i] ? same : other) += 1;
    }
    if (same + other == 0) continue;
    const double phi = static_cast<double>(same - other) / (same + other);
    sum += phi * phi;
    ++counted;
  }
  return counted > 0 ? sum / static_cast<double>(counted) : 0.0;
}

// Counter-flow at 1 person/m², half the crowd each way, randomly mixed at the start. In the
// bidirectional experiments of Zhang et al. (2012, J. Stat. Mech. P02002) lanes form within seconds
// at this density and people keep walking. Three seeds; for each, after 60 s: φ at least 0.4 (from
// about 0.2 mixed) and a mean speed along the corridor of at least 0.5 m/s (no jam). Measured:
// φ 0.98–1.0 at 0.62–0.66 m/s (before issue 22's side preference: φ 0.70–0.72 at 0.75–0.86 m/s).
TEST(CrowdFlowValidation, CounterFlowFormsLanes) {
  for (std::uint64_t seed : {70, 75, 77}) {
    const auto n = static_cast<std::size_t>(std::round(1.0 * ring_area(6.0)));
    Ring ring = make_ring(6.0, n, 0.5, seed);
    const double mixed = lane_order(ring);
    for (int k = 0; k < 1200; ++k) {  // 60 s
      if (k % 2 == 0) steer(ring);
      ring.sim.step();
    }
    const double lanes = lane_order(ring);
    double speed = 0.0;
    for (std::size_t i = 0; i < n; ++i) speed += tangential_speed(ring, i);
    speed /= static_cast<double>(n);
    std::cout << "seed " << seed << ": lane order parameter " << mixed << " mixed -> " << lanes
              << " after 60 s; mean speed " << speed << " m/s\n";
    EXPECT_LT(mixed, 0.3) << "seed " << seed;
    EXPECT_GE(lanes, 0.4) << "seed " << seed;
    EXPECT_GE(speed, 0.5) << "seed " << seed;
  }
}

}  // namespace
}  // namespace socsim::crowd
