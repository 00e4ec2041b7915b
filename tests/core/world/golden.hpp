#pragma once
// Golden-file comparison: the file starts with "# golden:" comment lines saying what it
// covers, then the exact expected bytes. SOCSIM_UPDATE_GOLDEN=1 rewrites the body (keeping
// the header) instead of comparing.
#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/core/world/world_text.hpp"

namespace socsim::world::testing {

inline std::string golden_path(const std::string& name) {
  return std::string(SOCSIM_SOURCE_DIR) + "/tests/core/world/golden/" + name;
}

inline void expect_golden(const std::string& name, const std::string& header, const std::string& actual) {
  const std::string path = golden_path(name);
  const std::string head = header;  // each line starts with "# golden:" (or "<!-- golden:" for XML)
  if (const char* u = std::getenv("SOCSIM_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    std::ofstream(path, std::ios::binary) << head << actual;
    GTEST_SKIP() << "rewrote " << path;
  }
  const std::string text = read_text(path);
  ASSERT_FALSE(text.empty()) << "missing golden file " << path << " (run with SOCSIM_UPDATE_GOLDEN=1)";
  ASSERT_EQ(text.substr(0, head.size()), head) << "golden header of " << path << " changed";
  EXPECT_EQ(text.substr(head.size()), actual) << "output differs from " << path;
}

}  // namespace socsim::world::testing
