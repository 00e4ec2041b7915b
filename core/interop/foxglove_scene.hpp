#pragma once
// foxglove.SceneUpdate messages (JSON encoding) of a world and of the people in it: what the MCAP
// export records on /scene/world and /scene/people and what the Foxglove live protocol sends on
// the same topics. The bytes depend only on the inputs.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/crowd/pedestrian_state.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

// The JSON Schema of foxglove.SceneUpdate as far as socsim uses it (the channels' schema).
const Json& scene_update_json_schema();

// Walls as boxes, zones as outlines with their names, doors as green openings, stamped `ns`.
std::string world_scene_update(const world::World& world, std::uint64_t ns, const std::string& frame_id);

// A fixed palette in role order, as a foxglove Color JSON object.
std::string role_color(std::size_t role);

// The shortest decimal that reads back as `v` (0 for NaN and infinities).
void put_shortest(std::string& out, double v);

// The per-frame people entity (a cylinder per person), written by hand: it is most of a large
// scene's JSON. diameters and colors are per role index.
class PeopleSceneEncoder {
 public:
  PeopleSceneEncoder(const std::string& frame_id, std::vector<double> diameters,
                     std::vector<std::string> colors);
  // roles[i] is people[i]'s role index; the result stays valid until the next call.
  const std::string& encode(std::uint64_t ns, std::span<const crowd::PedestrianState> people,
                            std::span<const std::uint16_t> roles);

 private:
  std::string frame_id_;
  std::vector<double> diameters_;
  std::vector<std::string> colors_;
  std::string out_;
};

}  // namespace socsim::interop
