#pragma once
// Which of many segments pass near a point, in O(log n + hits): a bulk-loaded R-tree over their
// bounding boxes. For checks that would otherwise compare every element with every edge
// (walls against zone boundaries, doors against the outline), which made large worlds quadratic.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "core/geometry/types.hpp"

namespace socsim::geometry {

class SegmentIndex {
 public:
  explicit SegmentIndex(std::vector<Segment> segments = {});
  ~SegmentIndex();
  SegmentIndex(SegmentIndex&&) noexcept;
  SegmentIndex& operator=(SegmentIndex&&) noexcept;
  SegmentIndex(const SegmentIndex&) = delete;
  SegmentIndex& operator=(const SegmentIndex&) = delete;

  [[nodiscard]] std::size_t size() const { return segments_.size(); }
  [[nodiscard]] const Segment& segment(std::size_t i) const { return segments_[i]; }

  // Adds a segment; its index is the previous size().
  void insert(Segment s);

  // Indices (in insertion order) of the segments at most `radius` from p, ascending.
  [[nodiscard]] std::vector<std::size_t> within(Point p, double radius) const;
  // Indices of the segments at most `radius` from segment s, ascending.
  [[nodiscard]] std::vector<std::size_t> within(const Segment& s, double radius) const;

  struct Nearest {
    std::size_t index = 0;
    double distance = 0.0;
  };
  // The segment closest to p (the lowest index among equals); nullopt when the index is empty.
  [[nodiscard]] std::optional<Nearest> nearest(Point p) const;

 private:
  struct Tree;
  std::vector<Segment> segments_;
  std::unique_ptr<Tree> tree_;
};

// The parts of the rings' edges (each ring open: the last point joins the first) lying within
// `tolerance` of some segment of `other`, as maximal straight segments longer than `tolerance`:
// Geos::shared_boundary computed from exact capsules instead of a buffer. GEOS's buffer of a
// boundary with features finer than the tolerance (a 10,000-vertex sawtooth) grows without bound
// in time and memory; this costs O(n log n + pairs within tolerance).
std::vector<Segment> pieces_near(const std::vector<std::vector<Point>>& rings, const SegmentIndex& other,
                                 double tolerance);

}  // namespace socsim::geometry
