#include "core/crowd/wall_grid.hpp"

#include <algorithm>
#include <cmath>

namespace socsim::crowd {
namespace {

bool segments_intersect(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  const double o1 = orient(p, q, a);
  const double o2 = orient(p, q, b);
  const double o3 = orient(a, b, p);
  const double o4 = orient(a, b, q);
  return ((o1 <= 0 && o2 >= 0) || (o1 >= 0 && o2 <= 0)) && ((o3 <= 0 && o4 >= 0) || (o3 >= 0 && o4 <= 0)) &&
         !(o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0 &&  // collinear: need overlapping extents
           (std::max(p.x, q.x) < std::min(a.x, b.x) || std::max(a.x, b.x) < std::min(p.x, q.x) ||
            std::max(p.y, q.y) < std::min(a.y, b.y) || std::max(a.y, b.y) < std::min(p.y, q.y)));
}

// Distance between segment [a, b] and the axis-aligned box [x0, x1] × [y0, y1].
double segment_box_distance(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) {
  auto inside = [&](Vec2 p) { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; };
  if (inside(a) || inside(b)) return 0.0;
  const Vec2 c[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (int i = 0; i < 4; ++i)
    if (segments_intersect(a, b, c[i], c[(i + 1) % 4])) return 0.0;
  double d = 1e300;
  for (int i = 0; i < 4; ++i) {
    d = std::min(d, point_segment_distance(c[i], a, b));
    d = std::min(d, point_segment_distance(a, c[i], c[(i + 1) % 4]));
    d = std::min(d, point_segment_distance(b, c[i], c[(i + 1) % 4]));
  }
  return d;
}

}  // namespace

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double ux = b.x - a.x;
  const double uy = b.y - a.y;
  const double len2 = ux * ux + uy * uy;
  double t = 0.0;
  if (len2 > 0.0) t = std::clamp(((p.x - a.x) * ux + (p.y - a.y) * uy) / len2, 0.0, 1.0);
  const double dx = p.x - (a.x + t * ux);
  const double dy = p.y - (a.y + t * uy);
  return std::sqrt(dx * dx + dy * dy);
}

bool move_blocked(Vec2 from, Vec2 to, Vec2 a, Vec2 b) {
  if (a == b) return false;
  const double o1 = orient(a, b, from);
  const double o2 = orient(a, b, to);
  if (o1 == 0.0) {
    // Starting on the wall's line: blocked only by sliding along the line into the wall itself.
    if (o2 != 0.0) return false;
    const double ux = b.x - a.x;
    const double uy = b.y - a.y;
    const double len2 = ux * ux + uy * uy;
    const double s_from = (from.x - a.x) * ux + (from.y - a.y) * uy;
    const double s_to = (to.x - a.x) * ux + (to.y - a.y) * uy;
    const bool from_inside = s_from >= 0.0 && s_from <= len2;
    const bool to_inside = s_to >= 0.0 && s_to <= len2;
    const bool passes = (s_from < 0.0 && s_to > len2) || (s_to < 0.0 && s_from > len2);
    return !from_inside && (to_inside || passes);
  }
  if ((o1 > 0.0 && o2 > 0.0) || (o1 < 0.0 && o2 < 0.0)) return false;
  const double o3 = orient(from, to, a);
  const double o4 = orient(from, to, b);
  return (o3 <= 0.0 && o4 >= 0.0) || (o3 >= 0.0 && o4 <= 0.0);
}

WallGrid::WallGrid(const std::vector<WallSegment>& walls, double cutoff, double cell_size) : cutoff_(cutoff) {
  if (walls.empty()) return;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const WallSegment& w : walls) {
    x0 = std::min({x0, w.a.x, w.b.x});
    y0 = std::min({y0, w.a.y, w.b.y});
    x1 = std::max({x1, w.a.x, w.b.x});
    y1 = std::max({y1, w.a.y, w.b.y});
  }
  x0 -= cutoff;
  y0 -= cutoff;
  x1 += cutoff;
  y1 += cutoff;
  // At most ~4M cells: grow the cells for very large worlds.
  constexpr double kMaxCells = 4.0e6;
  cell_ = std::max(cell_size, std::sqrt((x1 - x0) * (y1 - y0) / kMaxCells));
  origin_x_ = x0;
  origin_y_ = y0;
  nx_ = static_cast<std::int64_t>((x1 - x0) / cell_) + 1;
  ny_ = static_cast<std::int64_t>((y1 - y0) / cell_) + 1;
  const auto cells = static_cast<std::size_t>(nx_ * ny_);

  // Two passes (count, then fill) over the cells each wall's box touches.
  std::vector<std::uint32_t> count(cells + 1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> hits;  // (cell, wall)
  for (std::uint32_t w = 0; w < walls.size(); ++w) {
    const WallSegment& s = walls[w];
    const auto cx0 = static_cast<std::int64_t>((std::min(s.a.x, s.b.x) - cutoff - x0) / cell_);
    const auto cy0 = static_cast<std::int64_t>((std::min(s.a.y, s.b.y) - cutoff - y0) / cell_);
    const auto cx1 = static_cast<std::int64_t>((std::max(s.a.x, s.b.x) + cutoff - x0) / cell_);
    const auto cy1 = static_cast<std::int64_t>((std::max(s.a.y, s.b.y) + cutoff - y0) / cell_);
    for (std::int64_t cy = std::max<std::int64_t>(cy0, 0); cy <= std::min(cy1, ny_ - 1); ++cy) {
      for (std::int64_t cx = std::max<std::int64_t>(cx0, 0); cx <= std::min(cx1, nx_ - 1); ++cx) {
        const double bx0 = x0 + static_cast<double>(cx) * cell_;
        const double by0 = y0 + static_cast<double>(cy) * cell_;
        if (segment_box_distance(s.a, s.b, bx0, by0, bx0 + cell_, by0 + cell_) <= cutoff) {
          hits.emplace_back(static_cast<std::uint32_t>(cy * nx_ + cx), w);
          ++count[static_cast<std::size_t>(cy * nx_ + cx) + 1];
        }
      }
    }
  }
  for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
  start_ = count;
  items_.resize(hits.size());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (const auto& [cell, wall] : hits) items_[fill[cell]++] = wall;  // walls ascending per cell
}

std::span<const std::uint32_t> WallGrid::near(double x, double y) const {
  if (nx_ == 0) return {};
  const double fx = (x - origin_x_) / cell_;
  const double fy = (y - origin_y_) / cell_;
  if (!(fx >= 0.0 && fy >= 0.0 && fx < static_cast<double>(nx_) && fy < static_cast<double>(ny_))) return {};
  const auto c =
      static_cast<std::size_t>(static_cast<std::int64_t>(fy) * nx_ + static_cast<std::int64_t>(fx));
  return {items_.data() + start_[c], items_.data() + start_[c + 1]};
}

}  // namespace socsim::crowd
