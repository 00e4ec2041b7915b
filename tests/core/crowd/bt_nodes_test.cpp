// The behaviour-node library: every node is the knowledge store's node (same name, aliases and
// ports), HuNavSim's own trees load and run, and the scenario nodes (queues, seats,
// conversations, evacuation, robot reactions) do what their descriptions say.
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/crowd/bt_nodes.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/store/store.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/core/crowd/crowd_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::crowd {
namespace {
using fixtures::read;

using ::testing::HasSubstr;

world::World clinic() {
  auto w = world::world_from_yaml(
      read(std::filesystem::path(SOCSIM_SOURCE_DIR) / "schemas/examples/world_clinic.yaml"));
  EXPECT_TRUE(w) << w.error().message();
  return *w;
}

std::unique_ptr<ScenarioRunner> make(const world::World* w, const std::string& program_json,
                                     std::filesystem::path base = {}) {
  auto program = program_from_text(program_json);
  EXPECT_TRUE(program) << program.error().message();
  if (!program) return nullptr;
  RunnerOptions options;
  options.seed = 3;
  options.base_dir = std::move(base);
  auto runner = ScenarioRunner::create(w, *program, options);
  EXPECT_TRUE(runner) << runner.error().message();
  return runner ? std::move(*runner) : nullptr;
}

double dist(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

TEST(BtNodes, EveryNodeIsTheKnowledgeStoresNodeWithTheSamePorts) {
  testing::TempDir dir;
  auto store = store::Store::open(dir.file("k.db"));
  ASSERT_TRUE(store) << store.error().message();
  knowledge::KnowledgeBase kb(**store);
  auto sim = CrowdSimulation::create({});
  ASSERT_TRUE(sim);
  BtEnvironment env(*sim, nullptr);
  const BtRegistry registry = behavior_registry(env);

  std::set<std::string> implemented;
  for (const BtNodeType* t : registry.types()) {
    implemented.insert(t->name);
    auto node = kb.behavior_node(t->name);
    ASSERT_TRUE(node) << t->name << " is not in the knowledge store";
    EXPECT_EQ(node->name, t->name);
    std::set<std::string> ours;
    std::set<std::string> theirs;
    for (const BtPortSpec& p : t->ports) ours.insert(p.name);
    for (const knowledge::Port& p : node->ports) theirs.insert(p.name);
    EXPECT_EQ(ours, theirs) << t->name;
    for (const BtPortSpec& p : t->ports) {
      for (const knowledge::Port& k : node->ports) {
        if (k.name != p.name) continue;
        EXPECT_EQ(k.type, std::string(bt_port_type_name(p.type))) << t->name << "." << p.name;
        EXPECT_EQ(k.default_value, p.default_value) << t->name << "." << p.name;
      }
    }
    for (const std::string& alias : t->aliases) {
      auto by_alias = kb.behavior_node(alias);
      ASSERT_TRUE(by_alias) << alias;
      EXPECT_EQ(by_alias->name, t->name);
    }
  }
  auto all = kb.behavior_nodes();
  ASSERT_TRUE(all);
  for (const knowledge::BehaviorNode& n : *all)
    EXPECT_TRUE(implemented.count(n.name)) << n.name << " is not implemented";
}

// HuNavSim's trees (BT.CPP v3 files, one with <include>, and a v4 file) with three agents
// walking cyclic goals and no robot: the robot conditions fail and everyone keeps navigating.
TEST(BtNodes, HuNavSimTreesLoadAndRunWithoutARobot) {
  const std::filesystem::path peers = std::filesystem::path(SOCSIM_SHARED_DIR) / "peers/hunav";
  if (!std::filesystem::exists(peers / "BTScaredNav.xml")) GTEST_SKIP() << "HuNavSim trees not in " << peers;
  for (const char* file : {"BTRegularNav.xml", "BTScaredNav.xml", "BTThreateningNav.xml",
                           "isaac_warehouse_agents__agent_5_bt.xml"}) {
    SCOPED_TRACE(file);
    // Ten goals so the warehouse tree's SetGoal goal_id="9" exists.
    std::string goals = "[[8, 0], [8, 8], [0, 8], [0, 0], [4, 4], [6, 2], [2, 6], [7, 7], [1, 1], [5, 5]]";
    const std::string program = R"({"agents": [
        {"position": [0, 0], "goals": )" +
                                goals + R"(, "behavior": {"file": ")" + file + R"("}},
        {"position": [8, 8], "goals": [[0, 0], [8, 0]], "behavior": {"file": ")" +
                                file + R"("}},
        {"position": [0, 8], "goals": [[8, 0], [0, 8]], "behavior": {"file": ")" +
                                file + R"("}}]})";
    auto runner = make(nullptr, program, peers);
    ASSERT_TRUE(runner);
    std::vector<int> goal_changes(3, 0);
    std::vector<std::optional<Goal>> last(3);
    for (int k = 0; k < 600; ++k) {  // 30 s
      runner->step();
      for (std::uint32_t i = 0; i < 3; ++i) {
        const auto g = runner->environment().current_goal(AgentId(i));
        if (g && last[i] && !(g->position == last[i]->position)) ++goal_changes[i];
        last[i] = g;
      }
    }
    for (int c : goal_changes) EXPECT_GE(c, 2) << "agents reach goals and move on to the next";
    EXPECT_TRUE(runner->errors().empty() || std::string(file).find("isaac") != std::string::npos)
        << runner->errors().front();
  }
}

