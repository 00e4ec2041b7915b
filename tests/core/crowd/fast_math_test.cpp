// The deterministic exp/atan2 approximations used by the force model stay within their stated
// error over the ranges the model feeds them.
#include "core/crowd/fast_math.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/rng.hpp"

namespace socsim::crowd {
namespace {

TEST(FastMath, ExpMatchesLibmToBetterThan5e13) {
  double worst = 0.0;
  for (double x = -79.0; x <= 50.0; x += 0.001) {
    const double rel = std::abs(fast_exp(x) - std::exp(x)) / std::exp(x);
    worst = std::max(worst, rel);
  }
  EXPECT_LT(worst, 5e-13);
  EXPECT_EQ(fast_exp(-1000.0), 0.0);
  EXPECT_EQ(fast_exp(std::nan("")), 0.0);
  EXPECT_EQ(fast_exp(0.0), 1.0);
}

TEST(FastMath, FloatExpMatchesLibmToAFewUlp) {
  float worst = 0.0f;
  for (float x = -86.0f; x <= 80.0f; x += 0.01f) {
    const double ref = std::exp(static_cast<double>(x));
    worst = std::max(worst, static_cast<float>(std::abs(fast_expf(x) - ref) / ref));
  }
  EXPECT_LT(worst, 3e-7f);
  EXPECT_EQ(fast_expf(-100.0f), 0.0f);
}

TEST(FastMath, Atan2MatchesLibmInAllQuadrants) {
  Rng rng(5);
  double worst = 0.0;
  float worst_f = 0.0f;
  for (int i = 0; i < 200000; ++i) {
    const double y = rng.uniform(-10.0, 10.0);
    const double x = rng.uniform(-10.0, 10.0);
    worst = std::max(worst, std::abs(fast_atan2(y, x) - std::atan2(y, x)));
    const auto fy = static_cast<float>(y);
    const auto fx = static_cast<float>(x);
    worst_f = std::max(
        worst_f, static_cast<float>(std::abs(fast_atan2f(fy, fx) -
                                             std::atan2(static_cast<double>(fy), static_cast<double>(fx)))));
  }
  EXPECT_LT(worst, 3e-12);
  EXPECT_LT(worst_f, 1e-6f);
  EXPECT_EQ(fast_atan2(0.0, 0.0), 0.0);
  EXPECT_EQ(fast_atan2f(0.0f, 0.0f), 0.0f);
  EXPECT_DOUBLE_EQ(fast_atan2(0.0, -1.0), std::numbers::pi);
  EXPECT_DOUBLE_EQ(fast_atan2(1.0, 0.0), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(fast_atan2(-1.0, 0.0), -std::numbers::pi / 2);
}

// The batch form (vectorised where the processor allows) gives fast_atan2's bits: random
// directions over many scales, the axes, signed zeros, each branch's boundaries, tiny ratios.
TEST(FastMath, Atan2BatchGivesTheScalarBits) {
  Rng rng(11);
  std::vector<double> y;
  std::vector<double> x;
  for (int i = 0; i < 100000; ++i) {
    const double scale = std::pow(10.0, rng.uniform(-8.0, 3.0));
    y.push_back(scale * rng.uniform(-1.0, 1.0));
    x.push_back(scale * rng.uniform(-1.0, 1.0));
  }
  const double special[] = {0.0,
                            -0.0,
                            1.0,
                            -1.0,
                            1e-300,
                            -1e-300,
                            0.19891236737965800691,
                            0.66817863791929891999,
                            0.41421356237309504880,
                            1e300,
                            -1e300,
                            3.0,
                            -2.5};
  for (double a : special) {
    for (double b : special) {
      y.push_back(a);
      x.push_back(b);
    }
  }
  for (std::size_t offset = 0; offset < 4; ++offset) {  // every lane position and a scalar tail
    const std::size_t n = y.size() - offset;
    std::vector<double> out(n, 99.0);
    fast_atan2_batch(y.data() + offset, x.data() + offset, out.data(), n);
    for (std::size_t k = 0; k < n; ++k) {
      const double want = fast_atan2(y[k + offset], x[k + offset]);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(out[k]), std::bit_cast<std::uint64_t>(want))
          << "y=" << y[k + offset] << " x=" << x[k + offset];
    }
  }
}

}  // namespace
}  // namespace socsim::crowd
