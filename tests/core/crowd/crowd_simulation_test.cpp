// CrowdSimulation: validation of inputs, LightSFM's force terms, determinism (seed and thread
// count), agreement with the O(N²) reference, and the hard guarantees: no wall crossing, no NaN.
#include "core/crowd/crowd_simulation.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"

#include <cmath>
#include <cstring>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/common/rng.hpp"

namespace socsim::crowd {
namespace {
using fixtures::make;

using ::testing::Contains;
using ::testing::Field;

AgentId add(CrowdSimulation& sim, Vec2 p, Vec2 v = {}, double speed = 1.3, std::int64_t group = -1) {
  AgentSpec spec;
  spec.position = p;
  spec.velocity = v;
  spec.desired_speed = speed;
  spec.group_id = group;
  auto id = sim.add_agent(spec);
  EXPECT_TRUE(id) << id.error().message();
  return *id;
}

constexpr double kAdultRadius = 0.23;  // the default role's body radius

// A crowd for determinism and reference checks: random positions in a walled 20×20 m room with
// two inner walls, groups of 3, goals across the room.
CrowdSimulation busy_room(std::size_t n, unsigned threads, std::uint64_t seed) {
  SimulationConfig config;
  config.threads = threads;
  config.seed = seed;
  CrowdSimulation sim = make(config);
  const std::vector<Vec2> box = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
  EXPECT_TRUE(sim.add_polyline(box, true));
  EXPECT_TRUE(sim.add_wall({7, 4}, {7, 12}));
  EXPECT_TRUE(sim.add_wall({12, 16}, {16, 10}));
  Rng rng(seed);
  for (std::size_t k = 0; k < n; ++k) {
    AgentSpec spec;
    spec.position = {rng.uniform(0.5, 19.5), rng.uniform(0.5, 19.5)};
    spec.group_id = k % 4 == 0 ? -1 : static_cast<std::int64_t>(k / 3);
    auto id = sim.add_agent(spec);
    EXPECT_TRUE(id);
    EXPECT_TRUE(sim.set_goals(*id,
                              {Goal{{rng.uniform(1, 19), rng.uniform(1, 19)}, 0.5},
                               Goal{{rng.uniform(1, 19), rng.uniform(1, 19)}, 0.5}},
                              true));
  }
  return sim;
}

std::vector<double> snapshot(const CrowdSimulation& sim) {
  std::vector<double> out;
  for (std::uint32_t i = 0; i < sim.size(); ++i) {
    const Vec2 p = sim.position(AgentId(i));
    const Vec2 v = sim.velocity(AgentId(i));
    out.insert(out.end(), {p.x, p.y, v.x, v.y, sim.yaw(AgentId(i))});
  }
  return out;
}

bool bit_identical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// ---- validation ---------------------------------------------------------------------------

TEST(CrowdSimulation, RejectsBadConfiguration) {
  SimulationConfig c;
  c.dt = 1.0;  // huge steps are rejected, not integrated
  c.neighbor_cutoff = 0.0;
  c.threads = 0;
  c.body_stiffness = -1;
  auto sim = CrowdSimulation::create(c);
  ASSERT_FALSE(sim);
  const auto& e = sim.error().errors;
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/dt")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/neighbor_cutoff")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/threads")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/body_stiffness")));
  c = {};
  c.dt = std::nan("");
  EXPECT_FALSE(CrowdSimulation::create(c));
}

TEST(CrowdSimulation, RejectsBadAgentsWallsAndGoals) {
  CrowdSimulation sim = make();
  AgentSpec spec;
  spec.position = {std::nan(""), 0};
  spec.velocity = {1e9, 0};
  spec.role = "astronaut";
  spec.desired_speed = -1;
  spec.radius = 0;
  spec.group_id = -5;
  auto bad = sim.add_agent(spec);
  ASSERT_FALSE(bad);
  const auto& e = bad.error().errors;
  for (const char* p : {"/position", "/velocity", "/role", "/desired_speed", "/radius", "/group_id"})
    EXPECT_THAT(e, Contains(Field(&FieldError::pointer, p))) << p;
  EXPECT_EQ(sim.size(), 0u);

  EXPECT_FALSE(sim.add_wall({0, 0}, {INFINITY, 1}));
  EXPECT_FALSE(sim.add_wall({1e7, 0}, {0, 0}));
  const AgentId a = add(sim, {0, 0});
  EXPECT_FALSE(sim.set_goal(a, Goal{{std::nan(""), 0}, 0.3}));
  EXPECT_FALSE(sim.set_goal(a, Goal{{1, 0}, -1}));
  auto missing = sim.set_goal(AgentId(99), Goal{{1, 0}, 0.3});
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, ErrorCode::kNotFound);
  EXPECT_FALSE(sim.set_desired_speed(a, 100.0));
}

