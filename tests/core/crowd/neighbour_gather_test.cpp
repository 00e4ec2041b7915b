// The step's vectorised pieces give the same bits as their portable forms: the neighbour gather
// (AVX2 where the CPU has it) against the scalar loop, and the pair kernel's lanes and the headway
// search against the same pair computed alone.
#include "core/crowd/neighbour_gather.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/rng.hpp"
#include "core/crowd/social_kernel.hpp"

namespace socsim::crowd {
namespace {

struct Candidates {
  std::vector<float> x, y, vx, vy;
};

Candidates random_candidates(Rng& rng, std::size_t n) {
  Candidates c;
  for (std::size_t k = 0; k < n; ++k) {
    c.x.push_back(static_cast<float>(rng.uniform(-4.0, 4.0)));
    c.y.push_back(static_cast<float>(rng.uniform(-4.0, 4.0)));
    c.vx.push_back(static_cast<float>(rng.uniform(-1.5, 1.5)));
    c.vy.push_back(static_cast<float>(rng.uniform(-1.5, 1.5)));
  }
  c.x[n / 2] = 0.1f;  // one coincident with the agent's position and one within touching reach
  c.y[n / 2] = -0.2f;
  c.x[n / 3] = 0.4f;
  c.y[n / 3] = -0.2f;
  return c;
}

struct Collected {
  std::vector<float> dx, dy, dvx, dvy;
  std::vector<std::uint32_t> slot;
  std::vector<int> close;
};

// Gathers all ranges, emptying the batch whenever it fills, as NeighbourSums does.
template <class Gather>
Collected collect(const GatherQuery& q, std::vector<GatherRange> ranges, int capacity, Gather gather) {
  std::vector<float> dx(capacity), dy(capacity), dvx(capacity), dvy(capacity);
  std::vector<std::uint32_t> slot(capacity);
  std::vector<std::uint8_t> close(capacity);
  GatherBatch b{dx.data(), dy.data(), dvx.data(), dvy.data(), slot.data(), close.data(), capacity};
  Collected out;
  int done = 0;
  const auto drain = [&] {
    for (int m = 0; m < b.count; ++m) {
      out.dx.push_back(dx[m]);
      out.dy.push_back(dy[m]);
      out.dvx.push_back(dvx[m]);
      out.dvy.push_back(dvy[m]);
      out.slot.push_back(slot[m]);
    }
    for (int c = 0; c < b.close_count; ++c) out.close.push_back(static_cast<int>(slot[close[c]]));
    b.count = b.close_count = 0;
  };
  const int count = static_cast<int>(ranges.size());
  while (true) {
    done += gather(q, ranges.data() + done, count - done, b);
    drain();
    if (done == count) break;
  }
  return out;
}

TEST(NeighbourGather, DispatchedGatherMatchesScalarBitForBit) {
  Rng rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const std::size_t n = 40 + rng.below(200);
    Candidates c = random_candidates(rng, n);
    const auto self = static_cast<std::uint32_t>(rng.below(n));
    const GatherQuery q{c.x.data(),
                        c.y.data(),
                        c.vx.data(),
                        c.vy.data(),
                        0.1f,
                        -0.2f,
                        0.3f,
                        0.7f,
                        3.0f * 3.0f,
                        0.5f * 0.5f,
                        self,
                        nullptr,
                        static_cast<std::uint32_t>(n)};
    // Rows of every length 0–13, and ranges that end at the arrays' end (no room for an 8-wide read).
    std::vector<GatherRange> ranges;
    std::uint32_t k = 0;
    while (k < n) {
      const auto len = std::min<std::uint32_t>(static_cast<std::uint32_t>(rng.below(14)),
                                               static_cast<std::uint32_t>(n) - k);
      ranges.push_back({k, k + len});
      k += len + static_cast<std::uint32_t>(rng.below(3));
    }
    const int capacity = trial % 2 == 0 ? kBatch : 9;  // small batches fill mid-range
    const Collected a = collect(q, ranges, capacity, gather_neighbours);
    const Collected b = collect(q, ranges, capacity, gather_neighbours_scalar);
    ASSERT_EQ(a.slot, b.slot) << "trial " << trial;
    ASSERT_EQ(a.close, b.close) << "trial " << trial;
    for (std::size_t m = 0; m < a.slot.size(); ++m) {
      ASSERT_EQ(std::bit_cast<std::uint32_t>(a.dx[m]), std::bit_cast<std::uint32_t>(b.dx[m]));
      ASSERT_EQ(std::bit_cast<std::uint32_t>(a.dy[m]), std::bit_cast<std::uint32_t>(b.dy[m]));
      ASSERT_EQ(std::bit_cast<std::uint32_t>(a.dvx[m]), std::bit_cast<std::uint32_t>(b.dvx[m]));
      ASSERT_EQ(std::bit_cast<std::uint32_t>(a.dvy[m]), std::bit_cast<std::uint32_t>(b.dvy[m]));
    }
    // What was taken: exactly the candidates within the cut-off, without the agent itself.
    std::vector<std::uint32_t> expected;
    for (const GatherRange& r : ranges) {
      for (std::uint32_t j = r.begin; j < r.end; ++j) {
        const float dx = c.x[j] - 0.1f;
        const float dy = c.y[j] - -0.2f;
        if (j != self && dx * dx + dy * dy <= 9.0f) expected.push_back(j);
      }
    }
    EXPECT_EQ(a.slot, expected) << "trial " << trial;
  }
}

TEST(NeighbourGather, InactiveCandidatesAreSkipped) {
  Rng rng(3);
  Candidates c = random_candidates(rng, 32);
  std::vector<std::uint8_t> active(32, 1);
  for (std::size_t k = 0; k < 32; k += 3) active[k] = 0;
  const GatherQuery q{c.x.data(), c.y.data(), c.vx.data(), c.vy.data(), 0.0f,          0.0f, 0.0f,
                      0.0f,       100.0f,     0.0f,        99,          active.data(), 32};
  const Collected got = collect(q, {{0, 32}}, kBatch, gather_neighbours);
  ASSERT_EQ(got.slot.size(), 21u);
  for (std::uint32_t k : got.slot) EXPECT_NE(k % 3, 0u);
}

// The cell rows of a scan: the dispatched version (AVX2 where the CPU has it) gives the scalar
// ranges exactly, and every point within the reach lies in a cell of its row's range (start[k] = k
// here, so a range is a run of cell numbers). Agents anywhere on the grid, near its edges too.
// A random grid of cells at least a third of the cut-off wide, cell k starting at entry k.
struct RandomGrid {
  struct {
    double cutoff, cell;
    std::int64_t nx, ny;
    double ox, oy;
  } shape;
  std::vector<std::uint32_t> start;
};
RandomGrid random_grid(Rng& rng) {
  RandomGrid g;
  g.shape.cutoff = rng.uniform(0.5, 4.0);
  g.shape.cell = g.shape.cutoff / 3.0 * rng.uniform(1.0, 2.5);
  g.shape.nx = static_cast<std::int64_t>(rng.uniform(1.0, 40.0));
  g.shape.ny = static_cast<std::int64_t>(rng.uniform(1.0, 40.0));
  g.start.resize(static_cast<std::size_t>(g.shape.nx * g.shape.ny + 1));
  for (std::size_t k = 0; k < g.start.size(); ++k) g.start[k] = static_cast<std::uint32_t>(k);
  g.shape.ox = rng.uniform(-50.0, 50.0);
  g.shape.oy = rng.uniform(-50.0, 50.0);
  return g;
}

TEST(NeighbourGather, GridRowsMatchScalarAndCoverTheDisc) {
  Rng rng(11);
  for (int trial = 0; trial < 2000; ++trial) {
    const RandomGrid grid = random_grid(rng);
    const auto [cutoff, cell, nx, ny, ox, oy] = grid.shape;
    const std::vector<std::uint32_t>& start = grid.start;
    const double x = ox + rng.uniform(0.0, static_cast<double>(nx) * cell);
    const double y = oy + rng.uniform(0.0, static_cast<double>(ny) * cell);
    const GridQuery q{start.data(), ox, oy, cell, 1.0 / cell, cutoff + 1e-9, nx, ny, x, y};
    GatherRange fast[kMaxGridRows];
    GatherRange slow[kMaxGridRows];
    const int n = grid_ranges(q, fast);
    ASSERT_EQ(n, grid_ranges_scalar(q, slow)) << "trial " << trial;
    for (int r = 0; r < n; ++r) {
      EXPECT_EQ(fast[r].begin, slow[r].begin) << "trial " << trial << " row " << r;
      EXPECT_EQ(fast[r].end, slow[r].end) << "trial " << trial << " row " << r;
    }
    const auto first_row = static_cast<std::int64_t>(fast[0].begin) / nx;
    for (int k = 0; k < 50; ++k) {
      const double angle = rng.uniform(0.0, 6.283185307179586);
      const double dist = cutoff * std::sqrt(rng.uniform(0.0, 1.0));
      const double px = x + dist * std::cos(angle);
      const double py = y + dist * std::sin(angle);
      const auto cx = static_cast<std::int64_t>(std::floor((px - ox) / cell));
      const auto cy = static_cast<std::int64_t>(std::floor((py - oy) / cell));
      if (cx < 0 || cy < 0 || cx >= nx || cy >= ny) continue;  // off the grid: no cell holds it
      const std::int64_t r = cy - first_row;
      ASSERT_TRUE(r >= 0 && r < n) << "trial " << trial;
      const auto cell_index = static_cast<std::uint32_t>(cy * nx + cx);
      EXPECT_TRUE(cell_index >= fast[r].begin && cell_index < fast[r].end) << "trial " << trial;
    }
  }
}

// The upper rows without a square root per row (grid_ranges_upper, the pair step's) hold every
// cell grid_ranges does for the upper half (a superset: never a neighbour missed), on the same
// rows, each a few cells wider at most (in the benchmark about a tenth more candidates).
TEST(NeighbourGather, UpperRowsWithoutRootsCoverTheExactOnes) {
  Rng rng(12);
  for (int trial = 0; trial < 4000; ++trial) {
    const RandomGrid grid = random_grid(rng);
    const auto [cutoff, cell, nx, ny, ox, oy] = grid.shape;
    const std::vector<std::uint32_t>& start = grid.start;
    // Now and then exactly on a cell's edge.
    const double fx = trial % 7 == 0 ? std::floor(rng.uniform(0.0, static_cast<double>(nx)))
                                     : rng.uniform(0.0, static_cast<double>(nx));
    const double fy = trial % 5 == 0 ? std::floor(rng.uniform(0.0, static_cast<double>(ny)))
                                     : rng.uniform(0.0, static_cast<double>(ny));
    const double x = ox + fx * cell;
    const double y = oy + fy * cell;
    const GridQuery q{start.data(), ox, oy, cell, 1.0 / cell, cutoff + 1e-9, nx, ny, x, y, true};
    GatherRange exact[kMaxGridRows];
    GatherRange wide[kMaxGridRows];
    const int n = grid_ranges_scalar(q, exact);
    const RowHalves halves = row_halves(q.reach, q.cell);
    ASSERT_EQ(n, grid_ranges_upper(q, halves, wide)) << "trial " << trial;
    GatherRange portable[kMaxGridRows];
    ASSERT_EQ(n, grid_ranges_upper_scalar(q, halves, portable)) << "trial " << trial;
    for (int r = 0; r < n; ++r) {
      EXPECT_EQ(wide[r].begin, portable[r].begin) << "trial " << trial << " row " << r;
      EXPECT_EQ(wide[r].end, portable[r].end) << "trial " << trial << " row " << r;
      EXPECT_LE(wide[r].begin, exact[r].begin) << "trial " << trial << " row " << r;
      EXPECT_GE(wide[r].end, exact[r].end) << "trial " << trial << " row " << r;
      // At most the chord's change over one row of cells, each side: 2·⌈cutoff / cell⌉ + 2 cells.
      EXPECT_LE((wide[r].end - wide[r].begin) - (exact[r].end - exact[r].begin),
                2u * static_cast<std::uint32_t>(std::ceil(cutoff / cell)) + 2u)
          << "trial " << trial;
    }
  }
}

// A full batch of random pairs: offsets within ±dx, ±dy (m), relative velocities within ±dvx, ±dvy (m/s).
PairBatch random_batch(std::uint64_t seed, double dx, double dy, double dvx, double dvy) {
  Rng rng(seed);
  PairBatch batch{};
  for (int m = 0; m < kBatch; ++m) {
    batch.dx[m] = static_cast<float>(rng.uniform(-dx, dx));
    batch.dy[m] = static_cast<float>(rng.uniform(-dy, dy));
    batch.dvx[m] = static_cast<float>(rng.uniform(-dvx, dvx));
    batch.dvy[m] = static_cast<float>(rng.uniform(-dvy, dvy));
  }
  return batch;
}

TEST(SocialKernel, EveryLaneEqualsThePairComputedAlone) {
  const SocialParams p{2.0f, 0.35f, 1.0f / 0.35f, 2.0f, 3.0f, 2.1f};
  PairBatch batch = random_batch(17, 3.0, 3.0, 2.0, 2.0);
  batch.dx[5] = batch.dy[5] = 0.0f;  // coincident: the tie direction applies
  batch.tie_x[5] = 0.6f;
  batch.tie_y[5] = 0.8f;
  social_kernel(p, kBatch, batch.dx, batch.dy, batch.dvx, batch.dvy, batch.tie_x, batch.tie_y, batch.fx,
                batch.fy);
  int nonzero = 0;
  for (int m = 0; m < kBatch; ++m) {
    PairBatch one{};  // the pair in lane 0, the other lanes inert
    one.dx[0] = batch.dx[m];
    one.dy[0] = batch.dy[m];
    one.dvx[0] = batch.dvx[m];
    one.dvy[0] = batch.dvy[m];
    one.tie_x[0] = batch.tie_x[m];
    one.tie_y[0] = batch.tie_y[m];
    social_kernel(p, kBatchLanes, one.dx, one.dy, one.dvx, one.dvy, one.tie_x, one.tie_y, one.fx, one.fy);
    EXPECT_EQ(batch.fx[m], one.fx[0]) << "lane " << m;
    EXPECT_EQ(batch.fy[m], one.fy[0]) << "lane " << m;
    for (int l = 1; l < kBatchLanes; ++l) EXPECT_EQ(one.fx[l], 0) << "inert lane " << l;
    nonzero += batch.fx[m] != 0 || batch.fy[m] != 0;
  }
  EXPECT_GT(nonzero, kBatch / 2);  // the forces are not trivially zero
}

// The kernel the step runs (hand-written with AVX-512 where the CPU has it) gives the portable
// loop's bits for every lane, at every count (whole vectors, pairs of vectors and the partial
// ones at the end), with coincident pairs, pairs at rest relative to each other and −0 offsets.
TEST(SocialKernel, HandWrittenKernelEqualsThePortableLoop) {
  const SocialParams p{2.0f, 0.35f, 1.0f / 0.35f, 2.0f, 3.0f, 2.1f};
  Rng rng(61);
  constexpr int kLanes = 4096;
  std::vector<float> dx(kLanes), dy(kLanes), dvx(kLanes), dvy(kLanes), tx(kLanes, 0.0f), ty(kLanes, 0.0f);
  for (int m = 0; m < kLanes; ++m) {
    dx[m] = static_cast<float>(rng.uniform(-3.0, 3.0));
    dy[m] = static_cast<float>(rng.uniform(-3.0, 3.0));
    dvx[m] = static_cast<float>(rng.uniform(-2.5, 2.5));
    dvy[m] = static_cast<float>(rng.uniform(-2.5, 2.5));
    if (m % 97 == 0) {  // coincident: the tie direction
      dx[m] = dy[m] = 0.0f;
      tx[m] = 0.6f;
      ty[m] = -0.8f;
    }
    if (m % 89 == 0) dvx[m] = dvy[m] = 0.0f;
    if (m % 83 == 0) dx[m] = -0.0f;
    if (m % 79 == 0) {  // far and fast: exponents below the clamp
      dx[m] = 2.9f;
      dvx[m] = -2.5f;
    }
  }
  int nonzero = 0;
  for (int count : {1, 7, 8, 15, 16, 17, 24, 31, 32, 33, 40, 48, 63, 64, 4096}) {
    std::vector<std::int32_t> fx(count), fy(count), gx(count), gy(count);
    for (int start = 0; start + count <= kLanes; start += std::max(count, 512)) {
      social_kernel(p, count, dx.data() + start, dy.data() + start, dvx.data() + start, dvy.data() + start,
                    tx.data() + start, ty.data() + start, fx.data(), fy.data());
      social_kernel_portable(p, count, dx.data() + start, dy.data() + start, dvx.data() + start,
                             dvy.data() + start, tx.data() + start, ty.data() + start, gx.data(), gy.data());
      for (int m = 0; m < count; ++m) {
        ASSERT_EQ(fx[m], gx[m]) << "count " << count << " lane " << start + m;
        ASSERT_EQ(fy[m], gy[m]) << "count " << count << " lane " << start + m;
        nonzero += fx[m] != 0;
      }
    }
  }
  EXPECT_GT(nonzero, 1000);  // the forces are not trivially zero
}

// The headway cap over a whole batch (vector lanes) equals asking each pair alone (the scalar
// tail): the smallest (d − ℓ − τ·closing)/T, floored at 0, over the neighbours ahead, within the
// band, not coming towards the agent.
TEST(SocialKernel, HeadwayCapOverTheBatchEqualsPairByPair) {
  const PairBatch batch = random_batch(29, 3.0, 0.6, 2.0, 0.5);
  const float inf = std::numeric_limits<float>::infinity();
  const auto cap = [&](int begin, int count, float best) {
    return headway_speed_cap(count, batch.dx + begin, batch.dy + begin, batch.dvx + begin, batch.dvy + begin,
                             1.0f, 0.0f, 0.345f, 1.2f, 0.1f, 0.4f, 1.0f / 0.6f, 2.5f, best);
  };
  float alone = inf;
  int counted = 0;
  for (int m = 0; m < kBatch; ++m) {
    const float one = cap(m, 1, inf);
    const bool expected =
        batch.dx[m] > 0.0f && std::abs(batch.dy[m]) < 0.345f && 1.2f - batch.dvx[m] >= -0.1f;
    EXPECT_EQ(one != inf, expected) << "lane " << m;
    if (expected) {
      EXPECT_GE(one, 0.0f) << "lane " << m;
    }
    counted += expected;
    alone = std::min(alone, one);
  }
  ASSERT_GT(counted, 2);  // the case is not trivial
  EXPECT_EQ(cap(0, kBatch, inf), alone);
  EXPECT_EQ(cap(0, kBatch, 0.0f), 0.0f);  // a smaller cap found earlier stays
}

// The side push over a whole batch is the integer sum of the pairs' pushes, whatever the split.
TEST(SocialKernel, SidePushOverTheBatchEqualsPairByPair) {
  const PairBatch batch = random_batch(31, 3.0, 0.8, 3.0, 0.5);
  const auto push = [&](int begin, int count) {
    return oncoming_side_push(count, batch.dx + begin, batch.dy + begin, batch.dvx + begin, batch.dvy + begin,
                              1.0f, 0.0f, 0.7f, 1.2f, 0.1f, 0.1f, 1.5f, 1.0f / 1.5f);
  };
  std::int64_t sum = 0;
  int nonzero = 0;
  for (int m = 0; m < kBatch; ++m) {
    const std::int64_t one = push(m, 1);
    sum += one;
    nonzero += one != 0;
  }
  ASSERT_GT(nonzero, 2);  // the case is not trivial
  EXPECT_EQ(push(0, kBatch), sum);
  EXPECT_EQ(push(0, 24) + push(24, kBatch - 24), sum);
}

// The fused pass the step uses gives exactly the two kernels' results, over whole batches and
// over odd counts (the scalar tail).
TEST(SocialKernel, AheadTermsEqualTheHeadwayCapAndTheSidePush) {
  const float inf = std::numeric_limits<float>::infinity();
  for (std::uint64_t seed : {41, 43, 47}) {
    const PairBatch batch = random_batch(seed, 3.0, 0.8, 3.0, 0.6);
    const AheadParams p{0.6f,        0.8f, 1.2f, 0.1f, 0.345f, 0.4f,
                        1.0f / 0.6f, 2.5f, 0.7f, 0.1f, 1.5f,   1.0f / 1.5f};
    for (int count : {kBatch, 24, 13, 1}) {
      for (float best : {inf, 0.7f}) {
        const AheadTerms t = ahead_terms(count, batch.dx, batch.dy, batch.dvx, batch.dvy, p, best);
        const float cap =
            headway_speed_cap(count, batch.dx, batch.dy, batch.dvx, batch.dvy, p.ex, p.ey, p.headway_band,
                              p.speed_along, p.oncoming, p.distance, p.inv_time, p.anticipation, best);
        const std::int64_t push =
            oncoming_side_push(count, batch.dx, batch.dy, batch.dvx, batch.dvy, p.ex, p.ey, p.side_band,
                               p.speed_along, p.oncoming, p.side_bias, p.side_factor, p.side_inv_range);
        EXPECT_EQ(std::bit_cast<std::uint32_t>(t.speed_cap), std::bit_cast<std::uint32_t>(cap))
            << "seed " << seed << " count " << count;
        EXPECT_EQ(t.side_push, push) << "seed " << seed << " count " << count;
      }
    }
  }
}

// The step's single pass (social force and the ahead terms from the same loads) gives what the
// two functions give one after the other, to the bit, with and without people ahead or oncoming,
// with sums in 32-bit lanes and (large factor) in 64-bit ones.
TEST(SocialKernel, FusedPassEqualsTheKernelAndTheAheadTerms) {
  const float inf = std::numeric_limits<float>::infinity();
  int pushes = 0;
  for (std::uint64_t seed : {41, 43, 47, 59}) {
    // Two seeds with a social factor so large that the kernel sums in 64-bit lanes.
    const SocialParams sp{2.0f, 0.35f, 1.0f / 0.35f, 2.0f, 3.0f, seed < 47 ? 2.1f : 900.0f};
    PairBatch batch = random_batch(seed, 3.0, 0.8, 3.0, 0.6);
    batch.dx[5] = batch.dy[5] = 0.0f;  // coincident: the tie direction applies
    batch.tie_x[5] = 0.6f;
    batch.tie_y[5] = -0.8f;
    for (const float ex : {0.6f, -1.0f}) {
      const float ey = ex > 0.0f ? 0.8f : 0.0f;
      const AheadParams p{ex, ey, 1.2f, 0.1f, 0.345f, 0.4f, 1.0f / 0.6f, 2.5f, 0.7f, 0.1f, 1.5f, 1.0f / 1.5f};
      for (int count : {kBatch, 40, 24, 13, 1}) {
        for (float best : {inf, 0.7f}) {
          PairBatch fused = batch;
          const BatchTotals totals =
              social_kernel_with_ahead(sp, &p, best, count, fused.dx, fused.dy, fused.dvx, fused.dvy,
                                       fused.tie_x, fused.tie_y, fused.fx, fused.fy);
          const AheadTerms& t = totals.ahead;
          PairBatch apart = batch;
          social_kernel(sp, count, apart.dx, apart.dy, apart.dvx, apart.dvy, apart.tie_x, apart.tie_y,
                        apart.fx, apart.fy);
          const AheadTerms u = ahead_terms(count, apart.dx, apart.dy, apart.dvx, apart.dvy, p, best);
          const std::string where = "seed " + std::to_string(seed) + " count " + std::to_string(count);
          EXPECT_EQ(std::bit_cast<std::uint32_t>(t.speed_cap), std::bit_cast<std::uint32_t>(u.speed_cap))
              << where;
          EXPECT_EQ(t.side_push, u.side_push) << where;
          for (int m = 0; m < count; ++m) {
            EXPECT_EQ(fused.fx[m], apart.fx[m]) << where << " lane " << m;
            EXPECT_EQ(fused.fy[m], apart.fy[m]) << where << " lane " << m;
          }
          std::int64_t sx = 0, sy = 0;
          for (int m = 0; m < count; ++m) {
            sx += apart.fx[m];
            sy += apart.fy[m];
          }
          EXPECT_EQ(totals.fx, sx) << where;
          EXPECT_EQ(totals.fy, sy) << where;
          const BatchTotals alone =
              social_kernel_with_ahead(sp, nullptr, best, count, batch.dx, batch.dy, batch.dvx, batch.dvy,
                                       batch.tie_x, batch.tie_y, fused.fx, fused.fy);
          EXPECT_EQ(alone.fx, sx) << where;
          EXPECT_EQ(alone.ahead.side_push, 0) << where;
          pushes += u.side_push != 0;
        }
      }
    }
  }
  EXPECT_GT(pushes, 4);  // oncoming walkers were met, not only people ahead
}

// LightSFM's pair force is antisymmetric between agents with the same parameters, and the
// kernel keeps that to the bit: seen from j, every input is negated exactly (offset, relative
// velocity, tie direction), so F_ji = −F_ij. A step could therefore compute each such pair once
// (the step does: CrowdSimulation::step_pairs).
TEST(SocialKernel, PairForceIsAntisymmetricToTheBit) {
  const SocialParams p{2.0f, 0.35f, 1.0f / 0.35f, 2.0f, 3.0f, 2.1f};
  PairBatch batch = random_batch(53, 3.0, 3.0, 2.0, 2.0);
  batch.dx[7] = batch.dy[7] = 0.0f;  // coincident: the tie directions are opposite too
  batch.tie_x[7] = 0.6f;
  batch.tie_y[7] = -0.8f;
  PairBatch mirrored = batch;
  for (int m = 0; m < kBatch; ++m) {
    mirrored.dx[m] = -batch.dx[m];
    mirrored.dy[m] = -batch.dy[m];
    mirrored.dvx[m] = -batch.dvx[m];
    mirrored.dvy[m] = -batch.dvy[m];
    mirrored.tie_x[m] = -batch.tie_x[m];
    mirrored.tie_y[m] = -batch.tie_y[m];
  }
  social_kernel(p, kBatch, batch.dx, batch.dy, batch.dvx, batch.dvy, batch.tie_x, batch.tie_y, batch.fx,
                batch.fy);
  social_kernel(p, kBatch, mirrored.dx, mirrored.dy, mirrored.dvx, mirrored.dvy, mirrored.tie_x,
                mirrored.tie_y, mirrored.fx, mirrored.fy);
  int nonzero = 0;
  for (int m = 0; m < kBatch; ++m) {
    EXPECT_EQ(mirrored.fx[m], -batch.fx[m]) << "lane " << m;
    EXPECT_EQ(mirrored.fy[m], -batch.fy[m]) << "lane " << m;
    nonzero += batch.fx[m] != 0;
  }
  EXPECT_GT(nonzero, kBatch / 2);
}

// The pair kernel (each pair once) gives, lane by lane, what each of the two agents' own batches
// give: the force on i, minus the force on j, and both sides' headway caps and side pushes —
// with per-lane walking directions, agents without one, people ahead and oncoming walkers.
TEST(SocialKernel, PairKernelEqualsBothAgentsBatches) {
  const float inf = std::numeric_limits<float>::infinity();
  const SocialParams sp{2.0f, 0.35f, 1.0f / 0.35f, 2.0f, 3.0f, 2.1f};
  const PairAheadParams a{0.1f, 0.4f, 1.0f / 0.6f, 2.5f, 0.7f, 0.1f, 1.5f, 1.0f / 1.5f};
  int caps = 0, pushes = 0;
  for (std::uint64_t seed : {61, 67, 71}) {
    Rng rng(seed);
    const PairBatch batch = random_batch(seed, 3.0, 1.0, 2.0, 0.6);
    PairLanes l{};
    const auto heading = [&](float* ex, float* ey, float* along, float* band, int m) {
      const double angle = rng.uniform(-0.6, 0.6) + (rng.uniform(0.0, 1.0) < 0.5 ? 0.0 : 3.14159);
      const bool none = rng.uniform(0.0, 1.0) < 0.15;  // no goal: (0, 0)
      ex[m] = none ? 0.0f : static_cast<float>(std::cos(angle));
      ey[m] = none ? 0.0f : static_cast<float>(std::sin(angle));
      along[m] = none ? 0.0f : static_cast<float>(rng.uniform(0.0, 1.4));
      band[m] = static_cast<float>(rng.uniform(0.17, 0.35));
    };
    for (int m = 0; m < kBatch; ++m) {
      l.dx[m] = batch.dx[m];
      l.dy[m] = batch.dy[m];
      l.dvx[m] = batch.dvx[m];
      l.dvy[m] = batch.dvy[m];
      heading(l.ex_i, l.ey_i, l.along_i, l.band_i, m);
      heading(l.ex_j, l.ey_j, l.along_j, l.band_j, m);
    }
    l.dx[9] = l.dy[9] = 0.0f;  // coincident: the tie direction applies (−u for j)
    l.tie_x[9] = 0.6f;
    l.tie_y[9] = -0.8f;
    for (int count : {kBatch, 48, 16, pair_kernel_lanes()}) {
      PairLanes fast = l;
      PairLanes portable = l;
      pair_kernel(sp, a, count, fast);
      pair_kernel_portable(sp, a, count, portable);
      for (int m = 0; m < count; ++m) {
        const std::string where =
            "seed " + std::to_string(seed) + " count " + std::to_string(count) + " lane " + std::to_string(m);
        EXPECT_EQ(fast.fx[m], portable.fx[m]) << where;
        EXPECT_EQ(fast.fy[m], portable.fy[m]) << where;
        EXPECT_EQ(fast.cap_i[m], portable.cap_i[m]) << where;
        EXPECT_EQ(fast.cap_j[m], portable.cap_j[m]) << where;
        EXPECT_EQ(fast.push_i[m], portable.push_i[m]) << where;
        EXPECT_EQ(fast.push_j[m], portable.push_j[m]) << where;
        // Each side alone, as the agent-by-agent step computes it.
        for (const bool j : {false, true}) {
          const float sign = j ? -1.0f : 1.0f;
          PairBatch one{};
          one.dx[0] = sign * l.dx[m];
          one.dy[0] = sign * l.dy[m];
          one.dvx[0] = sign * l.dvx[m];
          one.dvy[0] = sign * l.dvy[m];
          one.tie_x[0] = sign * l.tie_x[m];
          one.tie_y[0] = sign * l.tie_y[m];
          const AheadParams p{j ? l.ex_j[m] : l.ex_i[m],
                              j ? l.ey_j[m] : l.ey_i[m],
                              j ? l.along_j[m] : l.along_i[m],
                              a.oncoming,
                              j ? l.band_j[m] : l.band_i[m],
                              a.distance,
                              a.inv_time,
                              a.anticipation,
                              a.side_band,
                              a.side_bias,
                              a.side_factor,
                              a.side_inv_range};
          const BatchTotals t = social_kernel_with_ahead(sp, &p, inf, kBatchLanes, one.dx, one.dy, one.dvx,
                                                         one.dvy, one.tie_x, one.tie_y, one.fx, one.fy);
          const std::int32_t cap = j ? fast.cap_j[m] : fast.cap_i[m];
          const std::int32_t push = j ? fast.push_j[m] : fast.push_i[m];
          EXPECT_EQ(static_cast<std::int64_t>(sign) * fast.fx[m], t.fx) << where << (j ? " j" : " i");
          EXPECT_EQ(static_cast<std::int64_t>(sign) * fast.fy[m], t.fy) << where << (j ? " j" : " i");
          EXPECT_EQ(std::min(cap, std::bit_cast<std::int32_t>(inf)),
                    std::bit_cast<std::int32_t>(t.ahead.speed_cap))
              << where << (j ? " j" : " i");
          EXPECT_EQ(push, t.ahead.side_push) << where << (j ? " j" : " i");
          caps += cap != INT32_MAX;
          pushes += push != 0;
        }
      }
    }
  }
  EXPECT_GT(caps, 10);  // the cases are not trivial
  EXPECT_GT(pushes, 10);
}

}  // namespace
}  // namespace socsim::crowd
