// Procedurally generated houses: 1–10 rooms of the four types, every room reachable through
// doors on shared walls, furniture inside its room and clear of doors, objects on receptacles
// they are allowed on, and the same seed gives the same house. Issue 18: ProcTHOR density,
// windows, oriented footprints clear of walls, door swings and each other.
#include "core/household/house.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

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

// A turned piece: a 2 × 1 m sofa at yaw 90 covers 1 m along x and 2 m along z.
TEST(House, FootprintsHonourYaw) {
  Entity sofa;
  sofa.position = {5.0, 0.0, 5.0};
  sofa.size_x = 2.0;
  sofa.size_z = 1.0;
  sofa.rotation = {0, 90, 0};
  double x0 = 1e9, x1 = -1e9, z0 = 1e9, z1 = -1e9;
  for (const auto& c : footprint(sofa))
    x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), z0 = std::min(z0, c.z), z1 = std::max(z1, c.z);
  EXPECT_NEAR(x1 - x0, 1.0, 1e-9);
  EXPECT_NEAR(z1 - z0, 2.0, 1e-9);
  const std::vector<FloorPoint> room = {{4.4, 3.9}, {4.4, 6.1}, {5.6, 6.1}, {5.6, 3.9}};
  EXPECT_TRUE(footprint_inside(room, footprint(sofa)));
  sofa.rotation = {0, 0, 0};  // unturned it sticks out of this narrow room
  EXPECT_FALSE(footprint_inside(room, footprint(sofa)));
  Entity table = sofa;
  table.position = {7.0, 0.0, 5.0};
  EXPECT_FALSE(footprints_overlap(footprint(sofa), footprint(table)));  // edges touch at x = 6
  table.rotation = {0, 45, 0};
  EXPECT_TRUE(footprints_overlap(footprint(sofa), footprint(table)));
}

TEST(House, ProcthorRangeInterpolatesThePeerHouses) {
  EXPECT_EQ(procthor_object_range(4), std::make_pair(102, 109));
  EXPECT_EQ(procthor_object_range(8), std::make_pair(124, 166));
  EXPECT_EQ(procthor_object_range(6), std::make_pair(113, 137));
  EXPECT_EQ(procthor_object_range(10), std::make_pair(135, 194));
}

// Issue 18's acceptance over 1,000 houses (100 per room count): as many objects with children
// as real ProcTHOR houses of that size, windows, every receptacle inside its room and clear of
// door swings and of every other receptacle, and what stands on a receptacle within its top.
TEST(House, ThousandHousesAreDenseAndClean) {
  int outside = 0, overlapping = 0, in_swing = 0, off_top = 0, out_of_range = 0, windowless = 0;
  for (int rooms = 1; rooms <= 10; ++rooms)
    for (std::uint64_t seed = 1000; seed < 1100; ++seed) {
      auto h = generate_house({rooms, std::nullopt, seed}, knowledge());
      ASSERT_TRUE(h) << rooms << "/" << seed << ": " << h.error().message();
      const auto [lo, hi] = procthor_object_range(rooms);
      const int count = objects_with_children(*h);
      if (count < lo || count > hi) {
        ++out_of_range;
        ADD_FAILURE() << rooms << " rooms, seed " << seed << ": " << count << " objects, want " << lo << "–"
                      << hi;
      }
      windowless += h->windows.empty();
      if (h->windows.empty()) ADD_FAILURE() << h->id << " has no window";
      std::vector<Footprint> fps;
      for (int r : h->receptacles) {
        const Entity& e = h->entities[static_cast<std::size_t>(r)];
        const Footprint fp = footprint(e);
        if (!footprint_inside(h->rooms[static_cast<std::size_t>(e.room)].floor, fp)) {
          ++outside;
          ADD_FAILURE() << h->id << ": " << e.id << " reaches outside its room";
        }
        for (const auto& d : door_clearances(*h, e.room))
          if (footprints_overlap(fp, d)) {
            ++in_swing;
            ADD_FAILURE() << h->id << ": " << e.id << " stands in a door's swing";
          }
        for (const auto& other : fps)
          if (footprints_overlap(fp, other)) {
            ++overlapping;
            ADD_FAILURE() << h->id << ": " << e.id << " overlaps another piece";
          }
        fps.push_back(fp);
      }
      for (const auto& e : h->entities) {
        if (e.parent < 0) continue;
        const Entity& rec = h->entities[static_cast<std::size_t>(e.parent)];
        // Back into the receptacle's own frame: inside half its size.
        const double yaw = rec.rotation.y * std::numbers::pi / 180.0;
        const double dx = e.position.x - rec.position.x, dz = e.position.z - rec.position.z;
        const double lx = dx * std::cos(yaw) - dz * std::sin(yaw),
                     lz = dx * std::sin(yaw) + dz * std::cos(yaw);
        if (std::abs(lx) > rec.size_x / 2 + 0.011 || std::abs(lz) > rec.size_z / 2 + 0.011) {
          ++off_top;
          ADD_FAILURE() << h->id << ": " << e.id << " is off the top of " << rec.id;
        }
      }
    }
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(overlapping, 0);
  EXPECT_EQ(in_swing, 0);
  EXPECT_EQ(off_top, 0);
  EXPECT_EQ(out_of_range, 0);
  EXPECT_EQ(windowless, 0);
}

// Windows sit in an outside wall of their room, inside the wall's length.
TEST(House, WindowsAreOnOutsideWalls) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    auto h = generate_house({6, std::nullopt, seed}, knowledge());
    ASSERT_TRUE(h);
    ASSERT_FALSE(h->windows.empty());
    for (const auto& w : h->windows) {
      const auto outside = std::find_if(h->walls.begin(), h->walls.end(),
                                        [&](const Wall& x) { return x.id == w["wall1"].get<std::string>(); });
      const auto inside = std::find_if(h->walls.begin(), h->walls.end(),
                                       [&](const Wall& x) { return x.id == w["wall0"].get<std::string>(); });
      ASSERT_NE(outside, h->walls.end());
      ASSERT_NE(inside, h->walls.end());
      EXPECT_NE(outside->id.find("|exterior|"), std::string::npos);
      EXPECT_EQ(inside->room_id, w["room0"].get<std::string>());
      const double len = std::hypot(inside->b.x - inside->a.x, inside->b.z - inside->a.z);
      EXPECT_GE(w["holePolygon"][0]["x"].get<double>(), 0.0);
      EXPECT_LE(w["holePolygon"][1]["x"].get<double>(), len);
    }
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
