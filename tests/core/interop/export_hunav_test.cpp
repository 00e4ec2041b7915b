// HuNavSim export: the agents YAML reads with yaml-cpp in hunav_loader's layout (the keys of the
// peer's newest agents file), every goal id exists, and each per-agent tree is BT.CPP v4 XML that
// uses only nodes HuNavSim registers and loads in socsim's own BT loader; queue and linger stops
// become GoTo + StopAndWaitTimerAction with their times; same seed → same bytes.
#include "core/interop/export_hunav.hpp"

#include <filesystem>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "core/crowd/bt_nodes.hpp"
#include "core/crowd/scenario_runner.hpp"
#include "core/interop/pedsim_program.hpp"
#include "core/world/xml_reader.hpp"
#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

using ::testing::HasSubstr;

// HuNavSim's behaviour nodes and the BT.CPP built-ins the exported trees may use.
const std::set<std::string>& hunav_nodes() {
  static const std::set<std::string> nodes = {
      "GoTo",    "StopAndWaitTimerAction", "RandomChanceCondition", "Sequence", "Fallback",
      "RunOnce", "AlwaysSuccess"};
  return nodes;
}

void collect_nodes(const world::XmlElement& e, std::vector<const world::XmlElement*>& out) {
  out.push_back(&e);
  for (const auto& c : e.children) collect_nodes(c, out);
}

struct Checked {
  YAML::Node params;
  std::size_t trees = 0;
};

// Checks the YAML and every tree; returns the parsed parameters.
Checked check_bundle(const std::vector<ExportFile>& files, const world::World& w, const crowd::Program& p) {
  Checked out;
  EXPECT_FALSE(files.empty());
  if (files.empty()) return out;
  const YAML::Node root = YAML::Load(files[0].content);
  out.params = root["hunav_loader"]["ros__parameters"];
  const YAML::Node& params = out.params;
  const std::string base = params["yaml_base_name"].as<std::string>();
  EXPECT_EQ(files[0].path, base + ".yaml");
  std::set<int> goal_ids;
  for (const auto& g : params["global_goals"]) {
    goal_ids.insert(g.first.as<int>());
    EXPECT_TRUE(g.second["x"].IsScalar() && g.second["y"].IsScalar());
  }
  const YAML::Node agents = params["agents"];
  EXPECT_EQ(files.size(), agents.size() + 1);
  // socsim's BT loader with HuNavSim's names (its aliases) checks node ports and types.
  auto runner = crowd::ScenarioRunner::create(&w, p, {});
  EXPECT_TRUE(runner) << runner.error().message();
  if (!runner) return out;
  const crowd::BtRegistry registry = crowd::behavior_registry((*runner)->environment());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const std::string key = agents[i].as<std::string>();
    const YAML::Node a = params[key];
    const int id = a["id"].as<int>();
    EXPECT_EQ(key, "agent" + std::to_string(id));
    EXPECT_EQ(a["behavior"]["type"].as<std::string>(), "Regular");
    EXPECT_GT(a["max_vel"].as<double>(), 0.0);
    for (const auto& g : a["goals"])
      EXPECT_TRUE(goal_ids.count(g.as<int>())) << key << " goal " << g.as<int>();
    const std::string path = "behavior_trees/" + base + "__agent_" + std::to_string(id) + "_bt.xml";
    EXPECT_EQ(files[i + 1].path, path);
    auto doc = world::parse_xml(files[i + 1].content);
    EXPECT_TRUE(doc) << path;
    if (!doc) continue;
    EXPECT_EQ(*doc->attribute("BTCPP_format"), "4");
    const auto trees = doc->children_named("BehaviorTree");
    EXPECT_EQ(trees.size(), 1u);
    EXPECT_EQ(*trees[0]->attribute("ID"), *doc->attribute("main_tree_to_execute"));
    std::vector<const world::XmlElement*> nodes;
    for (const auto& c : trees[0]->children) collect_nodes(c, nodes);
    for (const auto* n : nodes) {
      EXPECT_TRUE(hunav_nodes().count(n->name)) << path << ": <" << n->name << "> is not a HuNavSim node";
      if (n->name == "GoTo") {
        EXPECT_TRUE(goal_ids.count(std::stoi(*n->attribute("goal_id")))) << path;
      }
    }
    auto loaded = crowd::BtDocument::parse(files[i + 1].content, registry);
    EXPECT_TRUE(loaded) << path << ": " << loaded.error().message();
    ++out.trees;
  }
  return out;
}

HunavOptions seeded(std::uint64_t seed) {
  HunavOptions o;
  o.seed = seed;
  return o;
}

crowd::RunnerOptions runner_seed(std::uint64_t seed) {
  crowd::RunnerOptions o;
  o.seed = seed;
  return o;
}

