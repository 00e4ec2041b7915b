#include "core/crowd/neighbour_gather.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SOCSIM_GATHER_AVX2 1
#endif

namespace socsim::crowd {

namespace {

// Branch-free: every candidate is written at the batch's end, which only advances when the
// candidate is taken. Returns the first candidate not visited (the batch is full when < k1).
std::uint32_t gather_range(const GatherQuery& q, std::uint32_t k, std::uint32_t k1, GatherBatch& b) {
  const float* __restrict xs = q.x;
  const float* __restrict ys = q.y;
  const float* __restrict vxs = q.vx;
  const float* __restrict vys = q.vy;
  const std::uint8_t* __restrict act = q.active;
  float* __restrict bdx = b.dx;
  float* __restrict bdy = b.dy;
  float* __restrict bdvx = b.dvx;
  float* __restrict bdvy = b.dvy;
  std::uint32_t* __restrict bslot = b.slot;
  std::uint8_t* __restrict bclose = b.close;
  const float x = q.px, y = q.py, vx = q.pvx, vy = q.pvy, cut2 = q.cutoff2, close2 = q.close2;
  int m = b.count;
  int c = b.close_count;
  for (; k < k1 && m < b.capacity; ++k) {
    const float dx = xs[k] - x;
    const float dy = ys[k] - y;
    const float d2 = dx * dx + dy * dy;
    bool take = (d2 <= cut2) & (k != q.self);
    if (act != nullptr) take = take & (act[k] != 0);
    bdx[m] = dx;
    bdy[m] = dy;
    bdvx[m] = vx - vxs[k];
    bdvy[m] = vy - vys[k];
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

namespace {

std::int64_t floor_clamp(double v, std::int64_t hi) {
  if (!(v > 0.0)) return 0;  // also catches NaN
  if (v >= static_cast<double>(hi)) return hi;
  return static_cast<std::int64_t>(v);  // truncation = floor for positive values
}

// The first and last row of the scan (clamped to the grid).
std::pair<std::int64_t, std::int64_t> grid_rows(const GridQuery& q) {
  return {floor_clamp(((q.upper ? q.y : q.y - q.reach) - q.origin_y) * q.inv_cell, q.ny - 1),
          floor_clamp((q.y + q.reach - q.origin_y) * q.inv_cell, q.ny - 1)};
}

// The row's range scanned x ± half.
GatherRange range_of_row(const GridQuery& q, std::int64_t row, double half) {
  const std::int64_t x_lo = floor_clamp((q.x - half - q.origin_x) * q.inv_cell, q.nx - 1);
  const std::int64_t x_hi = floor_clamp((q.x + half - q.origin_x) * q.inv_cell, q.nx - 1);
  return {q.start[static_cast<std::size_t>(row * q.nx + x_lo)],
          q.start[static_cast<std::size_t>(row * q.nx + x_hi + 1)]};
}

}  // namespace

int grid_ranges_scalar(const GridQuery& q, GatherRange* ranges) {
  const auto [y_lo, y_hi] = grid_rows(q);
  const double c = q.reach;
  int count = 0;
  for (std::int64_t row = y_lo; row <= y_hi && count < kMaxGridRows; ++row) {
    const double band_lo = q.origin_y + static_cast<double>(row) * q.cell;
    // The distance from y to the row's band (0 inside it), less 1e-9.
    const double gap = std::max(std::max(0.0, band_lo - q.y), q.y - (band_lo + q.cell)) - 1e-9;
    ranges[count++] =
        range_of_row(q, row, gap > 0.0 ? std::sqrt(std::max(0.0, c * c - gap * gap)) + 1e-9 : c);
  }
  return count;
}

RowHalves row_halves(double reach, double cell) {
  // Row offset d >= 1 is at least (d − 1)·cell above the point (less 1e-6 m for rounding: the
  // point's row is found by a rounded division); row 0 holds it. The half-chord there, + 1e-6 m.
  RowHalves h{};
  for (int d = 0; d < kMaxGridRows + 3; ++d) {
    const double gap = d == 0 ? 0.0 : static_cast<double>(d - 1) * cell - 1e-6;
    h.half[d] = gap > 0.0 ? std::sqrt(std::max(0.0, reach * reach - gap * gap)) + 1e-6 : reach + 1e-6;
  }
  return h;
}

int grid_ranges_upper_scalar(const GridQuery& q, const RowHalves& halves, GatherRange* ranges) {
  const auto [y_lo, y_hi] = grid_rows(q);
  int count = 0;
  for (std::int64_t row = y_lo; row <= y_hi && count < kMaxGridRows; ++row) {
    ranges[count] = range_of_row(q, row, halves.half[count]);
    ++count;
  }
  return count;
}

#ifdef SOCSIM_GATHER_AVX2
namespace {

// grid_ranges_scalar four rows at a time: the same operations on each lane (subtraction,
// multiplication, maximum, square root, all correctly rounded), the clamp as max/min then
// truncation (the same integers for the finite values a scan sees), the cell indices in 64 bits.
// floor_clamp(v, hi) of each lane (hi = x_max, an integer), for the finite values of a scan.
__attribute__((target("avx2"), always_inline)) inline __m256i clamp_to_cells(__m256d v, __m256d x_max) {
  return _mm256_cvtepi32_epi64(
      _mm256_cvttpd_epi32(_mm256_min_pd(_mm256_max_pd(v, _mm256_setzero_pd()), x_max)));
}

// Rows y_lo + r .. + 3 (those below `rows`) scanned x ± half (per lane): their ranges.
__attribute__((target("avx2"), always_inline)) inline void ranges_of_rows(const GridQuery& q,
                                                                          std::int64_t y_lo, int r, int rows,
                                                                          __m256d half, GatherRange* ranges) {
  const __m256d x = _mm256_set1_pd(q.x);
  const __m256d ox = _mm256_set1_pd(q.origin_x);
  const __m256d inv = _mm256_set1_pd(q.inv_cell);
  const __m256d x_max = _mm256_set1_pd(static_cast<double>(q.nx - 1));
  const __m256i row = _mm256_add_epi64(_mm256_set1_epi64x(y_lo + r), _mm256_setr_epi64x(0, 1, 2, 3));
  const __m256i x_lo = clamp_to_cells(_mm256_mul_pd(_mm256_sub_pd(_mm256_sub_pd(x, half), ox), inv), x_max);
  const __m256i x_hi = clamp_to_cells(_mm256_mul_pd(_mm256_sub_pd(_mm256_add_pd(x, half), ox), inv), x_max);
  // row · nx: both below 2^31, so the product of their low 32 bits is the product.
  const __m256i base = _mm256_mul_epu32(row, _mm256_set1_epi64x(q.nx));
  alignas(32) std::int64_t lo_cell[4];
  alignas(32) std::int64_t hi_cell[4];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lo_cell), _mm256_add_epi64(base, x_lo));
  _mm256_store_si256(reinterpret_cast<__m256i*>(hi_cell),
                     _mm256_add_epi64(_mm256_add_epi64(base, x_hi), _mm256_set1_epi64x(1)));
  const int n = std::min(4, rows - r);
  for (int k = 0; k < n; ++k)
    ranges[r + k] = {q.start[static_cast<std::size_t>(lo_cell[k])],
                     q.start[static_cast<std::size_t>(hi_cell[k])]};
}

__attribute__((target("avx2"))) int grid_ranges_avx2(const GridQuery& q, GatherRange* ranges) {
  const auto [y_lo, y_hi] = grid_rows(q);
  const auto rows = static_cast<int>(std::min<std::int64_t>(y_hi - y_lo + 1, kMaxGridRows));
  const double c = q.reach;
  const __m256d zero = _mm256_setzero_pd();
  const __m256d cell = _mm256_set1_pd(q.cell);
  const __m256d y = _mm256_set1_pd(q.y);
  const __m256d reach = _mm256_set1_pd(c);
  const __m256d reach2 = _mm256_set1_pd(c * c);
  const __m256d eps = _mm256_set1_pd(1e-9);
  for (int r = 0; r < rows; r += 4) {
    // static_cast<double>(row): rows are small non-negative integers, exact either way.
    const __m256d row_d =
        _mm256_add_pd(_mm256_set1_pd(static_cast<double>(y_lo + r)), _mm256_setr_pd(0.0, 1.0, 2.0, 3.0));
    const __m256d band_lo = _mm256_add_pd(_mm256_set1_pd(q.origin_y), _mm256_mul_pd(row_d, cell));
    const __m256d gap = _mm256_sub_pd(_mm256_max_pd(_mm256_max_pd(zero, _mm256_sub_pd(band_lo, y)),
                                                    _mm256_sub_pd(y, _mm256_add_pd(band_lo, cell))),
                                      eps);
    const __m256d chord = _mm256_add_pd(
        _mm256_sqrt_pd(_mm256_max_pd(zero, _mm256_sub_pd(reach2, _mm256_mul_pd(gap, gap)))), eps);
    ranges_of_rows(q, y_lo, r, rows, _mm256_blendv_pd(reach, chord, _mm256_cmp_pd(gap, zero, _CMP_GT_OQ)),
                   ranges);
  }
  return rows;
}

// grid_ranges_upper_scalar four rows at a time (the same integers, as grid_ranges_avx2's).
__attribute__((target("avx2"))) int grid_ranges_upper_avx2(const GridQuery& q, const RowHalves& halves,
                                                           GatherRange* ranges) {
  const auto [y_lo, y_hi] = grid_rows(q);
  const auto rows = static_cast<int>(std::min<std::int64_t>(y_hi - y_lo + 1, kMaxGridRows));
  for (int r = 0; r < rows; r += 4)
    ranges_of_rows(q, y_lo, r, rows, _mm256_loadu_pd(halves.half + r), ranges);
  return rows;
}

// For each 8-bit mask of taken lanes: the lanes in order, packed to the front (8 kB).
struct CompressTable {
  alignas(32) std::int32_t lanes[256][8];
  constexpr CompressTable() : lanes{} {
    for (int mask = 0; mask < 256; ++mask) {
      int n = 0;
      for (int lane = 0; lane < 8; ++lane)
        if ((mask >> lane) & 1) lanes[mask][n++] = lane;
    }
  }
};
constexpr CompressTable kCompress;

// Eight candidates at a time: the same single-precision differences, products and comparisons as
// the scalar loop (so the same bits), taken lanes packed with a permutation from the table.
__attribute__((target("avx2,popcnt"))) int gather_avx2(const GatherQuery& q, GatherRange* ranges, int count,
                                                       GatherBatch& b) {
  const float* __restrict xs = q.x;
  const float* __restrict ys = q.y;
  const float* __restrict vxs = q.vx;
  const float* __restrict vys = q.vy;
  float* __restrict bdx = b.dx;
  float* __restrict bdy = b.dy;
  float* __restrict bdvx = b.dvx;
  float* __restrict bdvy = b.dvy;
  std::uint32_t* __restrict bslot = b.slot;
  std::uint8_t* __restrict bclose = b.close;
  const __m256 px = _mm256_set1_ps(q.px);
  const __m256 py = _mm256_set1_ps(q.py);
  const __m256 pvx = _mm256_set1_ps(q.pvx);
  const __m256 pvy = _mm256_set1_ps(q.pvy);
  const __m256 cut2 = _mm256_set1_ps(q.cutoff2);
  const __m256 close2 = _mm256_set1_ps(q.close2);
  const __m256i lane_index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const std::uint32_t self = q.self;
  const int capacity = b.capacity;
  int m = b.count;
  int c = b.close_count;
  for (int r = 0; r < count; ++r) {
    std::uint32_t k = ranges[r].begin;
    const std::uint32_t k1 = ranges[r].end;
    for (; k < k1 && k + 8 <= q.readable && m + 8 <= capacity; k += 8) {
      const __m256 dx = _mm256_sub_ps(_mm256_loadu_ps(xs + k), px);
      const __m256 dy = _mm256_sub_ps(_mm256_loadu_ps(ys + k), py);
      const __m256 d2 = _mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy));
      auto take = static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(d2, cut2, _CMP_LE_OQ)));
      if (k1 - k < 8) take &= (1u << (k1 - k)) - 1u;  // lanes past the range
      const unsigned self_lane = self - k;            // wraps to a large value when self < k
      if (self_lane < 8) take &= ~(1u << self_lane);
      unsigned close =
          take & static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(d2, close2, _CMP_LT_OQ)));
      const __m256i perm = _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompress.lanes[take]));
      _mm256_storeu_ps(bdx + m, _mm256_permutevar8x32_ps(dx, perm));
      _mm256_storeu_ps(bdy + m, _mm256_permutevar8x32_ps(dy, perm));
      _mm256_storeu_ps(bdvx + m,
                       _mm256_permutevar8x32_ps(_mm256_sub_ps(pvx, _mm256_loadu_ps(vxs + k)), perm));
      _mm256_storeu_ps(bdvy + m,
                       _mm256_permutevar8x32_ps(_mm256_sub_ps(pvy, _mm256_loadu_ps(vys + k)), perm));
      const __m256i slots = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(k)), lane_index);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(bslot + m), _mm256_permutevar8x32_epi32(slots, perm));
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

