#pragma once
// A World rasterised at a chosen resolution: cells outside every zone and cells within the
// inflation radius of a wall or of the plan's outline are blocked. Used for reachability,
// geodesic distances (flow fields, spawning, the navigation benchmark) and map exports.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/world/world.hpp"

namespace socsim::world {

struct GridOptions {
  double resolution = 0.1;  // m per cell
  double inflation = 0.0;   // m; agent radius: cells whose centre is closer to a wall are blocked
  // Above this many cells the resolution is coarsened (uniformly) until the grid fits.
  std::size_t max_cells = 4'000'000;
};

struct Cell {
  int x = 0;
  int y = 0;
  friend bool operator==(Cell, Cell) = default;
};

class OccupancyGrid {
 public:
  static OccupancyGrid rasterise(const World& world, const GridOptions& options);

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] double resolution() const { return resolution_; }
  // Lower-left corner of cell (0, 0); row y = 0 is the lowest row (smallest y).
  [[nodiscard]] Point origin() const { return origin_; }

  [[nodiscard]] bool in_bounds(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  [[nodiscard]] std::size_t index(Cell c) const {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x);
  }
  [[nodiscard]] bool blocked(Cell c) const { return !in_bounds(c) || blocked_[index(c)] != 0; }
  [[nodiscard]] std::optional<ZoneId> zone_of(Cell c) const;
  [[nodiscard]] Point center(Cell c) const {
    return {origin_.x + (c.x + 0.5) * resolution_, origin_.y + (c.y + 0.5) * resolution_};
  }
  [[nodiscard]] std::optional<Cell> cell_of(Point p) const;
  // Row-major blocked flags (1 = blocked), row 0 first.
  [[nodiscard]] std::span<const std::uint8_t> blocked_cells() const { return blocked_; }
  // Row-major zone index per cell (-1 outside every zone), row 0 first.
  [[nodiscard]] std::span<const std::int32_t> zone_cells() const { return zone_; }
  [[nodiscard]] std::size_t free_count() const;

  // 4-connected components of free cells: a label per cell, -1 for blocked cells.
  [[nodiscard]] std::vector<int> components() const;

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.1;
  Point origin_;
  std::vector<std::uint8_t> blocked_;
  std::vector<std::int32_t> zone_;  // zone index per cell, -1 outside every zone
};

}  // namespace socsim::world
