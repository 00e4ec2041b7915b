#pragma once
// Static walls bucketed in a uniform grid: each cell lists the wall segments that come within
// the cut-off distance of any point of the cell, so one lookup gives every wall that can push
// (or be reached by) an agent standing in that cell.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

namespace socsim::crowd {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Vec2&, const Vec2&) = default;
};

inline double distance(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}
inline double norm(Vec2 v) {
  return std::hypot(v.x, v.y);
}
// An angle in (-π, π], exactly (std::remainder).
inline double angle_in_pi(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

struct WallSegment {
  Vec2 a;
  Vec2 b;
  friend bool operator==(const WallSegment&, const WallSegment&) = default;
};

class WallGrid {
 public:
  WallGrid() = default;
  // Cells are about `cell_size` wide (larger when the walls span a huge area).
  WallGrid(const std::vector<WallSegment>& walls, double cutoff, double cell_size = 0.5);

  // Indices (ascending) of walls within `cutoff` of some point of the cell holding (x, y).
  [[nodiscard]] std::span<const std::uint32_t> near(double x, double y) const;
  [[nodiscard]] double cutoff() const { return cutoff_; }

 private:
  double cutoff_ = 0.0;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  double cell_ = 1.0;
  std::int64_t nx_ = 0;
  std::int64_t ny_ = 0;
  std::vector<std::uint32_t> start_;  // CSR offsets, nx*ny + 1
  std::vector<std::uint32_t> items_;
};

// Distance from point p to segment [a, b] (a == b allowed).
double point_segment_distance(Vec2 p, Vec2 a, Vec2 b);

// Twice the signed area of triangle a, b, c: > 0 when c lies left of a→b.
inline double orient(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// True when moving straight from `from` to `to` would cross or land on the wall [a, b].
// A point cannot be crossed (a == b), and a move starting exactly on the wall is never blocked by
// it, so an agent placed on a wall can always step off. Exact sign tests on doubles: the same
// inputs always give the same answer, which is what makes "never crosses" hold step after step.
bool move_blocked(Vec2 from, Vec2 to, Vec2 a, Vec2 b);

}  // namespace socsim::crowd