// fill_pair_sides_scalar, 8 lanes at a time: the 8 neighbours' 4 floats transposed into the 4
// j-side arrays, the owner's broadcast into the i-side ones.
__attribute__((target("avx2"))) void fill_pair_sides_avx2(const float* heading, const std::uint32_t* slot,
                                                          const float* own, std::uint32_t owner, int first,
                                                          int count, const SideLanes& out) {
  const __m256 ex = _mm256_set1_ps(own[0]);
  const __m256 ey = _mm256_set1_ps(own[1]);
  const __m256 along = _mm256_set1_ps(own[2]);
  const __m256 band = _mm256_set1_ps(own[3]);
  const __m256i who = _mm256_set1_epi32(static_cast<int>(owner));
  // Whole vectors, the last one past `count` (see the header).
  for (int m = first; m < count; m += 8) {
    // Lanes past `count` (the last vector) read the owner's own instead: their slots may hold anything.
    const auto row = [&](int q) {
      return _mm_loadu_ps(m + q < count ? heading + 4 * static_cast<std::size_t>(slot[m + q]) : own);
    };
    // t_q = (lane q | lane q + 4), each (ex, ey, along, band)
    const __m256 t0 = _mm256_insertf128_ps(_mm256_castps128_ps256(row(0)), row(4), 1);
    const __m256 t1 = _mm256_insertf128_ps(_mm256_castps128_ps256(row(1)), row(5), 1);
    const __m256 t2 = _mm256_insertf128_ps(_mm256_castps128_ps256(row(2)), row(6), 1);
    const __m256 t3 = _mm256_insertf128_ps(_mm256_castps128_ps256(row(3)), row(7), 1);
    const __m256 u0 = _mm256_unpacklo_ps(t0, t1);  // ex0 ex1 ey0 ey1 | ex4 ex5 ey4 ey5
    const __m256 u1 = _mm256_unpackhi_ps(t0, t1);  // along, band likewise
    const __m256 u2 = _mm256_unpacklo_ps(t2, t3);
    const __m256 u3 = _mm256_unpackhi_ps(t2, t3);
    _mm256_storeu_ps(out.ex_j + m, _mm256_shuffle_ps(u0, u2, 0x44));
    _mm256_storeu_ps(out.ey_j + m, _mm256_shuffle_ps(u0, u2, 0xEE));
    _mm256_storeu_ps(out.along_j + m, _mm256_shuffle_ps(u1, u3, 0x44));
    _mm256_storeu_ps(out.band_j + m, _mm256_shuffle_ps(u1, u3, 0xEE));
    _mm256_storeu_ps(out.ex_i + m, ex);
    _mm256_storeu_ps(out.ey_i + m, ey);
    _mm256_storeu_ps(out.along_i + m, along);
    _mm256_storeu_ps(out.band_i + m, band);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out.owner + m), who);
  }
}

