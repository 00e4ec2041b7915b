#pragma once
// Geodesic distance fields on an OccupancyGrid (fast marching, first-order Eikonal solver):
// shortest walking distance around walls to the nearest source, for flow fields, spawning
// and navigation-benchmark path lengths.
#include <optional>
#include <span>
#include <vector>

#include "core/world/occupancy_grid.hpp"

namespace socsim::world {

class GeodesicField {
 public:
  // Distances from the nearest source point; sources in blocked cells or off the grid are
  // ignored. Unreachable cells hold +infinity.
  static GeodesicField from_points(const OccupancyGrid& grid, std::span<const Point> sources);
  // Distances from every free cell whose centre lies in the polygon (a goal region / ROI).
  static GeodesicField from_region(const OccupancyGrid& grid, const Polygon& region);
  static GeodesicField from_cells(const OccupancyGrid& grid, std::span<const Cell> cells);

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] float at(Cell c) const;  // +inf outside the grid
  [[nodiscard]] std::span<const float> values() const { return values_; }
  [[nodiscard]] bool has_source() const { return has_source_; }

  // Distance at p, interpolated bilinearly over the finite neighbouring cells; nullopt when p
  // is off the grid or no neighbouring cell is reachable.
  [[nodiscard]] std::optional<double> distance(Point p) const;
  // Unit direction of steepest descent at p (towards the sources); nullopt at a source or
  // where the field is undefined.
  [[nodiscard]] std::optional<Point> descent(Point p) const;

 private:
  void march(const OccupancyGrid& grid, std::vector<std::pair<Cell, float>> seeds);

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.1;
  Point origin_;
  bool has_source_ = false;
  std::vector<float> values_;
};

}  // namespace socsim::world
