#include "core/crowd/social_kernel.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>

#include "core/crowd/fast_math.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
#include <immintrin.h>
#endif

// Kept in its own translation unit so the compiler vectorises this loop on its own terms
// (selects only, no branches); every lane computes the same IEEE operations a scalar loop would.
namespace socsim::crowd {

// On x86-64 an AVX-512 clone (16 lanes) or an AVX2 clone (8 lanes) is picked at load time where
// the CPU has it. -ffp-contract=off forbids fused multiply-adds, so every clone computes the same
// IEEE operations and gives identical bits (tests/core/crowd compares them with the scalar clone).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void social_kernel_portable(const SocialParams& p, int count, const float* __restrict dx,
                            const float* __restrict dy, const float* __restrict dvx, const float* __restrict dvy,
                            const float* __restrict tie_x, const float* __restrict tie_y, std::int32_t* __restrict fx,
                            std::int32_t* __restrict fy) {
  const float lambda = p.lambda;
  const float gamma = p.gamma;
  const float inv_gamma = p.inv_gamma;
  const float n = p.n;
  const float n_prime = p.n_prime;
  const float scale = p.factor * kForceQuantum;
  for (int m = 0; m < count; ++m) {
    const float rx = dx[m];
    const float ry = dy[m];
    const float ux = tie_x[m];
    const float uy = tie_y[m];
    const float d2 = rx * rx + ry * ry;
    const float d = std::sqrt(d2);
    // Either (rx, ry) = 0 (coincident: the tie direction u applies) or u = 0, so no select is needed.
    const float inv_d = 1.0f / std::max(d, 1e-30f);
    const float ex = rx * inv_d + ux;
    const float ey = ry * inv_d + uy;
    const float ix = lambda * dvx[m] + ex;
    const float iy = lambda * dvy[m] + ey;
    const float il2 = ix * ix + iy * iy;
    const bool live = il2 > 1e-12f;
    const float il = std::sqrt(il2);
    const float inv_il = 1.0f / std::max(il, 1e-6f);
    const float tx = ix * inv_il;
    const float ty = iy * inv_il;
    const float b = gamma * il;
    const float theta = fast_atan2f(tx * ey - ty * ex, tx * ex + ty * ey);
    const float base = -d * inv_il * inv_gamma;
    const float nb = n * b * theta;
    const float npb = n_prime * b * theta;
    const float along = -fast_expf(base - npb * npb);
    const float sign = theta > 0.0f ? 1.0f : (theta < 0.0f ? -1.0f : 0.0f);
    const float side = -sign * fast_expf(base - nb * nb);
    // |along|, |side| <= 1 and factor <= 1000, so |g| < 2^31: the conversion cannot overflow.
    const float gx = live ? scale * (along * tx - side * ty) : 0.0f;
    const float gy = live ? scale * (along * ty + side * tx) : 0.0f;
    fx[m] = static_cast<std::int32_t>(gx);
    fy[m] = static_cast<std::int32_t>(gy);
  }
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
#define SOCSIM_KERNEL_AVX512 1
namespace {

// The kernel by hand with AVX-512, N vectors of 16 lanes at a time, their operations interleaved
// one by one. The compiled loop works on one vector at a time: each lane is a chain of ~200
// dependent operations (two square roots, four divisions, an arctangent and two exponentials),
// longer than the processor can look ahead, so consecutive vectors barely overlap; two
// interleaved vectors keep its units busy (−28 % per pair at 32 lanes, docs/PERFORMANCE.md).
// Every operation is the portable loop's, in its order, with the same rounding: the same bits
// (SocialKernel.HandWrittenKernelEqualsThePortableLoop).
template <int N>
struct Pk {
  __m512 v[N];
};
template <int N>
struct Mk {
  __mmask16 v[N];
};

#define SOCSIM_AVX512 __attribute__((target("avx512f"), always_inline)) inline
#define SOCSIM_EACH for (int k = 0; k < N; ++k)

template <int N>
SOCSIM_AVX512 Pk<N> splat(float x) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_set1_ps(x);
  return r;
}
template <int N>
SOCSIM_AVX512 Pk<N> operator+(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_add_ps(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_AVX512 Pk<N> operator-(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_sub_ps(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_AVX512 Pk<N> operator*(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_mul_ps(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_AVX512 Pk<N> operator/(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_div_ps(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_AVX512 Pk<N> operator-(const Pk<N>& a) {  // unary minus: the sign bit flipped
  Pk<N> r;
  const __m512i sign = _mm512_set1_epi32(INT32_MIN);
  SOCSIM_EACH r.v[k] = _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a.v[k]), sign));
  return r;
}
template <int N>
SOCSIM_AVX512 Pk<N> root(const Pk<N>& a) {  // the masked form: no undefined source register
  Pk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_mask_sqrt_ps(a.v[k], 0xFFFF, a.v[k]);
  return r;
}
template <int N>
SOCSIM_AVX512 Mk<N> operator<(const Pk<N>& a, const Pk<N>& b) {
  Mk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_cmp_ps_mask(a.v[k], b.v[k], _CMP_LT_OQ);
  return r;
}
template <int N>
SOCSIM_AVX512 Mk<N> operator>(const Pk<N>& a, const Pk<N>& b) {
  Mk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_cmp_ps_mask(a.v[k], b.v[k], _CMP_GT_OQ);
  return r;
}
// m ? t : f, lane by lane
template <int N>
SOCSIM_AVX512 Pk<N> select(const Mk<N>& m, const Pk<N>& t, const Pk<N>& f) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = _mm512_mask_blend_ps(m.v[k], f.v[k], t.v[k]);
  return r;
}

template <int N>
SOCSIM_AVX512 Pk<N> exp_lanes(const Pk<N>& x) {  // fast_expf
  using namespace fast_float;
  const Pk<N> lo = splat<N>(kExpLow);
  const Pk<N> hi = splat<N>(kExpHigh);
  const Pk<N> clamped = select(x < lo, lo, select(x > hi, hi, x));
  const Pk<N> shift = splat<N>(kShift);
  const Pk<N> kf = (clamped * splat<N>(kLog2e) + shift) - shift;
  const Pk<N> r = (clamped - kf * splat<N>(kLn2Hi)) - kf * splat<N>(kLn2Lo);
  Pk<N> p = splat<N>(kExpPoly[0]);
  for (std::size_t i = 1; i < std::size(kExpPoly); ++i) p = p * r + splat<N>(kExpPoly[i]);
  Pk<N> scale;
  const __m512i bias = _mm512_set1_epi32(127);
  SOCSIM_EACH {
    const __m512i e = _mm512_mask_cvttps_epi32(bias, 0xFFFF, kf.v[k]);
    scale.v[k] = _mm512_castsi512_ps(_mm512_slli_epi32(_mm512_add_epi32(e, bias), 23));
  }
  return select(x < lo, splat<N>(0.0f), p * scale);
}

template <int N>
SOCSIM_AVX512 Pk<N> atan2_lanes(const Pk<N>& y, const Pk<N>& x) {  // fast_atan2f
  using namespace fast_float;
  const Pk<N> zero = splat<N>(0.0f);
  const Pk<N> one = splat<N>(1.0f);
  const Pk<N> ax = select(x < zero, -x, x);
  const Pk<N> ay = select(y < zero, -y, y);
  const Mk<N> x_wider = ax > ay;
  const Pk<N> mx = select(x_wider, ax, ay);
  const Pk<N> mn = select(x_wider, ay, ax);
  const Pk<N> a = mn / select(mx > zero, mx, one);
  const Mk<N> upper = a > splat<N>(kTanPi8);
  const Pk<N> t = select(upper, (a - one) / (a + one), a);
  const Pk<N> s = t * t;
  Pk<N> p = splat<N>(kAtanPoly[0]);
  for (std::size_t i = 1; i < std::size(kAtanPoly); ++i) p = p * s + splat<N>(kAtanPoly[i]);
  Pk<N> angle = select(upper, splat<N>(kPi4), zero) + t * p;
  angle = select(ay > ax, splat<N>(kPi2) - angle, angle);
  angle = select(x < zero, splat<N>(kPi) - angle, angle);
  return select(y < zero, -angle, angle);
}

// Lanes [m, m + 16·N) of the batch, those at or past `count` read as 0 and not written.
template <int N>
SOCSIM_AVX512 void kernel_lanes(const SocialParams& p, int m, int count, const float* dx, const float* dy,
                                const float* dvx, const float* dvy, const float* tie_x, const float* tie_y,
                                std::int32_t* fx, std::int32_t* fy) {
  Mk<N> in;
  SOCSIM_EACH {
    const int left = count - m - 16 * k;
    in.v[k] = left >= 16 ? __mmask16{0xFFFF}
                         : (left <= 0 ? __mmask16{0} : static_cast<__mmask16>((1u << left) - 1u));
  }
  Pk<N> rx, ry, ux, uy, vx, vy;
  SOCSIM_EACH {
    const int o = m + 16 * k;
    rx.v[k] = _mm512_maskz_loadu_ps(in.v[k], dx + o);
    ry.v[k] = _mm512_maskz_loadu_ps(in.v[k], dy + o);
    ux.v[k] = _mm512_maskz_loadu_ps(in.v[k], tie_x + o);
    uy.v[k] = _mm512_maskz_loadu_ps(in.v[k], tie_y + o);
    vx.v[k] = _mm512_maskz_loadu_ps(in.v[k], dvx + o);
    vy.v[k] = _mm512_maskz_loadu_ps(in.v[k], dvy + o);
  }
  const Pk<N> zero = splat<N>(0.0f);
  const Pk<N> one = splat<N>(1.0f);
  const Pk<N> d = root(rx * rx + ry * ry);
  const Pk<N> tiny = splat<N>(1e-30f);
  const Pk<N> inv_d = one / select(d < tiny, tiny, d);
  const Pk<N> ex = rx * inv_d + ux;
  const Pk<N> ey = ry * inv_d + uy;
  const Pk<N> lambda = splat<N>(p.lambda);
  const Pk<N> ix = lambda * vx + ex;
  const Pk<N> iy = lambda * vy + ey;
  const Pk<N> il2 = ix * ix + iy * iy;
  const Mk<N> live = il2 > splat<N>(1e-12f);
  const Pk<N> il = root(il2);
  const Pk<N> floor = splat<N>(1e-6f);
  const Pk<N> inv_il = one / select(il < floor, floor, il);
  const Pk<N> tx = ix * inv_il;
  const Pk<N> ty = iy * inv_il;
  const Pk<N> b = splat<N>(p.gamma) * il;
  const Pk<N> theta = atan2_lanes(tx * ey - ty * ex, tx * ex + ty * ey);
  const Pk<N> base = -d * inv_il * splat<N>(p.inv_gamma);
  const Pk<N> nb = splat<N>(p.n) * b * theta;
  const Pk<N> npb = splat<N>(p.n_prime) * b * theta;
  const Pk<N> along = -exp_lanes(base - npb * npb);
  const Pk<N> sign = select(theta > zero, one, select(theta < zero, splat<N>(-1.0f), zero));
  const Pk<N> side = -sign * exp_lanes(base - nb * nb);
  const Pk<N> scale = splat<N>(p.factor * kForceQuantum);
  const Pk<N> gx = select(live, scale * (along * tx - side * ty), zero);
  const Pk<N> gy = select(live, scale * (along * ty + side * tx), zero);
  const __m512i none = _mm512_setzero_si512();
  SOCSIM_EACH {
    const int o = m + 16 * k;
    _mm512_mask_storeu_epi32(fx + o, in.v[k], _mm512_mask_cvttps_epi32(none, 0xFFFF, gx.v[k]));
    _mm512_mask_storeu_epi32(fy + o, in.v[k], _mm512_mask_cvttps_epi32(none, 0xFFFF, gy.v[k]));
  }
}

__attribute__((target("avx512f"))) void social_kernel_avx512(const SocialParams& p, int count,
                                                             const float* dx, const float* dy,
                                                             const float* dvx, const float* dvy,
                                                             const float* tie_x, const float* tie_y,
                                                             std::int32_t* fx, std::int32_t* fy) {
  int m = 0;
  for (; count - m > 16; m += 32) kernel_lanes<2>(p, m, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
  if (m < count) kernel_lanes<1>(p, m, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
}

#undef SOCSIM_EACH
#undef SOCSIM_AVX512

}  // namespace
#endif

void social_kernel(const SocialParams& p, int count, const float* __restrict dx, const float* __restrict dy,
                   const float* __restrict dvx, const float* __restrict dvy, const float* __restrict tie_x,
                   const float* __restrict tie_y, std::int32_t* __restrict fx, std::int32_t* __restrict fy) {
#ifdef SOCSIM_KERNEL_AVX512
  static const bool avx512 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") != 0;
  }();
  if (avx512) {
    social_kernel_avx512(p, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
    return;
  }
#endif
  social_kernel_portable(p, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
float headway_speed_cap(int count, const float* __restrict dx, const float* __restrict dy,
                        const float* __restrict dvx, const float* __restrict dvy, float ex, float ey, float band,
                        float speed_along, float oncoming, float distance, float inv_time, float anticipation,
                        float best) {
  const float band2 = band * band;
  // One running minimum per lane of 8 and the selects written as integer masks: GCC turned the
  // boolean form of this loop into branches and left it scalar (18 % of a step in `perf`).
  constexpr int kLanes = 8;
  alignas(32) std::int32_t least[kLanes];
  for (int l = 0; l < kLanes; ++l) least[l] = std::bit_cast<std::int32_t>(best);
  const auto cap_bits = [&](int m) {
    const float ox = dx[m];
    const float oy = dy[m];
    const float ahead = ox * ex + oy * ey;
    const float side = ox * ey - oy * ex;
    const float closing = dvx[m] * ex + dvy[m] * ey;  // (v_i − v_j)·e
    const float toward = speed_along - closing;
    const float d = std::sqrt(ox * ox + oy * oy);
    const float cap = std::max((d - distance - anticipation * closing) * inv_time, 0.0f);
    const std::int32_t counts = -static_cast<std::int32_t>(ahead > 0.0f) &
                                -static_cast<std::int32_t>(side * side < band2) &
                                -static_cast<std::int32_t>(toward >= -oncoming);  // all ones or 0
    // Non-negative floats order like their bits; INT32_MAX where the neighbour does not count.
    return (std::bit_cast<std::int32_t>(cap) & counts) | (INT32_MAX & ~counts);
  };
  int m = 0;
  for (; m + kLanes <= count; m += kLanes) {
    for (int l = 0; l < kLanes; ++l) {
      const std::int32_t c = cap_bits(m + l);
      least[l] = least[l] < c ? least[l] : c;
    }
  }
  for (; m < count; ++m) least[0] = std::min(least[0], cap_bits(m));
  std::int32_t result = least[0];
  for (int l = 1; l < kLanes; ++l) result = std::min(result, least[l]);
  return std::bit_cast<float>(result);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
std::int64_t
oncoming_side_push(int count, const float* __restrict dx, const float* __restrict dy,
                   const float* __restrict dvx, const float* __restrict dvy, float ex, float ey, float band,
                   float speed_along, float oncoming, float bias, float factor, float inv_range) {
  const float band2 = band * band;
  const float scale = factor * kForceQuantum;
  // In blocks of 8 lanes with one integer sum per lane (as headway_speed_cap): no scalar tail
  // for the padded batches of the step, and an integer sum does not depend on the lanes' order.
  constexpr int kLanes = 8;
  const auto push = [&](int m) {
    const float ox = dx[m];
    const float oy = dy[m];
    const float ahead = ox * ex + oy * ey;
    const float right = ox * ey - oy * ex;  // > 0: the neighbour is right of the walking line
    const float toward = speed_along - (dvx[m] * ex + dvy[m] * ey);
    const std::int32_t counts = -static_cast<std::int32_t>(ahead > 0.0f) &
                                -static_cast<std::int32_t>(right * right < band2) &
                                -static_cast<std::int32_t>(toward < -oncoming);  // all ones or 0
    // Lanes that do not count are masked out after the conversion; ahead is floored at 0 so that
    // theirs stays within int32 too (|magnitude| <= scale < 2^31).
    const float magnitude = scale * fast_expf(-std::max(ahead, 0.0f) * inv_range);
    const float signed_push = right < bias ? magnitude : -magnitude;
    return static_cast<std::int32_t>(signed_push) & counts;
  };
  alignas(32) std::int32_t lane_sum[kLanes] = {};
  int m = 0;
  std::int64_t sum = 0;
  for (; m + kLanes <= count; m += kLanes) {
    for (int l = 0; l < kLanes; ++l) lane_sum[l] = push(m + l);
    for (int l = 0; l < kLanes; ++l) sum += lane_sum[l];
  }
  for (; m < count; ++m) sum += push(m);
  return sum;
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
AheadTerms
ahead_terms(int count, const float* __restrict dx, const float* __restrict dy, const float* __restrict dvx,
            const float* __restrict dvy, const AheadParams& p, float best) {
  // The lane computations of headway_speed_cap and oncoming_side_push, sharing the loads and the
  // projections on the walking direction.
  const float ex = p.ex, ey = p.ey, speed_along = p.speed_along, oncoming = p.oncoming;
  const float band2 = p.headway_band * p.headway_band;
  const float distance = p.distance, inv_time = p.inv_time, anticipation = p.anticipation;
  const float side_band2 = p.side_band * p.side_band;
  const float bias = p.side_bias, scale = p.side_factor * kForceQuantum, inv_range = p.side_inv_range;
  constexpr int kLanes = 8;
  alignas(32) std::int32_t least[kLanes];
  // Per-lane sums of the pushes in 32 bits: a lane sees at most kBatch / 8 = 8 neighbours of a
  // batch and |push| <= side_factor·2^20 <= 100·2^20, so 8 of them stay below 2^31 (widened once
  // at the end; integer sums, so the split into lanes does not change the total).
  alignas(32) std::int32_t lane_sum[kLanes] = {};
  for (int l = 0; l < kLanes; ++l) least[l] = std::bit_cast<std::int32_t>(best);
  std::int64_t sum = 0;
  const auto lane = [&](int m, std::int32_t* cap_bits, std::int32_t* push) {
    const float ox = dx[m];
    const float oy = dy[m];
    const float ahead = ox * ex + oy * ey;
    const float side = ox * ey - oy * ex;
    const float closing = dvx[m] * ex + dvy[m] * ey;  // (v_i − v_j)·e
    const float toward = speed_along - closing;
    const float d = std::sqrt(ox * ox + oy * oy);
    const float cap = std::max((d - distance - anticipation * closing) * inv_time, 0.0f);
    const std::int32_t in_front = -static_cast<std::int32_t>(ahead > 0.0f);
    const std::int32_t follows = in_front & -static_cast<std::int32_t>(side * side < band2) &
                                 -static_cast<std::int32_t>(toward >= -oncoming);
    *cap_bits = (std::bit_cast<std::int32_t>(cap) & follows) | (INT32_MAX & ~follows);
    const std::int32_t meets = in_front & -static_cast<std::int32_t>(side * side < side_band2) &
                               -static_cast<std::int32_t>(toward < -oncoming);
    const float magnitude = scale * fast_expf(-std::max(ahead, 0.0f) * inv_range);
    const float signed_push = side < bias ? magnitude : -magnitude;
    *push = static_cast<std::int32_t>(signed_push) & meets;
  };
  int m = 0;
  for (; m + kLanes <= count; m += kLanes) {
    for (int l = 0; l < kLanes; ++l) {
      std::int32_t c = 0;
      std::int32_t push = 0;
      lane(m + l, &c, &push);
      least[l] = least[l] < c ? least[l] : c;
      lane_sum[l] += push;
    }
  }
  for (int l = 0; l < kLanes; ++l) sum += lane_sum[l];
  for (; m < count; ++m) {
    std::int32_t c = 0;
    std::int32_t push = 0;
    lane(m, &c, &push);
    least[0] = std::min(least[0], c);
    sum += push;
  }
  std::int32_t result = least[0];
  for (int l = 1; l < kLanes; ++l) result = std::min(result, least[l]);
  return {std::bit_cast<float>(result), sum};
}

}  // namespace socsim::crowd
