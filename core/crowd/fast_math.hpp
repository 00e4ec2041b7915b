#pragma once
// Deterministic, inlinable exp and atan2 for the social-force inner loop: plain IEEE double
// arithmetic only (no libm calls, no table), so every platform and thread count gives the same bits.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>

namespace socsim::crowd {

// e^x for x <= ~700. Range reduction x = k·ln2 + r (|r| <= ln2/2), then a degree-10 Taylor
// polynomial in r (relative error < 5e-13 over the whole range). Returns 0 below -80, where the
// true value (< 2e-35) is far below anything a force sum can resolve.
inline double fast_exp(double x) {
  if (!(x > -80.0)) return 0.0;  // also maps NaN to 0
  if (x > 700.0) x = 700.0;
  constexpr double kLog2e = 1.4426950408889634;
  constexpr double kLn2Hi = 6.93147180369123816490e-01;  // ln2 split so k·kLn2Hi is exact
  constexpr double kLn2Lo = 1.90821492927058770002e-10;
  constexpr double kShift = 6755399441055744.0;  // 1.5·2^52: adding it rounds to nearest integer
  const double kd = (x * kLog2e + kShift) - kShift;
  const double r = (x - kd * kLn2Hi) - kd * kLn2Lo;
  double p = 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  const auto k = static_cast<std::int64_t>(kd);
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52u);
  return p * scale;
}

// atan(a) for 0 <= a <= 1: reduce to |t| <= tan(pi/16) around 0, pi/8 or pi/4, then the odd
// Taylor series to t^15 (error < 3e-12 rad).
inline double fast_atan_unit(double a) {
  constexpr double kTanPi16 = 0.19891236737965800691;
  constexpr double kTan3Pi16 = 0.66817863791929891999;
  constexpr double kTanPi8 = 0.41421356237309504880;
  constexpr double kPi8 = 0.39269908169872415481;
  constexpr double kPi4 = 0.78539816339744830962;
  double base = 0.0;
  double t = a;
  if (a > kTan3Pi16) {
    base = kPi4;
    t = (a - 1.0) / (a + 1.0);
  } else if (a > kTanPi16) {
    base = kPi8;
    t = (a - kTanPi8) / (1.0 + a * kTanPi8);
  }
  const double s = t * t;
  double p = -1.0 / 15.0;
  p = p * s + 1.0 / 13.0;
  p = p * s - 1.0 / 11.0;
  p = p * s + 1.0 / 9.0;
  p = p * s - 1.0 / 7.0;
  p = p * s + 1.0 / 5.0;
  p = p * s - 1.0 / 3.0;
  p = p * s + 1.0;
  return base + t * p;
}

// atan2(y, x) in (-pi, pi]; atan2(0, 0) = 0.
inline double fast_atan2(double y, double x) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kPi2 = 1.57079632679489661923;
  const double ax = x < 0.0 ? -x : x;
  const double ay = y < 0.0 ? -y : y;
  if (ax == 0.0 && ay == 0.0) return 0.0;
  const bool steep = ay > ax;
  const double a = steep ? ax / ay : ay / ax;
  double angle = fast_atan_unit(a);
  if (steep) angle = kPi2 - angle;
  if (x < 0.0) angle = kPi - angle;
  return y < 0.0 ? -angle : angle;
}

}  // namespace socsim::crowd

namespace socsim::crowd {

// Branch-free single-precision versions for the vectorised pair kernel (selects only, so the
// compiler can turn a loop of them into SIMD code; results are the same bits either way).

// The constants of fast_expf and fast_atan2f, shared with the hand-written AVX-512 kernel
// (social_kernel.cpp), which evaluates the same polynomials in the same order.
namespace fast_float {
inline constexpr float kExpLow = -87.0f;  // below: 0
inline constexpr float kExpHigh = 88.0f;
inline constexpr float kLog2e = 1.44269504088896341f;
inline constexpr float kLn2Hi = 0.693359375f;
inline constexpr float kLn2Lo = -2.12194440e-4f;
inline constexpr float kShift = 12582912.0f;  // 1.5·2^23: adding it rounds to an integer
// e^r on |r| <= ln2/2, Horner's order (highest degree first).
inline constexpr float kExpPoly[] = {1.0f / 720.0f, 1.0f / 120.0f, 1.0f / 24.0f, 1.0f / 6.0f,
                                     0.5f,          1.0f,          1.0f};
inline constexpr float kPi = 3.14159265358979f;
inline constexpr float kPi2 = 1.57079632679490f;
inline constexpr float kPi4 = 0.785398163397448f;
inline constexpr float kTanPi8 = 0.414213562373095f;
// atan(t)/t as a polynomial in s = t², Horner's order (the odd Taylor series to t^15).
inline constexpr float kAtanPoly[] = {-1.0f / 15.0f, 1.0f / 13.0f, -1.0f / 11.0f, 1.0f / 9.0f,
                                      -1.0f / 7.0f,  1.0f / 5.0f,  -1.0f / 3.0f,  1.0f};
}  // namespace fast_float

// e^x, relative error < 2e-7 for -87 < x < 88; 0 below -87.
inline float fast_expf(float x) {
  using namespace fast_float;
  const float clamped = x < kExpLow ? kExpLow : (x > kExpHigh ? kExpHigh : x);
  const float kf = (clamped * kLog2e + kShift) - kShift;
  const float r = (clamped - kf * kLn2Hi) - kf * kLn2Lo;
  float p = kExpPoly[0];
  for (std::size_t i = 1; i < std::size(kExpPoly); ++i) p = p * r + kExpPoly[i];
  const auto k = static_cast<std::int32_t>(kf);
  const float scale = std::bit_cast<float>(static_cast<std::uint32_t>(k + 127) << 23u);
  return x < kExpLow ? 0.0f : p * scale;
}

// atan2(y, x) in [-pi, pi], absolute error < 1e-7 rad; atan2(0, 0) = 0.
inline float fast_atan2f(float y, float x) {
  using namespace fast_float;
  const float ax = std::fabs(x);
  const float ay = std::fabs(y);
  const float mx = ax > ay ? ax : ay;
  const float mn = ax > ay ? ay : ax;
  // t = a or (a − 1)/(a + 1) for a = mn/mx, as one division: (mn − mx)/(mn + mx) above tan(π/8)
  // (mx = 0 only with mn = 0: t = 0).
  const bool upper = mn > kTanPi8 * mx;
  const float t = (upper ? mn - mx : mn) / (upper ? mn + mx : (mx > 0.0f ? mx : 1.0f));
  const float s = t * t;
  float p = kAtanPoly[0];
  for (std::size_t i = 1; i < std::size(kAtanPoly); ++i) p = p * s + kAtanPoly[i];  // a − b is a + (−b)
  float angle = (upper ? kPi4 : 0.0f) + t * p;
  angle = ay > ax ? kPi2 - angle : angle;
  angle = x < 0.0f ? kPi - angle : angle;
  return y < 0.0f ? -angle : angle;
}

// fast_atan2 of n pairs: out[k] = fast_atan2(y[k], x[k]), bit for bit (AVX2, four at a time,
// where the processor has it; fast_math.cpp).
void fast_atan2_batch(const double* y, const double* x, double* out, std::size_t n);

}  // namespace socsim::crowd
