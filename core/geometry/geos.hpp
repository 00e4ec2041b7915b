#pragma once
// Polygon operations (validity with reason, area, union, intersection, difference, shared
// boundaries, buffers, distances) on plain values, done by GEOS through its reentrant C API.
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/types.hpp"

namespace socsim::geometry {

// GEOS failed on input that should have been valid (a broken invariant, not bad user input).
class GeosError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Validity {
  bool valid = true;
  std::string reason;             // GEOS's wording, e.g. "Self-intersection"
  std::optional<Point> location;  // where the problem is, when GEOS names a place
};

// Owns one GEOS context handle. Not shareable between threads: make one per thread (cheap).
class Geos {
 public:
  Geos();
  ~Geos();
  Geos(const Geos&) = delete;
  Geos& operator=(const Geos&) = delete;

  // Checks ring sizes and finite coordinates first, then GEOS's OGC validity rules.
  [[nodiscard]] Validity validity(const Polygon& polygon) const;

  [[nodiscard]] double area(const MultiPolygon& shape) const;
  [[nodiscard]] MultiPolygon unite(const MultiPolygon& shapes) const;  // union of all parts
  [[nodiscard]] MultiPolygon unite(const MultiPolygon& a, const MultiPolygon& b) const;
  [[nodiscard]] MultiPolygon intersection(const MultiPolygon& a, const MultiPolygon& b) const;
  [[nodiscard]] MultiPolygon difference(const MultiPolygon& a, const MultiPolygon& b) const;
  [[nodiscard]] MultiPolygon buffer(const MultiPolygon& shape, double distance) const;

  // Point in polygon; points on the boundary count as covered.
  [[nodiscard]] bool covers(const MultiPolygon& shape, Point p) const;
  [[nodiscard]] double distance(const MultiPolygon& shape, Point p) const;
  [[nodiscard]] double distance(const MultiPolygon& a, const MultiPolygon& b) const;

  // The parts of a's boundary lying within `tolerance` of b's boundary, as maximal straight
  // segments (empty when the polygons only touch at points or not at all).
  [[nodiscard]] std::vector<Segment> shared_boundary(const Polygon& a, const Polygon& b,
                                                     double tolerance) const;

  // All rings of all polygons, noded and dissolved so that an edge shared by two polygons
  // appears once, as maximal straight segments in a deterministic order.
  [[nodiscard]] std::vector<Segment> boundary_segments(const MultiPolygon& shapes) const;

  // Length of the parts of `segments` that are not within `tolerance` of `shape`'s boundary
  // or interior (0 when the segments lie wholly on or in the shape).
  [[nodiscard]] double length_outside(std::span<const Segment> segments, const MultiPolygon& shape,
                                      double tolerance) const;

  // Faces enclosed by the segments once they are noded at their crossings.
  [[nodiscard]] MultiPolygon polygonize(std::span<const Segment> segments) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace socsim::geometry
