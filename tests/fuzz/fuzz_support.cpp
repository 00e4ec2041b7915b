#include "tests/fuzz/fuzz_support.hpp"

#include "core/world/world_yaml.hpp"

namespace socsim::fuzz {

const world::World& small_world() {
  // A lending library: hall with a desk queue, reading room with seats, and an exit.
  static const world::World w = [] {
    auto built = world::world_from_yaml(R"(name: "fuzz_library"
units: {length: m, angle: rad}
origin: [0, 0]
zones:
  - {name: "hall", type: "lobby", material: "plaster", polygon: [[0, 0], [8, 0], [8, 5], [0, 5]]}
  - {name: "reading_room", type: "waiting_room", material: "plaster", polygon: [[0, 5], [8, 5], [8, 10], [0, 10]]}
doors:
  - {name: "front_door", pose: [4, 0, 1.5707963267948966], width: 1.6, connects: ["hall"]}
  - {name: "hall_to_reading", pose: [2, 5], width: 1.2, connects: ["hall", "reading_room"]}
segmentation:
  - {name: "desk_queue", kind: "queue_lane", polygon: [[5, 1], [6, 1], [6, 4], [5, 4]]}
  - {name: "seats", kind: "seating_area", polygon: [[1, 7], [7, 7], [7, 9], [1, 9]]}
  - {name: "way_out", kind: "exit", polygon: [[3, 0], [5, 0], [5, 1], [3, 1]]}
  - {name: "entrance_area", kind: "entrance", polygon: [[3, 0.2], [5, 0.2], [5, 1.2], [3, 1.2]]}
entities:
  - {type: "counter", name: "loan_desk", pose: [5.5, 4.5, 3.14159], affordances: ["serve", "queue_target"]}
  - {type: "chair", name: "chair_1", pose: [2, 8], affordances: ["sit"]}
  - {type: "chair", name: "chair_2", pose: [3, 8], affordances: ["sit"]}
)");
    if (!built) broken(built.error().detail.c_str(), __FILE__, __LINE__);
    return std::move(*built);
  }();
  return w;
}

}  // namespace socsim::fuzz
