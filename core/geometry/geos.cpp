#include "core/geometry/geos.hpp"

#include <geos_c.h>

#include <cmath>
#include <cstdarg>
#include <utility>

namespace socsim::geometry {

struct Geos::Impl {
  GEOSContextHandle_t handle = nullptr;
  std::string last_error;

  struct Deleter {
    GEOSContextHandle_t handle;
    void operator()(GEOSGeometry* g) const {
      if (g) GEOSGeom_destroy_r(handle, g);
    }
  };
  using Geom = std::unique_ptr<GEOSGeometry, Deleter>;

  static void on_error(const char* message, void* userdata) {
    static_cast<Impl*>(userdata)->last_error = message ? message : "unknown GEOS error";
  }
  static void on_notice(const char* /*message*/, void* /*userdata*/) {}

  Impl() {
    handle = GEOS_init_r();
    if (!handle) throw GeosError("GEOS_init_r failed");
    GEOSContext_setErrorMessageHandler_r(handle, &Impl::on_error, this);
    GEOSContext_setNoticeMessageHandler_r(handle, &Impl::on_notice, this);
  }
  ~Impl() { GEOS_finish_r(handle); }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  Geom own(GEOSGeometry* g, const char* what) {
    if (!g) {
      std::string msg = std::string("GEOS ") + what + " failed";
      if (!last_error.empty()) msg += ": " + last_error;
      last_error.clear();
      throw GeosError(msg);
    }
    return Geom(g, Deleter{handle});
  }

  GEOSCoordSequence* coords(std::span<const Point> pts, bool close) {
    const auto n = static_cast<unsigned>(pts.size() + (close ? 1 : 0));
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(handle, n, 2);
    if (!seq) throw GeosError("GEOSCoordSeq_create_r failed");
    for (unsigned i = 0; i < pts.size(); ++i) GEOSCoordSeq_setXY_r(handle, seq, i, pts[i].x, pts[i].y);
    if (close && !pts.empty()) GEOSCoordSeq_setXY_r(handle, seq, n - 1, pts[0].x, pts[0].y);
    return seq;
  }

  GEOSGeometry* ring(std::span<const Point> pts) {
    GEOSGeometry* r = GEOSGeom_createLinearRing_r(handle, coords(pts, true));
    if (!r) throw GeosError("GEOS: cannot make a ring: " + last_error);
    return r;
  }

  Geom polygon(const Polygon& p) {
    GEOSGeometry* shell = ring(p.outer);
    std::vector<GEOSGeometry*> holes;
    holes.reserve(p.holes.size());
    for (const auto& h : p.holes) holes.push_back(ring(h));
    return own(GEOSGeom_createPolygon_r(handle, shell, holes.data(), static_cast<unsigned>(holes.size())),
               "createPolygon");
  }

  Geom multi(const MultiPolygon& m) {
    std::vector<GEOSGeometry*> parts;
    parts.reserve(m.size());
    for (const auto& p : m) parts.push_back(polygon(p).release());
    return own(GEOSGeom_createCollection_r(handle, GEOS_MULTIPOLYGON, parts.data(),
                                           static_cast<unsigned>(parts.size())),
               "createCollection");
  }

  Geom lines(std::span<const Segment> segs) {
    std::vector<GEOSGeometry*> parts;
    parts.reserve(segs.size());
    for (const auto& s : segs) {
      const Point pts[2] = {s.a, s.b};
      parts.push_back(
          own(GEOSGeom_createLineString_r(handle, coords(pts, false)), "createLineString").release());
    }
    return own(GEOSGeom_createCollection_r(handle, GEOS_MULTILINESTRING, parts.data(),
                                           static_cast<unsigned>(parts.size())),
               "createCollection");
  }

  Geom point(Point p) { return own(GEOSGeom_createPointFromXY_r(handle, p.x, p.y), "createPoint"); }

  std::vector<Point> read_ring(const GEOSGeometry* r, bool drop_closing) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(handle, r);
    unsigned n = 0;
    GEOSCoordSeq_getSize_r(handle, seq, &n);
    std::vector<Point> pts;
    pts.reserve(n);
    for (unsigned i = 0; i < n; ++i) {
      Point p;
      GEOSCoordSeq_getXY_r(handle, seq, i, &p.x, &p.y);
      pts.push_back(p);
    }
    if (drop_closing && pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
    return pts;
  }

  void collect_polygons(const GEOSGeometry* g, MultiPolygon& out) {
    const int type = GEOSGeomTypeId_r(handle, g);
    if (type == GEOS_POLYGON) {
      if (GEOSisEmpty_r(handle, g)) return;
      Polygon p;
      p.outer = read_ring(GEOSGetExteriorRing_r(handle, g), true);
      const int holes = GEOSGetNumInteriorRings_r(handle, g);
      for (int i = 0; i < holes; ++i)
        p.holes.push_back(read_ring(GEOSGetInteriorRingN_r(handle, g, i), true));
      out.push_back(std::move(p));
    } else if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
      const int n = GEOSGetNumGeometries_r(handle, g);
      for (int i = 0; i < n; ++i) collect_polygons(GEOSGetGeometryN_r(handle, g, i), out);
    }
  }