TEST(CrowdSimulation, StateCarriesTheMessageFields) {
  CrowdSimulation sim = make();
  AgentSpec spec;
  spec.position = {1, 2};
  spec.velocity = {0, 0.5};
  spec.role = "staff";
  spec.group_id = 7;
  spec.activity = Activity::kQueuing;
  spec.intent.target = "counter_1";
  spec.tags = {"spotlight"};
  auto id = sim.add_agent(spec);
  ASSERT_TRUE(id);
  ASSERT_TRUE(sim.set_bt_node(*id, "JoinQueue"));
  ASSERT_TRUE(sim.set_goal(*id, Goal{{5, 5}, 0.2}));
  const PedestrianState s = sim.state(*id);
  EXPECT_EQ(s.role, "staff");
  EXPECT_EQ(s.group_id, 7);
  EXPECT_EQ(s.activity, Activity::kQueuing);
  EXPECT_EQ(s.intent.target, "counter_1");
  EXPECT_EQ(s.intent.goal_id, 0);
  EXPECT_EQ(s.metadata.bt_node, "JoinQueue");
  EXPECT_EQ(s.metadata.tags, std::vector<std::string>{"spotlight"});
  EXPECT_NEAR(s.pose.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_GE(sim.desired_speed(*id), 0.8);  // sampled from the staff distribution
  EXPECT_LE(sim.desired_speed(*id), 2.2);
  auto round = pedestrian_state_from_json(to_json(s));
  ASSERT_TRUE(round);
  EXPECT_EQ(*round, s);
}

// ---- force terms (LightSFM) -----------------------------------------------------------------

// LightSFM's computeSocialForce for one pair, written out independently in double precision.
Vec2 lightsfm_social(Vec2 pi, Vec2 vi, Vec2 pj, Vec2 vj, const ForceParameters& f) {
  const double dx = pj.x - pi.x, dy = pj.y - pi.y, d = std::hypot(dx, dy);
  const double ex = dx / d, ey = dy / d;
  const double ix = f.lambda * (vi.x - vj.x) + ex, iy = f.lambda * (vi.y - vj.y) + ey;
  const double il = std::hypot(ix, iy), tx = ix / il, ty = iy / il;
  double theta = std::atan2(ey, ex) - std::atan2(ty, tx);
  while (theta <= -std::numbers::pi) theta += 2 * std::numbers::pi;
  while (theta > std::numbers::pi) theta -= 2 * std::numbers::pi;
  const double b = f.gamma * il;
  const double along = -std::exp(-d / b - std::pow(f.n_prime * b * theta, 2));
  const double sign = theta > 0 ? 1.0 : (theta < 0 ? -1.0 : 0.0);
  const double side = -sign * std::exp(-d / b - std::pow(f.n * b * theta, 2));
  return {f.social_factor * (along * tx + side * -ty), f.social_factor * (along * ty + side * tx)};
}

TEST(CrowdSimulation, SocialForceMatchesLightSfmFormula) {
  Rng rng(3);
  const ForceParameters f;
  for (int trial = 0; trial < 200; ++trial) {
    CrowdSimulation sim = make();
    const Vec2 pi{0, 0};
    const Vec2 vi{rng.uniform(-1.3, 1.3), rng.uniform(-1.3, 1.3)};
    const Vec2 pj{rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5)};
    const Vec2 vj{rng.uniform(-1.3, 1.3), rng.uniform(-1.3, 1.3)};
    if (norm({pj.x, pj.y}) < 0.1 || norm(pj) > 2.9) continue;
    const AgentId i = add(sim, pi, vi, 2.0);
    add(sim, pj, vj, 2.0);
    const Vec2 expected = lightsfm_social(pi, vi, pj, vj, f);
    const Vec2 got = sim.forces(i).social;
    const double tol = 1e-5 + 1e-5 * norm(expected);  // single-precision kernel
    EXPECT_NEAR(got.x, expected.x, tol) << "trial " << trial;
    EXPECT_NEAR(got.y, expected.y, tol) << "trial " << trial;
  }
}

TEST(CrowdSimulation, HeadOnAgentsRepelAndGoalAttracts) {
  CrowdSimulation sim = make();
  const AgentId a = add(sim, {0, 0}, {1, 0});
  add(sim, {1.5, 0.2}, {-1, 0});
  ASSERT_TRUE(sim.set_goal(a, Goal{{10, 0}, 0.3}));
  const ForceBreakdown f = sim.forces(a);
  EXPECT_LT(f.social.x, 0.0);  // slowed down by the oncoming agent
  EXPECT_LT(f.social.y, 0.0);  // and pushed to the side away from it
  // Desired force: 2.0·(1.3·e − v)/0.5 with v = (1, 0).
  EXPECT_NEAR(f.desired.x, 2.0 * (1.3 - 1.0) / 0.5, 1e-12);
  EXPECT_NEAR(f.desired.y, 0.0, 1e-12);
}

