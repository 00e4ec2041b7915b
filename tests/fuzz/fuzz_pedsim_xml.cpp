// Fuzz target: a pedsim_ros scenario XML (import_pedsim: strict XML reader, then obstacles,
// waypoints, queues, attractions and agent routes into a World).
#include <cstddef>
#include <cstdint>

#include "core/world/pedsim_import.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The walkable area is found by polygonizing every obstacle (GEOS) and the World builder checks
  // polygons pairwise: super-linear by design. Beyond 64 KiB inputs only slow the search down.
  if (size > 64 * 1024) return 0;
  (void)socsim::world::import_pedsim(socsim::fuzz::text(data, size));
  return 0;
}
