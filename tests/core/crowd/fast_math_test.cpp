// The deterministic exp/atan2 approximations used by the force model stay within their stated
// error over the ranges the model feeds them.
#include "core/crowd/fast_math.hpp"

#include <cmath>
#include <numbers>

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

}  // namespace
}  // namespace socsim::crowd