using SidesFn = void (*)(const float*, const std::uint32_t*, const float*, std::uint32_t, int, int,
                         const SideLanes&);
SidesFn pick_sides() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") ? fill_pair_sides_avx2 : fill_pair_sides_scalar;
}

using GridFn = int (*)(const GridQuery&, GatherRange*);
GridFn pick_grid() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") ? grid_ranges_avx2 : grid_ranges_scalar;
}

using UpperFn = int (*)(const GridQuery&, const RowHalves&, GatherRange*);
UpperFn pick_upper() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") ? grid_ranges_upper_avx2 : grid_ranges_upper_scalar;
}

using GatherFn = int (*)(const GatherQuery&, GatherRange*, int, GatherBatch&);
GatherFn pick_gather() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt")) return gather_avx2;
  return gather_neighbours_scalar;
}

}  // namespace
#endif

int grid_ranges(const GridQuery& q, GatherRange* ranges) {
#ifdef SOCSIM_GATHER_AVX2
  static const GridFn fn = pick_grid();
  return fn(q, ranges);
#else
  return grid_ranges_scalar(q, ranges);
#endif
}

int grid_ranges_upper(const GridQuery& q, const RowHalves& halves, GatherRange* ranges) {
#ifdef SOCSIM_GATHER_AVX2
  static const UpperFn fn = pick_upper();
  return fn(q, halves, ranges);
#else
  return grid_ranges_upper_scalar(q, halves, ranges);
#endif
}

