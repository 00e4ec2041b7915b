// Slow pedestrians through doorways (issue 5): single agents at 0.3–1.34 m/s walk from one room
// to the next through 0.9, 1.0 and 1.15 m doors (routed by the scenario runner, straight and
// oblique approaches), through openings in thick (polygon) walls, and from every patient room of
// generated hospital plans to the lobby.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/crowd/program.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/floorplan/offline.hpp"
#include "core/floorplan/rooms.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/store/store.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/support/knowledge_suite.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::crowd {
namespace {

constexpr double kSpeeds[] = {0.3, 0.5, 0.6, 0.8, 1.34};

// Two 5 × 4 m rooms side by side, one door of `width` in the shared wall at y = `door_y`.
std::string two_rooms(double width, double door_y) {
  std::ostringstream s;
  s << "name: \"two_rooms\"\n"
    << "units: {length: m, angle: rad}\n"
    << "zones:\n"
    << "  - {name: \"west\", type: \"office\", polygon: [[0, 0], [5, 0], [5, 4], [0, 4]]}\n"
    << "  - {name: \"east\", type: \"office\", polygon: [[5, 0], [10, 0], [10, 4], [5, 4]]}\n"
    << "doors:\n"
    << "  - {name: \"door\", pose: [5, " << door_y << "], width: " << width
    << ", connects: [\"west\", \"east\"]}\n";
  return s.str();
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// One agent of the given speed walking from `start` to `goal` (regular navigation, routed).
std::string walk_program(Vec2 start, const std::string& goal_json, double speed) {
  return std::string(R"({"version": 1, "name": "doorway", "dt": 0.05, "decision_period": 0.1, "agents": [)") +
         R"({"name": "walker", "position": [)" + number(start.x) + ", " + number(start.y) +
         R"(], "speed": )" + number(speed) + R"(, "goals": [)" + goal_json + R"(], "cyclic_goals": false}]})";
}

struct Walk {
  bool reached = false;
  double time = 0.0;          // s until within the goal radius
  Vec2 last;                  // where the agent was at the end
  double min_wall_gap = 1e9;  // closest body-to-wall distance seen
};

// Runs until the agent is within 0.3 m of the goal point or `limit` seconds have passed.
Walk walk(const world::World& w, Vec2 start, Vec2 goal, double speed, double limit) {
  const std::string text = walk_program(start, "[" + number(goal.x) + ", " + number(goal.y) + "]", speed);
  auto program = program_from_text(text);
  EXPECT_TRUE(program.has_value()) << (program ? "" : program.error().message());
  if (!program) return {};
  RunnerOptions options;
  options.seed = 1;
  auto runner = ScenarioRunner::create(&w, *program, options);
  EXPECT_TRUE(runner.has_value()) << (runner ? "" : runner.error().message());
  if (!runner) return {};
  CrowdSimulation& sim = (*runner)->sim();
  const AgentId id(0);
  Walk out;
  const auto steps = static_cast<int>(limit / sim.config().dt);
  for (int k = 0; k < steps; ++k) {
    (*runner)->step();
    const Vec2 p = sim.position(id);
    for (const WallSegment& s : sim.walls())
      out.min_wall_gap = std::min(out.min_wall_gap, point_segment_distance(p, s.a, s.b) - sim.radius(id));
    if (std::hypot(p.x - goal.x, p.y - goal.y) <= 0.3) {
      out.reached = true;
      out.time = (*runner)->time();
      break;
    }
  }
  out.last = sim.position(id);
  return out;
}

// Time limit: twice the free walking time along `path` plus 10 s.
double limit_for(double path, double speed) {
  return 2.0 * path / speed + 10.0;
}

struct DoorCase {
  double width;
  double door_y;
  Vec2 start;
  Vec2 goal;
};

TEST(Doorway, SlowAndFastAgentsPassTwoRoomDoors) {
  // Straight approaches on the door's line and oblique ones from the corners of the rooms.
  for (const double width : {0.9, 1.0, 1.15}) {
    for (const DoorCase& c :
         {DoorCase{width, 2.0, {1.0, 2.0}, {9.0, 2.0}}, DoorCase{width, 2.0, {1.0, 0.8}, {9.0, 3.2}},
          DoorCase{width, 0.9, {4.2, 3.4}, {8.0, 0.8}}}) {
      auto w = world::world_from_yaml(two_rooms(c.width, c.door_y));
      ASSERT_TRUE(w.has_value()) << w.error().message();
      for (const double v : kSpeeds) {
        const double path = std::hypot(5.0 - c.start.x, c.door_y - c.start.y) +
                            std::hypot(c.goal.x - 5.0, c.goal.y - c.door_y);
        const Walk r = walk(*w, c.start, c.goal, v, limit_for(path, v));
        EXPECT_TRUE(r.reached) << "door " << c.width << " m, speed " << v << " m/s, from (" << c.start.x
                               << ", " << c.start.y << "): stuck at (" << r.last.x << ", " << r.last.y << ")";
        EXPECT_GT(r.min_wall_gap, 0.0) << "door " << c.width << " m, speed " << v << ": body touched a wall";
      }
    }
  }
}

// Thick walls: the wall is a 0.2 m deep polygon on each side of the opening (as imported plans
// and obstacle maps draw them), so the jambs are corners shared by the wall's face and its reveal,
// not free wall ends. Slow walkers must still pass 0.9 and 1.0 m openings, straight and oblique
// (before corners were treated like free ends, 0.3–0.5 m/s walkers stopped 0.4–0.7 m before them).
TEST(Doorway, SlowAgentsPassDoorsInThickWalls) {
  for (const double width : {0.9, 1.0}) {
    for (const auto& [start, goal] :
         {std::pair<Vec2, Vec2>{{2.0, 2.0}, {8.0, 2.0}}, {{2.0, 1.0}, {8.0, 3.0}}}) {
      for (const double v : {0.3, 0.5, 1.34}) {
        auto created = CrowdSimulation::create(SimulationConfig{.seed = 3});
        ASSERT_TRUE(created);
        CrowdSimulation& sim = *created;
        const double lo = 2.0 - width / 2;
        const double hi = 2.0 + width / 2;
        const std::vector<Vec2> below = {{4.9, 0}, {5.1, 0}, {5.1, lo}, {4.9, lo}};
        const std::vector<Vec2> above = {{4.9, hi}, {5.1, hi}, {5.1, 4}, {4.9, 4}};
        ASSERT_TRUE(sim.add_polyline(below, true));
        ASSERT_TRUE(sim.add_polyline(above, true));
        ASSERT_TRUE(sim.add_wall({0, 0}, {10, 0}));
        ASSERT_TRUE(sim.add_wall({0, 4}, {10, 4}));
        AgentSpec spec;
        spec.position = start;
        spec.desired_speed = v;
        const AgentId a = *sim.add_agent(spec);
        // Via the middle of the opening, as a route would lead (the force model does not plan).
        ASSERT_TRUE(sim.set_goals(a, {Goal{{5.0, 2.0}, 0.3}, Goal{goal, 0.3}}));
        const double limit = limit_for(std::hypot(goal.x - start.x, goal.y - start.y), v);
        double gap = 1e9;
        while (sim.time() < limit && sim.current_goal(a)) {
          sim.step();
          for (const WallSegment& s : sim.walls())
            gap = std::min(gap, point_segment_distance(sim.position(a), s.a, s.b) - sim.radius(a));
        }
        EXPECT_GT(sim.position(a).x, 7.0) << "door " << width << " m, speed " << v;  // through the opening
        EXPECT_FALSE(sim.current_goal(a))
            << "door " << width << " m, speed " << v << " m/s, from (" << start.x << ", " << start.y
            << "): stuck at (" << sim.position(a).x << ", " << sim.position(a).y << ")";
        EXPECT_GT(gap, 0.0) << "door " << width << " m, speed " << v << ": body touched a wall";
      }
    }
  }
}

// The generated hospital plans of the scenario generator: from the middle of every patient room
// to the lobby, alone, at every speed.
class DoorwayHospital : public socsim::testing::KnowledgeSuite {
 protected:
};

Vec2 centroid(const geometry::Polygon& poly) {
  std::size_t count = poly.outer.size();
  if (count > 1 && poly.outer.front() == poly.outer.back()) --count;  // closed ring
  double x = 0.0, y = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    x += poly.outer[k].x;
    y += poly.outer[k].y;
  }
  const auto n = static_cast<double>(count);
  return {x / n, y / n};
}

TEST_F(DoorwayHospital, PatientsWalkFromEveryPatientRoomToTheLobby) {
  auto constraints = kb_->constraints_for("hospital");
  ASSERT_TRUE(constraints.has_value());
  // Seed 3 is the plan of the issue; a seed whose plan the generator cannot lay out is skipped
  // (that is the floor-plan tests' concern), but at least three plans must be walked.
  int plans = 0;
  for (const std::uint64_t seed : {3u, 4u, 5u, 6u, 7u, 8u}) {
    floorplan::OfflineOptions options;
    options.seed = seed;
    auto plan = floorplan::generate_floor_plan(floorplan::room_program("hospital"), *constraints, options);
    if (!plan) continue;
    ++plans;
    const world::World& w = plan->world;
    std::optional<Vec2> lobby;
    for (const world::Zone& z : w.zones())
      if (z.type == "lobby") lobby = centroid(z.polygon);
    ASSERT_TRUE(lobby.has_value()) << "seed " << seed << ": no lobby";
    int rooms = 0;
    for (const world::Zone& z : w.zones()) {
      if (z.type != "patient_room") continue;
      ++rooms;
      const Vec2 start = centroid(z.polygon);
      const double crow = std::hypot(lobby->x - start.x, lobby->y - start.y);
      for (const double v : kSpeeds) {
        const Walk r = walk(w, start, *lobby, v, limit_for(2.5 * crow, v));
        EXPECT_TRUE(r.reached) << "seed " << seed << ", " << z.name << " → lobby at " << v
                               << " m/s: stuck at (" << r.last.x << ", " << r.last.y << ")";
      }
    }
    EXPECT_GT(rooms, 0) << "seed " << seed << ": no patient room";
  }
  std::cout << "walked " << plans << " hospital plans\n";
  EXPECT_GE(plans, 3) << "the generator laid out fewer than three hospital plans";
}

}  // namespace
}  // namespace socsim::crowd
