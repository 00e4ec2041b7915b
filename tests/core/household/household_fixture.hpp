#pragma once
// Loads the curated household knowledge once per test binary from a fresh store (all migrations).
#include <gtest/gtest.h>

#include <memory>

#include "core/household/knowledge.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::household::testing {

inline const HouseholdKnowledge& knowledge() {
  static const HouseholdKnowledge k = [] {
    socsim::testing::TempDir dir;
    auto store = store::Store::open(dir.file("household.db"));
    if (!store) throw std::runtime_error(store.error().message());
    auto loaded = load_household_knowledge(**store);
    if (!loaded) throw std::runtime_error(loaded.error().message());
    (*store)->close();
    return std::move(*loaded);
  }();
  return k;
}

inline std::string shared_file(const std::string& relative) {
  return std::string(SOCSIM_SHARED_DIR) + "/" + relative;
}

}  // namespace socsim::household::testing