  MultiPolygon to_multi(const Geom& g) {
    MultiPolygon out;
    collect_polygons(g.get(), out);
    return out;
  }

  void collect_lines(const GEOSGeometry* g, std::vector<std::vector<Point>>& out) {
    const int type = GEOSGeomTypeId_r(handle, g);
    if (type == GEOS_LINESTRING || type == GEOS_LINEARRING) {
      if (!GEOSisEmpty_r(handle, g)) out.push_back(read_ring(g, false));
    } else if (type == GEOS_MULTILINESTRING || type == GEOS_GEOMETRYCOLLECTION) {
      const int n = GEOSGetNumGeometries_r(handle, g);
      for (int i = 0; i < n; ++i) collect_lines(GEOSGetGeometryN_r(handle, g, i), out);
    }
  }

  // Lines → maximal straight segments: consecutive collinear pieces are joined.
  std::vector<Segment> straight_segments(const Geom& g) {
    Geom merged = own(GEOSLineMerge_r(handle, g.get()), "LineMerge");
    std::vector<std::vector<Point>> polylines;
    collect_lines(merged.get(), polylines);
    std::vector<Segment> out;
    for (const auto& line : polylines) {
      std::vector<Point> pts;
      for (const Point& p : line) {
        if (!pts.empty() && pts.back() == p) continue;
        pts.push_back(p);
      }
      if (pts.size() < 2) continue;
      Point start = pts[0];
      for (std::size_t i = 1; i < pts.size(); ++i) {
        const bool last = i + 1 == pts.size();
        if (!last) {
          const Point& b = pts[i];
          const Point& c = pts[i + 1];
          const double ux = b.x - start.x, uy = b.y - start.y, vx = c.x - b.x, vy = c.y - b.y;
          const double lu = std::hypot(ux, uy), lv = std::hypot(vx, vy);
          const bool collinear = std::abs(ux * vy - uy * vx) <= 1e-9 * lu * lv && (ux * vx + uy * vy) > 0.0;
          if (collinear) continue;
        }
        out.push_back({start, pts[i]});
        start = pts[i];
      }
    }
    return out;
  }
};

Geos::Geos() : impl_(std::make_unique<Impl>()) {}
Geos::~Geos() = default;

Validity Geos::validity(const Polygon& polygon) const {
  auto check_ring = [](const std::vector<Point>& ring, const char* which) -> std::optional<Validity> {
    for (const Point& p : ring) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        return Validity{false, std::string("non-finite coordinate in ") + which, std::nullopt};
    }
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (ring[i] != ring[(i + 1) % ring.size()]) ++distinct;
    }
    if (distinct < 3)
      return Validity{false, std::string(which) + " needs at least 3 distinct points", std::nullopt};
    return std::nullopt;
  };
  if (auto bad = check_ring(polygon.outer, "outer ring")) return *bad;
  for (const auto& h : polygon.holes) {
    if (auto bad = check_ring(h, "hole")) return *bad;
  }
  auto g = impl_->polygon(polygon);
  char* reason = nullptr;
  GEOSGeometry* location = nullptr;
  const char ok = GEOSisValidDetail_r(impl_->handle, g.get(), 0, &reason, &location);
  Validity v;
  if (ok == 1) return v;
  v.valid = false;
  if (ok == 2) {
    v.reason = "GEOS could not check validity: " + impl_->last_error;
    return v;
  }
  if (reason) {
    v.reason = reason;
    GEOSFree_r(impl_->handle, reason);
  }
  if (location) {
    Point p;
    if (GEOSGeomGetX_r(impl_->handle, location, &p.x) == 1 &&
        GEOSGeomGetY_r(impl_->handle, location, &p.y) == 1) {
      v.location = p;
    }
    GEOSGeom_destroy_r(impl_->handle, location);
  }
  return v;
}

double Geos::area(const MultiPolygon& shape) const {
  auto g = impl_->multi(shape);
  double a = 0.0;
  if (!GEOSArea_r(impl_->handle, g.get(), &a)) throw GeosError("GEOS area failed: " + impl_->last_error);
  return a;
}

MultiPolygon Geos::unite(const MultiPolygon& shapes) const {
  auto g = impl_->multi(shapes);
  return impl_->to_multi(impl_->own(GEOSUnaryUnion_r(impl_->handle, g.get()), "union"));
}

MultiPolygon Geos::unite(const MultiPolygon& a, const MultiPolygon& b) const {
  auto ga = impl_->multi(a);
  auto gb = impl_->multi(b);
  return impl_->to_multi(impl_->own(GEOSUnion_r(impl_->handle, ga.get(), gb.get()), "union"));
}

