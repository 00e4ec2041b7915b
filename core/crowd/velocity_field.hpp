#pragma once
// Velocity fields for ambient crowds (paper 001 §III-F/G, Algorithm 1): a grid of velocity
// vectors over the world's bounding box, built along geodesic paths from a group's start
// regions to its goal regions, or supplied from outside (a diffusion model's 64×64×2 output).
#include <cstdint>
#include <span>
#include <vector>

#include "core/common/error.hpp"
#include "core/crowd/wall_grid.hpp"
#include "core/world/occupancy_grid.hpp"

namespace socsim::crowd {

class VelocityField {
 public:
  // values[i * height + j] is the velocity of column i (along x from bounds.min.x) and row j
  // (along y from bounds.min.y): Algorithm 1's V_index with index = (i, j).
  static Result<VelocityField> from_values(geometry::Box bounds, int width, int height,
                                           std::vector<Vec2> values);

  struct GeodesicSpec {
    std::vector<geometry::Polygon> start;  // where the group enters (checked to reach a goal)
    std::vector<geometry::Polygon> goal;   // where it heads
    int width = 64;                        // cells along x (Algorithm 1: 64)
    int height = 64;                       // cells along y
    double speed = 1.34;                   // m/s, magnitude of every vector
    double variation = 0.0;                // rad, amplitude of the seeded smooth heading noise
    std::uint64_t seed = 0;
  };
  // Each cell holds speed × the direction of steepest descent of the geodesic distance to the
  // goal regions (sampled at five points of the cell, averaged over the walkable ones), turned
  // by a smooth seeded angle field of amplitude `variation`. Cells with no walkable sample take
  // their neighbours' mean direction (up to three cells out); goal cells hold zero. Errors (kValidation,
  // pointer "/start/<k>" or
  // "/goal/<k>"): empty or off-grid regions, a start region that cannot reach any goal.
  static Result<VelocityField> from_geodesic(const world::OccupancyGrid& grid, geometry::Box bounds,
                                             const GeodesicSpec& spec);

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] const geometry::Box& bounds() const { return bounds_; }
  [[nodiscard]] std::span<const Vec2> values() const { return values_; }
  // Algorithm 1's lookup: index = ⌊(pos − min) / size × n⌋ per axis, clamped to the grid.
  [[nodiscard]] Vec2 sample(Vec2 position) const;

 private:
  geometry::Box bounds_;
  int width_ = 0;
  int height_ = 0;
  std::vector<Vec2> values_;
};

// Algorithm 1: the intermediate goal for an agent at `position`: goal = pos + vel·dt, pushed
// out to at least 2·tol ahead when the sampled velocity is non-zero. The LightSFM desired force
// towards it (with goal radius tol) is then applied by the simulation.
Vec2 velocity_field_goal(const VelocityField& field, Vec2 position, double dt, double tolerance);

}  // namespace socsim::crowd
