#pragma once
// Fast plane geometry on plain doubles for hot loops (rasterisation, per-agent queries),
// where a round trip through GEOS would cost more than the answer.
#include <span>
#include <vector>

#include "core/geometry/types.hpp"

namespace socsim::geometry {

double length(const Segment& s);
double distance(Point a, Point b);
// Closest point of segment s to p, and the distance to it.
Point closest_point(const Segment& s, Point p);
double distance(const Segment& s, Point p);
// Smallest distance between two segments (0 when they cross).
double distance(const Segment& s, const Segment& t);

// Shoelace area; positive for counter-clockwise rings.
double signed_area(std::span<const Point> ring);
// Area of the outer ring minus the holes.
double area(const Polygon& polygon);
// Area-weighted centroid of the outer ring (the vertex mean for degenerate rings).
Point centroid(std::span<const Point> ring);
Box bounds(std::span<const Point> points);
Box bounds(const MultiPolygon& polygons);

// Even-odd test on the outer ring and holes; points on the boundary count as inside.
bool contains(const Polygon& polygon, Point p, double boundary_tolerance = 1e-9);

// The ring's edges in order, closing edge included.
std::vector<Segment> edges(std::span<const Point> ring);

// Maps a point given in `frame` coordinates into the parent frame (rotate by yaw, then translate).
Point to_parent(const Pose2& frame, Point p);
Pose2 to_parent(const Pose2& frame, const Pose2& p);

}  // namespace socsim::geometry
