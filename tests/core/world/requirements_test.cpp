// World requirements: the typed form of what a prompt asks a world to hold — read from JSON with
// a pointer on every bad field, written back unchanged; feature words and plurals; features
// counted in a world.
#include "core/world/requirements.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/core/world/world_text.hpp"

namespace socsim::world {
namespace {

using ::testing::HasSubstr;

TEST(WorldRequirements, ReadAndWrittenBack) {
  const Json j = Json::parse(R"({
    "features": [{"feature": "exit", "count": 3, "words": "emergency exits"},
                 {"feature": "checkouts", "count": 2, "at_least": true}],
    "rooms": [{"name": "waiting room"}, {"name": "Maternity Ward", "type": "patient_room", "count": 2}],
    "objects": [{"name": "music system", "room": "hall"}, {"name": "coffee machine", "count": 2}],
    "occupants": 120})");
  auto r = world_requirements_from_json(j);
  ASSERT_TRUE(r) << r.error().message();
  ASSERT_EQ(r->features.size(), 2u);
  EXPECT_EQ(r->features[0], (FeatureCount{Feature::kExit, 3, false, "emergency exits"}));
  EXPECT_EQ(r->features[1].feature, Feature::kCheckout);
  EXPECT_TRUE(r->features[1].at_least);
  EXPECT_EQ(r->rooms[0], (NamedRoom{"waiting room", "waiting_room", 1}));
  EXPECT_EQ(r->rooms[1], (NamedRoom{"Maternity Ward", "patient_room", 2}));
  EXPECT_EQ(r->objects[0], (NamedObject{"music system", "music_system", 1, "hall"}));
  EXPECT_EQ(r->objects[1].count, 2);
  EXPECT_EQ(r->occupants, 120);
  EXPECT_EQ(r->find(Feature::kExit)->count, 3);
  EXPECT_EQ(r->find(Feature::kGate), nullptr);
  auto again = world_requirements_from_json(to_json(*r));
  ASSERT_TRUE(again) << again.error().message();
  EXPECT_EQ(*again, *r);
  EXPECT_TRUE(world_requirements_from_json(Json::object())->empty());
}

TEST(WorldRequirements, EveryBadFieldHasItsPointer) {
  const Json j = Json::parse(R"({
    "features": [{"feature": "moat", "count": 1}, {"feature": "exit", "count": 13},
                 {"feature": "exits", "count": 2}, {"feature": "fire exit", "count": 2}, {"count": 1}],
    "rooms": [{"name": ""}, {"name": "hall", "count": 0}, {"name": "??"}],
    "objects": [{"name": "music system", "type": "Music System"}, "piano"],
    "occupants": -1, "colour": "red"})");
  auto r = world_requirements_from_json(j, "/requirements");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kValidation);
  std::map<std::string, std::string> at;
  for (const auto& e : r.error().errors) at[e.pointer] = e.message;
  EXPECT_THAT(at["/requirements/features/0/feature"],
              HasSubstr("unknown feature 'moat' (known: exit, entrance"));
  EXPECT_TRUE(at.count("/requirements/features/1/count"));
  EXPECT_TRUE(at.count("/requirements/features/2/count") == 0);
  EXPECT_EQ(at["/requirements/features/3/feature"],
            "feature 'exit' is already asked for at /requirements/features/1");
  EXPECT_TRUE(at.count("/requirements/features/4/feature"));
  EXPECT_TRUE(at.count("/requirements/rooms/0/name"));
  EXPECT_TRUE(at.count("/requirements/rooms/1/count"));
  EXPECT_EQ(at["/requirements/rooms/2/name"], "must contain a letter or digit");
  EXPECT_THAT(at["/requirements/objects/0/type"], HasSubstr("lower-case letters, digits and '_'"));
  EXPECT_TRUE(at.count("/requirements/objects/1"));
  EXPECT_TRUE(at.count("/requirements/occupants"));
  EXPECT_TRUE(at.count("/requirements/colour"));
  EXPECT_FALSE(world_requirements_from_json(Json::array(), "/requirements"));
}

TEST(WorldRequirements, FeatureWords) {
  EXPECT_EQ(feature_from_word("exits"), Feature::kExit);
  EXPECT_EQ(feature_from_word("Emergency Exits"), Feature::kExit);
  EXPECT_EQ(feature_from_word("north exit"), Feature::kExit);
  EXPECT_EQ(feature_from_word("tills"), Feature::kCheckout);
  EXPECT_EQ(feature_from_word("self checkouts"), Feature::kCheckout);
  EXPECT_EQ(feature_from_word("turnstiles"), Feature::kGate);
  EXPECT_EQ(feature_from_word("lifts"), Feature::kElevator);
  EXPECT_EQ(feature_from_word("stairs"), Feature::kStair);
  EXPECT_EQ(feature_from_word("benches"), Feature::kSeat);
  EXPECT_EQ(feature_from_word("shelves"), Feature::kShelf);
  EXPECT_EQ(feature_from_word("reception desk"), Feature::kCounter);
  EXPECT_EQ(feature_from_word("desks"), Feature::kDesk);
  EXPECT_EQ(feature_from_word("restrooms"), Feature::kToilet);
  EXPECT_EQ(feature_from_word("music system"), std::nullopt);
  EXPECT_EQ(feature_from_word(""), std::nullopt);
  for (const auto& f : features()) {
    EXPECT_EQ(feature_from_word(f.key), f.feature) << f.key;
    EXPECT_EQ(feature_from_word(f.plural), f.feature) << f.plural;
  }
  EXPECT_EQ(snake_case("Music System!"), "music_system");
  EXPECT_EQ(snake_case("  Café  crème "), "cafe_creme");
}

TEST(WorldRequirements, FeaturesAreCountedInAWorld) {
  const World w = testing::load(R"(zones:
  - {name: shop, type: sales_floor, polygon: [[0, 0], [10, 0], [10, 8], [0, 8]]}
  - {name: wc, type: toilet, polygon: [[10, 0], [12, 0], [12, 3], [10, 3]]}
doors:
  - {name: in, pose: [5, 0], width: 1.8, connects: [shop]}
  - {name: out, pose: [0, 4], width: 1.0, connects: [shop]}
  - {name: wc_door, pose: [10, 1.5], width: 0.9, connects: [shop, wc]}
entities:
  - {type: counter, name: till_1, pose: [2, 2], affordances: [pay, queue_target]}
  - {type: counter, name: till_2, pose: [4, 2], affordances: [pay, queue_target]}
  - {type: counter, name: info, pose: [8, 2], affordances: [serve]}
  - {type: shelf, name: s1, pose: [2, 6]}
  - {type: chair, name: c1, pose: [6, 6]}
  - {type: bench, name: b1, pose: [7, 6]}
)");
  EXPECT_EQ(count_feature(w, Feature::kExit), 2);
  EXPECT_EQ(count_feature(w, Feature::kEntrance), 2);
  EXPECT_EQ(count_feature(w, Feature::kDoor), 3);
  EXPECT_EQ(count_feature(w, Feature::kCheckout), 2);
  EXPECT_EQ(count_feature(w, Feature::kCounter), 1);
  EXPECT_EQ(count_feature(w, Feature::kShelf), 1);
  EXPECT_EQ(count_feature(w, Feature::kSeat), 2);
  EXPECT_EQ(count_feature(w, Feature::kToilet), 1);
  EXPECT_EQ(count_feature(w, Feature::kGate), 0);
}

}  // namespace
}  // namespace socsim::world
