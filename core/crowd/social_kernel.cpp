#include "core/crowd/social_kernel.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>

#include "core/crowd/fast_math.hpp"

// Kept in its own translation unit so the compiler vectorises this loop on its own terms
// (selects only, no branches); every lane computes the same IEEE operations a scalar loop would.
namespace socsim::crowd {

// On x86-64 an AVX-512 clone (16 lanes) or an AVX2 clone (8 lanes) is picked at load time where
// the CPU has it. -ffp-contract=off forbids fused multiply-adds, so every clone computes the same
// IEEE operations and gives identical bits (tests/core/crowd compares them with the scalar clone).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void social_kernel(const SocialParams& p, int count, const float* __restrict dx, const float* __restrict dy,
                   const float* __restrict dvx, const float* __restrict dvy, const float* __restrict tie_x,
                   const float* __restrict tie_y, std::int32_t* __restrict fx, std::int32_t* __restrict fy) {
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
