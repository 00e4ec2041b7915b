#pragma once
// Plain-double 2-D geometry values shared by the world model, the crowd engine and exports.
// No library types leak out of core/geometry: GEOS and Eigen stay inside its .cpp files.
#include <vector>

namespace socsim::geometry {

struct Point {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point&, const Point&) = default;
};

struct Segment {
  Point a;
  Point b;
  friend bool operator==(const Segment&, const Segment&) = default;
};

// Position and heading (radians, counter-clockwise from +x).
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
  [[nodiscard]] Point position() const { return {x, y}; }
  friend bool operator==(const Pose2&, const Pose2&) = default;
};

// A polygon as its outer ring and holes; rings are open (the first point is not repeated).
struct Polygon {
  std::vector<Point> outer;
  std::vector<std::vector<Point>> holes;
  friend bool operator==(const Polygon&, const Polygon&) = default;
};

using MultiPolygon = std::vector<Polygon>;

struct Box {
  Point min;
  Point max;
  [[nodiscard]] double width() const { return max.x - min.x; }
  [[nodiscard]] double height() const { return max.y - min.y; }
};

}  // namespace socsim::geometry