TEST(BtNodes, ScaredAgentRunsFromTheRobotAndThreateningOneBlocksIt) {
  const std::filesystem::path peers = std::filesystem::path(SOCSIM_SHARED_DIR) / "peers/hunav";
  if (!std::filesystem::exists(peers / "BTScaredNav.xml")) GTEST_SKIP() << "HuNavSim trees not in " << peers;
  auto runner = make(nullptr, R"({"agents": [
      {"position": [2, 0], "goals": [[20, 0]], "behavior": {"file": "BTScaredNav.xml"}},
      {"position": [0, 10], "goals": [[20, 10]], "behavior": {"file": "BTThreateningNav.xml"}}],
    "robot": {"position": [0, 0], "goals": [[30, 0]], "speed": 0.5}})",
                     peers);
  ASSERT_TRUE(runner);
  const AgentId scared(0);
  const AgentId robot(2);
  bool saw_scared = false;
  for (int k = 0; k < 60; ++k) {
    runner->step();
    saw_scared = saw_scared || runner->sim().state(scared).metadata.bt_node == "ScaredNav";
  }
  EXPECT_TRUE(saw_scared);
  EXPECT_GT(dist(runner->sim().position(scared), runner->sim().position(robot)), 3.0);
  // The threatening agent (10 m away) does not see the robot: it walks its goals.
  EXPECT_EQ(runner->sim().state(AgentId(1)).metadata.bt_node, "RegularNav");
}

TEST(BtNodes, EvacuateLeavesThroughTheNearestExit) {
  const world::World w = clinic();
  auto runner = make(&w, R"({
    "behavior_trees": {"evacuate": {"xml": "<root BTCPP_format=\"4\"><BehaviorTree ID=\"E\"><Evacuate agent_id=\"{id}\" speed_factor=\"1.2\"/></BehaviorTree></root>"}},
    "agents": [
      {"spawn": "patient_room_01", "count": 3, "behavior": "evacuate"},
      {"spawn": "waiting_room", "count": 3, "behavior": "evacuate"},
      {"position": [5, 3], "behavior": "evacuate"}]})");
  ASSERT_TRUE(runner);
  runner->run(60.0);
  for (std::uint32_t i = 0; i < 7; ++i) {
    EXPECT_EQ(runner->sim().state(AgentId(i)).activity, Activity::kExited) << "agent " << i;
    // Out by the main entrance (y = 0, 1.8 m wide), walking straight out, and only once 2 m past
    // its wall line (beyond the reach of those behind).
    const Vec2 p = runner->sim().position(AgentId(i));
    EXPECT_LE(p.y, -2.0) << "agent " << i << " removed while still near the doorway";
    EXPECT_NEAR(p.x, 5.0, 0.9) << "agent " << i << " did not walk straight out of the opening";
  }
  EXPECT_TRUE(runner->errors().empty());
}

