// pedsim_ros scenario → scenario program: our own small scenario for each rule, and the six real
// files of ../shared/peers/pedsim (skipped when absent): corridor.xml fails naming its waypoint
// outside the walls; the five others convert, pass the ScenarioRunner and simulate 30 s with
// every agent inside the walls, no NaN, and the crowd walking its routes.
#include "core/interop/pedsim_program.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/crowd/scenario_runner.hpp"
#include "core/geometry/planar.hpp"
#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

using ::testing::HasSubstr;

using testing::kHall;
using testing::read_text;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string peer(const std::string& file) {
  return testing::peer("pedsim", file);
}

TEST(PedsimProgram, ClustersBecomeAgentsWithRolesSpawnsRoutesAndTrees) {
  auto imported = import_pedsim_scenario(kHall);
  ASSERT_TRUE(imported) << imported.error().message();
  const Json& p = imported->program.program;
  ASSERT_EQ(p["agents"].size(), 3u);
  // Cluster 0 queues: a tree with GoTo door, JoinQueue + ServeAtCounter on the lane, GoTo platform.
  const Json& queuers = p["agents"][0];
  EXPECT_EQ(queuers["role"], "adult");
  EXPECT_EQ(queuers["count"], 10);
  ASSERT_TRUE(queuers.contains("spawn"));
  const std::string tree = p["behavior_trees"][queuers["behavior"].get<std::string>()]["xml"];
  const auto door = tree.find("<GoTo goal=\"door\"/>");
  const auto join = tree.find("<JoinQueue queue=\"tickets\"");
  const auto serve = tree.find("<ServeAtCounter counter=\"tickets\" queue=\"tickets\"");
  const auto platform = tree.find("<GoTo goal=\"platform\"/>");
  ASSERT_NE(door, std::string::npos);
  ASSERT_NE(join, std::string::npos);
  ASSERT_NE(serve, std::string::npos);
  ASSERT_NE(platform, std::string::npos);
  EXPECT_LT(door, join);
  EXPECT_LT(join, serve);
  EXPECT_LT(serve, platform);
  // Cluster 1 (children) passes the kiosk next to the window: it lingers there with p = 4 / 10.
  const Json& kids = p["agents"][1];
  EXPECT_EQ(kids["role"], "child");
  ASSERT_TRUE(p["roles"].contains("child"));
  const std::string kid_tree = p["behavior_trees"][kids["behavior"].get<std::string>()]["xml"];
  EXPECT_THAT(kid_tree, HasSubstr("<RandomChance probability=\"0.4\"/>"));
  EXPECT_THAT(kid_tree, HasSubstr("<Wander region=\"window\""));
  // Cluster 2 (elders) only walks: plain cyclic goals with the waypoint radii, no tree.
  const Json& elders = p["agents"][2];
  EXPECT_EQ(elders["role"], "elderly");
  EXPECT_FALSE(elders.contains("behavior"));
  ASSERT_EQ(elders["goals"].size(), 2u);
  EXPECT_EQ(elders["goals"][0]["place"], "platform");
  EXPECT_EQ(elders["goals"][0]["radius"], 2.0);
  EXPECT_TRUE(elders["cyclic_goals"].get<bool>());
  // The robot (type 2) is the program's robot, walking its waypoints.
  EXPECT_EQ(p["robot"]["position"], Json::array({3.0, 3.0}));
  EXPECT_EQ(p["robot"]["goals"][1]["place"], "door");
}

TEST(PedsimProgram, SpawnAreasAreClippedToTheWalls) {
  const std::string text = replaced(kHall, "n=\"4\" dx=\"1\" dy=\"1\"", "n=\"4\" dx=\"9\" dy=\"9\"");
  auto imported = import_pedsim_scenario(text);
  ASSERT_TRUE(imported) << imported.error().message();
  for (const Json& pt : imported->program.program["agents"][2]["spawn"]) {
    EXPECT_GE(pt[0].get<double>(), -1e-9);
    EXPECT_GE(pt[1].get<double>(), -1e-9);
    EXPECT_LE(pt[1].get<double>(), 11.0 + 1e-9);
  }
}