TEST(CrowdSimulation, ObstacleForceIsLightSfmsExponential) {
  CrowdSimulation sim = make();
  ASSERT_TRUE(sim.add_wall({-5, 0}, {5, 0}));
  const AgentId a = add(sim, {0, 0.8});
  const ForceBreakdown f = sim.forces(a);
  EXPECT_NEAR(f.obstacle.x, 0.0, 1e-12);
  EXPECT_NEAR(f.obstacle.y, 10.0 * std::exp(-(0.8 - kAdultRadius) / 0.2), 1e-9);
  // A corner seen from outside: the shared vertex pushes once, not twice.
  CrowdSimulation corner = make();
  ASSERT_TRUE(corner.add_wall({0, 0}, {0, 5}));
  ASSERT_TRUE(corner.add_wall({0, 0}, {5, 0}));
  const AgentId c = add(corner, {-0.6, -0.8});
  EXPECT_NEAR(norm(corner.forces(c).obstacle), 10.0 * std::exp(-(1.0 - kAdultRadius) / 0.2), 1e-9);
}

// A wall cut into pieces pushes like the whole wall: the ends where pieces meet are not extra
// obstacles (each end pushes only where it is the nearest point of every wall meeting there).
TEST(CrowdSimulation, PolylineWallsPushLikeOneSmoothWall) {
  CrowdSimulation whole = make();
  ASSERT_TRUE(whole.add_wall({-5, 0}, {5, 0}));
  CrowdSimulation pieces = make();
  const std::vector<Vec2> line = {{-5, 0}, {-0.4, 0}, {0.3, 0}, {0.9, 0}, {5, 0}};
  ASSERT_TRUE(pieces.add_polyline(line, false));
  for (const Vec2 p : {Vec2{0, 0.5}, Vec2{0.3, 0.7}, Vec2{-0.2, 0.35}}) {
    CrowdSimulation a = make();
    ASSERT_TRUE(a.add_wall({-5, 0}, {5, 0}));
    CrowdSimulation b = make();
    ASSERT_TRUE(b.add_polyline(line, false));
    const Vec2 fa = a.forces(add(a, p)).obstacle;
    const Vec2 fb = b.forces(add(b, p)).obstacle;
    EXPECT_NEAR(fb.x, fa.x, 1e-12) << p.x;
    EXPECT_NEAR(fb.y, fa.y, 1e-12) << p.x;
  }
  // Inside a circle of 96 sides (radius 5 m), 0.6 m from the wall: the push is that of the nearest
  // side alone, pointing to the centre (before, each of the 12 vertices within the 2 m cut-off
  // added its own push and the ring pushed 3.6 times as hard here).
  CrowdSimulation ring = make();
  std::vector<Vec2> circle;
  for (int k = 0; k < 96; ++k)
    circle.push_back({5 * std::cos(2 * std::numbers::pi * (k + 0.5) / 96),
                      5 * std::sin(2 * std::numbers::pi * (k + 0.5) / 96)});
  ASSERT_TRUE(ring.add_polyline(circle, true));
  const double apothem = 5 * std::cos(std::numbers::pi / 96);
  const Vec2 f = ring.forces(add(ring, {apothem - 0.6, 0})).obstacle;
  EXPECT_NEAR(f.x, -10.0 * std::exp(-(0.6 - kAdultRadius) / 0.2), 1e-9);
  EXPECT_NEAR(f.y, 0.0, 1e-9);
}

TEST(CrowdSimulation, GroupForcesPullMembersTogether) {
  CrowdSimulation sim = make();
  const AgentId a = add(sim, {0, 0}, {}, 1.3, 5);
  add(sim, {4, 0}, {}, 1.3, 5);
  add(sim, {4, 1}, {}, 1.3, 5);
  const ForceBreakdown f = sim.forces(a);
  EXPECT_GT(f.group.x, 0.5);  // coherence towards the others
  // Gaze: walking away from the group (goal at −x) slows the agent along its direction.
  ASSERT_TRUE(sim.set_goal(a, Goal{{-10, 0}, 0.3}));
  const ForceBreakdown g = sim.forces(a);
  EXPECT_GT(g.group.x, f.group.x);
  // Repulsion between touching members.
  CrowdSimulation pair = make();
  const AgentId p = add(pair, {0, 0}, {}, 1.3, 1);
  add(pair, {0.4, 0}, {}, 1.3, 1);
  CrowdSimulation strangers = make();
  const AgentId s = add(strangers, {0, 0});
  add(strangers, {0.4, 0});
  EXPECT_LT(pair.forces(p).group.x, 0.0);
  EXPECT_EQ(strangers.forces(s).group.x, 0.0);
  // Groups can be formed and left while running (behaviour trees' SetGroupId, SetGroupWalk).
  ASSERT_TRUE(strangers.set_group(s, 9));
  ASSERT_TRUE(strangers.set_group(AgentId(1), 9));
  EXPECT_LT(strangers.forces(s).group.x, 0.0);
  EXPECT_EQ(strangers.state(s).group_id, 9);
  ASSERT_TRUE(strangers.set_group(s, -1));
  EXPECT_EQ(strangers.forces(s).group.x, 0.0);
  EXPECT_EQ(strangers.state(s).group_id, -1);
  EXPECT_FALSE(strangers.set_group(s, -2));
  EXPECT_FALSE(strangers.set_group(AgentId(7), 1));
}

