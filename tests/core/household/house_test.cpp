// Procedurally generated houses: 1–10 rooms of the four types, every room reachable through
// doors on shared walls, furniture inside its room and clear of doors, objects on receptacles
// they are allowed on, and the same seed gives the same house.
#include "core/household/house.hpp"

#include <gtest/gtest.h>

#include "tests/core/household/household_fixture.hpp"

namespace socsim::household {
namespace {

using testing::knowledge;

TEST(House, EveryRoomCountGivesAConnectedFurnishedHouse) {
  for (int rooms = 1; rooms <= 10; ++rooms)
    for (std::uint64_t seed = 0; seed < 25; ++seed) {
      auto h = generate_house({rooms, std::nullopt, seed}, knowledge());
      ASSERT_TRUE(h) << rooms << " rooms, seed " << seed << ": " << h.error().message();
      ASSERT_EQ(static_cast<int>(h->rooms.size()), rooms);
      EXPECT_TRUE(h->connected()) << rooms << "/" << seed;
      EXPECT_GE(h->rooms_of(RoomType::kBedroom).size(), 1u);
      if (rooms >= 4) {
        EXPECT_EQ(h->rooms_of(RoomType::kKitchen).size(), 1u);
        EXPECT_GE(h->rooms_of(RoomType::kLivingRoom).size(), 1u);
        EXPECT_GE(h->rooms_of(RoomType::kBathroom).size(), 1u);
      }
      if (rooms >= 8) {
        EXPECT_GE(h->rooms_of(RoomType::kBedroom).size(), 3u) << "room for the hard split's 3–4 residents";
      }
      int front_doors = 0;
      for (const auto& d : h->doors) front_doors += d.room0 == d.room1;
      EXPECT_EQ(front_doors, 1);
      for (int r : h->receptacles) {
        const Entity& e = h->entities[static_cast<std::size_t>(r)];
        const Room& room = h->rooms[static_cast<std::size_t>(e.room)];
        EXPECT_TRUE(point_in_polygon(room.floor, e.position.x, e.position.z)) << e.id;
        EXPECT_TRUE(knowledge().receptacle(e.type)->allowed_in(room.type)) << e.id;
      }
      for (int o : h->objects) {
        const Entity& e = h->entities[static_cast<std::size_t>(o)];
        ASSERT_GE(e.parent, 0);
        const Entity& rec = h->entities[static_cast<std::size_t>(e.parent)];
        EXPECT_EQ(rec.kind, EntityKind::kReceptacle);
        bool allowed = false;
        for (const auto& [t, w] : knowledge().receptacle(rec.type)->contents) allowed |= t == e.type;
        EXPECT_TRUE(allowed) << e.type << " on " << rec.type;
      }
    }
}

TEST(House, SameSeedSameHouse) {
  EXPECT_EQ(*generate_house({7, std::nullopt, 5}, knowledge()),
            *generate_house({7, std::nullopt, 5}, knowledge()));
  EXPECT_NE(*generate_house({7, std::nullopt, 5}, knowledge()),
            *generate_house({7, std::nullopt, 6}, knowledge()));
}

TEST(House, FurnitureDoesNotOverlap) {
  auto h = generate_house({9, std::nullopt, 77}, knowledge());
  ASSERT_TRUE(h);
  for (std::size_t i = 0; i < h->receptacles.size(); ++i)
    for (std::size_t j = i + 1; j < h->receptacles.size(); ++j) {
      const Entity& a = h->entities[static_cast<std::size_t>(h->receptacles[i])];
      const Entity& b = h->entities[static_cast<std::size_t>(h->receptacles[j])];
      const bool overlap = std::abs(a.position.x - b.position.x) < (a.size_x + b.size_x) / 2 - 1e-6 &&
                           std::abs(a.position.z - b.position.z) < (a.size_z + b.size_z) / 2 - 1e-6;
      EXPECT_FALSE(overlap) << a.id << " / " << b.id;
    }
}

TEST(House, BadRequestsNameTheField) {
  auto h = generate_house({11, std::nullopt, 0}, knowledge());
  ASSERT_FALSE(h);
  EXPECT_EQ(h.error().errors.at(0).pointer, "/rooms");
  h = generate_house({4, 4, 0}, knowledge());
  ASSERT_FALSE(h);
  EXPECT_EQ(h.error().errors.at(0).pointer, "/bedrooms");
  auto ok = generate_house({6, 4, 0}, knowledge());
  ASSERT_TRUE(ok) << ok.error().message();
  EXPECT_EQ(ok->rooms_of(RoomType::kBedroom).size(), 4u);
}

}  // namespace
}  // namespace socsim::household
