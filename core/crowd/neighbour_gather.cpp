#include "core/crowd/neighbour_gather.hpp"

#include <bit>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SOCSIM_GATHER_AVX2 1
#endif

namespace socsim::crowd {

namespace {

// Branch-free: every candidate is written at the batch's end, which only advances when the
// candidate is taken. Returns the first candidate not visited (the batch is full when < k1).
std::uint32_t gather_range(const GatherQuery& q, std::uint32_t k, std::uint32_t k1, GatherBatch& b) {
  const double* __restrict xs = q.x;
  const double* __restrict ys = q.y;
  const double* __restrict vxs = q.vx;
  const double* __restrict vys = q.vy;
  const std::uint8_t* __restrict act = q.active;
  float* __restrict bdx = b.dx;
  float* __restrict bdy = b.dy;
  float* __restrict bdvx = b.dvx;
  float* __restrict bdvy = b.dvy;
  std::uint32_t* __restrict bslot = b.slot;
  std::uint8_t* __restrict bclose = b.close;
  const double x = q.px, y = q.py, vx = q.pvx, vy = q.pvy, cut2 = q.cutoff2, close2 = q.close2;
  int m = b.count;
  int c = b.close_count;
  for (; k < k1 && m < b.capacity; ++k) {
    const double dx = xs[k] - x;
    const double dy = ys[k] - y;
    const double d2 = dx * dx + dy * dy;
    bool take = (d2 <= cut2) & (k != q.self);
    if (act != nullptr) take = take & (act[k] != 0);
    bdx[m] = static_cast<float>(dx);
    bdy[m] = static_cast<float>(dy);
    bdvx[m] = static_cast<float>(vx - vxs[k]);
    bdvy[m] = static_cast<float>(vy - vys[k]);
    bslot[m] = k;
    bclose[c] = static_cast<std::uint8_t>(m);
    c += (take & (d2 < close2)) ? 1 : 0;
    m += take ? 1 : 0;
  }
  b.count = m;
  b.close_count = c;
  return k;
}

}  // namespace

int gather_neighbours_scalar(const GatherQuery& q, GatherRange* ranges, int count, GatherBatch& b) {
  for (int r = 0; r < count; ++r) {
    ranges[r].begin = gather_range(q, ranges[r].begin, ranges[r].end, b);
    if (ranges[r].begin < ranges[r].end) return r;
  }
  return count;
}

#ifdef SOCSIM_GATHER_AVX2
namespace {

// For each 4-bit mask of taken lanes: the lanes in order, packed to the front.
struct CompressTable {
  alignas(16) std::int32_t lanes[16][4];
  constexpr CompressTable() : lanes{} {
    for (int mask = 0; mask < 16; ++mask) {
      int n = 0;
      for (int lane = 0; lane < 4; ++lane)
        if ((mask >> lane) & 1) lanes[mask][n++] = lane;
    }
  }
};
constexpr CompressTable kCompress;

__attribute__((target("avx2"), always_inline)) inline __m128 pack(__m256d v, __m128i perm) {
  return _mm_permutevar_ps(_mm256_cvtpd_ps(v), perm);
}

// Four candidates at a time: the same double-precision differences and products, the same
// round-to-nearest conversions to float and the same comparisons as the scalar loop (so the
// same bits), taken lanes packed with a permutation from the table.
__attribute__((target("avx2,popcnt"))) int gather_avx2(const GatherQuery& q, GatherRange* ranges, int count,
                                                       GatherBatch& b) {
  const double* __restrict xs = q.x;
  const double* __restrict ys = q.y;
  const double* __restrict vxs = q.vx;
  const double* __restrict vys = q.vy;
  float* __restrict bdx = b.dx;
  float* __restrict bdy = b.dy;
  float* __restrict bdvx = b.dvx;
  float* __restrict bdvy = b.dvy;
  std::uint32_t* __restrict bslot = b.slot;
  std::uint8_t* __restrict bclose = b.close;
  const __m256d px = _mm256_set1_pd(q.px);
  const __m256d py = _mm256_set1_pd(q.py);
  const __m256d pvx = _mm256_set1_pd(q.pvx);
  const __m256d pvy = _mm256_set1_pd(q.pvy);
  const __m256d cut2 = _mm256_set1_pd(q.cutoff2);
  const __m256d close2 = _mm256_set1_pd(q.close2);
  const __m128i lane_index = _mm_setr_epi32(0, 1, 2, 3);
  const std::uint32_t self = q.self;
  const int capacity = b.capacity;
  int m = b.count;
  int c = b.close_count;
  for (int r = 0; r < count; ++r) {
    std::uint32_t k = ranges[r].begin;
    const std::uint32_t k1 = ranges[r].end;
    for (; k < k1 && k + 4 <= q.readable && m + 4 <= capacity; k += 4) {
      const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(xs + k), px);
      const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(ys + k), py);
      const __m256d d2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
      auto take = static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(d2, cut2, _CMP_LE_OQ)));
      if (k1 - k < 4) take &= (1u << (k1 - k)) - 1u;  // lanes past the range
      const unsigned self_lane = self - k;            // wraps to a large value when self < k
      if (self_lane < 4) take &= ~(1u << self_lane);
      unsigned close =
          take & static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(d2, close2, _CMP_LT_OQ)));
      const __m128i perm = _mm_load_si128(reinterpret_cast<const __m128i*>(kCompress.lanes[take]));
      _mm_storeu_ps(bdx + m, pack(dx, perm));
      _mm_storeu_ps(bdy + m, pack(dy, perm));
      _mm_storeu_ps(bdvx + m, pack(_mm256_sub_pd(pvx, _mm256_loadu_pd(vxs + k)), perm));
      _mm_storeu_ps(bdvy + m, pack(_mm256_sub_pd(pvy, _mm256_loadu_pd(vys + k)), perm));
      const __m128i slots = _mm_add_epi32(_mm_set1_epi32(static_cast<int>(k)), lane_index);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(bslot + m),
                       _mm_castps_si128(_mm_permutevar_ps(_mm_castsi128_ps(slots), perm)));
      while (close != 0) {  // rare: a neighbour within touching reach
        const int lane = std::countr_zero(close);
        close &= close - 1;
        bclose[c++] = static_cast<std::uint8_t>(m + std::popcount(take & ((1u << lane) - 1u)));
      }
      m += std::popcount(take);
    }
    if (k >= k1) continue;
    // Near the arrays' end or the batch's: finish with the scalar loop as far as the batch allows.
    b.count = m;
    b.close_count = c;
    ranges[r].begin = gather_range(q, k, k1, b);
    m = b.count;
    c = b.close_count;
    if (ranges[r].begin < k1) return r;
  }
  b.count = m;
  b.close_count = c;
  return count;
}

using GatherFn = int (*)(const GatherQuery&, GatherRange*, int, GatherBatch&);
GatherFn pick_gather() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt")) return gather_avx2;
  return gather_neighbours_scalar;
}

}  // namespace
#endif

int gather_neighbours(const GatherQuery& q, GatherRange* ranges, int count, GatherBatch& b) {
#ifdef SOCSIM_GATHER_AVX2
  static const GatherFn fn = pick_gather();
  if (q.active == nullptr) return fn(q, ranges, count, b);
#endif
  return gather_neighbours_scalar(q, ranges, count, b);
}

}  // namespace socsim::crowd