// Speed–headway adaptation: following someone 0.9 m ahead on the walking line at the same speed
// caps the desired speed at (0.9 − 0.4)/0.6 = 0.83 m/s; closing in on them at 0.3 m/s takes the
// gap 2.5 s ahead, 0.9 − 0.75 m, which is below 0.4 m: stop. Someone beside the line (beyond 1.5
// radii), behind, or coming the other way does not cap the speed.
TEST(CrowdSimulation, FollowersSlowToTheirHeadway) {
  const auto desired_x = [](Vec2 other, Vec2 other_velocity) {
    CrowdSimulation sim = make();
    const AgentId a = add(sim, {0, 0}, {1.3, 0});
    add(sim, other, other_velocity);
    EXPECT_TRUE(sim.set_goal(a, Goal{{20, 0}, 0.3}));
    return sim.forces(a).desired.x;
  };
  EXPECT_NEAR(desired_x({0.9, 0.0}, {1.3, 0}), 2.0 * ((0.9 - 0.4) / 0.6 - 1.3) / 0.5, 1e-5);
  EXPECT_NEAR(desired_x({0.9, 0.0}, {1.0, 0}), 2.0 * (0.0 - 1.3) / 0.5, 1e-5);  // closing in
  EXPECT_NEAR(desired_x({0.9, 0.4}, {1.0, 0}), 0.0, 1e-12);                     // beside the walking line
  EXPECT_NEAR(desired_x({-0.9, 0.0}, {1.0, 0}), 0.0, 1e-12);                    // behind
  EXPECT_NEAR(desired_x({0.9, 0.0}, {-1.0, 0}), 0.0, 1e-12);  // oncoming: left to the social force
  EXPECT_NEAR(desired_x({0.3, 0.0}, {0.0, 0}), 2.0 * (0.0 - 1.3) / 0.5, 1e-12);  // closer than 0.4 m: stop
}

// The zipper: in a narrow opening (walls within zipper_reach on both sides of the walking line)
// someone 0.2 m beside the line — inside the 1.5-radius band, outside the 0.75-radius one — no
// longer caps the follower's speed; in the open, or in a 2 m wide door, it does. Someone
// straight ahead caps it in the opening too.
TEST(CrowdSimulation, ZipperLanesInNarrowOpenings) {
  const auto desired_x = [](double door, Vec2 other) {
    CrowdSimulation sim = make();
    if (door > 0.0) {  // a thin wall across x = 0.3 with an opening of width `door` round y = 0
      EXPECT_TRUE(sim.add_wall({0.3, door / 2.0}, {0.3, 5.0}));
      EXPECT_TRUE(sim.add_wall({0.3, -5.0}, {0.3, -door / 2.0}));
    }
    const AgentId a = add(sim, {0, 0}, {1.0, 0});
    add(sim, other, {1.0, 0});
    EXPECT_TRUE(sim.set_goal(a, Goal{{20, 0}, 0.3}));
    return sim.forces(a).desired.x;
  };
  const double capped = 2.0 * ((std::hypot(0.6, 0.2) - 0.4) / 0.6 - 1.0) / 0.5;
  const double free = 2.0 * (1.3 - 1.0) / 0.5;
  EXPECT_NEAR(desired_x(0.0, {0.6, 0.2}), capped, 1e-5);  // in the open: the person ahead counts
  EXPECT_NEAR(desired_x(0.8, {0.6, 0.2}), free, 1e-5);    // in a 0.8 m door: a staggered lane
  EXPECT_NEAR(desired_x(2.0, {0.6, 0.2}), capped, 1e-5);  // a wide door: no zipper
  EXPECT_NEAR(desired_x(0.8, {0.6, 0.0}), 2.0 * ((0.6 - 0.4) / 0.6 - 1.0) / 0.5, 1e-5);  // in line
}

// Side preference: someone coming head-on pushes the agent to its right (−y when walking +x);
// someone coming well to the agent's right pushes it left; nobody coming the same way pushes.
TEST(CrowdSimulation, OncomingWalkersPushToTheRight) {
  const auto social_y = [](Vec2 other, Vec2 other_velocity) {
    CrowdSimulation sim = make();
    const AgentId a = add(sim, {0, 0}, {1.3, 0});
    add(sim, other, other_velocity);
    EXPECT_TRUE(sim.set_goal(a, Goal{{20, 0}, 0.3}));
    return sim.forces(a).social.y;
  };
  // Exactly head-on LightSFM's sideways term vanishes (θ = 0): the push alone breaks the tie.
  EXPECT_NEAR(social_y({2.0, 0.0}, {-1.3, 0}), -1.5 * std::exp(-2.0 / 1.5), 1e-5);
  EXPECT_GT(social_y({2.0, -0.5}, {-1.3, 0}), 0.0);  // already passing on the right: go left
  EXPECT_NEAR(social_y({2.0, 0.0}, {1.3, 0}), 0.0, 1e-12);
}

// ---- determinism and the reference ------------------------------------------------------------

