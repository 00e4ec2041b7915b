#include "core/world/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/geometry/planar.hpp"

namespace socsim::world {

namespace {

// Fills the cells whose centres lie inside the polygon (even-odd over outer ring and holes).
template <class Fn>
void scan_fill(const Polygon& poly, Point origin, double res, int width, int height, Fn&& mark) {
  std::vector<Segment> rings = geometry::edges(poly.outer);
  for (const auto& h : poly.holes) {
    const auto e = geometry::edges(h);
    rings.insert(rings.end(), e.begin(), e.end());
  }
  const geometry::Box box = geometry::bounds(poly.outer);
  const int y0 = std::max(0, static_cast<int>(std::floor((box.min.y - origin.y) / res)));
  const int y1 = std::min(height - 1, static_cast<int>(std::ceil((box.max.y - origin.y) / res)));
  std::vector<double> xs;
  for (int iy = y0; iy <= y1; ++iy) {
    const double y = origin.y + (iy + 0.5) * res;
    xs.clear();
    for (const auto& e : rings) {
      if ((e.a.y > y) != (e.b.y > y)) xs.push_back(e.a.x + (y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y));
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      // Cells whose centre x is in [xs[k], xs[k+1]].
      const int ix0 = std::max(0, static_cast<int>(std::ceil((xs[k] - origin.x) / res - 0.5)));
      const int ix1 = std::min(width - 1, static_cast<int>(std::floor((xs[k + 1] - origin.x) / res - 0.5)));
      for (int ix = ix0; ix <= ix1; ++ix) mark(ix, iy);
    }
  }
}

}  // namespace

OccupancyGrid OccupancyGrid::rasterise(const World& world, const GridOptions& options) {
  OccupancyGrid g;
  const geometry::Box box = world.bounds();
  double res = options.resolution > 0 ? options.resolution : 0.1;
  const double margin_cells = 1.0;
  auto dims = [&](double r) {
    const double w = std::ceil(box.width() / r + 2 * margin_cells);
    const double h = std::ceil(box.height() / r + 2 * margin_cells);
    return std::pair<double, double>{std::max(1.0, w), std::max(1.0, h)};
  };
  auto [w, h] = dims(res);
  const double max_cells = static_cast<double>(std::max<std::size_t>(options.max_cells, 1));
  while (w * h > max_cells) {
    res *= std::sqrt(w * h / max_cells) * 1.01;
    std::tie(w, h) = dims(res);
  }
  g.width_ = static_cast<int>(w);
  g.height_ = static_cast<int>(h);
  g.resolution_ = res;
  g.origin_ = {box.min.x - margin_cells * res, box.min.y - margin_cells * res};
  const std::size_t n = static_cast<std::size_t>(g.width_) * static_cast<std::size_t>(g.height_);
  g.blocked_.assign(n, 1);
  g.zone_.assign(n, -1);

  const auto zones = world.zones();
  for (std::size_t z = 0; z < zones.size(); ++z) {
    scan_fill(zones[z].polygon, g.origin_, res, g.width_, g.height_, [&](int ix, int iy) {
      const std::size_t i = g.index({ix, iy});
      if (g.zone_[i] < 0) {
        g.zone_[i] = static_cast<std::int32_t>(z);
        g.blocked_[i] = 0;
      }
    });
  }

  // Walls and the outline block every cell they pass through (half a cell diagonal), and
  // every cell closer than the inflation radius.
  const double touch = 0.5 * res * std::sqrt(2.0) + 1e-12;
  const double reach = std::max(touch, options.inflation);
  auto block_near = [&](const Segment& s) {
    const int x0 =
        std::max(0, static_cast<int>(std::floor((std::min(s.a.x, s.b.x) - reach - g.origin_.x) / res)));
    const int x1 = std::min(
        g.width_ - 1, static_cast<int>(std::floor((std::max(s.a.x, s.b.x) + reach - g.origin_.x) / res)));
    const int y0 =
        std::max(0, static_cast<int>(std::floor((std::min(s.a.y, s.b.y) - reach - g.origin_.y) / res)));
    const int y1 = std::min(
        g.height_ - 1, static_cast<int>(std::floor((std::max(s.a.y, s.b.y) + reach - g.origin_.y) / res)));
    for (int iy = y0; iy <= y1; ++iy) {
      for (int ix = x0; ix <= x1; ++ix) {
        const std::size_t i = g.index({ix, iy});
        if (g.blocked_[i]) continue;
        const double d = geometry::distance(s, g.center({ix, iy}));
        if (d <= touch || d < options.inflation) g.blocked_[i] = 1;
      }
    }
  };
  for (const auto& wall : world.walls()) block_near(wall.segment);
  for (const auto& s : world.outline()) block_near(s);
  return g;
}

std::optional<ZoneId> OccupancyGrid::zone_of(Cell c) const {
  if (!in_bounds(c)) return std::nullopt;
  const std::int32_t z = zone_[index(c)];
  if (z < 0) return std::nullopt;
  return ZoneId(static_cast<std::uint32_t>(z));
}

std::optional<Cell> OccupancyGrid::cell_of(Point p) const {
  const double fx = std::floor((p.x - origin_.x) / resolution_);
  const double fy = std::floor((p.y - origin_.y) / resolution_);
  if (!(fx >= 0 && fy >= 0 && fx < width_ && fy < height_)) return std::nullopt;
  return Cell{static_cast<int>(fx), static_cast<int>(fy)};
}

std::size_t OccupancyGrid::free_count() const {
  return static_cast<std::size_t>(std::count(blocked_.begin(), blocked_.end(), std::uint8_t{0}));
}

std::vector<int> OccupancyGrid::components() const {
  // Runs of free cells along each row, joined (union-find) with the runs they touch in the row
  // below; components are numbered in the order of their first cell in row-major order, as a
  // flood fill started from each unlabelled cell in that order would number them.
  struct Run {
    int y, x0, x1;  // cells x0 .. x1 - 1 of row y
  };
  std::vector<Run> runs;
  std::vector<std::size_t> row_start(static_cast<std::size_t>(height_) + 1, 0);
  for (int y = 0; y < height_; ++y) {
    row_start[static_cast<std::size_t>(y)] = runs.size();
    const std::uint8_t* row = blocked_.data() + index({0, y});
    for (int x = 0; x < width_;) {
      if (row[x]) {
        ++x;
        continue;
      }
      const int x0 = x;
      while (x < width_ && !row[x]) ++x;
      runs.push_back({y, x0, x});
    }
  }
  row_start[static_cast<std::size_t>(height_)] = runs.size();
  std::vector<std::size_t> parent(runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) parent[r] = r;
  auto root = [&parent](std::size_t r) {
    while (parent[r] != r) r = parent[r] = parent[parent[r]];
    return r;
  };
  for (int y = 1; y < height_; ++y) {
    std::size_t below = row_start[static_cast<std::size_t>(y - 1)];
    const std::size_t below_end = row_start[static_cast<std::size_t>(y)];
    for (std::size_t r = row_start[static_cast<std::size_t>(y)];
         r < row_start[static_cast<std::size_t>(y) + 1]; ++r) {
      while (below < below_end && runs[below].x1 <= runs[r].x0) ++below;
      for (std::size_t b = below; b < below_end && runs[b].x0 < runs[r].x1; ++b) {
        const std::size_t ra = root(r), rb = root(b);
        if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
      }
    }
  }
  std::vector<int> label(blocked_.size(), -1);
  std::vector<int> number(runs.size(), -1);
  int next = 0;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    int& n = number[root(r)];
    if (n < 0) n = next++;
    const std::size_t row = index({0, runs[r].y});
    std::fill(label.begin() + static_cast<std::ptrdiff_t>(row + static_cast<std::size_t>(runs[r].x0)),
              label.begin() + static_cast<std::ptrdiff_t>(row + static_cast<std::size_t>(runs[r].x1)), n);
  }
  return label;
}

}  // namespace socsim::world
