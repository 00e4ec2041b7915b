#include "core/world/geodesic.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/geometry/planar.hpp"

namespace socsim::world {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();

// The marching front: a 4-ary min-heap of cells keyed by their trial distance, with each cell's
// place recorded so that a lowered distance moves the cell up instead of adding a second entry.
// Ties go to the lower cell index, so the order (and every distance) is reproducible. Each entry
// carries its key, so sifting compares neighbouring entries instead of reading a distance array
// at random (most of the march's time on large grids was those cache misses).
class Front {
 public:
  explicit Front(std::size_t cells) : place_(cells, kAbsent) {}
  [[nodiscard]] bool empty() const { return heap_.empty(); }

  // Adds the cell with `key` or, when it is already waiting, moves it up to its (lowered) key.
  void push_or_lower(std::uint32_t cell, double key) {
    std::size_t at = place_[cell];
    if (at == kAbsent) {
      at = heap_.size();
      heap_.push_back({key, cell});
    }
    up(at, {key, cell});
  }

  std::uint32_t pop() {
    const std::uint32_t top = heap_.front().cell;
    place_[top] = kDone;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) down(0, last);
    return top;
  }

 private:
  struct Entry {
    double key;
    std::uint32_t cell;
  };
  static constexpr std::uint32_t kAbsent = UINT32_MAX;
  static constexpr std::uint32_t kDone = UINT32_MAX - 1;

  [[nodiscard]] static bool before(const Entry& a, const Entry& b) {
    return a.key < b.key || (a.key == b.key && a.cell < b.cell);
  }
  void put(std::size_t at, const Entry& e) {
    heap_[at] = e;
    place_[e.cell] = static_cast<std::uint32_t>(at);
  }
  void up(std::size_t at, const Entry& e) {
    while (at > 0) {
      const std::size_t parent = (at - 1) / 4;
      if (!before(e, heap_[parent])) break;
      put(at, heap_[parent]);
      at = parent;
    }
    put(at, e);
  }
  void down(std::size_t at, const Entry& e) {
    const std::size_t n = heap_.size();
    while (true) {
      const std::size_t first = 4 * at + 1;
      if (first >= n) break;
      std::size_t best = first;
      const std::size_t last = std::min(first + 4, n);
      for (std::size_t c = first + 1; c < last; ++c)
        if (before(heap_[c], heap_[best])) best = c;
      if (!before(heap_[best], e)) break;
      put(at, heap_[best]);
      at = best;
    }
    put(at, e);
  }

  std::vector<std::uint32_t> place_;
  std::vector<Entry> heap_;
};

}  // namespace

GeodesicField GeodesicField::from_points(const OccupancyGrid& grid, std::span<const Point> sources) {
  std::vector<std::pair<Cell, float>> seeds;
  // First-order marching from a single cell overestimates off-axis distances (≈3 % at 22°);
  // seeding exact distances on a small disk around the source removes most of that, when
  // the whole disk is free (so no straight line crosses a wall).
  constexpr int kSeedRadius = 4;
  for (const Point& p : sources) {
    const auto c = grid.cell_of(p);
    if (!c || grid.blocked(*c)) continue;
    bool disk_free = true;
    for (int dy = -kSeedRadius; dy <= kSeedRadius && disk_free; ++dy) {
      for (int dx = -kSeedRadius; dx <= kSeedRadius && disk_free; ++dx) {
        if (dx * dx + dy * dy <= kSeedRadius * kSeedRadius) disk_free = !grid.blocked({c->x + dx, c->y + dy});
      }
    }
    const int r = disk_free ? kSeedRadius : 0;
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        if (dx * dx + dy * dy > r * r) continue;
        const Cell n{c->x + dx, c->y + dy};
        seeds.emplace_back(n, static_cast<float>(geometry::distance(p, grid.center(n))));
      }
    }
  }
  GeodesicField f;
  f.march(grid, std::move(seeds));
  return f;
}

GeodesicField GeodesicField::from_region(const OccupancyGrid& grid, const Polygon& region) {
  std::vector<std::pair<Cell, float>> seeds;
  const geometry::Box box = geometry::bounds(region.outer);
  const auto lo = grid.cell_of(box.min).value_or(Cell{0, 0});
  const auto hi = grid.cell_of(box.max).value_or(Cell{grid.width() - 1, grid.height() - 1});
  for (int y = std::max(0, lo.y); y <= std::min(grid.height() - 1, hi.y); ++y) {
    for (int x = std::max(0, lo.x); x <= std::min(grid.width() - 1, hi.x); ++x) {
      const Cell c{x, y};
      if (!grid.blocked(c) && geometry::contains(region, grid.center(c))) seeds.emplace_back(c, 0.0f);
    }
  }
  GeodesicField f;
  f.march(grid, std::move(seeds));
  return f;
}

GeodesicField GeodesicField::from_cells(const OccupancyGrid& grid, std::span<const Cell> cells) {
  std::vector<std::pair<Cell, float>> seeds;
  for (const Cell& c : cells) {
    if (!grid.blocked(c)) seeds.emplace_back(c, 0.0f);
  }
  GeodesicField f;
  f.march(grid, std::move(seeds));
  return f;
}