TEST(CrowdSimulation, SameSeedGivesBitIdenticalTrajectories) {
  CrowdSimulation a = busy_room(200, 1, 99);
  CrowdSimulation b = busy_room(200, 1, 99);
  CrowdSimulation c = busy_room(200, 1, 100);
  for (int k = 0; k < 100; ++k) {
    a.step();
    b.step();
    c.step();
  }
  EXPECT_TRUE(bit_identical(snapshot(a), snapshot(b)));
  EXPECT_FALSE(bit_identical(snapshot(a), snapshot(c)));
}

TEST(CrowdSimulation, ThreadCountDoesNotChangeAnyBit) {
  CrowdSimulation one = busy_room(300, 1, 5);
  CrowdSimulation two = busy_room(300, 2, 5);
  CrowdSimulation three = busy_room(300, 3, 5);
  for (int k = 0; k < 100; ++k) {
    one.step();
    two.step();
    three.step();
  }
  EXPECT_TRUE(bit_identical(snapshot(one), snapshot(two)));
  EXPECT_TRUE(bit_identical(snapshot(one), snapshot(three)));
}

TEST(CrowdSimulation, CellListAgreesWithBruteForceReference) {
  // N = 500 for 100 steps: same forces and cut-off; pair forces are summed in fixed point, so
  // the visiting order does not matter and the two agree to the bit (the issue asks 1e-4 m).
  CrowdSimulation grid = busy_room(500, 2, 21);
  CrowdSimulation brute = busy_room(500, 2, 21);
  for (int k = 0; k < 100; ++k) {
    grid.step();
    brute.step_reference();
  }
  double worst = 0.0;
  for (std::uint32_t i = 0; i < grid.size(); ++i) {
    const Vec2 p = grid.position(AgentId(i));
    const Vec2 q = brute.position(AgentId(i));
    worst = std::max(worst, std::hypot(p.x - q.x, p.y - q.y));
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_TRUE(bit_identical(snapshot(grid), snapshot(brute)));
}

// Each pair once (the default where every role shares the pair terms) and agent by agent give the
// same bits: a crowd of 400 in a 20 × 20 m room (1 /m², groups, walls, every fifth an elderly
// person: a role that differs in speeds only), with two agents on the same spot, one pair just
// touching, a robot driven from outside (visible) and one invisible, on 1 and 2 threads; and a
// crowd with children (a role with other pair terms) falls back to agent by agent.
TEST(CrowdSimulation, PairsOnceGivesTheSameBitsAsAgentByAgent) {
  const auto run = [](bool pairs_once, unsigned threads, bool children) {
    SimulationConfig config;
    config.threads = threads;
    config.seed = 13;
    config.pairs_once = pairs_once;
    // Children: adults' parameters with a stronger social force (pair terms that differ).
    RoleTable roles = RoleTable::defaults();
    RoleParameters child = roles.at(*roles.index_of("adult"));
    child.name = "child";
    child.forces.social_factor = 3.0;
    EXPECT_TRUE(roles.put(child));
    auto created = CrowdSimulation::create(config, roles);
    EXPECT_TRUE(created);
    CrowdSimulation sim = std::move(*created);
    const std::vector<Vec2> box = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
    EXPECT_TRUE(sim.add_polyline(box, true));
    EXPECT_TRUE(sim.add_wall({7, 4}, {7, 12}));
    Rng rng(13);
    for (std::size_t k = 0; k < 400; ++k) {
      AgentSpec spec;
      spec.position = {rng.uniform(0.5, 19.5), rng.uniform(0.5, 19.5)};
      if (k == 1) spec.position = {10.0, 10.0};  // coincident with agent 0
      if (k == 0) spec.position = {10.0, 10.0};
      if (k == 3) spec.position = {4.0, 4.0};  // 3 and 4 touching
      if (k == 4) spec.position = {4.45, 4.0};
      spec.group_id = k % 4 == 0 ? -1 : static_cast<std::int64_t>(k / 3);
      if (k % 5 == 2) spec.role = "elderly";
      if (children && k % 5 == 0) spec.role = "child";
      auto id = sim.add_agent(spec);
      EXPECT_TRUE(id);
      EXPECT_TRUE(sim.set_goals(*id,
                                {Goal{{rng.uniform(1, 19), rng.uniform(1, 19)}, 0.5},
                                 Goal{{rng.uniform(1, 19), rng.uniform(1, 19)}, 0.5}},
                                true));
    }
    EXPECT_TRUE(sim.set_driven(AgentId(7), Presence::kVisible));
    EXPECT_TRUE(sim.set_driven(AgentId(8), Presence::kInvisible));
    for (int k = 0; k < 60; ++k) {
      EXPECT_TRUE(sim.set_driven_state(AgentId(7), Pose2{2.0 + 0.05 * k, 15.0, 0.0}, Twist2{1.0, 0.0, 0.0}));
      sim.step();
    }
    return snapshot(sim);
  };
  const std::vector<double> by_agent = run(false, 1, false);
  EXPECT_TRUE(bit_identical(run(true, 1, false), by_agent));
  EXPECT_TRUE(bit_identical(run(true, 2, false), by_agent));
  EXPECT_FALSE(bit_identical(run(true, 2, true), by_agent));  // the children change the crowd
  EXPECT_TRUE(bit_identical(run(true, 2, true), run(false, 1, true)));
}

// The pair step's per-thread scratch outlives a simulation: a small crowd stepped after a large one
// in the same threads reads nothing of the large one's (ASan checks the reads) and gives the
// same bits as agent by agent.
TEST(CrowdSimulation, PairsOnceAfterALargerSimulation) {
  const auto small = [](bool pairs_once) {
    SimulationConfig config;
    config.threads = 2;
    config.pairs_once = pairs_once;
    CrowdSimulation sim = make(config);
    for (int k = 0; k < 30; ++k) {
      const AgentId id = add(sim, {0.5 * (k % 6), 0.6 * (k / 6)}, {0.5, 0.0});
      EXPECT_TRUE(sim.set_goal(id, Goal{{k % 2 == 0 ? 20.0 : -20.0, 1.0}, 0.3}));
    }
    for (int k = 0; k < 40; ++k) sim.step();
    return snapshot(sim);
  };
  CrowdSimulation large = busy_room(400, 2, 17);
  for (int k = 0; k < 5; ++k) large.step();
  EXPECT_TRUE(bit_identical(small(true), small(false)));
}

// A periodic corridor 20 m long, 4 m wide, with people walking both ways (contacts, headway,
// side preference and images across the boundary all in play).
CrowdSimulation periodic_corridor(std::size_t n, unsigned threads, std::uint64_t seed) {
  SimulationConfig config;
  config.threads = threads;
  config.seed = seed;
  config.periodic_length = 20.0;
  CrowdSimulation sim = make(config);
  EXPECT_TRUE(sim.add_wall({-3, 0}, {23, 0}));
  EXPECT_TRUE(sim.add_wall({-3, 4}, {23, 4}));
  Rng rng(seed);
  for (std::size_t k = 0; k < n; ++k) {
    AgentSpec spec;
    spec.position = {20.0 * (static_cast<double>(k) + rng.uniform(0.0, 0.5)) / static_cast<double>(n),
                     rng.uniform(0.4, 3.6)};
    auto id = sim.add_agent(spec);
    EXPECT_TRUE(id);
    EXPECT_TRUE(sim.set_goal(*id, Goal{{k % 3 == 0 ? -1e5 : 1e5, 2.0}, 0.3}));
  }
  return sim;
}

TEST(CrowdSimulation, PeriodicBoundaryWrapsAndSeesAcrossIt) {
  SimulationConfig config;
  config.periodic_length = 10.0;
  config.periodic_origin = -2.0;
  EXPECT_FALSE(CrowdSimulation::create(SimulationConfig{.periodic_length = 5.0}));  // < 2 cut-offs + 0.5
  EXPECT_FALSE(CrowdSimulation::create(SimulationConfig{.periodic_length = -1.0}));
  CrowdSimulation sim = make(config);
  const AgentId a = add(sim, {7.9, 1.0}, {1.3, 0});   // x in [-2, 8): just before the end
  const AgentId b = add(sim, {-1.6, 1.0}, {1.3, 0});  // 0.5 m ahead of a, across the boundary
  const AgentId far = add(sim, {25.0, 3.0});          // placed two periods out: wrapped in
  EXPECT_NEAR(sim.position(far).x, 5.0, 1e-12);
  EXPECT_TRUE(sim.set_goal(a, Goal{{1e5, 1.0}, 0.3}));
  // b, 0.5 m ahead through the boundary, caps a's desired speed (0.5 − 0.4)/0.6 and pushes it back.
  const ForceBreakdown f = sim.forces(a);
  EXPECT_NEAR(f.desired.x, 2.0 * ((0.5 - 0.4) / 0.6 - 1.3) / 0.5, 1e-5);
  EXPECT_LT(f.social.x, 0.0);
  for (int k = 0; k < 4; ++k) sim.step();
  EXPECT_GE(sim.position(a).x, -2.0);
  EXPECT_LT(sim.position(a).x, 8.0);
  EXPECT_LT(sim.position(b).x, 8.0);
}

TEST(CrowdSimulation, PeriodicCellListAgreesWithReferenceToTheBit) {
  CrowdSimulation grid = periodic_corridor(160, 2, 8);
  CrowdSimulation brute = periodic_corridor(160, 1, 8);
  for (int k = 0; k < 200; ++k) {
    grid.step();
    brute.step_reference();
  }
  EXPECT_TRUE(bit_identical(snapshot(grid), snapshot(brute)));
  for (std::uint32_t i = 0; i < grid.size(); ++i) {
    EXPECT_GE(grid.position(AgentId(i)).x, 0.0);
    EXPECT_LT(grid.position(AgentId(i)).x, 20.0);
  }
}

TEST(CrowdSimulation, CellIndexBuiltInRangesGivesTheSameBits) {
  // The cell index is built in one range of agents per thread once there are 256 agents a range:
  // 1,200 agents on 1, 2 and 3 threads (1, 2 and 3 ranges) end in the same bits, and 520 agents
  // in a periodic corridor (two ranges of agents, two of their images) match the O(N²) reference.
  CrowdSimulation one = busy_room(1200, 1, 9);
  CrowdSimulation two = busy_room(1200, 2, 9);
  CrowdSimulation three = busy_room(1200, 3, 9);
  for (int k = 0; k < 30; ++k) {
    one.step();
    two.step();
    three.step();
  }
  EXPECT_TRUE(bit_identical(snapshot(one), snapshot(two)));
  EXPECT_TRUE(bit_identical(snapshot(one), snapshot(three)));

  CrowdSimulation grid = periodic_corridor(520, 3, 12);
  CrowdSimulation brute = periodic_corridor(520, 1, 12);
  for (int k = 0; k < 30; ++k) {
    grid.step();
    brute.step_reference();
  }
  EXPECT_TRUE(bit_identical(snapshot(grid), snapshot(brute)));
}

// ---- hard guarantees ----------------------------------------------------------------------

// Independent crossing check: the move p→q properly crosses wall ab.
bool crosses(Vec2 p, Vec2 q, const WallSegment& w) {
  auto side = [](Vec2 a, Vec2 b, Vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); };
  const double s1 = side(w.a, w.b, p), s2 = side(w.a, w.b, q);
  if (s1 == 0.0) return false;                          // started on the wall's line
  if (s2 != 0.0 && (s1 > 0) == (s2 > 0)) return false;  // stayed on its side
  const double t1 = side(p, q, w.a), t2 = side(p, q, w.b);
  return (t1 > 0) != (t2 > 0) || t1 == 0.0 || t2 == 0.0;
}

