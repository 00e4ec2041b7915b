// The compute pool hands out every index exactly once and reports failures.
#include "core/crowd/worker_pool.hpp"

#include <atomic>
#include <stdexcept>

#include <gtest/gtest.h>

namespace socsim::crowd {
namespace {

TEST(WorkerPool, CoversEveryIndexOnceForAnyThreadCount) {
  for (unsigned threads : {1u, 2u, 4u}) {
    WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    // (130 and 200: fewer chunks of 64 than threads have parts, and a last chunk cut short.)
    for (std::size_t count : {0u, 1u, 7u, 130u, 200u, 1000u, 12345u}) {
      std::vector<std::atomic<int>> hits(count);
      for (int round = 0; round < 3; ++round) {
        pool.parallel_for(count, 64, [&](std::size_t b, std::size_t e) {
          ASSERT_LT(b, e);
          ASSERT_TRUE(e - b <= 64u || (b == 0 && e == count && (threads == 1 || count <= 64u)));
          for (std::size_t i = b; i < e; ++i) hits[i].fetch_add(1);
        });
      }
      for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(hits[i].load(), 3) << "index " << i;
    }
  }
}

TEST(WorkerPool, RethrowsAnExceptionFromAWorkerAndStaysUsable) {
  WorkerPool pool(2);
  EXPECT_THROW(pool.parallel_for(1000, 10,
                                 [](std::size_t b, std::size_t) {
                                   if (b == 500) throw std::runtime_error("boom");
                                 }),
               std::runtime_error);
  std::atomic<std::size_t> sum{0};
  pool.parallel_for(100, 10, [&](std::size_t b, std::size_t e) { sum += e - b; });
  EXPECT_EQ(sum.load(), 100u);
}

}  // namespace
}  // namespace socsim::crowd