TEST(BtNodes, SitAtTakesTheFreeSeatAndFailsWhenNoneIsLeft) {
  const world::World w = clinic();
  auto runner = make(&w, R"({
    "behavior_trees": {"sit": {"xml": "<root BTCPP_format=\"4\"><BehaviorTree ID=\"S\"><SitAt agent_id=\"{id}\" seat=\"waiting_seats\" duration=\"100\"/></BehaviorTree></root>"}},
    "agents": [{"position": [1.5, 7], "behavior": "sit"}, {"position": [4, 7], "behavior": "sit"},
               {"position": [8, 7], "behavior": "sit"}]})");
  ASSERT_TRUE(runner);
  runner->run(15.0);
  // waiting_seats holds two chairs (2, 9) and (3, 9): the first two agents sit, each on the
  // chair nearest to them when they started; the third finds none free and its SitAt fails.
  EXPECT_EQ(runner->sim().state(AgentId(0)).activity, Activity::kSitting);
  EXPECT_LT(dist(runner->sim().position(AgentId(0)), {2, 9}), 0.25);
  EXPECT_EQ(runner->sim().state(AgentId(1)).activity, Activity::kSitting);
  EXPECT_LT(dist(runner->sim().position(AgentId(1)), {3, 9}), 0.25);
  EXPECT_NE(runner->sim().state(AgentId(2)).activity, Activity::kSitting);
  EXPECT_EQ(runner->tree(AgentId(2))->root().status(), BtStatus::kFailure);
}

TEST(BtNodes, ConversationFormationGathersEveryoneRoundTheMeetingPoint) {
  const world::World w = clinic();
  auto runner = make(&w, R"({
    "agents": [
      {"position": [2, 2], "behavior": {"xml": "<root BTCPP_format=\"4\"><BehaviorTree ID=\"C\"><Sequence><ConversationFormation main_agent_id=\"{id}\" non_main_agent_ids=\"1;2\" goal=\"lobby\" conversation_duration=\"5\"/><SetBlackboard output_key=\"done\" value=\"1\"/><StopAndWait wait_duration=\"100\"/></Sequence></BehaviorTree></root>"}},
      {"position": [8, 1]}, {"position": [8, 5]}]})");
  ASSERT_TRUE(runner);
  const Vec2 centre = runner->environment().place("lobby")->point;
  bool all_talking = false;
  for (int k = 0; k < 400 && !all_talking; ++k) {
    runner->step();
    all_talking = true;
    for (std::uint32_t i = 0; i < 3; ++i)
      all_talking = all_talking && runner->sim().state(AgentId(i)).activity == Activity::kInteracting;
  }
  ASSERT_TRUE(all_talking);
  for (std::uint32_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(dist(runner->sim().position(AgentId(i)), centre), 0.55, 0.4);
    // Standing agents face the centre.
    const PedestrianState s = runner->environment().state(AgentId(i));
    const double bearing = std::atan2(centre.y - s.pose.y, centre.x - s.pose.x);
    EXPECT_LT(std::abs(std::remainder(bearing - s.pose.yaw, 2 * M_PI)), 0.2);
  }
  runner->run(8.0);
  EXPECT_TRUE(runner->tree(AgentId(0))->blackboard().get("done") != nullptr);
}

TEST(BtNodes, UnknownPlacesAndBadPortsAreReportedBeforeTheRunWithPointerAndLine) {
  const world::World w = clinic();
  auto program = program_from_text(R"({"agents": [{"position": [2, 2], "behavior": {"xml":
    "<root BTCPP_format=\"4\">\n<BehaviorTree ID=\"A\">\n<Sequence>\n<GoTo goal=\"recepton_counter\"/>\n<RandomChance probability=\"1.5\"/>\n<JoinQueue queue=\"lobby\"/></Sequence></BehaviorTree></root>"}}]})");
  ASSERT_TRUE(program);
  auto runner = ScenarioRunner::create(&w, *program, {});
  ASSERT_FALSE(runner);
  const Error& e = runner.error();
  ASSERT_GE(e.errors.size(), 3u);
  EXPECT_EQ(e.errors[0].pointer, "/agents/0/behavior");
  EXPECT_EQ(e.errors[0].line, 4);
  EXPECT_THAT(e.errors[0].message, HasSubstr("no ROI, POI, door or zone named 'recepton_counter'"));
  EXPECT_EQ(e.errors[1].line, 5);
  EXPECT_THAT(e.errors[1].message, HasSubstr("must be in [0, 1]"));
  EXPECT_EQ(e.errors[2].line, 6);
  EXPECT_THAT(e.errors[2].message,
              HasSubstr("no queue_lane ROI named 'lobby' (queue lanes: reception_queue)"));
}

TEST(BtNodes, AgentIdListsParse) {
  EXPECT_EQ(*parse_agent_ids("2;3; 4"), (std::vector<std::int64_t>{2, 3, 4}));
  EXPECT_EQ(*parse_agent_ids("1,5"), (std::vector<std::int64_t>{1, 5}));
  EXPECT_FALSE(parse_agent_ids("2;x"));
  EXPECT_FALSE(parse_agent_ids("-1"));
}

}  // namespace
}  // namespace socsim::crowd