TEST(CrowdSimulation, NoAgentEverCrossesAWallInADenseRandomBox) {
  Rng rng(2024);
  SimulationConfig config;
  config.threads = 2;
  config.body_stiffness = 50.0;
  CrowdSimulation sim = make(config);
  const std::vector<Vec2> box = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  ASSERT_TRUE(sim.add_polyline(box, true));
  for (int w = 0; w < 25; ++w) {  // random inner walls, some degenerate
    const Vec2 a{rng.uniform(0, 10), rng.uniform(0, 10)};
    const Vec2 b = rng.chance(0.2) ? a : Vec2{rng.uniform(0, 10), rng.uniform(0, 10)};
    ASSERT_TRUE(sim.add_wall(a, b));
  }
  for (int k = 0; k < 250; ++k) {  // 2.5 agents/m², random velocities, goals partly outside
    AgentSpec spec;
    spec.position = {rng.uniform(0.05, 9.95), rng.uniform(0.05, 9.95)};
    spec.velocity = {rng.uniform(-2, 2), rng.uniform(-2, 2)};
    spec.role = rng.chance(0.1) ? "jogger" : "adult";
    auto id = sim.add_agent(spec);
    ASSERT_TRUE(id);
    ASSERT_TRUE(sim.set_goals(*id,
                              {Goal{{rng.uniform(-5, 15), rng.uniform(-5, 15)}, 0.2},
                               Goal{{rng.uniform(-5, 15), rng.uniform(-5, 15)}, 0.2}},
                              true));
  }
  const std::vector<WallSegment> walls = sim.walls();
  std::size_t crossings = 0;
  for (int step = 0; step < 300; ++step) {
    std::vector<Vec2> before(sim.size());
    for (std::uint32_t i = 0; i < sim.size(); ++i) before[i] = sim.position(AgentId(i));
    sim.step();
    for (std::uint32_t i = 0; i < sim.size(); ++i) {
      const Vec2 after = sim.position(AgentId(i));
      ASSERT_TRUE(std::isfinite(after.x) && std::isfinite(after.y));
      for (const WallSegment& w : walls) crossings += crosses(before[i], after, w) ? 1 : 0;
    }
  }
  EXPECT_EQ(crossings, 0u);
  for (std::uint32_t i = 0; i < sim.size(); ++i) {
    const Vec2 p = sim.position(AgentId(i));
    EXPECT_TRUE(p.x > 0 && p.x < 10 && p.y > 0 && p.y < 10) << "agent " << i << " left the box";
  }
}

