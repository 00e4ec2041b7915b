#include "core/geometry/segment_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

// Boost.Geometry 1.74 still includes a header Boost itself marks deprecated; it is not ours to fix.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "core/geometry/planar.hpp"

namespace socsim::geometry {
namespace {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoostPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BoostBox = bg::model::box<BoostPoint>;
using Entry = std::pair<BoostBox, std::size_t>;

double distance(const BoostBox& b, Point p) {
  const double dx = std::max({b.min_corner().get<0>() - p.x, 0.0, p.x - b.max_corner().get<0>()});
  const double dy = std::max({b.min_corner().get<1>() - p.y, 0.0, p.y - b.max_corner().get<1>()});
  return std::hypot(dx, dy);
}

BoostBox box_of(const Segment& s) {
  return {{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)}, {std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)}};
}
}  // namespace

struct SegmentIndex::Tree {
  bgi::rtree<Entry, bgi::rstar<16>> rtree;
};

SegmentIndex::SegmentIndex(std::vector<Segment> segments)
    : segments_(std::move(segments)), tree_(std::make_unique<Tree>()) {
  std::vector<Entry> entries;
  entries.reserve(segments_.size());
  for (std::size_t i = 0; i < segments_.size(); ++i) entries.emplace_back(box_of(segments_[i]), i);
  tree_->rtree = bgi::rtree<Entry, bgi::rstar<16>>(entries);  // the range constructor packs (STR)
}

SegmentIndex::~SegmentIndex() = default;
SegmentIndex::SegmentIndex(SegmentIndex&&) noexcept = default;
SegmentIndex& SegmentIndex::operator=(SegmentIndex&&) noexcept = default;

void SegmentIndex::insert(Segment s) {
  segments_.push_back(s);
  tree_->rtree.insert(Entry(box_of(s), segments_.size() - 1));
}

std::vector<std::size_t> SegmentIndex::within(Point p, double radius) const {
  const BoostBox query{{p.x - radius, p.y - radius}, {p.x + radius, p.y + radius}};
  std::vector<std::size_t> out;
  for (auto it = tree_->rtree.qbegin(bgi::intersects(query)); it != tree_->rtree.qend(); ++it)
    if (distance(segments_[it->second], p) <= radius) out.push_back(it->second);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::size_t> SegmentIndex::within(const Segment& s, double radius) const {
  const BoostBox b = box_of(s);
  const BoostBox query{{b.min_corner().get<0>() - radius, b.min_corner().get<1>() - radius},
                       {b.max_corner().get<0>() + radius, b.max_corner().get<1>() + radius}};
  std::vector<std::size_t> out;
  for (auto it = tree_->rtree.qbegin(bgi::intersects(query)); it != tree_->rtree.qend(); ++it)
    if (distance(segments_[it->second], s) <= radius) out.push_back(it->second);
  std::sort(out.begin(), out.end());
  return out;
}

std::optional<SegmentIndex::Nearest> SegmentIndex::nearest(Point p) const {
  if (segments_.empty()) return std::nullopt;
  // Boxes nearest first: once a box is farther than the best segment found, none can be closer.
  Nearest best{0, std::numeric_limits<double>::infinity()};
  const BoostPoint q{p.x, p.y};
  for (auto it = tree_->rtree.qbegin(bgi::nearest(q, static_cast<unsigned>(segments_.size())));
       it != tree_->rtree.qend(); ++it) {
    if (distance(it->first, p) > best.distance) break;
    const double d = distance(segments_[it->second], p);
    if (d < best.distance || (d == best.distance && it->second < best.index)) best = {it->second, d};
  }
  return best;
}

namespace {

// The parameters t of the points p + t·u (|u| = 1) within r of segment f, as [lo, hi]; lo > hi
// when none. The capsule around f is convex, so the points form one interval: the union of the
// line's intervals in the two end disks and in the band between them.
std::pair<double, double> capsule_interval(Point p, Point u, const Segment& f, double r) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto disk = [&](Point c) {
    const double along = (c.x - p.x) * u.x + (c.y - p.y) * u.y;
    const double across = (c.x - p.x) * u.y - (c.y - p.y) * u.x;
    const double d2 = r * r - across * across;
    if (d2 < 0) return;
    const double s = std::sqrt(d2);
    lo = std::min(lo, along - s);
    hi = std::max(hi, along + s);
  };
  disk(f.a);
  disk(f.b);
  const double fl = length(f);
  if (fl > 0) {
    const Point v{(f.b.x - f.a.x) / fl, (f.b.y - f.a.y) / fl};
    double a = -std::numeric_limits<double>::infinity(), b = -a;
    // min ≤ c0 + t·c1 ≤ max
    const auto clip = [&](double c0, double c1, double min, double max) {
      if (c1 == 0.0) {
        if (c0 < min || c0 > max) a = std::numeric_limits<double>::infinity();
        return;
      }
      double t0 = (min - c0) / c1, t1 = (max - c0) / c1;
      if (t0 > t1) std::swap(t0, t1);
      a = std::max(a, t0);
      b = std::min(b, t1);
    };
    clip((p.x - f.a.x) * v.x + (p.y - f.a.y) * v.y, u.x * v.x + u.y * v.y, 0.0, fl);
    clip((p.x - f.a.x) * v.y - (p.y - f.a.y) * v.x, u.x * v.y - u.y * v.x, -r, r);
    if (a <= b) {
      lo = std::min(lo, a);
      hi = std::max(hi, b);
    }
  }
  return {lo, hi};
}

struct Piece {
  Segment s;
  std::size_t edge = 0;
  bool from_start = false, to_end = false;  // reaches its edge's first / last point
};

bool continues(const Segment& x, const Segment& y) {
  const double ux = x.b.x - x.a.x, uy = x.b.y - x.a.y, vx = y.b.x - y.a.x, vy = y.b.y - y.a.y;
  const double lu = std::hypot(ux, uy), lv = std::hypot(vx, vy);
  return std::abs(ux * vy - uy * vx) <= 1e-9 * lu * lv && (ux * vx + uy * vy) > 0.0;
}

}  // namespace