void fill_pair_sides_scalar(const float* heading, const std::uint32_t* slot, const float* own,
                            std::uint32_t owner, int first, int count, const SideLanes& out) {
  for (int m = first; m < count; ++m) {
    const float* other = heading + 4 * static_cast<std::size_t>(slot[m]);
    out.ex_i[m] = own[0];
    out.ey_i[m] = own[1];
    out.along_i[m] = own[2];
    out.band_i[m] = own[3];
    out.ex_j[m] = other[0];
    out.ey_j[m] = other[1];
    out.along_j[m] = other[2];
    out.band_j[m] = other[3];
    out.owner[m] = owner;
  }
}

void fill_pair_sides(const float* heading, const std::uint32_t* slot, const float* own, std::uint32_t owner,
                     int first, int count, const SideLanes& out) {
#ifdef SOCSIM_GATHER_AVX2
  static const SidesFn fn = pick_sides();
  fn(heading, slot, own, owner, first, count, out);
#else
  fill_pair_sides_scalar(heading, slot, own, owner, first, count, out);
#endif
}

int gather_neighbours(const GatherQuery& q, GatherRange* ranges, int count, GatherBatch& b) {
#ifdef SOCSIM_GATHER_AVX2
  static const GatherFn fn = pick_gather();
  if (q.active == nullptr) return fn(q, ranges, count, b);
#endif
  return gather_neighbours_scalar(q, ranges, count, b);
}

}  // namespace socsim::crowd