TEST(CrowdSimulation, DegenerateInputsNeverProduceNaN) {
  SimulationConfig config;
  config.body_stiffness = 100.0;
  CrowdSimulation sim = make(config);
  ASSERT_TRUE(sim.add_wall({0, 0}, {0, 0}));  // zero-length wall
  ASSERT_TRUE(sim.add_wall({-3, 1}, {3, 1}));
  ASSERT_TRUE(sim.add_wall({3, 1}, {3, 1}));                              // duplicate point on a vertex
  ASSERT_TRUE(sim.add_wall({-3, 1}, {3, 1}));                             // duplicate wall
  for (int k = 0; k < 6; ++k) add(sim, {0, 0}, {}, 1.3, k < 3 ? 1 : -1);  // coincident, on a point wall
  const AgentId on_wall = add(sim, {1, 1});                               // exactly on a wall
  const AgentId on_vertex = add(sim, {3, 1}, {1, 1});
  const AgentId still = add(sim, {-2, -2}, {}, 0.0);      // desired speed 0
  add(sim, {-2, -2}, {0.5, 0});                           // coincident with it, moving
  ASSERT_TRUE(sim.set_goal(on_wall, Goal{{1, 1}, 0.0}));  // goal at its own position, radius 0
  ASSERT_TRUE(sim.set_goal(on_vertex, Goal{{3, 5}, 0.0}));
  ASSERT_TRUE(sim.set_goal(still, Goal{{5, -2}, 0.1}));
  for (int step = 0; step < 200; ++step) {
    sim.step();
    for (std::uint32_t i = 0; i < sim.size(); ++i) {
      const PedestrianState s = sim.state(AgentId(i));
      ASSERT_TRUE(std::isfinite(s.pose.x) && std::isfinite(s.pose.y) && std::isfinite(s.pose.yaw) &&
                  std::isfinite(s.twist.vx) && std::isfinite(s.twist.vy) && std::isfinite(s.twist.omega))
          << "agent " << i << " at step " << step;
    }
  }
  // The coincident agents parted.
  EXPECT_GT(norm({sim.position(AgentId(0)).x - sim.position(AgentId(1)).x,
                  sim.position(AgentId(0)).y - sim.position(AgentId(1)).y}),
            0.1);
  EXPECT_EQ(norm(sim.velocity(still)), 0.0);  // desired speed 0: never moves
}

