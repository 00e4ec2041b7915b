#pragma once
// Extent of point sets: the largest distance between two points, via the convex hull (for
// building diagonals, which were a loop over every pair of vertices).
#include <span>

#include "core/geometry/types.hpp"

namespace socsim::geometry {

// The largest distance between two of the points (0 for fewer than two), in O(n log n): convex
// hull, then rotating calipers over the hull (exactly the maximum of the pairwise distances).
double diameter(std::span<const Point> points);

}  // namespace socsim::geometry
