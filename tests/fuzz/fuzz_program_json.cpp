// Fuzz target: a scenario program (schemas/program.schema.json) as posted to the API: parsed
// (program_from_text), then checked against a world the way generated programs are
// (check_program: places, behaviour trees, counts, and a dry run of ScenarioRunner::create).
#include <cstddef>
#include <cstdint>

#include "core/common/json_io.hpp"
#include "core/crowd/program.hpp"
#include "core/scenario/program_check.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = socsim::fuzz::text(data, size);
  auto program = socsim::crowd::program_from_text(text);
  if (!program) return 0;
  auto json = socsim::parse_json_untrusted(text);
  SOCSIM_FUZZ_CHECK(json.has_value());
  // The dry run spawns every agent and builds each ambient group's velocity field: its cost grows
  // with the counts and resolutions the limits allow, so a small limit keeps runs fast.
  socsim::scenario::ScenarioLimits limits;
  limits.max_agents = 200;
  limits.max_spotlight = 16;
  (void)socsim::scenario::check_program(*json, socsim::fuzz::small_world(), limits);
  return 0;
}
