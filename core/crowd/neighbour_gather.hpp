#pragma once
// Collecting the neighbours of one agent within the cut-off into a pair batch (the step's hottest
// loop): a scalar version and, on x86-64 CPUs with AVX2, an 8-wide one that gives the same bits.
#include <cstdint>

namespace socsim::crowd {

// Candidates are entries of the cell-sorted arrays; the agent's own entry is `self`. Positions
// and velocities in single precision: the offsets and relative velocities are computed in single
// precision (x_k − px rounds the same either way round, so a pair's offsets stay exactly opposite).
struct GatherQuery {
  const float *x, *y, *vx, *vy;  // candidate positions and velocities
  float px, py, pvx, pvy;        // the agent's
  float cutoff2;                 // take candidates with d² <= cutoff2
  float close2;                  // and list those with d² < close2 (they may touch the agent)
  std::uint32_t self;
  const std::uint8_t* active = nullptr;  // per candidate, 0 = skip; nullptr: all are active
  // Entries of x, y, vx, vy that may be read (>= every k1): reading up to kGatherSlack entries
  // past k1 lets the vector version finish a range without a scalar tail; the extra lanes are
  // never taken.
  std::uint32_t readable = 0;
};
inline constexpr std::uint32_t kGatherSlack = 7;

// The batch being filled: per taken candidate the offset (x_k − px, y_k − py), relative velocity
// (pvx − vx_k, pvy − vy_k) and entry index; `close` lists batch positions of
// close candidates. Arrays hold `capacity` entries.
struct GatherBatch {
  float *dx, *dy, *dvx, *dvy;
  std::uint32_t* slot;
  std::uint8_t* close;
  int capacity;
  int count = 0;
  int close_count = 0;
};

// A run of consecutive candidates [begin, end) (one row of grid cells).
struct GatherRange {
  std::uint32_t begin, end;
};

// The cell rows of a uniform grid that can hold a candidate within `reach` of (x, y): per row, the
// run of cells [x_lo, x_hi] whose x-range meets the disc's chord over that row's y-band (widened by
// 1e-9 m so rounding can never hide a candidate), as a range of entries of the cell-sorted arrays
// (`start[cell]` .. `start[cell + 1]`, cells numbered row by row, nx per row). Rows outside the
// grid are clamped to its edge.
struct GridQuery {
  const std::uint32_t* start;  // nx·ny + 1 entries
  double origin_x, origin_y, cell, inv_cell;
  double reach;  // the cut-off (+ 1e-9)
  std::int64_t nx, ny;
  double x, y;
  // Only the rows from the one holding (x, y) upwards (the half of the disc that comes later in
  // the cells' order: each pair once, CrowdSimulation::step_pairs).
  bool upper = false;
};
inline constexpr int kMaxGridRows = 10;  // cells at least a third of the cut-off tall: <= 8 rows

// Writes the rows' ranges, lowest row first, into ranges[0 .. returned count) (at most
// kMaxGridRows). On x86-64 CPUs with AVX2, four rows at a time with the same IEEE operations as
// the portable version: the same ranges.
int grid_ranges(const GridQuery& q, GatherRange* ranges);
int grid_ranges_scalar(const GridQuery& q, GatherRange* ranges);

// The upper rows' ranges (q.upper) without a square root per row: every row as wide as the disc
// is anywhere within it for a point anywhere in its own row of cells (row_halves, below), so a
// few more cells than grid_ranges (about a tenth more candidates), never fewer.
struct RowHalves {
  // By row offset from the point's own row: the x-reach to scan (3 to spare: read 4 at a time).
  double half[kMaxGridRows + 3];
};
// For cells `cell` wide and a reach (the cut-off) `reach`: GridQuery's cell and reach.
RowHalves row_halves(double reach, double cell);
// Dispatched as grid_ranges (AVX2: four rows at a time, the same ranges).
int grid_ranges_upper(const GridQuery& q, const RowHalves& halves, GatherRange* ranges);
int grid_ranges_upper_scalar(const GridQuery& q, const RowHalves& halves, GatherRange* ranges);

// Visits the ranges in order until done or the batch is full; returns how many ranges were
// finished (fewer than `count` when the batch filled up: the next range's `begin` is advanced to
// the first candidate not visited). Entries past `count` may be overwritten with scratch values.
int gather_neighbours(const GatherQuery& q, GatherRange* ranges, int count, GatherBatch& b);

// The portable version, always available (tests compare it with the dispatched one).
int gather_neighbours_scalar(const GatherQuery& q, GatherRange* ranges, int count, GatherBatch& b);

// The pair batch's per-side inputs for lanes [first, count) (CrowdSimulation::step_pairs): each
// agent's walking direction, speed along it and headway band are 4 floats at heading + 4·entry;
// `own` (the owner's) goes to every lane's i side, that of the entry slot[m] to lane m's j side;
// the owner's entry to owner[m]. On x86-64 CPUs with AVX2, 8 lanes at a time (the same values
// in lanes [first, count)): lanes up to count + 7 are written too (with whatever), so every
// output array needs kFillSlack entries to spare.
inline constexpr int kFillSlack = 8;
struct SideLanes {
  float *ex_i, *ey_i, *along_i, *band_i, *ex_j, *ey_j, *along_j, *band_j;
  std::uint32_t* owner;
};
void fill_pair_sides(const float* heading, const std::uint32_t* slot, const float* own, std::uint32_t owner,
                     int first, int count, const SideLanes& out);
void fill_pair_sides_scalar(const float* heading, const std::uint32_t* slot, const float* own,
                            std::uint32_t owner, int first, int count, const SideLanes& out);

}  // namespace socsim::crowd
