// world + program → pedsim_ros scenario XML: only elements pedsim_ros knows; pedsim scenarios
// (ours and the five valid peer files) come back with the same walls, waypoints, queues,
// attractions and agents per type; programs written for socsim worlds get waypoints for the
// places and points their routes use.
#include "core/interop/export_pedsim_scenario.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/interop/pedsim_program.hpp"
#include "core/world/xml_reader.hpp"
#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

using ::testing::HasSubstr;

// Elements and attributes of pedsim_ros's scenario reader.
void expect_pedsim_elements(const world::XmlElement& e, const std::string& where) {
  static const std::map<std::string, std::set<std::string>> known = {
      {"scenario", {}},
      {"obstacle", {"x1", "y1", "x2", "y2"}},
      {"waypoint", {"id", "x", "y", "r", "b"}},
      {"queue", {"id", "x", "y", "direction"}},
      {"attraction", {"id", "x", "y", "width", "height", "strength"}},
      {"agent", {"x", "y", "n", "dx", "dy", "type"}},
      {"source", {"x", "y", "n", "dx", "dy", "type"}},
      {"addwaypoint", {"id"}},
      {"addqueue", {"id"}}};
  const auto it = known.find(e.name);
  ASSERT_NE(it, known.end()) << where << ": <" << e.name << "> is not a pedsim_ros element (line " << e.line
                             << ")";
  for (const auto& [k, v] : e.attributes)
    EXPECT_TRUE(it->second.count(k)) << where << ": <" << e.name << " " << k << ">";
  for (const auto& c : e.children) expect_pedsim_elements(c, where);
}

std::map<int, int> agents_by_type(const world::PedsimScenario& s) {
  std::map<int, int> out;
  for (const auto& a : s.agents) out[a.type] += a.count;
  return out;
}

// Exports the imported scenario and imports it again; compares what pedsim_ros would see.
void expect_round_trip(const std::string& xml, const std::string& file) {
  auto first = import_pedsim_scenario(xml);
  ASSERT_TRUE(first) << file << ": " << first.error().message();
  auto text = export_pedsim_scenario(first->scenario.world, first->parsed);
  ASSERT_TRUE(text) << file << ": " << text.error().message();
  auto doc = world::parse_xml(*text);
  ASSERT_TRUE(doc) << file << ": " << doc.error().message();
  expect_pedsim_elements(*doc, file);
  auto again = import_pedsim_scenario(*text);
  ASSERT_TRUE(again) << file << " does not import again: " << again.error().message() << "\n" << *text;
  const world::PedsimScenario& a = first->scenario;
  const world::PedsimScenario& b = again->scenario;
  EXPECT_EQ(b.world.walls().size(), a.world.walls().size()) << file;
  EXPECT_EQ(b.enclosed, a.enclosed) << file;
  ASSERT_EQ(b.waypoints.size(), a.waypoints.size()) << file;
  for (std::size_t i = 0; i < a.waypoints.size(); ++i) {
    EXPECT_EQ(b.waypoints[i].id, a.waypoints[i].id) << file;
    EXPECT_NEAR(b.waypoints[i].position.x, a.waypoints[i].position.x, 1e-5)
        << file << " " << a.waypoints[i].id;
    EXPECT_NEAR(b.waypoints[i].position.y, a.waypoints[i].position.y, 1e-5)
        << file << " " << a.waypoints[i].id;
    EXPECT_NEAR(b.waypoints[i].radius, a.waypoints[i].radius, 1e-5) << file << " " << a.waypoints[i].id;
  }
  ASSERT_EQ(b.queues.size(), a.queues.size()) << file;
  for (std::size_t i = 0; i < a.queues.size(); ++i) {
    EXPECT_EQ(b.queues[i].id, a.queues[i].id) << file;
    EXPECT_NEAR(b.queues[i].position.x, a.queues[i].position.x, 1e-5) << file;
    EXPECT_NEAR(b.queues[i].position.y, a.queues[i].position.y, 1e-5) << file;
  }
  ASSERT_EQ(b.attractions.size(), a.attractions.size()) << file;
  for (std::size_t i = 0; i < a.attractions.size(); ++i)
    EXPECT_EQ(b.attractions[i].id, a.attractions[i].id) << file;
  EXPECT_EQ(agents_by_type(b), agents_by_type(a)) << file;
  // Each cluster keeps its route (cluster order is kept; n = 0 clusters are not exported).
  std::vector<const world::PedsimAgentCluster*> before;
  for (const auto& c : a.agents)
    if (c.count > 0) before.push_back(&c);
  ASSERT_EQ(b.agents.size(), before.size()) << file;
  // The robot is written after the clusters: compare by type 2 separately.
  auto routes = [](const std::vector<const world::PedsimAgentCluster*>& cs) {
    std::multiset<std::string> out;
    for (const auto* c : cs) {
      std::string r = std::to_string(c->type) + ":" + std::to_string(c->count) + ":";
      for (const auto& s : c->route)
        r += (s.kind == world::PedsimRouteStep::Kind::kQueue ? "q." : "w.") + s.id + " ";
      out.insert(r);
    }
    return out;
  };
  std::vector<const world::PedsimAgentCluster*> after;
  for (const auto& c : b.agents) after.push_back(&c);
  EXPECT_EQ(routes(after), routes(before)) << file;
  // The program made from the export has the same behaviour trees (named by cluster index, which
  // moves when the robot is written last).
  auto trees = [](const Json& program) {
    std::multiset<std::string> out;
    const Json trees_of = program.value("behavior_trees", Json::object());
    for (const auto& [name, tree] : trees_of.items()) out.insert(tree.dump());
    return out;
  };
  EXPECT_EQ(trees(again->program.program), trees(first->program.program)) << file;
}