void GeodesicField::march(const OccupancyGrid& grid, std::vector<std::pair<Cell, float>> seeds) {
  width_ = grid.width();
  height_ = grid.height();
  resolution_ = grid.resolution();
  origin_ = grid.origin();
  const std::size_t n = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  values_.assign(n, kInf);

  // Work on a copy padded by one blocked cell on every side: no bounds checks in the loop.
  // `known` holds accepted distances (+inf until accepted), so the upwind update reads four
  // neighbours without branching on their state.
  const int pw = width_ + 2;
  const std::size_t pn = static_cast<std::size_t>(pw) * static_cast<std::size_t>(height_ + 2);
  std::vector<std::uint8_t> open(pn, 0);  // free and not yet accepted
  std::vector<double> known(pn, static_cast<double>(kInf));
  std::vector<double> trial(pn, static_cast<double>(kInf));
  const auto blocked = grid.blocked_cells();
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
      open[static_cast<std::size_t>(y + 1) * static_cast<std::size_t>(pw) + static_cast<std::size_t>(x + 1)] =
          blocked[i] ? 0 : 1;
    }
  }
  const double h = resolution_;
  const double two_h2 = 2.0 * h * h;

  Front front(pn);
  auto padded = [pw](Cell c) {
    return static_cast<std::size_t>(c.y + 1) * static_cast<std::size_t>(pw) +
           static_cast<std::size_t>(c.x + 1);
  };
  for (const auto& [c, d] : seeds) {
    const std::size_t i = padded(c);
    if (d < trial[i]) {
      trial[i] = d;
      front.push_or_lower(static_cast<std::uint32_t>(i), d);
    }
  }
  has_source_ = !front.empty();
  const std::size_t stride = static_cast<std::size_t>(pw);

  while (!front.empty()) {
    const std::size_t i = front.pop();
    if (!open[i]) continue;  // a blocked seed
    open[i] = 0;
    known[i] = trial[i];
    const std::size_t nbrs[4] = {i - 1, i + 1, i - stride, i + stride};
    for (const std::size_t j : nbrs) {
      if (!open[j]) continue;
      const double a = std::min(known[j - 1], known[j + 1]);
      const double b = std::min(known[j - stride], known[j + stride]);
      const double lo = std::min(a, b);
      const double hi = std::max(a, b);
      const double diff = hi - lo;
      const double t = diff >= h ? lo + h : 0.5 * (lo + hi + std::sqrt(two_h2 - diff * diff));
      if (t < trial[j]) {
        trial[j] = t;
        front.push_or_lower(static_cast<std::uint32_t>(j), t);
      }
    }
  }
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      values_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)] =
          static_cast<float>(known[padded({x, y})]);
    }
  }
}

float GeodesicField::at(Cell c) const {
  if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_) return kInf;
  return values_[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) +
                 static_cast<std::size_t>(c.x)];
}

std::optional<double> GeodesicField::distance(Point p) const {
  // Bilinear interpolation between the four cell centres around p, renormalised over the
  // finite ones (so points next to a wall still get a value).
  const double gx = (p.x - origin_.x) / resolution_ - 0.5;
  const double gy = (p.y - origin_.y) / resolution_ - 0.5;
  if (!(gx >= -0.5 && gy >= -0.5 && gx <= width_ - 0.5 && gy <= height_ - 0.5)) return std::nullopt;
  const int x0 = static_cast<int>(std::floor(gx));
  const int y0 = static_cast<int>(std::floor(gy));
  const double fx = gx - x0;
  const double fy = gy - y0;
  double sum = 0.0;
  double weight = 0.0;
  for (int dy = 0; dy <= 1; ++dy) {
    for (int dx = 0; dx <= 1; ++dx) {
      const float v = at({x0 + dx, y0 + dy});
      if (!std::isfinite(v)) continue;
      const double wgt = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
      sum += wgt * v;
      weight += wgt;
    }
  }
  if (weight <= 1e-12) {
    // p sits on a cell centre whose own value decides.
    const float v = at({static_cast<int>(std::floor(gx + 0.5)), static_cast<int>(std::floor(gy + 0.5))});
    if (!std::isfinite(v)) return std::nullopt;
    return static_cast<double>(v);
  }
  return sum / weight;
}

std::optional<Point> GeodesicField::descent(Point p) const {
  const double gx = (p.x - origin_.x) / resolution_;
  const double gy = (p.y - origin_.y) / resolution_;
  if (!(gx >= 0 && gy >= 0 && gx < width_ && gy < height_)) return std::nullopt;
  const Cell c{static_cast<int>(gx), static_cast<int>(gy)};
  const float here = at(c);
  if (!std::isfinite(here)) return std::nullopt;
  // One-sided differences towards the lower finite neighbour on each axis (central where both are finite).
  auto axis = [&](Cell lo, Cell hi) -> double {
    const float a = at(lo);
    const float b = at(hi);
    const bool fa = std::isfinite(a);
    const bool fb = std::isfinite(b);
    if (fa && fb) return (static_cast<double>(b) - a) / (2.0 * resolution_);
    if (fa) return std::max(0.0, static_cast<double>(here) - a) / resolution_;
    if (fb) return std::min(0.0, static_cast<double>(b) - here) / resolution_;
    return 0.0;
  };
  const double dx = axis({c.x - 1, c.y}, {c.x + 1, c.y});
  const double dy = axis({c.x, c.y - 1}, {c.x, c.y + 1});
  const double len = std::sqrt(dx * dx + dy * dy);
  if (len < 1e-9) return std::nullopt;
  return Point{-dx / len, -dy / len};
}

}  // namespace socsim::world
