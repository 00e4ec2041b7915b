#include "core/geometry/hull.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry/planar.hpp"

namespace socsim::geometry {

double diameter(std::span<const Point> points) {
  std::vector<Point> pts(points.begin(), points.end());
  std::sort(pts.begin(), pts.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 2) return 0.0;
  const auto cross = [](Point o, Point a, Point b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  // Andrew's monotone chain, counter-clockwise, collinear points dropped.
  std::vector<Point> hull(2 * pts.size());
  std::size_t k = 0;
  for (const Point& p : pts) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  const std::size_t h = hull.size();
  double best = 0.0;
  if (h <= 64) {
    for (std::size_t i = 0; i < h; ++i)
      for (std::size_t j = i + 1; j < h; ++j) best = std::max(best, distance(hull[i], hull[j]));
    return best;
  }
  // Rotating calipers: for each hull edge, the vertex farthest from its line.
  std::size_t j = 1;
  for (std::size_t i = 0; i < h; ++i) {
    const std::size_t ni = (i + 1) % h;
    while (std::abs(cross(hull[i], hull[ni], hull[(j + 1) % h])) >
           std::abs(cross(hull[i], hull[ni], hull[j])))
      j = (j + 1) % h;
    best = std::max({best, distance(hull[i], hull[j]), distance(hull[ni], hull[j])});
  }
  return best;
}

}  // namespace socsim::geometry
