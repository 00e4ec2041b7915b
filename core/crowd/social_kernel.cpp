#include "core/crowd/social_kernel.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>

#include "core/crowd/fast_math.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
#include <immintrin.h>
#endif

// Clones for AVX-512, AVX2 and the baseline, picked at load time. GCC only: clang 14 accepts the
// attribute but emitted a single function with AVX-512 instructions in it (the sanitizer build
// died with SIGILL on an AVX2-only CPU), so with clang these are compiled for the baseline.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define SOCSIM_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SOCSIM_CLONES
#endif

// Kept in its own translation unit so the compiler vectorises this loop on its own terms
// (selects only, no branches); every lane computes the same IEEE operations a scalar loop would.
namespace socsim::crowd {

namespace {

// One lane of the portable loops, inlined into each clone: the social force on the agent from a
// neighbour at (rx, ry) with relative velocity (dvx, dvy) = v_i − v_j and tie direction (ux, uy).
struct SocialLane {
  std::int32_t fx, fy;
};
[[gnu::always_inline]] inline SocialLane social_lane(const SocialParams& p, float rx, float ry, float dvx,
                                                     float dvy, float ux, float uy) {
  const float d2 = rx * rx + ry * ry;
  const float d = std::sqrt(d2);
  // Either (rx, ry) = 0 (coincident: the tie direction u applies) or u = 0, so no select is needed.
  const float inv_d = 1.0f / std::max(d, 1e-30f);
  const float ex = rx * inv_d + ux;
  const float ey = ry * inv_d + uy;
  const float ix = p.lambda * dvx + ex;
  const float iy = p.lambda * dvy + ey;
  const float il2 = ix * ix + iy * iy;
  const bool live = il2 > 1e-12f;
  const float il = std::sqrt(il2);
  const float inv_il = 1.0f / std::max(il, 1e-6f);
  const float tx = ix * inv_il;
  const float ty = iy * inv_il;
  const float b = p.gamma * il;
  // The angle from i to e (the same as from t = i/|i|): it need not wait for the division.
  const float theta = fast_atan2f(ix * ey - iy * ex, ix * ex + iy * ey);
  const float base = -d * inv_il * p.inv_gamma;
  const float nb = p.n * b * theta;
  const float npb = p.n_prime * b * theta;
  const float along = -fast_expf(base - npb * npb);
  const float sign = theta > 0.0f ? 1.0f : (theta < 0.0f ? -1.0f : 0.0f);
  const float side = -sign * fast_expf(base - nb * nb);
  // |along|, |side| <= 1 and factor <= 1000, so |g| < 2^31: the conversion cannot overflow.
  const float scale = p.factor * kForceQuantum;
  const float gx = live ? scale * (along * tx - side * ty) : 0.0f;
  const float gy = live ? scale * (along * ty + side * tx) : 0.0f;
  return {static_cast<std::int32_t>(gx), static_cast<std::int32_t>(gy)};
}

// One lane of the ahead terms (ahead_terms' and the pair kernel's): the headway cap's bits
// (INT32_MAX where the neighbour at (ox, oy) does not count) and the side push (0 where it does
// not meet the agent), for an agent walking along (ex, ey) at speed_along = v·e with headway band
// `band`; (dvx, dvy) = v_agent − v_neighbour.
struct AheadLane {
  std::int32_t cap, push;
};
[[gnu::always_inline]] inline AheadLane ahead_lane(const PairAheadParams& a, float ex, float ey,
                                                   float speed_along, float band, float ox, float oy,
                                                   float dvx, float dvy) {
  const float ahead = ox * ex + oy * ey;
  const float side = ox * ey - oy * ex;
  const float closing = dvx * ex + dvy * ey;  // (v_i − v_j)·e
  const float toward = speed_along - closing;
  const float d = std::sqrt(ox * ox + oy * oy);
  const float cap = std::max((d - a.distance - a.anticipation * closing) * a.inv_time, 0.0f);
  const std::int32_t in_front = -static_cast<std::int32_t>(ahead > 0.0f);
  const std::int32_t follows = in_front & -static_cast<std::int32_t>(side * side < band * band) &
                               -static_cast<std::int32_t>(toward >= -a.oncoming);
  const std::int32_t meets = in_front & -static_cast<std::int32_t>(side * side < a.side_band * a.side_band) &
                             -static_cast<std::int32_t>(toward < -a.oncoming);
  const float magnitude =
      a.side_factor * kForceQuantum * fast_expf(-std::max(ahead, 0.0f) * a.side_inv_range);
  const float signed_push = side < a.side_bias ? magnitude : -magnitude;
  return {(std::bit_cast<std::int32_t>(cap) & follows) | (INT32_MAX & ~follows),
          static_cast<std::int32_t>(signed_push) & meets};
}

}  // namespace

// On x86-64 an AVX-512 clone (16 lanes) or an AVX2 clone (8 lanes) is picked at load time where
// the CPU has it. -ffp-contract=off forbids fused multiply-adds, so every clone computes the same
// IEEE operations and gives identical bits (tests/core/crowd compares them with the scalar clone).
SOCSIM_CLONES
void social_kernel_portable(const SocialParams& p, int count, const float* __restrict dx,
                            const float* __restrict dy, const float* __restrict dvx,
                            const float* __restrict dvy, const float* __restrict tie_x,
                            const float* __restrict tie_y, std::int32_t* __restrict fx,
                            std::int32_t* __restrict fy) {
  for (int m = 0; m < count; ++m) {
    const SocialLane f = social_lane(p, dx[m], dy[m], dvx[m], dvy[m], tie_x[m], tie_y[m]);
    fx[m] = f.fx;
    fy[m] = f.fy;
  }
}

SOCSIM_CLONES
void pair_kernel_portable(const SocialParams& p, const PairAheadParams& a, int count, PairLanes& b) {
  for (int m = 0; m < count; ++m) {
    const float rx = b.dx[m];
    const float ry = b.dy[m];
    const float vx = b.dvx[m];
    const float vy = b.dvy[m];
    const SocialLane f = social_lane(p, rx, ry, vx, vy, b.tie_x[m], b.tie_y[m]);
    b.fx[m] = f.fx;
    b.fy[m] = f.fy;
    const AheadLane i = ahead_lane(a, b.ex_i[m], b.ey_i[m], b.along_i[m], b.band_i[m], rx, ry, vx, vy);
    const AheadLane j = ahead_lane(a, b.ex_j[m], b.ey_j[m], b.along_j[m], b.band_j[m], -rx, -ry, -vx, -vy);
    b.cap_i[m] = i.cap;
    b.push_i[m] = i.push;
    b.cap_j[m] = j.cap;
    b.push_j[m] = j.push;
  }
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
#define SOCSIM_KERNEL_BY_HAND 1
// The kernel by hand for AVX-512 and for AVX2 (core/crowd/social_kernel_lanes.hpp, once each): what
// differs between the two is the vector type, how a comparison is held and selected with, and the
// loads and stores of a partly filled vector.
namespace {

#define SOCSIM_SIMD(isa) __attribute__((target(isa), always_inline)) static inline

namespace avx512 {
struct Simd {
  using vec = __m512;
  using mask = __mmask16;
  using lanes = __mmask16;  // the lanes of a vector that are in the batch
  static constexpr int kLanes = 16;
  static constexpr int kInterleave = 2;  // −28 % per pair against one vector at a time
  static constexpr int kPairInterleave = 2;
  SOCSIM_SIMD("avx512f") vec set1(float x) { return _mm512_set1_ps(x); }
  SOCSIM_SIMD("avx512f") vec add(vec a, vec b) { return _mm512_add_ps(a, b); }
  SOCSIM_SIMD("avx512f") vec sub(vec a, vec b) { return _mm512_sub_ps(a, b); }
  SOCSIM_SIMD("avx512f") vec mul(vec a, vec b) { return _mm512_mul_ps(a, b); }
  SOCSIM_SIMD("avx512f") vec div(vec a, vec b) { return _mm512_div_ps(a, b); }
  SOCSIM_SIMD("avx512f") vec neg(vec a) {
    return _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a), _mm512_set1_epi32(INT32_MIN)));
  }
  // The masked forms here and below: no undefined source register (GCC 12 warns of those).
  SOCSIM_SIMD("avx512f") vec sqrt(vec a) { return _mm512_mask_sqrt_ps(a, 0xFFFF, a); }
  SOCSIM_SIMD("avx512f") mask less(vec a, vec b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
  // For finite lanes: a < b ? b : a, a > b ? b : a, |a| (the sign bit cleared).
  SOCSIM_SIMD("avx512f") vec max(vec a, vec b) { return _mm512_max_ps(a, b); }
  SOCSIM_SIMD("avx512f") vec min(vec a, vec b) { return _mm512_min_ps(a, b); }
  SOCSIM_SIMD("avx512f") vec abs(vec a) {
    return _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32(INT32_MAX)));
  }
  SOCSIM_SIMD("avx512f") vec select(mask m, vec t, vec f) { return _mm512_mask_blend_ps(m, f, t); }
  // 2^k for the integral k in each lane of kf (the scale of fast_expf)
  SOCSIM_SIMD("avx512f") vec exp2_integer(vec kf) {
    const __m512i bias = _mm512_set1_epi32(127);
    const __m512i e = _mm512_mask_cvttps_epi32(bias, 0xFFFF, kf);
    const __m512i biased = _mm512_add_epi32(e, bias);
    return _mm512_castsi512_ps(_mm512_mask_slli_epi32(biased, 0xFFFF, biased, 23));
  }
  // The first `left` lanes (all when left >= kLanes)
  SOCSIM_SIMD("avx512f") lanes first(int left) {
    return left >= kLanes ? lanes{0xFFFF} : static_cast<lanes>((1u << left) - 1u);
  }
  SOCSIM_SIMD("avx512f") vec load(lanes in, const float* p) { return _mm512_maskz_loadu_ps(in, p); }
  // static_cast<std::int32_t> of each lane in the batch
  SOCSIM_SIMD("avx512f") void store_ints(lanes in, std::int32_t* p, __m512i v) {
    _mm512_mask_storeu_epi32(p, in, v);
  }
  // For the ahead terms: masks combined, integer lanes (running minimum, sums).
  using ivec = __m512i;
  SOCSIM_SIMD("avx512f") mask both(mask a, mask b) { return static_cast<mask>(a & b); }
  SOCSIM_SIMD("avx512f") mask greater_equal(vec a, vec b) { return _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ); }
  SOCSIM_SIMD("avx512f") bool any(mask m) { return m != 0; }
  SOCSIM_SIMD("avx512f") ivec iset1(std::int32_t x) { return _mm512_set1_epi32(x); }
  SOCSIM_SIMD("avx512f") ivec bits(vec a) { return _mm512_castps_si512(a); }
  SOCSIM_SIMD("avx512f") ivec truncate(vec a) {
    return _mm512_mask_cvttps_epi32(_mm512_setzero_si512(), 0xFFFF, a);
  }
  SOCSIM_SIMD("avx512f") ivec imin(ivec a, ivec b) { return _mm512_min_epi32(a, b); }
  SOCSIM_SIMD("avx512f") ivec iadd(ivec a, ivec b) { return _mm512_add_epi32(a, b); }
  SOCSIM_SIMD("avx512f") ivec iselect(mask m, ivec t, ivec f) { return _mm512_mask_blend_epi32(m, f, t); }
  SOCSIM_SIMD("avx512f") void istore(std::int32_t* p, ivec v) { _mm512_storeu_si512(p, v); }
  // 64-bit running sums of integer lanes: acc + (the low half of v widened) + (its high half)
  SOCSIM_SIMD("avx512f") ivec widen_add(ivec acc, ivec v) {
    const __m512i lo = _mm512_cvtepi32_epi64(_mm512_castsi512_si256(v));
    const __m512i hi = _mm512_cvtepi32_epi64(_mm512_extracti64x4_epi64(v, 1));
    return _mm512_add_epi64(acc, _mm512_add_epi64(lo, hi));
  }
};
}  // namespace avx512