TEST(PedsimProgram, ASecondRobotIsNamedWithItsLine) {
  std::string text = kHall;
  text.insert(text.find("</scenario>"), "  <agent x=\"5\" y=\"5\" n=\"1\" type=\"2\"/>\n");
  auto imported = import_pedsim_scenario(text);
  ASSERT_FALSE(imported);
  ASSERT_EQ(imported.error().errors.size(), 1u);
  EXPECT_EQ(imported.error().errors[0].pointer, "/agents/4");
  EXPECT_EQ(imported.error().errors[0].line, 29);
  EXPECT_THAT(imported.error().errors[0].message, HasSubstr("second robot"));
  EXPECT_THAT(imported.error().errors[0].message, HasSubstr("line 25"));
}

TEST(PedsimProgram, RunnerErrorsPointBackToThePedsimElement) {
  // 400 agents cannot stand in a 1 x 1 m box: the runner's spawn error names the <agent> line.
  const std::string text = replaced(kHall, "n=\"4\" dx=\"1\" dy=\"1\"", "n=\"400\" dx=\"0.5\" dy=\"0.5\"");
  auto imported = import_pedsim_scenario(text);
  ASSERT_FALSE(imported);
  const FieldError& fe = imported.error().errors.at(0);
  EXPECT_EQ(fe.pointer, "/agents/2");
  EXPECT_EQ(fe.line, 21);
  EXPECT_THAT(fe.message, HasSubstr("program /agents/2/spawn"));
  EXPECT_THAT(fe.message, HasSubstr("no free spot"));
}

TEST(PedsimProgram, PeerCorridorFailsNamingItsWaypointOutsideTheWalls) {
  const std::string path = peer("corridor.xml");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "peer file " << path << " is absent (needs ../shared)";
  auto imported = import_pedsim_scenario(read_text(path));
  ASSERT_FALSE(imported);
  ASSERT_EQ(imported.error().errors.size(), 1u);
  EXPECT_EQ(imported.error().errors[0].pointer, "/waypoints/2");
  EXPECT_EQ(imported.error().errors[0].line, 13);
  EXPECT_THAT(imported.error().errors[0].message,
              HasSubstr("'robot_goal' at (22, 27) lies outside the walls"));
}

