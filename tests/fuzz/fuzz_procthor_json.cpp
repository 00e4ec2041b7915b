// Fuzz target: a ProcTHOR house JSON as posted to the household API (parse_json_untrusted, then
// import_procthor against the curated household knowledge). An imported house must export to
// ProcTHOR JSON that imports again.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/common/json_io.hpp"
#include "core/household/knowledge.hpp"
#include "core/household/procthor.hpp"
#include "core/store/store.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

// The seed tables, read once from a fresh store (all migrations) in a directory removed afterwards.
const socsim::household::HouseholdKnowledge& knowledge() {
  static const socsim::household::HouseholdKnowledge k = [] {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("socsim-fuzz-procthor-" + std::to_string(static_cast<long>(getpid())));
    std::filesystem::create_directories(dir);
    auto store = socsim::store::Store::open((dir / "knowledge.db").string());
    if (!store) socsim::fuzz::broken(store.error().detail.c_str(), __FILE__, __LINE__);
    auto loaded = socsim::household::load_household_knowledge(**store);
    if (!loaded) socsim::fuzz::broken(loaded.error().detail.c_str(), __FILE__, __LINE__);
    (*store)->close();
    std::filesystem::remove_all(dir);
    return std::move(*loaded);
  }();
  return k;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& k = knowledge();
  auto json = socsim::parse_json_untrusted(socsim::fuzz::text(data, size));
  if (!json) return 0;
  auto house = socsim::household::import_procthor(*json, k, "fuzz");
  if (!house) return 0;
  auto again = socsim::household::import_procthor(socsim::household::export_procthor(*house), k, "fuzz");
  SOCSIM_FUZZ_CHECK(again.has_value());
  return 0;
}