MultiPolygon Geos::intersection(const MultiPolygon& a, const MultiPolygon& b) const {
  auto ga = impl_->multi(a);
  auto gb = impl_->multi(b);
  return impl_->to_multi(impl_->own(GEOSIntersection_r(impl_->handle, ga.get(), gb.get()), "intersection"));
}

MultiPolygon Geos::difference(const MultiPolygon& a, const MultiPolygon& b) const {
  auto ga = impl_->multi(a);
  auto gb = impl_->multi(b);
  return impl_->to_multi(impl_->own(GEOSDifference_r(impl_->handle, ga.get(), gb.get()), "difference"));
}

MultiPolygon Geos::buffer(const MultiPolygon& shape, double distance) const {
  auto g = impl_->multi(shape);
  return impl_->to_multi(impl_->own(GEOSBuffer_r(impl_->handle, g.get(), distance, 8), "buffer"));
}

bool Geos::covers(const MultiPolygon& shape, Point p) const {
  auto g = impl_->multi(shape);
  auto pt = impl_->point(p);
  const char r = GEOSCovers_r(impl_->handle, g.get(), pt.get());
  if (r == 2) throw GeosError("GEOS covers failed: " + impl_->last_error);
  return r == 1;
}

double Geos::distance(const MultiPolygon& shape, Point p) const {
  auto g = impl_->multi(shape);
  auto pt = impl_->point(p);
  double d = 0.0;
  if (!GEOSDistance_r(impl_->handle, g.get(), pt.get(), &d))
    throw GeosError("GEOS distance failed: " + impl_->last_error);
  return d;
}

double Geos::distance(const MultiPolygon& a, const MultiPolygon& b) const {
  auto ga = impl_->multi(a);
  auto gb = impl_->multi(b);
  double d = 0.0;
  if (!GEOSDistance_r(impl_->handle, ga.get(), gb.get(), &d))
    throw GeosError("GEOS distance failed: " + impl_->last_error);
  return d;
}

std::vector<Segment> Geos::shared_boundary(const Polygon& a, const Polygon& b, double tolerance) const {
  auto ga = impl_->polygon(a);
  auto gb = impl_->polygon(b);
  auto ba = impl_->own(GEOSBoundary_r(impl_->handle, ga.get()), "boundary");
  auto bb = impl_->own(GEOSBoundary_r(impl_->handle, gb.get()), "boundary");
  Impl::Geom shared = [&] {
    if (tolerance <= 0.0)
      return impl_->own(GEOSIntersection_r(impl_->handle, ba.get(), bb.get()), "intersection");
    auto band = impl_->own(GEOSBuffer_r(impl_->handle, bb.get(), tolerance, 4), "buffer");
    return impl_->own(GEOSIntersection_r(impl_->handle, ba.get(), band.get()), "intersection");
  }();
  // Keep only the linear parts: touching corners are not a shared boundary.
  std::vector<std::vector<Point>> polylines;
  impl_->collect_lines(shared.get(), polylines);
  std::vector<Segment> pieces;
  for (const auto& line : polylines) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) pieces.push_back({line[i], line[i + 1]});
  }
  if (pieces.empty()) return {};
  auto merged = impl_->lines(pieces);
  std::vector<Segment> out;
  for (const auto& s : impl_->straight_segments(merged)) {
    if (std::hypot(s.b.x - s.a.x, s.b.y - s.a.y) > tolerance) out.push_back(s);
  }
  return out;
}

std::vector<Segment> Geos::boundary_segments(const MultiPolygon& shapes) const {
  std::vector<Segment> edges;
  for (const auto& p : shapes) {
    auto add_ring = [&](const std::vector<Point>& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
    };
    add_ring(p.outer);
    for (const auto& h : p.holes) add_ring(h);
  }
  if (edges.empty()) return {};
  auto g = impl_->lines(edges);
  auto noded = impl_->own(GEOSUnaryUnion_r(impl_->handle, g.get()), "union");
  return impl_->straight_segments(noded);
}

double Geos::length_outside(std::span<const Segment> segments, const MultiPolygon& shape,
                            double tolerance) const {
  if (segments.empty()) return 0.0;
  auto g = impl_->lines(segments);
  auto s = impl_->multi(shape);
  auto band = impl_->own(GEOSBuffer_r(impl_->handle, s.get(), tolerance, 4), "buffer");
  auto rest = impl_->own(GEOSDifference_r(impl_->handle, g.get(), band.get()), "difference");
  double len = 0.0;
  if (!GEOSLength_r(impl_->handle, rest.get(), &len))
    throw GeosError("GEOS length failed: " + impl_->last_error);
  return len;
}

MultiPolygon Geos::polygonize(std::span<const Segment> segments) const {
  if (segments.empty()) return {};
  auto g = impl_->lines(segments);
  auto noded = impl_->own(GEOSUnaryUnion_r(impl_->handle, g.get()), "union");
  const GEOSGeometry* parts[] = {noded.get()};
  auto faces = impl_->own(GEOSPolygonize_r(impl_->handle, parts, 1), "polygonize");
  return impl_->to_multi(faces);
}

}  // namespace socsim::geometry