std::vector<Segment> pieces_near(const std::vector<std::vector<Point>>& rings, const SegmentIndex& other,
                                 double tolerance) {
  std::vector<Segment> out;
  for (const auto& ring : rings) {
    const std::size_t n = ring.size();
    std::vector<Piece> pieces;
    for (std::size_t i = 0; i < n && n >= 2; ++i) {
      const Segment e{ring[i], ring[(i + 1) % n]};
      const double len = length(e);
      if (!(len > 0)) continue;
      const Point u{(e.b.x - e.a.x) / len, (e.b.y - e.a.y) / len};
      std::vector<std::pair<double, double>> spans;
      for (std::size_t k : other.within(e, tolerance)) {
        auto [lo, hi] = capsule_interval(e.a, u, other.segment(k), tolerance);
        lo = std::max(lo, 0.0);
        hi = std::min(hi, len);
        if (lo <= hi) spans.emplace_back(lo, hi);
      }
      std::sort(spans.begin(), spans.end());
      for (std::size_t k = 0; k < spans.size();) {
        auto [lo, hi] = spans[k];
        for (++k; k < spans.size() && spans[k].first <= hi; ++k) hi = std::max(hi, spans[k].second);
        const bool from_start = lo <= 0.0, to_end = hi >= len;
        const Point a = from_start ? e.a : Point{e.a.x + u.x * lo, e.a.y + u.y * lo};
        const Point b = to_end ? e.b : Point{e.a.x + u.x * hi, e.a.y + u.y * hi};
        pieces.push_back({{a, b}, i, from_start, to_end});
      }
    }
    // Join pieces that run on straight through a vertex into one segment.
    std::vector<Piece> joined;
    for (const Piece& p : pieces) {
      if (!joined.empty()) {
        Piece& last = joined.back();
        if (last.to_end && p.from_start && p.edge == last.edge + 1 && continues(last.s, p.s)) {
          last.s.b = p.s.b;
          last.edge = p.edge;
          last.to_end = p.to_end;
          continue;
        }
      }
      joined.push_back(p);
    }
    if (joined.size() > 1) {  // across the ring's first point
      Piece& last = joined.back();
      const Piece& first = joined.front();
      if (last.to_end && last.edge == n - 1 && first.from_start && first.edge == 0 &&
          continues(last.s, first.s)) {
        joined.front().s.a = last.s.a;
        joined.pop_back();
      }
    }
    for (const Piece& p : joined)
      if (length(p.s) > tolerance) out.push_back(p.s);
  }
  return out;
}

}  // namespace socsim::geometry
