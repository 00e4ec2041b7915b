#include "core/crowd/velocity_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/common/rng.hpp"
#include "core/crowd/role_parameters.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/geodesic.hpp"

namespace socsim::crowd {

namespace {

constexpr int kMaxCells = 4096;  // per axis

}  // namespace

Result<VelocityField> VelocityField::from_values(geometry::Box bounds, int width, int height,
                                                 std::vector<Vec2> values) {
  std::vector<FieldError> errors;
  if (width < 1 || height < 1 || width > kMaxCells || height > kMaxCells)
    errors.push_back(FieldError("/size", "width and height must be in [1, 4096]"));
  else if (values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    errors.push_back(FieldError("/values", "must hold width × height vectors (" + std::to_string(width) +
                                               " × " + std::to_string(height) + "), has " +
                                               std::to_string(values.size())));
  if (!(std::isfinite(bounds.min.x) && std::isfinite(bounds.min.y) && std::isfinite(bounds.max.x) &&
        std::isfinite(bounds.max.y) && bounds.width() > 0.0 && bounds.height() > 0.0))
    errors.push_back(FieldError("/bounds", "must be a finite box of positive size"));
  for (std::size_t k = 0; k < values.size() && errors.size() < 10; ++k) {
    const Vec2 v = values[k];
    if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::abs(v.x) <= kMaxAgentSpeed &&
          std::abs(v.y) <= kMaxAgentSpeed))
      errors.push_back(FieldError("/values/" +
                                      std::to_string(k / static_cast<std::size_t>(std::max(height, 1))) +
                                      "/" + std::to_string(k % static_cast<std::size_t>(std::max(height, 1))),
                                  "components must be finite and within ±8 m/s"));
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid velocity field", std::move(errors));
  VelocityField f;
  f.bounds_ = bounds;
  f.width_ = width;
  f.height_ = height;
  f.values_ = std::move(values);
  return f;
}

Result<VelocityField> VelocityField::from_geodesic(const world::OccupancyGrid& grid, geometry::Box bounds,
                                                   const GeodesicSpec& spec) {
  std::vector<FieldError> errors;
  if (spec.width < 2 || spec.height < 2 || spec.width > kMaxCells || spec.height > kMaxCells)
    errors.push_back(FieldError("/resolution", "must be in [2, 4096]"));
  if (!(std::isfinite(spec.speed) && spec.speed > 0.0 && spec.speed <= kMaxAgentSpeed))
    errors.push_back(FieldError("/speed", "must be in (0, 8] m/s"));
  if (!(std::isfinite(spec.variation) && spec.variation >= 0.0 && spec.variation <= std::numbers::pi / 2))
    errors.push_back(FieldError("/variation", "must be in [0, π/2] rad"));
  if (spec.goal.empty()) errors.push_back(FieldError("/goal", "needs at least one goal region"));
  if (!(bounds.width() > 0.0 && bounds.height() > 0.0))
    errors.push_back(FieldError("/bounds", "empty world"));
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid velocity field", std::move(errors));

  // Geodesic distance to the union of the goal regions.
  std::vector<world::Cell> goal_cells;
  for (std::size_t k = 0; k < spec.goal.size(); ++k) {
    const geometry::Box box = geometry::bounds(spec.goal[k].outer);
    std::size_t found = 0;
    for (int y = 0; y < grid.height(); ++y) {
      const double cy = grid.origin().y + (y + 0.5) * grid.resolution();
      if (cy < box.min.y || cy > box.max.y) continue;
      for (int x = 0; x < grid.width(); ++x) {
        const world::Cell c{x, y};
        const world::Point p = grid.center(c);
        if (p.x < box.min.x || p.x > box.max.x || grid.blocked(c) || !geometry::contains(spec.goal[k], p))
          continue;
        goal_cells.push_back(c);
        ++found;
      }
    }
    if (found == 0)
      errors.push_back(FieldError("/goal/" + std::to_string(k), "covers no walkable cell of the world"));
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid velocity field", std::move(errors));
  const world::GeodesicField distance = world::GeodesicField::from_cells(grid, goal_cells);
  for (std::size_t k = 0; k < spec.start.size(); ++k) {
    const geometry::Polygon& region = spec.start[k];
    bool reaches = false;
    bool walkable = false;
    const geometry::Box box = geometry::bounds(region.outer);
    for (int y = 0; y < grid.height() && !reaches; ++y) {
      for (int x = 0; x < grid.width() && !reaches; ++x) {
        const world::Cell c{x, y};
        const world::Point p = grid.center(c);
        if (p.x < box.min.x || p.x > box.max.x || p.y < box.min.y || p.y > box.max.y) continue;
        if (grid.blocked(c) || !geometry::contains(region, p)) continue;
        walkable = true;
        reaches = std::isfinite(distance.at(c));
      }
    }
    if (!walkable)
      errors.push_back(FieldError("/start/" + std::to_string(k), "covers no walkable cell of the world"));
    else if (!reaches)
      errors.push_back(
          FieldError("/start/" + std::to_string(k), "cannot reach any goal region around the walls"));
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid velocity field", std::move(errors));

  // Smooth seeded heading noise: three random plane waves, scaled so |angle| <= variation.
  Rng rng(spec.seed ^ fnv1a64("velocity_field"));
  struct Wave {
    double a, fx, fy, phase;
  };
  std::array<Wave, 3> waves{};
  double amplitude_sum = 0.0;
  for (Wave& w : waves) {
    w.a = rng.uniform(0.5, 1.0);
    w.fx = static_cast<double>(rng.between(-2, 2));
    w.fy = static_cast<double>(rng.between(1, 3));
    w.phase = rng.uniform(0.0, 2.0 * std::numbers::pi);
    amplitude_sum += w.a;
  }

  VelocityField f;
  f.bounds_ = bounds;
  f.width_ = spec.width;
  f.height_ = spec.height;
  f.values_.assign(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height), Vec2{});
  const double cw = bounds.width() / spec.width;
  const double ch = bounds.height() / spec.height;
  static constexpr std::array<std::array<double, 2>, 5> kSamples = {
      {{0.5, 0.5}, {0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}}};
  const bool fine = std::max(cw, ch) <= 2.0 * grid.resolution();
  // Per cell: 0 = no walkable sample (filled from neighbours below), 1 = vector, 2 = goal cell.
  std::vector<std::uint8_t> kind(f.values_.size(), 0);
  const auto at = [&](int i, int j) {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(spec.height) + static_cast<std::size_t>(j);
  };
  for (int i = 0; i < spec.width; ++i) {
    for (int j = 0; j < spec.height; ++j) {
      double sx = 0.0;
      double sy = 0.0;
      bool goal = false;
      // Cells no larger than two routing cells read their centre only (the other samples would
      // fall in the same routing cells); larger cells average five samples.
      const std::size_t first = fine ? 1 : kSamples.size();
      for (std::size_t k = 0; k < kSamples.size(); ++k) {
        if (k >= first && (sx != 0.0 || sy != 0.0)) break;  // fine cells: others only if the centre fails
        const auto& smp = kSamples[k];
        const world::Point p{bounds.min.x + (i + smp[0]) * cw, bounds.min.y + (j + smp[1]) * ch};
        const auto d = distance.descent(p);
        if (!d) {
          const auto c = grid.cell_of(p);
          goal = goal || (c && distance.at(*c) == 0.0f);
          continue;
        }
        sx += d->x;
        sy += d->y;
      }
      const double len = std::sqrt(sx * sx + sy * sy);
      if (len < 1e-9) {
        kind[at(i, j)] = goal ? 2 : 0;
        continue;
      }
      kind[at(i, j)] = 1;
      f.values_[at(i, j)] = {sx / len, sy / len};
    }
  }
  // Cells whose samples all fell next to a wall (blocked by the grid's inflation) take the mean
  // direction of their neighbours, so an agent pressed against a wall still has a way to go.
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<std::uint8_t> next = kind;
    for (int i = 0; i < spec.width; ++i) {
      for (int j = 0; j < spec.height; ++j) {
        if (kind[at(i, j)] != 0) continue;
        double sx = 0.0;
        double sy = 0.0;
        for (const auto& [di, dj] : std::array<std::pair<int, int>, 4>{{{-1, 0}, {1, 0}, {0, -1}, {0, 1}}}) {
          const int ni = i + di;
          const int nj = j + dj;
          if (ni < 0 || nj < 0 || ni >= spec.width || nj >= spec.height || kind[at(ni, nj)] != 1) continue;
          sx += f.values_[at(ni, nj)].x;
          sy += f.values_[at(ni, nj)].y;
        }
        const double len = std::sqrt(sx * sx + sy * sy);
        if (len < 1e-9) continue;
        f.values_[at(i, j)] = {sx / len, sy / len};
        next[at(i, j)] = 1;
      }
    }
    kind = std::move(next);
  }
  std::vector<double> col_sin, col_cos, row_sin, row_cos;
  for (const Wave& wave : waves) {
    for (int i = 0; i < spec.width; ++i) {
      const double x = 2.0 * std::numbers::pi * wave.fx * (i + 0.5) / spec.width + wave.phase;
      col_sin.push_back(std::sin(x));
      col_cos.push_back(std::cos(x));
    }
    for (int j = 0; j < spec.height; ++j) {
      const double y = 2.0 * std::numbers::pi * wave.fy * (j + 0.5) / spec.height;
      row_sin.push_back(std::sin(y));
      row_cos.push_back(std::cos(y));
    }
  }
  for (int i = 0; i < spec.width; ++i) {
    for (int j = 0; j < spec.height; ++j) {
      Vec2& v = f.values_[at(i, j)];
      if (kind[at(i, j)] != 1) {
        v = {};
        continue;
      }
      double ux = v.x;
      double uy = v.y;
      if (spec.variation > 0.0) {
        // sin(x_i + y_j) = sin x_i cos y_j + cos x_i sin y_j, with the per-column and per-row
        // terms computed once.
        double angle = 0.0;
        for (std::size_t w = 0; w < waves.size(); ++w) {
          const std::size_t ci = w * static_cast<std::size_t>(spec.width) + static_cast<std::size_t>(i);
          const std::size_t rj = w * static_cast<std::size_t>(spec.height) + static_cast<std::size_t>(j);
          angle += waves[w].a * (col_sin[ci] * row_cos[rj] + col_cos[ci] * row_sin[rj]);
        }
        angle *= spec.variation / amplitude_sum;
        const double c = std::cos(angle);
        const double sn = std::sin(angle);
        const double rx = c * ux - sn * uy;
        uy = sn * ux + c * uy;
        ux = rx;
      }
      v = {spec.speed * ux, spec.speed * uy};
    }
  }
  return f;
}

Vec2 VelocityField::sample(Vec2 position) const {
  if (values_.empty()) return {};
  const double fx = (position.x - bounds_.min.x) / bounds_.width() * width_;
  const double fy = (position.y - bounds_.min.y) / bounds_.height() * height_;
  const int i = std::clamp(std::isfinite(fx) ? static_cast<int>(std::floor(std::clamp(fx, -1.0, 1.0e7))) : 0,
                           0, width_ - 1);
  const int j = std::clamp(std::isfinite(fy) ? static_cast<int>(std::floor(std::clamp(fy, -1.0, 1.0e7))) : 0,
                           0, height_ - 1);
  return values_[static_cast<std::size_t>(i) * static_cast<std::size_t>(height_) +
                 static_cast<std::size_t>(j)];
}

Vec2 velocity_field_goal(const VelocityField& field, Vec2 position, double dt, double tolerance) {
  const Vec2 vel = field.sample(position);
  Vec2 goal{position.x + vel.x * dt, position.y + vel.y * dt};
  const double dx = goal.x - position.x;
  const double dy = goal.y - position.y;
  const double d = std::sqrt(dx * dx + dy * dy);
  const double speed = std::sqrt(vel.x * vel.x + vel.y * vel.y);
  if (speed > 0.0 && d < 2.0 * tolerance && d > 0.0) {
    goal = {position.x + dx * 2.0 * tolerance / d, position.y + dy * 2.0 * tolerance / d};
  }
  return goal;
}

}  // namespace socsim::crowd