TEST(ExportHunav, PedsimHallBecomesAgentsYamlAndOneTreePerAgent) {
  auto in = import_pedsim_scenario(testing::kHall);
  ASSERT_TRUE(in) << in.error().message();
  HunavOptions options = seeded(3);
  options.base_name = "hall";
  auto files = export_hunav(in->scenario.world, in->parsed, options);
  ASSERT_TRUE(files) << files.error().message();
  const Checked c = check_bundle(*files, in->scenario.world, in->parsed);
  EXPECT_EQ(c.trees, 20u);  // 21 agents, the robot is not a HuNavSim agent
  EXPECT_EQ(c.params["map"].as<std::string>(), "pedsim_scenario");
  // A queuing agent: door, the queue's head with the 8 s service, then the platform.
  const YAML::Node a1 = c.params["agent1"];
  EXPECT_EQ(a1["goals"].size(), 3u);
  EXPECT_TRUE(a1["cyclic_goals"].as<bool>());
  const std::string& tree = (*files)[1].content;
  EXPECT_THAT(tree, HasSubstr("stop 2: queue tickets"));
  EXPECT_THAT(tree, HasSubstr("<StopAndWaitTimerAction agent_id=\"{id}\" wait_duration=\"8\"/>"));
  // A child passing the window lingers there with the attraction's chance.
  const std::string& kid = (*files)[11].content;
  EXPECT_THAT(kid, HasSubstr("<RandomChanceCondition agent_id=\"{id}\" probability=\"0.4\"/>"));
  EXPECT_THAT(kid, HasSubstr("<StopAndWaitTimerAction agent_id=\"{id}\" wait_duration=\"20\"/>"));
  // Initial poses are where the runner spawns the agents with that seed.
  auto runner = crowd::ScenarioRunner::create(&in->scenario.world, in->parsed, runner_seed(3));
  ASSERT_TRUE(runner);
  const auto s0 = (*runner)->states().at(0);
  EXPECT_NEAR(a1["init_pose"]["x"].as<double>(), s0.pose.x, 1e-6);
  EXPECT_NEAR(a1["init_pose"]["y"].as<double>(), s0.pose.y, 1e-6);
}

TEST(ExportHunav, SameSeedSameBytesOtherSeedOtherPoses) {
  auto in = import_pedsim_scenario(testing::kHall);
  ASSERT_TRUE(in);
  const auto a = export_hunav(in->scenario.world, in->parsed, seeded(5)).value();
  const auto b = export_hunav(in->scenario.world, in->parsed, seeded(5)).value();
  const auto c = export_hunav(in->scenario.world, in->parsed, seeded(6)).value();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].content, b[i].content) << a[i].path;
  EXPECT_NE(a[0].content, c[0].content);
}

TEST(ExportHunav, ClinicProgramsExportWithTheirStops) {
  const world::World w = testing::clinic();
  for (const char* file : {"program_queue.json", "program_ambient.json", "program_evacuation.json"}) {
    const crowd::Program p = testing::example_program(file);
    auto files = export_hunav(w, p);
    ASSERT_TRUE(files) << file << ": " << files.error().message();
    check_bundle(*files, w, p);
  }
  // Patients queue at the reception (8 s service), then sit in the waiting area: one pass only
  // would repeat, so the route is cyclic like HuNavSim's own trees.
  const auto files = export_hunav(w, testing::example_program("program_queue.json")).value();
  EXPECT_EQ(files[0].path, "clinic_reception_queue_agents.yaml");
  EXPECT_THAT(files[2].content, HasSubstr("queue reception_queue"));
  EXPECT_THAT(files[2].content, HasSubstr("wait_duration=\"8\""));
  EXPECT_THAT(files[2].content, HasSubstr("stay waiting_seats"));
}

TEST(ExportHunav, YamlHasTheKeysOfHunavSimsOwnAgentsFile) {
  const std::string path = testing::peer("hunav", "isaac_warehouse_agents.yaml");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "peer file " << path << " is absent (needs ../shared)";
  const YAML::Node theirs = YAML::LoadFile(path)["hunav_loader"]["ros__parameters"];
  auto in = import_pedsim_scenario(testing::kHall);
  ASSERT_TRUE(in);
  const auto files = export_hunav(in->scenario.world, in->parsed).value();
  const YAML::Node ours = YAML::Load(files[0].content)["hunav_loader"]["ros__parameters"];
  auto keys = [](const YAML::Node& n) {
    std::set<std::string> k;
    for (const auto& e : n) k.insert(e.first.as<std::string>());
    return k;
  };
  const std::string their_first = theirs["agents"][0].as<std::string>();
  EXPECT_EQ(keys(ours["agent1"]), keys(theirs[their_first]));
  EXPECT_EQ(keys(ours["agent1"]["behavior"]), keys(theirs[their_first]["behavior"]));
  EXPECT_EQ(keys(ours["agent1"]["init_pose"]), keys(theirs[their_first]["init_pose"]));
  for (const char* k : {"yaml_base_name", "simulator", "map", "publish_people", "global_goals", "agents"})
    EXPECT_TRUE(ours[k]) << k;
}

}  // namespace
}  // namespace socsim::interop