namespace avx2 {
struct Simd {
  using vec = __m256;
  using mask = __m256;  // all ones or all zeros in each lane
  struct lanes {
    __m256i mask;
    bool full;  // every lane: plain loads and stores (the padded batches of the step)
  };
  static constexpr int kLanes = 8;
  // Five vectors interleaved: the step's batches are mostly 32 or 40 lanes, and a batch of 40 then
  // runs as one chain of dependent operations instead of two in a row (four, then one). Timed
  // alone (socsim-bench crowd-kernel, batches of 28–40 pairs, best of 6 alternated runs on an AVX2
  // EPYC): 7.57 ns per pair with four, 7.15 with five, 7.46 with six, 7.36 with eight (spills
  // grow); against the compiled AVX2 loop four gave about −40 % (2: −15 %, 3: −30 %).
  static constexpr int kInterleave = 5;
  // The pair kernel (both sides' ahead terms, more live values): three (socsim-bench crowd-kernel,
  // pairs_once_ns_per_pair, three alternated runs: 7.2–7.5 ns with three, 7.5–7.7 with four,
  // 8.0–8.2 with five, 7.9–10 with two).
  static constexpr int kPairInterleave = 3;
  SOCSIM_SIMD("avx2") vec set1(float x) { return _mm256_set1_ps(x); }
  SOCSIM_SIMD("avx2") vec add(vec a, vec b) { return _mm256_add_ps(a, b); }
  SOCSIM_SIMD("avx2") vec sub(vec a, vec b) { return _mm256_sub_ps(a, b); }
  SOCSIM_SIMD("avx2") vec mul(vec a, vec b) { return _mm256_mul_ps(a, b); }
  SOCSIM_SIMD("avx2") vec div(vec a, vec b) { return _mm256_div_ps(a, b); }
  SOCSIM_SIMD("avx2") vec neg(vec a) { return _mm256_xor_ps(a, _mm256_set1_ps(-0.0f)); }
  SOCSIM_SIMD("avx2") vec sqrt(vec a) { return _mm256_sqrt_ps(a); }
  SOCSIM_SIMD("avx2") mask less(vec a, vec b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
  SOCSIM_SIMD("avx2") vec max(vec a, vec b) { return _mm256_max_ps(a, b); }
  SOCSIM_SIMD("avx2") vec min(vec a, vec b) { return _mm256_min_ps(a, b); }
  SOCSIM_SIMD("avx2") vec abs(vec a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a); }
  SOCSIM_SIMD("avx2") vec select(mask m, vec t, vec f) { return _mm256_blendv_ps(f, t, m); }
  SOCSIM_SIMD("avx2") vec exp2_integer(vec kf) {
    const __m256i e = _mm256_add_epi32(_mm256_cvttps_epi32(kf), _mm256_set1_epi32(127));
    return _mm256_castsi256_ps(_mm256_slli_epi32(e, 23));
  }
  SOCSIM_SIMD("avx2") lanes first(int left) {
    const __m256i index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    return {_mm256_cmpgt_epi32(_mm256_set1_epi32(left), index), left >= kLanes};
  }
  // Masked-off lanes read as 0 and are not touched: no fault past the end of the batch.
  SOCSIM_SIMD("avx2") vec load(const lanes& in, const float* p) {
    return in.full ? _mm256_loadu_ps(p) : _mm256_maskload_ps(p, in.mask);
  }
  SOCSIM_SIMD("avx2") void store_ints(const lanes& in, std::int32_t* p, __m256i v) {
    if (in.full)
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v);
    else
      _mm256_maskstore_epi32(p, in.mask, v);
  }
  using ivec = __m256i;
  SOCSIM_SIMD("avx2") mask both(mask a, mask b) { return _mm256_and_ps(a, b); }
  SOCSIM_SIMD("avx2") mask greater_equal(vec a, vec b) { return _mm256_cmp_ps(a, b, _CMP_GE_OQ); }
  SOCSIM_SIMD("avx2") bool any(mask m) { return _mm256_movemask_ps(m) != 0; }
  SOCSIM_SIMD("avx2") ivec iset1(std::int32_t x) { return _mm256_set1_epi32(x); }
  SOCSIM_SIMD("avx2") ivec bits(vec a) { return _mm256_castps_si256(a); }
  SOCSIM_SIMD("avx2") ivec truncate(vec a) { return _mm256_cvttps_epi32(a); }
  SOCSIM_SIMD("avx2") ivec imin(ivec a, ivec b) { return _mm256_min_epi32(a, b); }
  SOCSIM_SIMD("avx2") ivec iadd(ivec a, ivec b) { return _mm256_add_epi32(a, b); }
  SOCSIM_SIMD("avx2") ivec iselect(mask m, ivec t, ivec f) {
    return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(f), _mm256_castsi256_ps(t), m));
  }
  SOCSIM_SIMD("avx2") void istore(std::int32_t* p, ivec v) {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v);
  }
  SOCSIM_SIMD("avx2") ivec widen_add(ivec acc, ivec v) {
    const __m256i lo = _mm256_cvtepi32_epi64(_mm256_castsi256_si128(v));
    const __m256i hi = _mm256_cvtepi32_epi64(_mm256_extracti128_si256(v, 1));
    return _mm256_add_epi64(acc, _mm256_add_epi64(lo, hi));
  }
};
}  // namespace avx2

