// ProcTHOR house JSON: the four real houses in ../shared/peers/procthor import (non-convex floors,
// open walls), export, and re-import to the same house; objects get AI2-THOR types from asset ids;
// broken files are refused with JSON pointers.
#include "core/household/procthor.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/core/household/household_fixture.hpp"

namespace socsim::household {
namespace {

using testing::knowledge;

std::optional<Json> read_peer(const std::string& name) {
  std::ifstream in(testing::shared_file("peers/procthor/" + name));
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  auto j = parse_json_untrusted(ss.str());
  if (!j) return std::nullopt;
  return *j;
}

const char* kHouses[] = {"zhiyuan_houses20_house_6.json", "zhiyuan_houses20_house_15.json",
                         "quinlan_hallway_houses_3.json", "quinlan_hallway_houses_4.json"};

TEST(ProcThor, RealHousesImportExportAndRoundTrip) {
  int seen = 0;
  for (const char* name : kHouses) {
    auto json = read_peer(name);
    if (!json) GTEST_SKIP() << "peer house not present: " << name;
    ++seen;
    auto h = import_procthor(*json, knowledge(), name);
    ASSERT_TRUE(h) << name << ": " << h.error().message();
    EXPECT_EQ(h->rooms.size(), (*json)["rooms"].size());
    EXPECT_EQ(h->doors.size(), (*json)["doors"].size());
    EXPECT_TRUE(h->connected()) << name;
    EXPECT_GT(h->objects.size(), 20u) << name;
    EXPECT_GT(h->receptacles.size(), 10u) << name;
    for (int o : h->objects) EXPECT_GE(h->entities[static_cast<std::size_t>(o)].parent, 0);
    const Json out = export_procthor(*h);
    auto again = import_procthor(out, knowledge(), name);
    ASSERT_TRUE(again) << again.error().message();
    EXPECT_EQ(*again, *h) << name << " survives export → import";
    EXPECT_EQ(out["objects"].size(), (*json)["objects"].size());
    EXPECT_EQ(out["walls"].size(), (*json)["walls"].size());
  }
  EXPECT_EQ(seen, 4);
}

TEST(ProcThor, NonConvexFloorsAndOpenWalls) {
  auto json = read_peer("quinlan_hallway_houses_4.json");
  if (!json) GTEST_SKIP() << "peer house not present";
  auto h = import_procthor(*json, knowledge());
  ASSERT_TRUE(h);
  int empty = 0;
  for (const auto& w : h->walls) empty += w.empty;
  EXPECT_EQ(empty, 2);
  const auto links = h->room_links();
  EXPECT_GT(links.size(), h->doors.size() - 2) << "the open wall links two rooms";
  // The kitchen's 10-vertex floor is not convex: its bounding-box centre lies outside it.
  const Room& kitchen = h->rooms[static_cast<std::size_t>(h->room_index("room|2"))];
  EXPECT_EQ(kitchen.floor.size(), 10u);
  EXPECT_FALSE(point_in_polygon(kitchen.floor, 2.0, 2.0));
  EXPECT_TRUE(point_in_polygon(kitchen.floor, 2.0, 6.0));
  auto house6 = read_peer("zhiyuan_houses20_house_6.json");
  ASSERT_TRUE(house6);
  auto h6 = import_procthor(*house6, knowledge());
  ASSERT_TRUE(h6);
  bool nine = false;
  for (const auto& r : h6->rooms) nine |= r.floor.size() == 9;
  EXPECT_TRUE(nine);
}

TEST(ProcThor, AssetIdsMapToAi2ThorTypes) {
  const auto& k = knowledge();
  EXPECT_EQ(object_type_from_asset("Dining_Table_208_1", k), "DiningTable");
  EXPECT_EQ(object_type_from_asset("RoboTHOR_dining_table_jokkmokk_v", k), "DiningTable");
  EXPECT_EQ(object_type_from_asset("Alarm_Clock_23", k), "AlarmClock");
  EXPECT_EQ(object_type_from_asset("bin_12", k), "GarbageCan");
  EXPECT_EQ(object_type_from_asset("Remote_2", k), "RemoteControl");
  EXPECT_EQ(object_type_from_asset("RoboTHOR_salt_pepper_shaker_bnyd_pepper_v", k), "PepperShaker");
  EXPECT_EQ(object_type_from_asset("Countertop_L_6x4", k), "CounterTop");
  EXPECT_EQ(object_type_from_asset("Shelving_Unit_206_1", k), "ShelvingUnit");
  EXPECT_EQ(object_type_from_asset("Mug_2", k), "Mug");
  EXPECT_EQ(object_type_from_asset("Wall_Decor_Photo_1V", k), "Painting");
  EXPECT_EQ(object_type_from_asset("Toilet_Paper_Used_Up", k), "ToiletPaper");
}

TEST(ProcThor, ExportMovesObjectsToAGivenPlacement) {
  auto json = read_peer("zhiyuan_houses20_house_15.json");
  if (!json) GTEST_SKIP() << "peer house not present";
  auto h = import_procthor(*json, knowledge());
  ASSERT_TRUE(h);
  std::vector<int> placement(h->objects.size());
  for (std::size_t o = 0; o < placement.size(); ++o)
    placement[o] = h->entities[static_cast<std::size_t>(h->objects[o])].parent;
  placement[0] = h->receptacles.back();
  auto moved = import_procthor(export_procthor(*h, &placement), knowledge());
  ASSERT_TRUE(moved);
  const std::string& id = h->entities[static_cast<std::size_t>(h->objects[0])].id;
  bool found = false;
  for (int o : moved->objects) {
    const Entity& e = moved->entities[static_cast<std::size_t>(o)];
    if (e.id != id) continue;
    found = true;
    EXPECT_EQ(moved->entities[static_cast<std::size_t>(e.parent)].id,
              h->entities[static_cast<std::size_t>(h->receptacles.back())].id);
  }
  EXPECT_TRUE(found);
}

TEST(ProcThor, BrokenHousesAreRefusedWithPointers) {
  Json j =
      Json::parse(R"({"rooms":[{"id":"room|1","roomType":"Garage","floorPolygon":[{"x":0,"z":0},{"x":1}]}],
                           "walls":[{"id":"w","roomId":"room|1","polygon":[{"x":0,"y":0,"z":0}]}],
                           "doors":[{"id":"d","room0":"room|1","room1":"room|9","wall0":"w","wall1":"w","holePolygon":[]}],
                           "objects":[]})");
  auto h = import_procthor(j, knowledge());
  ASSERT_FALSE(h);
  std::set<std::string> ptrs;
  for (const auto& f : h.error().errors) ptrs.insert(f.pointer);
  for (const char* p : {"/rooms/0/roomType", "/rooms/0/floorPolygon", "/rooms/0/floorPolygon/1/z",
                        "/walls/0/polygon", "/doors/0/room1", "/doors/0/holePolygon"})
    EXPECT_TRUE(ptrs.count(p)) << p;
  EXPECT_FALSE(import_procthor(Json::array(), knowledge()));
}

// Found by tests/fuzz (procthor_json): a number where a room, wall, door or point belongs threw
// nlohmann's type_error from erase() (a 500 at POST /households) or was silently skipped.
TEST(ProcThor, ElementsThatAreNotObjectsAreRefusedWithPointers) {
  Json j = Json::parse(R"({"rooms":[{"id":"r","roomType":"Kitchen","floorPolygon":[1,2,3]}, 7],
                           "walls":[5, {"id":"w","roomId":"r","polygon":[[0,0,0],{"x":1,"y":2,"z":0}]}],
                           "doors":["d", {"id":"d","room0":"r","room1":"r","wall0":"w","wall1":"w",
                                          "holePolygon":[1,{"x":1,"y":2}]}],
                           "objects":[]})");
  auto h = import_procthor(j, knowledge());
  ASSERT_FALSE(h);
  std::set<std::string> ptrs;
  for (const auto& f : h.error().errors) ptrs.insert(f.pointer);
  for (const char* p : {"/rooms/0/floorPolygon/0", "/rooms/0/floorPolygon/2", "/rooms/1", "/walls/0",
                        "/walls/1/polygon/0", "/doors/0", "/doors/1/holePolygon/0"})
    EXPECT_TRUE(ptrs.count(p)) << p;
}

TEST(ProcThor, GeneratedHousesRoundTripToo) {
  auto h = generate_house({8, std::nullopt, 4}, knowledge());
  ASSERT_TRUE(h);
  auto again = import_procthor(export_procthor(*h), knowledge(), h->id);
  ASSERT_TRUE(again) << again.error().message();
  EXPECT_EQ(again->rooms, h->rooms);
  EXPECT_EQ(again->doors, h->doors);
  ASSERT_EQ(again->objects.size(), h->objects.size());
  EXPECT_TRUE(again->connected());
}

}  // namespace
}  // namespace socsim::household
