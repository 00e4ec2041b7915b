// The RNG is part of the determinism contract: these constants must never change, on any
// platform, or every stored card would replay differently.
#include "core/common/rng.hpp"

#include <gtest/gtest.h>

#include <array>

namespace socsim {

TEST(Rng, SplitMix64MatchesReferenceValues) {
  // Reference: Vigna's splitmix64.c with seed 1234567.
  std::uint64_t s = 1234567;
  EXPECT_EQ(splitmix64(s), 6457827717110365317ULL);
  EXPECT_EQ(splitmix64(s), 3203168211198807973ULL);
  EXPECT_EQ(splitmix64(s), 9817491932198370423ULL);
}

TEST(Rng, FirstOutputsArePinned) {
  Rng r(42);
  std::array<std::uint32_t, 4> got{r.next_u32(), r.next_u32(), r.next_u32(), r.next_u32()};
  Rng again(42);
  for (auto v : got) EXPECT_EQ(v, again.next_u32());
  // Pinned on first implementation; a change here breaks replay of every stored card.
  EXPECT_EQ(got[0], 1268952930u);
  EXPECT_EQ(got[1], 3588173663u);
}

TEST(Rng, DifferentSeedsAndStreamsDiffer) {
  Rng a(1), b(2), c(1, 7);
  EXPECT_NE(a.next_u64(), b.next_u64());
  Rng a2(1);
  EXPECT_NE(a2.next_u64(), c.next_u64());
}

TEST(Rng, UniformIsInRangeAndRoughlyFlat) {
  Rng r(7);
  std::array<int, 10> bins{};
  for (int i = 0; i < 100000; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    ++bins[static_cast<std::size_t>(u * 10)];
  }
  for (int b : bins) EXPECT_NEAR(b, 10000, 500);
}

TEST(Rng, BelowIsUnbiasedAndBounded) {
  Rng r(9);
  std::array<int, 3> counts{};
  for (int i = 0; i < 30000; ++i) ++counts[r.below(3)];
  for (int c : counts) EXPECT_NEAR(c, 10000, 400);
  for (int i = 0; i < 1000; ++i) {
    const auto v = r.between(-2, 2);
    EXPECT_GE(v, -2);
    EXPECT_LE(v, 2);
  }
}

TEST(Rng, NormalHasRequestedMoments) {
  Rng r(11);
  double sum = 0, sq = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = r.normal(1.34, 0.26);
    sum += x;
    sq += x * x;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 1.34, 0.005);
  EXPECT_NEAR(std::sqrt(sq / n - mean * mean), 0.26, 0.005);
}

TEST(Rng, WeightedFollowsWeightsAndSkipsZeros) {
  Rng r(3);
  std::array<double, 3> w{0.0, 1.0, 3.0};
  std::array<int, 3> c{};
  for (int i = 0; i < 40000; ++i) ++c[r.weighted(w)];
  EXPECT_EQ(c[0], 0);
  EXPECT_NEAR(c[2] / static_cast<double>(c[1]), 3.0, 0.15);
}

TEST(Rng, ForkIsIndependentOfParentConsumption) {
  Rng parent(5);
  Rng f1 = parent.fork("rooms");
  Rng f2 = parent.fork("rooms");
  EXPECT_EQ(f1.next_u64(), f2.next_u64());
  Rng other = parent.fork("agents");
  Rng f3 = parent.fork("rooms");
  EXPECT_NE(other.next_u64(), f3.next_u64());
}

}  // namespace socsim
