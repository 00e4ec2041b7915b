// Replays fuzz inputs without libFuzzer, so that the GCC builds (presets ci and asan) run every
// target over its whole corpus as a CTest test: socsim_fuzz_replay <target> <file or directory>...
// Each target's LLVMFuzzerTestOneInput is compiled under the name socsim_fuzz_<target>
// (tests/fuzz/CMakeLists.txt), so one executable holds them all.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#define SOCSIM_FUZZ_TARGET(name) extern "C" int socsim_fuzz_##name(const std::uint8_t*, std::size_t);
#include "fuzz_targets.inc"
#undef SOCSIM_FUZZ_TARGET

namespace {

struct Target {
  std::string_view name;
  int (*run)(const std::uint8_t*, std::size_t);
};

constexpr Target kTargets[] = {
#define SOCSIM_FUZZ_TARGET(name) {#name, socsim_fuzz_##name},
#include "fuzz_targets.inc"
#undef SOCSIM_FUZZ_TARGET
};

std::vector<std::filesystem::path> inputs(const std::vector<std::filesystem::path>& args) {
  std::vector<std::filesystem::path> out;
  for (const auto& a : args) {
    if (!std::filesystem::is_directory(a)) {
      out.push_back(a);
      continue;
    }
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(a))
      if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());  // the same order on every machine
    out.insert(out.end(), files.begin(), files.end());
  }
  return out;
}

int usage() {
  std::fprintf(stderr, "usage: socsim_fuzz_replay <target> <file or directory>...\ntargets:");
  for (const Target& t : kTargets)
    std::fprintf(stderr, " %.*s", static_cast<int>(t.name.size()), t.name.data());
  std::fprintf(stderr, "\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string_view name = argv[1];
  const auto target =
      std::find_if(std::begin(kTargets), std::end(kTargets), [&](const Target& t) { return t.name == name; });
  if (target == std::end(kTargets)) return usage();
  const auto files = inputs(std::vector<std::filesystem::path>(argv + 2, argv + argc));
  if (files.empty()) {
    std::fprintf(stderr, "no inputs\n");
    return 1;
  }
  double slowest = 0.0;
  std::string slowest_file;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "cannot read %s\n", f.c_str());
      return 1;
    }
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    // A copy in a buffer of exactly its size, so that ASan sees reads past the end.
    const std::vector<std::uint8_t> data(bytes.begin(), bytes.end());
    const auto start = std::chrono::steady_clock::now();
    target->run(data.data(), data.size());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (s > slowest) slowest = s, slowest_file = f.filename().string();
  }
  std::printf("%.*s: %zu inputs replayed; slowest %.3f s (%s)\n", static_cast<int>(name.size()), name.data(),
              files.size(), slowest, slowest_file.c_str());
  return 0;
}