// Whether the step a → b crosses wall w (proper crossing, not touching).
bool crosses(crowd::Vec2 a, crowd::Vec2 b, const world::Segment& w) {
  auto side = [](crowd::Vec2 p, crowd::Vec2 q, crowd::Vec2 r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  };
  const crowd::Vec2 c{w.a.x, w.a.y};
  const crowd::Vec2 d{w.b.x, w.b.y};
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

struct RunOutcome {
  std::size_t agents = 0;
  std::size_t walked = 0;  // spotlight agents that reached or closed in on their first route stop
  std::size_t routed = 0;  // spotlight agents with a route
};

// Simulates 30 s and checks every frame; returns how many agents made progress on their routes.
RunOutcome simulate(const ImportedPedsim& in, const std::string& file) {
  auto runner = crowd::ScenarioRunner::create(&in.scenario.world, in.parsed, crowd::RunnerOptions{});
  EXPECT_TRUE(runner) << file << ": " << runner.error().message();
  if (!runner) return {};
  crowd::ScenarioRunner& r = **runner;
  const world::World& w = in.scenario.world;
  // First route stop of each program agent entry, from the cluster it came from.
  std::map<std::string, std::string> first_stop;
  for (const PedsimSource& s : in.program.sources) {
    const std::size_t i = std::stoul(s.pedsim_pointer.substr(8));
    if (!in.scenario.agents[i].route.empty())
      first_stop[s.program_pointer] = in.scenario.agents[i].route[0].id;
  }
  std::vector<double> start_distance;
  std::vector<double> best_distance;
  auto distance_to = [&](std::size_t k, crowd::Vec2 p) {
    const crowd::RunnerAgent& a = r.agents()[k];
    auto it = first_stop.find(a.pointer);
    if (a.kind != crowd::AgentKind::kSpotlight || it == first_stop.end()) return -1.0;
    const world::Roi& roi = w.roi(*w.find_roi(it->second));
    if (geometry::contains(roi.polygon, {p.x, p.y})) return 0.0;
    return geometry::distance(geometry::centroid(roi.polygon.outer), {p.x, p.y});
  };
  std::vector<crowd::Vec2> last;
  std::size_t frames = 0;
  r.run(
      30.0,
      [&](double, std::span<const crowd::PedestrianState> states) {
        ++frames;
        if (last.empty()) {
          for (std::size_t k = 0; k < states.size(); ++k) {
            last.push_back({states[k].pose.x, states[k].pose.y});
            start_distance.push_back(distance_to(k, last.back()));
          }
          best_distance = start_distance;
        }
        for (std::size_t k = 0; k < states.size(); ++k) {
          const crowd::Vec2 p{states[k].pose.x, states[k].pose.y};
          ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(states[k].twist.vx) &&
                      std::isfinite(states[k].twist.vy))
              << file << ": agent " << k << " has a non-finite state";
          ASSERT_TRUE(w.zone_at({p.x, p.y}))
              << file << ": agent " << k << " at (" << p.x << ", " << p.y << ") is outside the walls";
          for (const world::Wall& wall : w.walls())
            ASSERT_FALSE(crosses(last[k], p, wall.segment))
                << file << ": agent " << k << " walked through a wall";
          last[k] = p;
          if (best_distance[k] >= 0) best_distance[k] = std::min(best_distance[k], distance_to(k, p));
        }
      },
      10);
  EXPECT_GE(frames, 30u) << file;
  RunOutcome out;
  out.agents = r.agents().size();
  for (std::size_t k = 0; k < start_distance.size(); ++k) {
    if (start_distance[k] < 0) continue;
    ++out.routed;
    // Reached the first stop, or covered a good part of the way (at least 10 m or half of it).
    const double gained = start_distance[k] - best_distance[k];
    if (best_distance[k] == 0.0 || gained >= std::min(10.0, 0.5 * start_distance[k])) ++out.walked;
  }
  return out;
}

TEST(PedsimProgram, OwnHallSimulatesInsideItsWalls) {
  auto imported = import_pedsim_scenario(kHall);
  ASSERT_TRUE(imported) << imported.error().message();
  const RunOutcome out = simulate(*imported, "hall");
  EXPECT_EQ(out.agents, 21u);
  EXPECT_EQ(out.routed, 20u);
  EXPECT_GE(out.walked, 18u);
}

TEST(PedsimProgram, PeerScenariosConvertAndSimulateThirtySeconds) {
  const std::map<std::string, std::size_t> agents = {{"airport.xml", 191},
                                                     {"airport_activities.xml", 316},
                                                     {"contexts_queueing.xml", 31},
                                                     {"scene1.xml", 262},
                                                     {"social_contexts.xml", 31}};
  for (const auto& [file, count] : agents) {
    const std::string path = peer(file);
    if (!std::filesystem::exists(path))
      GTEST_SKIP() << "peer file " << path << " is absent (needs ../shared)";
    auto imported = import_pedsim_scenario(read_text(path));
    ASSERT_TRUE(imported) << file << ": " << imported.error().message();
    const RunOutcome out = simulate(*imported, file);
    std::printf("%s: %zu agents, %zu of %zu with a route reached or closed in on its first stop in 30 s\n",
                file.c_str(), out.agents, out.walked, out.routed);
    EXPECT_EQ(out.agents, count) << file;
    // Most of the crowd walks its route within 30 s (some wait in long queues or in a crowd).
    EXPECT_GE(static_cast<double>(out.walked), 0.8 * static_cast<double>(out.routed))
        << file << ": " << out.walked << " of " << out.routed << " agents made progress on their routes";
  }
}

}  // namespace
}  // namespace socsim::interop
