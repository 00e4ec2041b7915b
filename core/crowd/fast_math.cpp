#include "core/crowd/fast_math.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SOCSIM_ATAN_AVX2 1
#endif

namespace socsim::crowd {

namespace {

void atan2_scalar(const double* y, const double* x, double* out, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) out[k] = fast_atan2(y[k], x[k]);
}

#ifdef SOCSIM_ATAN_AVX2
#define SOCSIM_ATAN_LANES __attribute__((target("avx2"), always_inline)) inline
SOCSIM_ATAN_LANES __m256d less(__m256d a, __m256d b) {
  return _mm256_cmp_pd(a, b, _CMP_LT_OQ);
}
SOCSIM_ATAN_LANES __m256d select(__m256d m, __m256d t, __m256d f) {
  return _mm256_blendv_pd(f, t, m);
}
SOCSIM_ATAN_LANES __m256d horner(__m256d p, __m256d s, double c) {
  return _mm256_add_pd(_mm256_mul_pd(p, s), _mm256_set1_pd(c));
}
#undef SOCSIM_ATAN_LANES

// fast_atan2 on four lanes: each branch's operations on every lane, the branch's result kept by a
// select. The same operations in the same order, correctly rounded, no fused multiply-add (this
// file is compiled with -ffp-contract=off and the target has no FMA): the same bits.
__attribute__((target("avx2"))) void atan2_avx2(const double* y, const double* x, double* out,
                                                std::size_t n) {
  constexpr double kTanPi16 = 0.19891236737965800691;
  constexpr double kTan3Pi16 = 0.66817863791929891999;
  constexpr double kTanPi8 = 0.41421356237309504880;
  constexpr double kPi8 = 0.39269908169872415481;
  constexpr double kPi4 = 0.78539816339744830962;
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kPi2 = 1.57079632679489661923;
  const __m256d zero = _mm256_setzero_pd();
  const __m256d one = _mm256_set1_pd(1.0);
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m256d vy = _mm256_loadu_pd(y + k);
    const __m256d vx = _mm256_loadu_pd(x + k);
    // x < 0 ? -x : x (as fast_atan2: -0.0 stays -0.0)
    const __m256d ax = select(less(vx, zero), _mm256_sub_pd(zero, vx), vx);
    const __m256d ay = select(less(vy, zero), _mm256_sub_pd(zero, vy), vy);
    const __m256d origin =
        _mm256_and_pd(_mm256_cmp_pd(ax, zero, _CMP_EQ_OQ), _mm256_cmp_pd(ay, zero, _CMP_EQ_OQ));
    const __m256d steep = less(ax, ay);
    const __m256d a = _mm256_div_pd(select(steep, ax, ay), select(steep, ay, ax));
    // fast_atan_unit(a)
    const __m256d wide = less(_mm256_set1_pd(kTan3Pi16), a);
    const __m256d middle = _mm256_andnot_pd(wide, less(_mm256_set1_pd(kTanPi16), a));
    const __m256d tan8 = _mm256_set1_pd(kTanPi8);
    const __m256d num = select(wide, _mm256_sub_pd(a, one), select(middle, _mm256_sub_pd(a, tan8), a));
    const __m256d den =
        select(wide, _mm256_add_pd(a, one), select(middle, _mm256_add_pd(one, _mm256_mul_pd(a, tan8)), one));
    const __m256d t = _mm256_div_pd(num, den);  // a / 1 = a in the narrow range
    const __m256d base = select(wide, _mm256_set1_pd(kPi4), select(middle, _mm256_set1_pd(kPi8), zero));
    const __m256d s = _mm256_mul_pd(t, t);
    __m256d p = _mm256_set1_pd(-1.0 / 15.0);
    p = horner(p, s, 1.0 / 13.0);
    p = horner(p, s, -1.0 / 11.0);
    p = horner(p, s, 1.0 / 9.0);
    p = horner(p, s, -1.0 / 7.0);
    p = horner(p, s, 1.0 / 5.0);
    p = horner(p, s, -1.0 / 3.0);
    p = horner(p, s, 1.0);
    __m256d angle = _mm256_add_pd(base, _mm256_mul_pd(t, p));
    angle = select(steep, _mm256_sub_pd(_mm256_set1_pd(kPi2), angle), angle);
    angle = select(less(vx, zero), _mm256_sub_pd(_mm256_set1_pd(kPi), angle), angle);
    angle = select(less(vy, zero), _mm256_xor_pd(angle, _mm256_set1_pd(-0.0)), angle);  // -angle
    _mm256_storeu_pd(out + k, select(origin, zero, angle));
  }
  atan2_scalar(y + k, x + k, out + k, n - k);
}

using Atan2Fn = void (*)(const double*, const double*, double*, std::size_t);
Atan2Fn pick_atan2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") ? atan2_avx2 : atan2_scalar;
}
#endif

}  // namespace

void fast_atan2_batch(const double* y, const double* x, double* out, std::size_t n) {
#ifdef SOCSIM_ATAN_AVX2
  static const Atan2Fn fn = pick_atan2();
  fn(y, x, out, n);
#else
  atan2_scalar(y, x, out, n);
#endif
}

}  // namespace socsim::crowd