#undef SOCSIM_SIMD

}  // namespace
}  // namespace socsim::crowd

#define SOCSIM_LANES_NAMESPACE avx512
#define SOCSIM_LANES_TARGET "avx512f"
#include "core/crowd/social_kernel_lanes.hpp"
#undef SOCSIM_LANES_TARGET
#undef SOCSIM_LANES_NAMESPACE

#define SOCSIM_LANES_NAMESPACE avx2
#define SOCSIM_LANES_TARGET "avx2"
#include "core/crowd/social_kernel_lanes.hpp"
#undef SOCSIM_LANES_TARGET
#undef SOCSIM_LANES_NAMESPACE

namespace socsim::crowd {
namespace {
enum class Isa { kAvx512, kAvx2, kOther };
Isa kernel_isa() {
  static const Isa isa = [] {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f")) return Isa::kAvx512;
    return __builtin_cpu_supports("avx2") ? Isa::kAvx2 : Isa::kOther;
  }();
  return isa;
}
}  // namespace
#endif

void social_kernel(const SocialParams& p, int count, const float* __restrict dx, const float* __restrict dy,
                   const float* __restrict dvx, const float* __restrict dvy, const float* __restrict tie_x,
                   const float* __restrict tie_y, std::int32_t* __restrict fx, std::int32_t* __restrict fy) {
  (void)social_kernel_with_ahead(p, nullptr, 0.0f, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
}

BatchTotals social_kernel_with_ahead(const SocialParams& p, const AheadParams* ahead, float best, int count,
                                     const float* __restrict dx, const float* __restrict dy,
                                     const float* __restrict dvx, const float* __restrict dvy,
                                     const float* __restrict tie_x, const float* __restrict tie_y,
                                     std::int32_t* __restrict fx, std::int32_t* __restrict fy) {
#ifdef SOCSIM_KERNEL_BY_HAND
  const Isa isa = kernel_isa();
  if (isa == Isa::kAvx512)
    return avx512::social_kernel_lanes(p, ahead, best, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
  if (isa == Isa::kAvx2)
    return avx2::social_kernel_lanes(p, ahead, best, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
#endif
  social_kernel_portable(p, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
  BatchTotals t{{best, 0}, 0, 0};
  if (ahead != nullptr) t.ahead = ahead_terms(count, dx, dy, dvx, dvy, *ahead, best);
  for (int m = 0; m < count; ++m) {
    t.fx += fx[m];
    t.fy += fy[m];
  }
  return t;
}

int pair_kernel_lanes() {
#ifdef SOCSIM_KERNEL_BY_HAND
  if (kernel_isa() == Isa::kAvx512) return 16;
#endif
  return 8;
}

void pair_kernel(const SocialParams& p, const PairAheadParams& a, int count, PairLanes& b) {
#ifdef SOCSIM_KERNEL_BY_HAND
  const Isa isa = kernel_isa();
  if (isa == Isa::kAvx512) return avx512::pair_kernel_lanes(p, a, count, b);
  if (isa == Isa::kAvx2) return avx2::pair_kernel_lanes(p, a, count, b);
#endif
  pair_kernel_portable(p, a, count, b);
}

SOCSIM_CLONES
float headway_speed_cap(int count, const float* __restrict dx, const float* __restrict dy,
                        const float* __restrict dvx, const float* __restrict dvy, float ex, float ey,
                        float band, float speed_along, float oncoming, float distance, float inv_time,
                        float anticipation, float best) {
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

SOCSIM_CLONES
std::int64_t oncoming_side_push(int count, const float* __restrict dx, const float* __restrict dy,
                                const float* __restrict dvx, const float* __restrict dvy, float ex, float ey,
                                float band, float speed_along, float oncoming, float bias, float factor,
                                float inv_range) {
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

SOCSIM_CLONES
AheadTerms ahead_terms(int count, const float* __restrict dx, const float* __restrict dy,
                       const float* __restrict dvx, const float* __restrict dvy, const AheadParams& p,
                       float best) {
  // The lane computations of headway_speed_cap and oncoming_side_push, sharing the loads and the
  // projections on the walking direction.
  const PairAheadParams shared{p.oncoming,  p.distance,  p.inv_time,    p.anticipation,
                               p.side_band, p.side_bias, p.side_factor, p.side_inv_range};
  constexpr int kLanes = 8;
  alignas(32) std::int32_t least[kLanes];
  // Per-lane sums of the pushes in 32 bits: a lane sees at most kBatch / 8 = 8 neighbours of a
  // batch and |push| <= side_factor·2^20 <= 100·2^20, so 8 of them stay below 2^31 (widened once
  // at the end; integer sums, so the split into lanes does not change the total).
  alignas(32) std::int32_t lane_sum[kLanes] = {};
  for (int l = 0; l < kLanes; ++l) least[l] = std::bit_cast<std::int32_t>(best);
  std::int64_t sum = 0;
  const auto lane = [&](int m, std::int32_t* cap_bits, std::int32_t* push) {
    const AheadLane r =
        ahead_lane(shared, p.ex, p.ey, p.speed_along, p.headway_band, dx[m], dy[m], dvx[m], dvy[m]);
    *cap_bits = r.cap;
    *push = r.push;
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
