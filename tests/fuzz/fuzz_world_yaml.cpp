// Fuzz target: a user's world.yaml text, read as the REST API and the CLI read it
// (world_from_yaml: strict YAML → document → checked World). A World that reads must write back
// (world_to_yaml) to text that reads again to the same text: the format's promise.
#include <cstddef>
#include <cstdint>

#include "core/world/world_yaml.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Building a World checks every polygon against every other (overlaps, walls from zone edges):
  // super-linear by design, bounded in the API by the body limit. Beyond 64 KiB inputs only slow
  // the search down.
  if (size > 64 * 1024) return 0;
  auto world = socsim::world::world_from_yaml(socsim::fuzz::text(data, size));
  if (!world) return 0;
  const std::string written = socsim::world::world_to_yaml(*world);
  auto again = socsim::world::world_from_yaml(written);
  SOCSIM_FUZZ_CHECK(again.has_value());
  SOCSIM_FUZZ_CHECK(socsim::world::world_to_yaml(*again) == written);
  return 0;
}
