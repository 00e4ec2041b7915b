#include "core/geometry/planar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace socsim::geometry {

double length(const Segment& s) {
  return std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
}

double distance(Point a, Point b) {
  return std::hypot(b.x - a.x, b.y - a.y);
}

Point closest_point(const Segment& s, Point p) {
  const double dx = s.b.x - s.a.x;
  const double dy = s.b.y - s.a.y;
  const double len2 = dx * dx + dy * dy;
  if (len2 <= 0.0) return s.a;
  const double t = std::clamp(((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2, 0.0, 1.0);
  return {s.a.x + t * dx, s.a.y + t * dy};
}

double distance(const Segment& s, Point p) {
  return distance(closest_point(s, p), p);
}

namespace {
double cross(Point o, Point a, Point b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
}  // namespace

double distance(const Segment& s, const Segment& t) {
  const double d1 = cross(s.a, s.b, t.a);
  const double d2 = cross(s.a, s.b, t.b);
  const double d3 = cross(t.a, t.b, s.a);
  const double d4 = cross(t.a, t.b, s.b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
  return std::min({distance(s, t.a), distance(s, t.b), distance(t, s.a), distance(t, s.b)});
}

double signed_area(std::span<const Point> ring) {
  double twice = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % n];
    twice += p.x * q.y - q.x * p.y;
  }
  return 0.5 * twice;
}

double area(const Polygon& polygon) {
  double a = std::abs(signed_area(polygon.outer));
  for (const auto& hole : polygon.holes) a -= std::abs(signed_area(hole));
  return a;
}

Point centroid(std::span<const Point> ring) {
  if (ring.empty()) return {};
  const double a = signed_area(ring);
  if (std::abs(a) < 1e-12) {
    Point m;
    for (const Point& p : ring) {
      m.x += p.x;
      m.y += p.y;
    }
    return {m.x / static_cast<double>(ring.size()), m.y / static_cast<double>(ring.size())};
  }
  // Shift to the first vertex to keep the products small (precision far from the origin).
  const Point o = ring[0];
  double cx = 0.0;
  double cy = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point p{ring[i].x - o.x, ring[i].y - o.y};
    const Point q{ring[(i + 1) % n].x - o.x, ring[(i + 1) % n].y - o.y};
    const double c = p.x * q.y - q.x * p.y;
    cx += (p.x + q.x) * c;
    cy += (p.y + q.y) * c;
  }
  return {o.x + cx / (6.0 * a), o.y + cy / (6.0 * a)};
}

Box bounds(std::span<const Point> points) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box b{{inf, inf}, {-inf, -inf}};
  for (const Point& p : points) {
    b.min.x = std::min(b.min.x, p.x);
    b.min.y = std::min(b.min.y, p.y);
    b.max.x = std::max(b.max.x, p.x);
    b.max.y = std::max(b.max.y, p.y);
  }
  return b;
}

Box bounds(const MultiPolygon& polygons) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box b{{inf, inf}, {-inf, -inf}};
  for (const auto& poly : polygons) {
    const Box r = bounds(poly.outer);
    b.min.x = std::min(b.min.x, r.min.x);
    b.min.y = std::min(b.min.y, r.min.y);
    b.max.x = std::max(b.max.x, r.max.x);
    b.max.y = std::max(b.max.y, r.max.y);
  }
  return b;
}

namespace {
// Crossing-number test; boundary handled by the caller.
bool inside_ring(std::span<const Point> ring, Point p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) in = !in;
    }
  }
  return in;
}

bool on_ring(std::span<const Point> ring, Point p, double tol) {
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    if (distance(Segment{ring[j], ring[i]}, p) <= tol) return true;
  }
  return false;
}
}  // namespace

bool contains(const Polygon& polygon, Point p, double boundary_tolerance) {
  if (polygon.outer.size() < 3) return false;
  if (on_ring(polygon.outer, p, boundary_tolerance)) return true;
  if (!inside_ring(polygon.outer, p)) return false;
  for (const auto& hole : polygon.holes) {
    if (hole.size() < 3) continue;
    if (on_ring(hole, p, boundary_tolerance)) return true;
    if (inside_ring(hole, p)) return false;
  }
  return true;
}

std::vector<Segment> edges(std::span<const Point> ring) {
  std::vector<Segment> out;
  if (ring.size() < 2) return out;
  out.reserve(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) out.push_back({ring[i], ring[(i + 1) % ring.size()]});
  return out;
}

Point to_parent(const Pose2& frame, Point p) {
  const Eigen::Vector2d v = Eigen::Rotation2Dd(frame.yaw) * Eigen::Vector2d(p.x, p.y);
  return {v.x() + frame.x, v.y() + frame.y};
}

Pose2 to_parent(const Pose2& frame, const Pose2& p) {
  const Point q = to_parent(frame, Point{p.x, p.y});
  return {q.x, q.y, p.yaw + frame.yaw};
}

}  // namespace socsim::geometry
