// Scene graphs: the schema and the rules it cannot say, each problem with its pointer; room
// programmes per building type; prompts with numbers and room words.
#include "core/floorplan/scene_graph.hpp"

#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::floorplan {
namespace {

using ::testing::HasSubstr;

int count_type(const SceneGraph& g, const std::string& type) {
  return static_cast<int>(
      std::count_if(g.rooms.begin(), g.rooms.end(), [&](const SceneRoom& r) { return r.type == type; }));
}

std::vector<std::string> pointers(const Error& e) {
  std::vector<std::string> out;
  for (const auto& f : e.errors) out.push_back(f.pointer);
  return out;
}

TEST(SceneGraph, ReadsRoomsEdgesAndFillsDomainAndEntrance) {
  auto g = scene_graph_from_json(Json::parse(R"({"rooms": [
      {"name": "lobby", "type": "Lobby"}, {"name": "corridor", "type": "corridor"},
      {"name": "ward_1", "type": "ward", "area": 18}, {"name": "nurses", "type": "nurse station"}],
      "adjacency": [["lobby", "corridor"], ["corridor", "ward_1"], ["corridor", "nurses"]]})"));
  ASSERT_TRUE(g) << g.error().message();
  EXPECT_EQ(g->domain, "hospital");
  EXPECT_EQ(g->entrance, "lobby");
  EXPECT_EQ(g->rooms[2].type, "patient_room");
  EXPECT_EQ(g->rooms[3].type, "nurse_station");
  EXPECT_EQ(*g->rooms[2].area, 18.0);
  // Round trip through JSON.
  auto again = scene_graph_from_json(to_json(*g));
  ASSERT_TRUE(again);
  EXPECT_EQ(*again, *g);
}

TEST(SceneGraph, EveryProblemIsNamedWithItsPointer) {
  auto bad = scene_graph_from_json(Json::parse(R"({"rooms": [{"name": "a", "type": "kitchen"}, {"name": "b"},
      {"name": "bad name!", "type": "x"}], "adjacency": [["a"]], "color": 1, "domain": "castle"})"));
  ASSERT_FALSE(bad);
  EXPECT_THAT(pointers(bad.error()), ::testing::IsSupersetOf({"/rooms/1/type", "/rooms/2/name",
                                                              "/adjacency/0", "/color", "/domain"}));
  auto rules = scene_graph_from_json(
      Json::parse(R"({"rooms": [{"name": "a", "type": "kitchen"}, {"name": "a", "type": "bedroom"},
      {"name": "c", "type": "bedroom"}, {"name": "d", "type": "bathroom"}],
      "adjacency": [["a", "zz"], ["c", "c"], ["a", "c"], ["c", "a"]], "entrance": "nowhere"})"));
  ASSERT_FALSE(rules);
  EXPECT_THAT(pointers(rules.error()),
              ::testing::UnorderedElementsAre("/rooms/1/name", "/adjacency/0/1", "/adjacency/1",
                                              "/adjacency/3", "/entrance"));
  auto island = scene_graph_from_json(Json::parse(R"({"rooms": [{"name": "a", "type": "kitchen"},
      {"name": "b", "type": "bedroom"}, {"name": "c", "type": "bathroom"}], "adjacency": [["a", "b"]]})"));
  ASSERT_FALSE(island);
  ASSERT_EQ(island.error().errors.size(), 1u);
  EXPECT_EQ(island.error().errors[0].pointer, "/rooms/2");
  EXPECT_THAT(island.error().errors[0].message, HasSubstr("'c' is not connected"));
}

TEST(SceneGraph, ProgrammesPerBuildingType) {
  // A small home has no hallway: every room opens onto the living room (ProcTHOR-style).
  const SceneGraph home = room_program("residential");
  EXPECT_EQ(home.entrance, "living_room");
  EXPECT_EQ(count_type(home, "bedroom"), 2);
  EXPECT_EQ(count_type(home, "living_room"), 1);
  EXPECT_EQ(count_type(home, "hallway"), 0);
  EXPECT_THAT(home.adjacency,
              ::testing::Contains(std::pair<std::string, std::string>{"living_room", "kitchen"}));
  for (const auto& [a, b] : home.adjacency) EXPECT_EQ(a, "living_room") << b;
  // A larger one keeps its hallway; the kitchen opens onto the living room, the rest onto the hallway.
  const SceneGraph house = room_program("residential", {{"bedroom", 3}});
  EXPECT_EQ(house.entrance, "hallway");
  EXPECT_EQ(count_type(house, "hallway"), 1);
  EXPECT_THAT(house.adjacency,
              ::testing::Contains(std::pair<std::string, std::string>{"living_room", "kitchen"}));
  const SceneGraph office = room_program("office", {{"meeting_room", 4}});
  EXPECT_EQ(count_type(office, "meeting_room"), 4);
  EXPECT_EQ(office.entrance, "reception");
  const SceneGraph hospital = room_program("hospital");
  for (const char* t : {"lobby", "corridor", "patient_room", "nurse_station", "treatment_room", "toilet"})
    EXPECT_GE(count_type(hospital, t), 1) << t;
  for (const char* d : {"canteen", "retail", "warehouse", "school", "airport"}) {
    const SceneGraph g = room_program(d);
    EXPECT_EQ(g.domain, d);
    auto j = scene_graph_from_json(to_json(g));
    EXPECT_TRUE(j) << d << ": " << j.error().message();
  }
}

TEST(SceneGraph, PromptNumbersAndRoomWordsAreHonoured) {
  auto clinic = scene_graph_from_prompt("a clinic with six patient rooms, 3 exam rooms and a waiting room");
  ASSERT_TRUE(clinic) << clinic.error().message();
  EXPECT_EQ(clinic->graph.domain, "hospital");
  EXPECT_EQ(count_type(clinic->graph, "patient_room"), 6);
  EXPECT_EQ(count_type(clinic->graph, "treatment_room"), 3);
  EXPECT_EQ(count_type(clinic->graph, "waiting_room"), 1);
  EXPECT_EQ(clinic->counts.at("patient_room"), 6);

  auto flat = scene_graph_from_prompt("a family apartment with three bedrooms, two bathrooms and a study");
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->graph.domain, "residential");
  EXPECT_EQ(count_type(flat->graph, "bedroom"), 3);
  EXPECT_EQ(count_type(flat->graph, "bathroom"), 2);
  EXPECT_EQ(count_type(flat->graph, "study"), 1);

  auto office = scene_graph_from_prompt("an office without a kitchenette and with 4 small meeting rooms");
  ASSERT_TRUE(office);
  EXPECT_EQ(count_type(office->graph, "meeting_room"), 4);
  EXPECT_EQ(count_type(office->graph, "kitchenette"),
            1);  // programme rooms stay; negation only drops additions

  auto given = scene_graph_from_prompt("a couple of toilets", std::string("canteen"));
  ASSERT_TRUE(given);
  EXPECT_EQ(given->graph.domain, "canteen");
  EXPECT_EQ(count_type(given->graph, "toilet"), 2);

  auto huge = scene_graph_from_prompt("a hospital with 99 patient rooms");
  ASSERT_FALSE(huge);
  EXPECT_EQ(huge.error().errors[0].pointer, "/prompt");
  auto empty = scene_graph_from_prompt("  ");
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().errors[0].pointer, "/prompt");
  auto domain = scene_graph_from_prompt("a house", std::string("castle"));
  ASSERT_FALSE(domain);
  EXPECT_EQ(domain.error().errors[0].pointer, "/domain");
}

}  // namespace
}  // namespace socsim::floorplan
