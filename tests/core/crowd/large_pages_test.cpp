// The crowd step's large arrays: aligned blocks that hold what is stored in them, huge-page
// advice on the large ones (as the kernel reports it in /proc/self/smaps), none on small ones.
#include "core/crowd/large_pages.hpp"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace socsim::crowd {
namespace {

// The VmFlags line of the mapping that holds p ("" when none does).
std::string vm_flags_of(const void* p) {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t from = 0;
    std::uintptr_t to = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> from >> dash >> to && dash == '-') {
      inside = from <= at && at < to;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

struct alignas(32) Wide {
  double x, y, vx, vy;
};

TEST(LargePages, LargeBlocksAreAlignedToHugePagesAndAdvised) {
  LargeVector<Wide> v(100000);  // 3.2 MB: two huge pages
  ASSERT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % kHugePage, 0u);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = {double(i), -double(i), 0.5, 0.25};
  EXPECT_EQ(v.back().x, 99999.0);
  EXPECT_EQ(v[12345].y, -12345.0);
  const std::string flags = vm_flags_of(v.data());
  if (flags.empty()) GTEST_SKIP() << "/proc/self/smaps is not readable here";
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;  // MADV_HUGEPAGE
}

TEST(LargePages, SmallBlocksComeFromTheHeapWithTheirAlignment) {
  LargeVector<Wide> small(10);  // 320 bytes
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % alignof(Wide), 0u);
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables != nullptr && std::string(tunables).find("hugetlb") != std::string::npos)
    GTEST_SKIP() << "GLIBC_TUNABLES asks glibc for huge pages on its own heap: " << tunables;
  const std::string flags = vm_flags_of(small.data());
  EXPECT_EQ(flags.find(" hg"), std::string::npos) << flags;
}

TEST(LargePages, GrowingAcrossTheThresholdKeepsEveryValue) {
  LargeVector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < 300000; ++i) v.push_back(i * 7u);  // 4 B → 1.2 MB, reallocated
  for (std::uint32_t i = 0; i < 300000; ++i) ASSERT_EQ(v[i], i * 7u);
  LargeVector<std::uint32_t> copy = v;
  EXPECT_EQ(std::accumulate(copy.begin(), copy.end(), std::uint64_t{0}),
            std::accumulate(v.begin(), v.end(), std::uint64_t{0}));
  v.clear();
  v.shrink_to_fit();  // back below the threshold: unmapped, then a heap block
  v.resize(3, 1u);
  EXPECT_EQ(v[2], 1u);
}

}  // namespace
}  // namespace socsim::crowd
