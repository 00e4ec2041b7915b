#pragma once
// Shared by the navbench tests: the curated household knowledge (one fresh store per binary), a
// small resident pool, and houses drawn as ASCII art for hand-built scenes.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/household/scene.hpp"
#include "core/navbench/benchmark.hpp"
#include "tests/core/household/household_fixture.hpp"

namespace socsim::navbench::testing {

using household::testing::knowledge;

// Six residents with five days from Wednesday: enough variety, fast to build in Debug.
inline const ResidentPool& small_pool() {
  static const ResidentPool pool = [] {
    ResidentPool out;
    auto vocab = household::ActivityVocabulary::initial(knowledge());
    for (const char* id : {"grace-whitfield", "tobias-brenner", "aiyana-redcloud", "ben-okafor",
                           "rosa-bianchi", "kofi-mensah"}) {
      auto r = household::make_resident_offline(*knowledge().persona(id), knowledge(),
                                                {5, household::Weekday::kWednesday, 21}, vocab);
      if (!r) throw std::runtime_error(r.error().message());
      out.push_back(std::make_shared<const household::ResidentProfile>(std::move(*r)));
    }
    return out;
  }();
  return pool;
}

// A scene-prior training set small enough for unit tests.
inline std::shared_ptr<const PlacementCounts> small_counts() {
  static const auto counts = [] {
    auto c = count_training_placements(knowledge(), 200, 1, 2);
    if (!c) throw std::runtime_error(c.error().message());
    return std::make_shared<const PlacementCounts>(std::move(*c));
  }();
  return counts;
}

}  // namespace socsim::navbench::testing

namespace socsim::navbench::testing {

// Rectangular rooms, doors on shared walls and receptacles, written out by hand for tests.
struct RoomBox {
  household::RoomType type;
  double x0, z0, x1, z1;
};
struct DoorAt {
  int room0, room1;
  double x, z;  // centre of the opening, on room0's wall
  double width = 0.9;
};
struct Furniture {
  std::string type;
  int room;
  double x, z, size_x = 0.4, size_z = 0.4;
};

inline household::House hand_built_house(const std::vector<RoomBox>& boxes, const std::vector<DoorAt>& doors,
                                         const std::vector<Furniture>& furniture) {
  household::House h;
  h.id = "hand-built";
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const auto& b = boxes[i];
    household::Room r;
    r.id = "room|" + std::to_string(i);
    r.type = b.type;
    r.floor = {{b.x0, b.z0}, {b.x0, b.z1}, {b.x1, b.z1}, {b.x1, b.z0}};
    for (std::size_t e = 0; e < 4; ++e) {
      household::Wall w;
      w.room_id = r.id;
      w.a = r.floor[e];
      w.b = r.floor[(e + 1) % 4];
      w.id = "wall|" + std::to_string(i) + "|" + std::to_string(e);
      h.walls.push_back(w);
    }
    h.rooms.push_back(std::move(r));
  }
  for (const auto& d : doors) {
    // room0's wall through the door's centre
    for (const auto& w : h.walls) {
      if (w.room_id != h.rooms[static_cast<std::size_t>(d.room0)].id) continue;
      const double len = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
      const double t = ((d.x - w.a.x) * (w.b.x - w.a.x) + (d.z - w.a.z) * (w.b.z - w.a.z)) / len;
      const double off = std::abs((w.b.x - w.a.x) * (d.z - w.a.z) - (w.b.z - w.a.z) * (d.x - w.a.x)) / len;
      if (off > 1e-9 || t < 0 || t > len) continue;
      household::Door door;
      door.id = "door|" + std::to_string(d.room0) + "|" + std::to_string(d.room1);
      door.room0 = h.rooms[static_cast<std::size_t>(d.room0)].id;
      door.room1 = h.rooms[static_cast<std::size_t>(d.room1)].id;
      door.wall0 = w.id;
      door.hole_min = {t - d.width / 2, 0, 0};
      door.hole_max = {t + d.width / 2, 2.1, 0};
      h.doors.push_back(door);
      break;
    }
  }
  int n = 0;
  for (const auto& f : furniture) {
    household::Entity e;
    e.kind = household::EntityKind::kReceptacle;
    e.type = f.type;
    e.id = f.type + "|" + std::to_string(n++);
    e.room = f.room;
    e.position = {f.x, 0.4, f.z};
    e.size_x = f.size_x;
    e.size_z = f.size_z;
    h.entities.push_back(e);
  }
  h.index();
  return h;
}

inline NavMap map_of(const household::House& house, const NavConfig& config = {}) {
  auto m = build_nav_map(house, config);
  if (!m) throw std::runtime_error(m.error().message());
  return std::move(*m);
}

// The cell whose centre is nearest (x, z).
inline int cell_near(const NavMap& map, double x, double z) {
  const int ix = static_cast<int>((x - map.origin_x()) / map.cell_size());
  const int iz = static_cast<int>((z - map.origin_z()) / map.cell_size());
  return iz * map.width() + ix;
}

}  // namespace socsim::navbench::testing
