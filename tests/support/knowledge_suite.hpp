#pragma once
// A test suite over one knowledge store with every migration applied (building codes and room
// types the floor-plan generators read), opened once per suite. Derive a suite from it.
#include <gtest/gtest.h>

#include "core/knowledge/knowledge_base.hpp"
#include "core/store/store.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::testing {

class KnowledgeSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new socsim::testing::TempDir();
    store_ = store::Store::open(dir_->file("kb.db")).value().release();
    kb_ = new knowledge::KnowledgeBase(*store_);
  }
  static void TearDownTestSuite() {
    delete kb_;
    delete store_;
    delete dir_;
    kb_ = nullptr;
    store_ = nullptr;
    dir_ = nullptr;
  }
  static inline socsim::testing::TempDir* dir_ = nullptr;
  static inline store::Store* store_ = nullptr;
  static inline knowledge::KnowledgeBase* kb_ = nullptr;
};

}  // namespace socsim::testing
