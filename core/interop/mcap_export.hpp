#pragma once
// A card's trajectory as an MCAP recording (issue 20) for ros2 bag, Foxglove and MCAP tools:
//   /people        socsim_people_msgs/msg/People, ros2msg schema, CDR; one message per log frame
//   /scene/world   foxglove.SceneUpdate, jsonschema, JSON; walls, zones, doors once at the first frame
//   /scene/people  foxglove.SceneUpdate, jsonschema, JSON; a cylinder per person per frame
// plus a "socsim_map" Metadata record (frame, world bounds and origin, card id, seed). Log times
// are the frames' times; the bytes depend only on the inputs.
#include <cstdint>
#include <optional>
#include <string>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/interop/mcap_writer.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/world/world.hpp"

namespace socsim::interop {

struct McapExportOptions {
  std::string card_id;          // written to the map metadata
  std::uint64_t seed = 0;       // written to the map metadata
  Json roles = Json::object();  // the program's role overrides (proxemics, radius per role)
  std::string frame_id = "map";
  McapCompression compression = McapCompression::kZstd;
  // zstd's fastest level: on people's states it is both faster and smaller than the default 3
  // (socsim-bench mcap, docs/PERFORMANCE.md).
  int zstd_level = 1;
  std::size_t chunk_size = McapOptions{}.chunk_size;
  // /scene/people, a cylinder per person per frame for Foxglove's 3D panel, as large again as
  // /people once compressed. Unset: written for cards of at most kScenePeopleLimit people.
  std::optional<bool> scene_people;
};

inline constexpr std::size_t kScenePeopleLimit = 2000;

// kValidation when the program's roles do not apply.
Result<std::string> export_mcap(const scenario::TrajectoryLog& log, const world::World& world,
                                const McapExportOptions& options);

}  // namespace socsim::interop