TEST(ExportPedsimScenario, OwnHallComesBackWithWaypointsQueuesAttractionsAndAgents) {
  expect_round_trip(testing::kHall, "hall");
  auto first = import_pedsim_scenario(testing::kHall);
  ASSERT_TRUE(first);
  const std::string text = export_pedsim_scenario(first->scenario.world, first->parsed).value();
  EXPECT_THAT(text, HasSubstr("<attraction id=\"window\" x=\"12\" y=\"11\" width=\"6\" height=\"1.5\""));
  EXPECT_THAT(text, HasSubstr("<queue id=\"tickets\" x=\"16\" y=\"6\" direction=\"180\"/>"));
  EXPECT_THAT(text, HasSubstr("<waypoint id=\"platform\" x=\"21\" y=\"3\" r=\"2\"/>"));
  EXPECT_THAT(text, HasSubstr("<agent x=\"3\" y=\"3\" n=\"1\" dx=\"0\" dy=\"0\" type=\"2\">"));
  EXPECT_THAT(text, HasSubstr("n=\"10\" dx=\"2\" dy=\"3\" type=\"0\">\n    <addwaypoint id=\"door\"/>\n"
                              "    <addqueue id=\"tickets\"/>\n    <addwaypoint id=\"platform\"/>"));
}

TEST(ExportPedsimScenario, PeerScenariosComeBack) {
  for (const char* file : {"airport.xml", "airport_activities.xml", "contexts_queueing.xml", "scene1.xml",
                           "social_contexts.xml"}) {
    const std::string path = testing::peer("pedsim", file);
    if (!std::filesystem::exists(path))
      GTEST_SKIP() << "peer file " << path << " is absent (needs ../shared)";
    expect_round_trip(testing::read_text(path), file);
  }
}

TEST(ExportPedsimScenario, SocsimProgramsGetWaypointsForTheirPlacesAndPoints) {
  const world::World w = testing::clinic();
  for (const char* file : {"program_queue.json", "program_ambient.json", "program_evacuation.json"}) {
    const crowd::Program p = testing::example_program(file);
    PedsimExportOptions options;
    options.seed = 7;
    auto text = export_pedsim_scenario(w, p, options);
    ASSERT_TRUE(text) << file << ": " << text.error().message();
    auto doc = world::parse_xml(*text);
    ASSERT_TRUE(doc) << file;
    expect_pedsim_elements(*doc, file);
    auto again = world::import_pedsim(*text);
    ASSERT_TRUE(again) << file << ": " << again.error().message() << "\n" << *text;
    // As many agents as the program has (robot included), and no route names a missing waypoint.
    std::size_t agents = p.robot ? 1 : 0;
    for (const auto& a : p.agents) agents += a.count;
    for (const auto& g : p.ambient_groups) agents += g.size;
    std::size_t exported = 0;
    for (const auto& c : again->agents) exported += static_cast<std::size_t>(c.count);
    EXPECT_EQ(exported, agents) << file;
  }
  // The queue program: patients queue at the reception lane, then sit in the waiting seats, which
  // pedsim models as an attraction (strength 10: every patient goes there); the robot's bare points
  // get waypoints of their own.
  const std::string queue = export_pedsim_scenario(w, testing::example_program("program_queue.json")).value();
  EXPECT_THAT(queue, HasSubstr("<addqueue id=\"reception_queue\"/>\n  </agent>"));
  EXPECT_THAT(queue, HasSubstr("<attraction id=\"waiting_seats\" x=\"5\" y=\"9.5\" width=\"8\" height=\"3\" "
                               "strength=\"10\"/>"));
  EXPECT_THAT(queue, HasSubstr("<waypoint id=\"goal_1\" x=\"8.5\" y=\"5\""));
  EXPECT_THAT(queue, HasSubstr("<waypoint id=\"reception_counter\" x=\"5\" y=\"4.8\" r=\"1\"/>"));
}

TEST(ExportPedsimScenario, AProgramThatDoesNotRunInTheWorldIsRefused) {
  crowd::Program p = testing::example_program("program_queue.json");
  p.agents[1].spawn = crowd::ProgramRegion{std::string("no_such_room"), "/agents/1/spawn"};
  auto text = export_pedsim_scenario(testing::clinic(), p);
  ASSERT_FALSE(text);
  EXPECT_EQ(text.error().code, ErrorCode::kValidation);
  EXPECT_EQ(text.error().errors.at(0).pointer, "/agents/1/spawn");
}

}  // namespace
}  // namespace socsim::interop
