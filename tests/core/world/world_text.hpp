#pragma once
// Small worlds for the tests, written as world.yaml text, plus a file reader.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/world/world_builder.hpp"
#include "core/world/world_yaml.hpp"

namespace socsim::world::testing {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string example(const std::string& name) {
  return read_text(std::string(SOCSIM_SOURCE_DIR) + "/schemas/examples/" + name);
}

// Two 4 x 4 rooms side by side, joined by a door in the middle of the shared wall:
//   +----+----+
//   | a  d  b |
//   +----+----+
inline constexpr const char* kTwoRooms = R"(zones:
  - {name: a, type: office, polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]}
  - {name: b, type: office, polygon: [[4, 0], [8, 0], [8, 4], [4, 4]]}
doors:
  - {name: d, pose: [4, 2], width: 1.0, connects: [a, b]}
)";

inline World load(const std::string& yaml, const BuildOptions& options = {}) {
  auto w = world_from_yaml(yaml, options);
  if (!w) ADD_FAILURE() << w.error().message();
  return w ? std::move(*w) : world_from_yaml(kTwoRooms).value();
}

// A row of n rooms (4 x 5 m each) above a corridor (2 m deep) that spans them, one door per
// room into the corridor and an entrance at the corridor's west end — the shape a floor-plan
// generator produces, built through the builder API directly.
inline WorldBuilder row_of_rooms(int n) {
  WorldBuilder b;
  b.set_name("row_of_" + std::to_string(n));
  const double w = 4.0;
  b.add_zone(Zone{"corridor", "corridor", "washable_paint", {{{0, 0}, {w * n, 0}, {w * n, 2}, {0, 2}}, {}}});
  for (int i = 0; i < n; ++i) {
    const std::string name = "room_" + std::to_string(i);
    const double x0 = w * i;
    b.add_zone(Zone{name, "office", "painted_plaster", {{{x0, 2}, {x0 + w, 2}, {x0 + w, 7}, {x0, 7}}, {}}});
    b.add_door(DoorSpec{name + "_door", {x0 + w / 2, 2, 0}, 0.9, {"corridor", name}});
  }
  b.add_door(DoorSpec{"entrance", {0, 1, 0}, 1.2, {"corridor"}});
  return b;
}

}  // namespace socsim::world::testing