TEST(CrowdSimulation, GoalsAreVisitedInOrderAndInactiveAgentsFreeze) {
  CrowdSimulation sim = make();
  const AgentId a = add(sim, {0, 0});
  ASSERT_TRUE(sim.set_goals(a, {Goal{{3, 0}, 0.3}, Goal{{3, 3}, 0.3}}));
  const AgentId frozen = add(sim, {10, 10}, {1, 0});
  ASSERT_TRUE(sim.set_active(frozen, false));
  bool saw_second = false;
  for (int k = 0; k < 400 && sim.current_goal(a); ++k) {
    sim.step();
    if (sim.state(a).intent.goal_id == 1) saw_second = true;
  }
  EXPECT_TRUE(saw_second);
  EXPECT_FALSE(sim.current_goal(a));
  EXPECT_EQ(sim.state(a).intent.goal_id, -1);
  EXPECT_LT(std::hypot(sim.position(a).x - 3, sim.position(a).y - 3), 0.5);
  EXPECT_EQ(sim.position(frozen), (Vec2{10, 10}));
}

// An agent pressed by others (within touching reach: it has contacts) that leaves the crowd —
// deactivated, as after an exit — stays exactly where it was, and the others walk through its
// place: its contact list from the step before is never used again (the step does not empty the
// counts every step).
TEST(CrowdSimulation, APressedAgentTakenOutStaysFrozenAndStopsBlocking) {
  CrowdSimulation sim = make();
  const AgentId blocker = add(sim, {0, 0}, {}, 0.0);  // desired speed 0: stands
  std::vector<AgentId> queue;
  for (int k = 1; k <= 4; ++k) {
    queue.push_back(add(sim, {-0.5 * k, 0.0}, {1, 0}));
    ASSERT_TRUE(sim.set_goal(queue.back(), Goal{{6, 0}, 0.3}));
  }
  for (int k = 0; k < 6; ++k) sim.step();
  const auto gap = [&](AgentId a) {
    return std::hypot(sim.position(a).x - sim.position(blocker).x,
                      sim.position(a).y - sim.position(blocker).y);
  };
  ASSERT_LT(gap(queue[0]), 0.6);  // the first of the queue is touching the blocker (0.46 m)
  const Vec2 held = sim.position(blocker);
  ASSERT_TRUE(sim.set_active(blocker, false));
  double closest = gap(queue[0]);
  for (int k = 0; k < 200; ++k) {
    sim.step();
    closest = std::min(closest, gap(queue[0]));
  }
  EXPECT_EQ(sim.position(blocker), held);
  EXPECT_LT(closest, 0.2);  // walked through its place: nothing kept it apart
  for (const AgentId a : queue) EXPECT_GT(sim.position(a).x, 3.0) << "agent " << a.value();
}

// Each thread keeps its pair sums between steps and empties them when it takes part in a step's
// pairs; the step reads only the sums of the threads that took part. A crowd that shrinks to one
// chunk of the pair loop (stepped by the calling thread alone) must not pick up what the other
// thread summed when the crowd was larger.
TEST(CrowdSimulation, ACrowdThatShrinksToOneThreadsWorkGetsNoStaleSums) {
  CrowdSimulation two = busy_room(300, 2, 5);
  CrowdSimulation one = busy_room(300, 1, 5);
  for (int k = 0; k < 5; ++k) {
    two.step();
    one.step();
  }
  ASSERT_TRUE(bit_identical(snapshot(two), snapshot(one)));
  for (std::uint32_t i = 40; i < 300; ++i) {
    ASSERT_TRUE(two.set_active(AgentId(i), false));
    ASSERT_TRUE(one.set_active(AgentId(i), false));
  }
  for (int k = 0; k < 20; ++k) {
    two.step();
    one.step();
  }
  EXPECT_TRUE(bit_identical(snapshot(two), snapshot(one)));
}

}  // namespace
}  // namespace socsim::crowd
