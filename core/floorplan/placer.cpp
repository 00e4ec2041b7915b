#include "core/floorplan/placer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/floorplan/rooms.hpp"
#include "core/geometry/geos.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/footprint.hpp"

namespace socsim::floorplan {

using geometry::MultiPolygon;

bool axis_aligned_rectangle(const Polygon& p) {
  if (!p.holes.empty()) return false;
  std::vector<Point> r = p.outer;
  if (r.size() > 1 && r.front() == r.back()) r.pop_back();
  if (r.size() != 4) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point& a = r[i];
    const Point& b = r[(i + 1) % 4];
    if (std::abs(a.x - b.x) > 1e-9 && std::abs(a.y - b.y) > 1e-9) return false;
  }
  return true;
}

Box inner_box(const Polygon& polygon) {
  const Box bb = geometry::bounds(polygon.outer);
  if (axis_aligned_rectangle(polygon)) return bb;
  geometry::Geos geos;
  const MultiPolygon shape{polygon};
  Box best{{0, 0}, {0, 0}};
  double best_area = 0.0;
  std::vector<Point> centres{geometry::centroid(polygon.outer)};
  for (double fx : {0.25, 0.5, 0.75})
    for (double fy : {0.25, 0.5, 0.75})
      centres.push_back({bb.min.x + fx * bb.width(), bb.min.y + fy * bb.height()});
  for (const Point& c : centres) {
    if (!geometry::contains(polygon, c)) continue;
    auto box_at = [&](double s) {
      return Box{{c.x - s * bb.width() / 2, c.y - s * bb.height() / 2},
                 {c.x + s * bb.width() / 2, c.y + s * bb.height() / 2}};
    };
    auto fits = [&](double s) {
      const Box b = box_at(s);
      const Polygon r{{b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}}, {}};
      return geos.area(geos.difference({r}, shape)) < 1e-6;
    };
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 14; ++i) {
      const double mid = (lo + hi) / 2;
      (fits(mid) ? lo : hi) = mid;
    }
    const Box b = box_at(lo);
    if (b.width() * b.height() > best_area) {
      best_area = b.width() * b.height();
      best = b;
    }
  }
  return best;
}

double wrap(double a) {
  while (a > kPi) a -= 2 * kPi;
  while (a <= -kPi) a += 2 * kPi;
  return a;
}

int nearest_side(const Box& b, Point p) {
  const double d[4] = {std::abs(p.y - b.min.y), std::abs(p.x - b.max.x), std::abs(p.y - b.max.y),
                       std::abs(p.x - b.min.x)};
  return static_cast<int>(std::min_element(d, d + 4) - d);
}

std::string numbered(const std::string& base, int i) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "_%02d", i);
  return base + buf;
}

bool overlaps(const Box& a, const Box& b, double gap) {
  return a.min.x < b.max.x + gap - 1e-9 && b.min.x < a.max.x + gap - 1e-9 && a.min.y < b.max.y + gap - 1e-9 &&
         b.min.y < a.max.y + gap - 1e-9;
}

double box_distance(const Box& b, const Segment& s) {
  // Distance between an axis-aligned box and a segment (0 when they meet).
  const Point corners[4] = {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
  auto inside = [&](Point p) { return p.x >= b.min.x && p.x <= b.max.x && p.y >= b.min.y && p.y <= b.max.y; };
  if (inside(s.a) || inside(s.b)) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) {
    const Segment e{corners[k], corners[(k + 1) % 4]};
    d = std::min(d, geometry::distance(e, s));
  }
  return d;
}

Box footprint_box(const std::string& type, const Pose2& pose) {
  return geometry::bounds(footprint_polygon(type, pose).outer);
}

namespace {

// No footprint reaches farther than this from its entity's pose (half the largest diagonal of
// the footprint table, or of the default footprint).
double footprint_reach() {
  static const double reach = [] {
    double r = std::hypot(Footprint{}.width, Footprint{}.depth) / 2;
    for (const auto& f : entity_footprints()) r = std::max(r, std::hypot(f.size.width, f.size.depth) / 2);
    return r + 0.01;
  }();
  return reach;
}

// Whether the entity's footprint may reach `b` (grown by `margin`): a cheap test on its pose
// that spares the footprint lookup for the furniture of other rooms.
bool may_reach(const EntitySpec& e, const Box& b, double margin) {
  const double r = footprint_reach() + margin;
  return e.pose.x >= b.min.x - r && e.pose.x <= b.max.x + r && e.pose.y >= b.min.y - r &&
         e.pose.y <= b.max.y + r;
}

}  // namespace

Placer::Placer(const Zone& zone, const Frame& frame, std::vector<DoorAt> doors, Furnishing& out)
    : zone_(zone), f_(frame), doors_(std::move(doors)), out_(out) {
  for (const auto& d : doors_) {
    const int side = nearest_side(f_.box, d.centre);
    const bool horizontal = side == 0 || side == 2;
    const double h = d.width / 2;
    door_segments_.push_back(horizontal
                                 ? Segment{{d.centre.x - h, d.centre.y}, {d.centre.x + h, d.centre.y}}
                                 : Segment{{d.centre.x, d.centre.y - h}, {d.centre.x, d.centre.y + h}});
  }
}

bool Placer::clear(Point p, double radius) const {
  for (const auto& d : doors_)
    if (geometry::distance(p, d.centre) < d.width / 2 + 0.6 + radius) return false;
  return true;
}

bool Placer::box_free(const Box& b, std::optional<std::size_t> skip, Areas areas) const {
  if (b.min.x < f_.box.min.x + kWallGap - 1e-9 || b.min.y < f_.box.min.y + kWallGap - 1e-9 ||
      b.max.x > f_.box.max.x - kWallGap + 1e-9 || b.max.y > f_.box.max.y - kWallGap + 1e-9)
    return false;
  for (const auto& s : door_segments_)
    if (box_distance(b, s) < kDoorGap) return false;
  for (std::size_t k = 0; k < out_.entities.size(); ++k) {
    if (skip && *skip == k) continue;
    const EntitySpec& e = out_.entities[k];
    if (!may_reach(e, b, kItemGap)) continue;
    const Box eb = footprint_box(e.type, e.pose);
    if (mine(eb) && overlaps(b, eb, kItemGap)) return false;
  }
  if (areas != Areas::kNone) {
    for (std::size_t k = 0; k < out_.rois.size(); ++k) {
      const Roi& r = out_.rois[k];
      const bool lane = r.kind == "queue_lane" || r.kind == "walkway";
      if (!lane && (areas == Areas::kLanes || (r.kind != "entrance" && r.kind != "exit"))) continue;
      if (overlaps(b, geometry::bounds(r.polygon.outer), 0.0)) return false;
    }
  }
  return true;
}

std::pair<double, double> Placer::half_extents(const std::string& type, double local_yaw) {
  const Footprint fp = footprint_of(type);
  const bool across = std::abs(std::sin(local_yaw)) > 0.5;  // facing along ±u
  return across ? std::pair{fp.depth / 2, fp.width / 2} : std::pair{fp.width / 2, fp.depth / 2};
}

std::optional<Point> Placer::fit(const std::string& type, double u, double v, double local_yaw) const {
  const auto [hu, hv] = half_extents(type, local_yaw);
  if (2 * (hu + kWallGap) > f_.len || 2 * (hv + kWallGap) > f_.depth) return std::nullopt;
  u = std::clamp(u, hu + kWallGap, f_.len - hu - kWallGap);
  v = std::clamp(v, hv + kWallGap, f_.depth - hv - kWallGap);
  const Point p = f_.at(u, v);
  if (!box_free(footprint_box(type, {p.x, p.y, f_.yaw(local_yaw)}))) return std::nullopt;
  return Point{u, v};
}

std::optional<Point> Placer::entity(const std::string& type, const std::string& suffix,
                                    std::initializer_list<std::pair<double, double>> candidates,
                                    double local_yaw, std::vector<std::string> affordances) {
  std::vector<std::pair<double, double>> tries(candidates);
  if (!tries.empty()) {
    const auto [u0, v0] = tries.front();
    const int steps = static_cast<int>(std::ceil(f_.len / 0.25));
    for (int k = 1; k <= steps; ++k) {
      for (int sgn : {1, -1}) tries.emplace_back(u0 + sgn * 0.25 * k, v0);
    }
  }
  for (const auto& [u, v] : tries) {
    const auto at = fit(type, u, v, local_yaw);
    if (!at) continue;
    const Point p = f_.at(at->x, at->y);
    out_.entities.push_back({type, zone_.name + "_" + suffix, {p.x, p.y, f_.yaw(local_yaw)}, affordances});
    if (walkable()) return *at;
    out_.entities.pop_back();  // it would wall something in: the next place
  }
  return std::nullopt;
}

namespace {

// The 0.1 m grid over a room's rectangle that walkable() floods: a cell is blocked when a person
// of radius 0.25 m centred there would touch a wall or a footprint.
struct WalkCells {
  static constexpr double kRes = 0.1, kRadius = 0.25, kReach = 0.4;
  Box b;
  int nx, ny;
  explicit WalkCells(const Box& box)
      : b(box),
        nx(std::max(1, static_cast<int>(std::ceil(box.width() / kRes)))),
        ny(std::max(1, static_cast<int>(std::ceil(box.height() / kRes)))) {}
  [[nodiscard]] std::size_t size() const {
    return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  }
  [[nodiscard]] Point centre(int x, int y) const {
    return {b.min.x + (x + 0.5) * kRes, b.min.y + (y + 0.5) * kRes};
  }
  [[nodiscard]] std::size_t at(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(x);
  }
  // Cell range [x0, x1] × [y0, y1] of a box grown by `margin`, clamped to the grid.
  [[nodiscard]] std::array<int, 4> range(const Box& fb, double margin) const {
    return {std::max(0, static_cast<int>(std::floor((fb.min.x - margin - b.min.x) / kRes))),
            std::min(nx - 1, static_cast<int>(std::floor((fb.max.x + margin - b.min.x) / kRes))),
            std::max(0, static_cast<int>(std::floor((fb.min.y - margin - b.min.y) / kRes))),
            std::min(ny - 1, static_cast<int>(std::floor((fb.max.y + margin - b.min.y) / kRes)))};
  }
  static double distance(const Box& fb, Point c) {
    const double dx = std::max({fb.min.x - c.x, 0.0, c.x - fb.max.x});
    const double dy = std::max({fb.min.y - c.y, 0.0, c.y - fb.max.y});
    return std::hypot(dx, dy);
  }
  // Blocks the cells a footprint takes; lists those that were free in `newly` when given.
  void block(const Box& fb, std::vector<std::uint8_t>& blocked, std::vector<std::size_t>* newly) const {
    const auto [x0, x1, y0, y1] = range(fb, kRadius);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const std::size_t k = at(x, y);
        if (blocked[k] || distance(fb, centre(x, y)) >= kRadius) continue;
        blocked[k] = 1;
        if (newly) newly->push_back(k);
      }
  }
  // Whether a reached cell lies within reach of the footprint (a person can use it).
  [[nodiscard]] bool near(const Box& fb, const std::vector<std::uint8_t>& reached) const {
    const auto [x0, x1, y0, y1] = range(fb, kRadius + kReach);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        if (reached[at(x, y)] && distance(fb, centre(x, y)) <= kRadius + kReach - 0.05) return true;
    return false;
  }
};

bool same_box(const Box& a, const Box& b) {
  return a.min.x == b.min.x && a.min.y == b.min.y && a.max.x == b.max.x && a.max.y == b.max.y;
}

}  // namespace

// The door seeds: a cell just inside each door.
std::vector<std::size_t> Placer::door_cells() const {
  const WalkCells g(f_.box);
  std::vector<std::size_t> seeds;
  for (const auto& d : doors_) {
    const int side = nearest_side(g.b, d.centre);
    Point p = d.centre;
    const double in = WalkCells::kRadius + 0.1;
    if (side == 0) p.y = g.b.min.y + in;
    if (side == 1) p.x = g.b.max.x - in;
    if (side == 2) p.y = g.b.max.y - in;
    if (side == 3) p.x = g.b.min.x + in;
    const int x = std::clamp(static_cast<int>(std::floor((p.x - g.b.min.x) / WalkCells::kRes)), 0, g.nx - 1);
    const int y = std::clamp(static_cast<int>(std::floor((p.y - g.b.min.y) / WalkCells::kRes)), 0, g.ny - 1);
    seeds.push_back(g.at(x, y));
  }
  return seeds;
}

// One footprint added to a grid that passed: the cells it newly blocks can only cut paths through
// themselves, so when the reached cells bordering them still connect within a window around
// them, every cell reached before and not blocked now is still reached — the flood fill's
// answer without flooding. nullopt when that cannot be shown here (the caller floods).
std::optional<bool> Placer::walkable_after_one(const std::vector<Box>& boxes) const {
  if (!walk_ || walk_->boxes.size() + 1 != boxes.size()) return std::nullopt;
  for (std::size_t k = 0; k < walk_->boxes.size(); ++k)
    if (!same_box(walk_->boxes[k], boxes[k])) return std::nullopt;
  const WalkCells g(f_.box);
  WalkGrid& w = *walk_;
  const Box& added = boxes.back();
  std::vector<std::size_t> newly;
  g.block(added, w.blocked, &newly);
  std::vector<std::size_t> lost;  // newly blocked cells that were reached
  auto restore = [&] {
    for (std::size_t k : lost) w.reached[k] = 1;
    for (std::size_t k : newly) w.blocked[k] = 0;
  };
  const auto xy = [&](std::size_t k) {
    return std::pair{static_cast<int>(k % static_cast<std::size_t>(g.nx)),
                     static_cast<int>(k / static_cast<std::size_t>(g.nx))};
  };
  int x0 = g.nx, x1 = -1, y0 = g.ny, y1 = -1;  // the newly blocked cells' bounds
  std::vector<std::size_t> rim;                // reached free cells next to them
  for (std::size_t k : newly) {
    const auto [x, y] = xy(k);
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    const int next[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= g.nx || n[1] >= g.ny) continue;
      const std::size_t c = g.at(n[0], n[1]);
      if (!w.blocked[c] && w.reached[c]) rim.push_back(c);
    }
  }
  for (std::size_t s : door_cells())
    if (w.blocked[s]) {  // a door walled in: what the flood fill says too
      restore();
      return false;
    }
  if (rim.size() > 1) {
    constexpr int kMargin = 10;  // cells (1 m) around the newly blocked ones
    const int wx0 = std::max(0, x0 - kMargin), wx1 = std::min(g.nx - 1, x1 + kMargin);
    const int wy0 = std::max(0, y0 - kMargin), wy1 = std::min(g.ny - 1, y1 + kMargin);
    const int ww = wx1 - wx0 + 1;
    std::vector<std::uint8_t> seen(static_cast<std::size_t>(ww) * static_cast<std::size_t>(wy1 - wy0 + 1), 0);
    const auto local = [&](std::size_t c) {
      const auto [x, y] = xy(c);
      return static_cast<std::size_t>(y - wy0) * static_cast<std::size_t>(ww) +
             static_cast<std::size_t>(x - wx0);
    };
    std::vector<std::size_t> queue{rim.front()};
    seen[local(rim.front())] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto [x, y] = xy(queue[head]);
      const int next[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
      for (const auto& n : next) {
        if (n[0] < wx0 || n[1] < wy0 || n[0] > wx1 || n[1] > wy1) continue;
        const std::size_t c = g.at(n[0], n[1]);
        if (w.blocked[c] || seen[local(c)]) continue;
        seen[local(c)] = 1;
        queue.push_back(c);
      }
    }
    if (!std::all_of(rim.begin(), rim.end(), [&](std::size_t c) { return seen[local(c)] != 0; })) {
      restore();
      return std::nullopt;
    }
  }
  for (std::size_t k : newly)
    if (w.reached[k]) {
      w.reached[k] = 0;
      lost.push_back(k);
    }
  // Every footprint must still have a reached cell within reach: the new one, and those whose
  // reach could have lost one.
  const double reach = WalkCells::kRadius + WalkCells::kReach;
  for (const Box& fb : boxes) {
    if (!newly.empty() && &fb != &added) {
      const auto [bx0, bx1, by0, by1] = g.range(fb, reach);
      if (bx1 < x0 || bx0 > x1 || by1 < y0 || by0 > y1) continue;
    } else if (&fb != &added) {
      continue;
    }
    if (!g.near(fb, w.reached)) {
      restore();
      return false;
    }
  }
  w.boxes.push_back(added);
  return true;
}

bool Placer::walkable(std::size_t from, std::vector<std::size_t>* drop) const {
  const WalkCells g(f_.box);
  std::vector<Box> boxes;
  std::vector<std::size_t> index_of;
  for (std::size_t k = 0; k < out_.entities.size(); ++k) {
    const EntitySpec& e = out_.entities[k];
    if (!may_reach(e, f_.box, 0.0)) continue;
    const Box eb = footprint_box(e.type, e.pose);
    if (!mine(eb)) continue;
    boxes.push_back(eb);
    index_of.push_back(k);
  }
  if (!drop && !doors_.empty()) {
    if (auto quick = walkable_after_one(boxes)) return *quick;
  }

  std::vector<std::uint8_t> blocked(g.size(), 0);
  for (int y = 0; y < g.ny; ++y)
    for (int x = 0; x < g.nx; ++x) {
      const Point c = g.centre(x, y);
      if (c.x - g.b.min.x < WalkCells::kRadius || g.b.max.x - c.x < WalkCells::kRadius ||
          c.y - g.b.min.y < WalkCells::kRadius || g.b.max.y - c.y < WalkCells::kRadius)
        blocked[g.at(x, y)] = 1;
    }
  for (const Box& fb : boxes) g.block(fb, blocked, nullptr);
  const std::vector<std::size_t> seeds = door_cells();
  for (std::size_t s : seeds)
    if (blocked[s]) return false;
  if (seeds.empty()) return true;
  std::vector<std::uint8_t> reached(blocked.size(), 0);
  std::vector<std::size_t> queue{seeds.front()};
  reached[seeds.front()] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int x = static_cast<int>(queue[head] % static_cast<std::size_t>(g.nx));
    const int y = static_cast<int>(queue[head] / static_cast<std::size_t>(g.nx));
    const int next[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= g.nx || n[1] >= g.ny) continue;
      const std::size_t k = g.at(n[0], n[1]);
      if (blocked[k] || reached[k]) continue;
      reached[k] = 1;
      queue.push_back(k);
    }
  }
  for (std::size_t s : seeds)
    if (!reached[s]) return false;
  bool ok = true;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    if (g.near(boxes[k], reached)) continue;
    const std::size_t index = index_of[k];
    if (drop && index >= from) {
      drop->push_back(index);
    } else {
      ok = false;
    }
  }
  if (ok && (!drop || drop->empty()))
    walk_ = WalkGrid{std::move(boxes), std::move(blocked), std::move(reached)};
  return ok;
}

void Placer::keep_walkable(std::size_t from) {
  std::vector<std::size_t> drop;
  const bool ok = walkable(from, &drop);
  if (ok && drop.empty()) return;  // everything reachable: walkable() would say so again
  if (!ok && drop.empty()) {
    while (out_.entities.size() > from && !walkable()) out_.entities.pop_back();
    return;
  }
  for (auto it = drop.rbegin(); it != drop.rend(); ++it)
    out_.entities.erase(out_.entities.begin() + static_cast<std::ptrdiff_t>(*it));
  while (out_.entities.size() > from && !walkable()) out_.entities.pop_back();
}

bool Placer::lane_clear(double u0, double v0, double u1, double v1, std::size_t keep,
                        std::size_t first_roi) const {
  const Box lane = geometry::bounds(f_.rect(u0, v0, u1, v1).outer);
  for (std::size_t k = 0; k < out_.entities.size(); ++k) {
    if (k == keep || !may_reach(out_.entities[k], f_.box, 0.0) ||
        !mine(footprint_box(out_.entities[k].type, out_.entities[k].pose)))
      continue;
    const EntitySpec& e = out_.entities[k];
    const bool serves =
        e.type == "counter" || e.type == "desk" || e.type == "reception" ||
        std::find(e.affordances.begin(), e.affordances.end(), "serve") != e.affordances.end() ||
        std::find(e.affordances.begin(), e.affordances.end(), "queue_target") != e.affordances.end();
    if (overlaps(lane, footprint_box(e.type, e.pose), serves ? 1.0 : 0.3)) return false;
  }
  const Box& b = lane;
  for (std::size_t k = first_roi; k < out_.rois.size(); ++k) {
    const Roi& o = out_.rois[k];
    if (o.kind == "corridor" || o.kind == "work_area") continue;
    const Box ob = geometry::bounds(o.polygon.outer);
    if (ob.min.x < b.max.x - 1e-9 && b.min.x < ob.max.x - 1e-9 && ob.min.y < b.max.y - 1e-9 &&
        b.min.y < ob.max.y - 1e-9)
      return false;
  }
  for (const auto& s : door_segments_)
    if (box_distance(lane, s) < 0.3) return false;
  return true;
}

std::optional<Area> Placer::roi(const std::string& kind, const std::string& suffix, double u0, double v0,
                                double u1, double v1, bool may_touch_doors) {
  u0 = std::max(u0, 0.1);
  v0 = std::max(v0, 0.1);
  u1 = std::min(u1, f_.len - 0.1);
  v1 = std::min(v1, f_.depth - 0.1);
  if (!may_touch_doors) {
    for (const auto& d : doors_) {
      const Point q = f_.local(d.centre);
      const double c = d.width / 2 + 0.3;
      if (q.x < u0 - c || q.x > u1 + c || q.y < v0 - c || q.y > v1 + c) continue;
      const double cuts[4][4] = {{u0, v0, u1, std::min(v1, q.y - c)},
                                 {u0, std::max(v0, q.y + c), u1, v1},
                                 {u0, v0, std::min(u1, q.x - c), v1},
                                 {std::max(u0, q.x + c), v0, u1, v1}};
      double best = -1.0;
      std::size_t pick = 0;
      for (std::size_t k = 0; k < 4; ++k) {
        const double a = std::max(0.0, cuts[k][2] - cuts[k][0]) * std::max(0.0, cuts[k][3] - cuts[k][1]);
        if (a > best) {
          best = a;
          pick = k;
        }
      }
      u0 = cuts[pick][0];
      v0 = cuts[pick][1];
      u1 = cuts[pick][2];
      v1 = cuts[pick][3];
    }
  }
  if (u1 - u0 < 0.5 || v1 - v0 < 0.5) return std::nullopt;
  out_.rois.push_back({zone_.name + "_" + suffix, kind, f_.rect(u0, v0, u1, v1)});
  return Area{u0, v0, u1, v1};
}

void Placer::poi_lanes(std::size_t first, std::size_t first_roi, double width, double length) {
  for (std::size_t k = first; k < out_.entities.size(); ++k) {
    EntitySpec& poi = out_.entities[k];
    if (poi.type != "water_dispenser" && poi.type != "coffee_machine" && poi.type != "vending_machine")
      continue;
    const Point at = f_.local({poi.pose.x, poi.pose.y});
    // Facing in room coordinates: the world yaw turned back by the frame's base heading.
    const double local = wrap(poi.pose.yaw - f_.yaw(0.0)) + kPi / 2;
    const int facing = static_cast<int>(std::lround(local / (kPi / 2))) & 3;  // 0 +u, 1 +v, 2 -u, 3 -v
    const auto [hu, hv] = half_extents(poi.type, 0.0);
    for (int turn : {0, 1, 3}) {
      const int dir = (facing + turn) & 3;
      const double du = dir == 0 ? 1.0 : dir == 2 ? -1.0 : 0.0, dv = dir == 1 ? 1.0 : dir == 3 ? -1.0 : 0.0;
      const double near = std::max(hu, hv) + 0.35, far = near + length;
      // Across the lane: centred on the machine, moved off the walls (the machine stays in it).
      auto across = [&](double c, double extent) {
        return std::clamp(c - width / 2, std::min(0.1, c - 0.05),
                          std::max(0.1, std::min(extent - 0.1 - width, c + 0.05 - width)));
      };
      const double u0 = du != 0 ? std::min(at.x + du * near, at.x + du * far) : across(at.x, len());
      const double u1 = du != 0 ? std::max(at.x + du * near, at.x + du * far) : u0 + width;
      const double v0 = dv != 0 ? std::min(at.y + dv * near, at.y + dv * far) : across(at.y, depth());
      const double v1 = dv != 0 ? std::max(at.y + dv * near, at.y + dv * far) : v0 + width;
      if (!inside(u0, v0, 0.1) || !inside(u1, v1, 0.1)) continue;
      if (!lane_clear(u0, v0, u1, v1, k, first_roi)) continue;
      const auto lane = roi("queue_lane", poi.name.substr(zone_.name.size() + 1) + "_queue", u0, v0, u1, v1);
      if (!lane) continue;
      if ((lane->u1 - lane->u0) * (lane->v1 - lane->v0) < (u1 - u0) * (v1 - v0) - 1e-6) {
        out_.rois.pop_back();  // cut by a door's swing: too short to queue in
        continue;
      }
      poi.affordances.push_back("queue_target");
      break;
    }
  }
}

int Placer::grid(const std::string& type, const std::string& base, double u0, double v0, double u1, double v1,
                 double du, double dv, int max_items, double local_yaw,
                 const std::vector<std::string>& affordances) {
  const int nu = std::max(0, static_cast<int>(std::floor((u1 - u0) / du + 1e-9)));
  const int nv = std::max(0, static_cast<int>(std::floor((v1 - v0) / dv + 1e-9)));
  const double su = u0 + ((u1 - u0) - nu * du) / 2 + du / 2;
  const double sv = v0 + ((v1 - v0) - nv * dv) / 2 + dv / 2;
  const auto [hu, hv] = half_extents(type, local_yaw);
  int placed = 0;
  for (int j = 0; j < nv && placed < max_items; ++j)
    for (int i = 0; i < nu && placed < max_items; ++i) {
      const double u = su + i * du, v = sv + j * dv;
      if (!inside(u, v, 0.0) || u - hu < kWallGap || v - hv < kWallGap || u + hu > f_.len - kWallGap ||
          v + hv > f_.depth - kWallGap)
        continue;
      const Point p = f_.at(u, v);
      const Pose2 pose{p.x, p.y, f_.yaw(local_yaw)};
      if (!box_free(footprint_box(type, pose), std::nullopt, Areas::kNone)) continue;
      std::string name;
      for (int k = placed + 1;; ++k) {
        name = zone_.name + "_" + numbered(base, k);
        if (std::none_of(out_.entities.begin(), out_.entities.end(),
                         [&](const EntitySpec& e) { return e.name == name; }))
          break;
      }
      out_.entities.push_back({type, name, pose, affordances});
      ++placed;
    }
  const std::size_t before = out_.entities.size();
  keep_walkable(before - static_cast<std::size_t>(placed));
  return placed - static_cast<int>(before - out_.entities.size());
}

std::optional<CounterPlace> Placer::counter_with_queue(const std::string& type, const std::string& name,
                                                       double u, double v, double lane, bool inward,
                                                       double lane_width,
                                                       std::vector<std::string> affordances) {
  const auto [hu, hv] = half_extents(type, inward ? 0.0 : kPi);
  v = std::clamp(v, hv + kWallGap, depth() - hv - kWallGap);
  lane = inward ? std::min(lane, depth() - v - hv - 0.3 - 1.0) : std::min(lane, v - hv - 0.3 - 0.9);
  if (lane < 1.5) return std::nullopt;
  for (double du : {0.0, -1.2, 1.2, -2.4, 2.4, -3.6, 3.6}) {
    const double uu = u + du;
    if (uu - hu < kWallGap || uu + hu > len() - kWallGap) continue;
    if (uu - lane_width / 2 < 0.1 || uu + lane_width / 2 > len() - 0.1) continue;
    const Point p = f_.at(uu, v);
    const Pose2 pose{p.x, p.y, f_.yaw(inward ? 0.0 : kPi)};
    if (!box_free(footprint_box(type, pose))) continue;
    const double v0 = inward ? v + hv + 0.3 : v - hv - 0.3 - lane;
    const Box lane_box =
        geometry::bounds(f_.rect(uu - lane_width / 2, v0, uu + lane_width / 2, v0 + lane).outer);
    // The lane may lead into the entrance area (people queue from the door) but not into another lane.
    if (!box_free(lane_box, std::nullopt, Areas::kLanes)) continue;
    if (!roi("queue_lane", name + "_queue", uu - lane_width / 2, v0, uu + lane_width / 2, v0 + lane, true))
      continue;
    out_.entities.push_back({type, zone_.name + "_" + name, pose, affordances});
    if (!walkable()) {
      out_.entities.pop_back();
      out_.rois.pop_back();
      continue;
    }
    return CounterPlace{uu, v, std::min(v0, v - hv), std::max(v0 + lane, v + hv)};
  }
  return std::nullopt;
}

std::vector<DoorAt> doors_of(const Zone& z, std::span<const Zone> zones, std::span<const DoorSpec> doors) {
  std::vector<DoorAt> here;
  for (const auto& d : doors) {
    const auto it = std::find(d.connects.begin(), d.connects.end(), z.name);
    if (it == d.connects.end()) continue;
    DoorAt a{d.pose.position(), d.width, d.connects.size() == 1, "", d.name};
    if (!a.exterior) {
      const std::string& other = d.connects[it == d.connects.begin() ? 1 : 0];
      for (const auto& o : zones)
        if (o.name == other) a.other_type = canonical_room_type(o.type);
    }
    here.push_back(std::move(a));
  }
  return here;
}

std::optional<Placer> placer_for(const Zone& z, std::span<const Zone> zones, std::span<const DoorSpec> doors,
                                 Furnishing& out) {
  const Box box = inner_box(z.polygon);
  if (box.width() < 1.0 || box.height() < 1.0) return std::nullopt;
  const std::vector<DoorAt> here = doors_of(z, zones, doors);
  const std::string type = canonical_room_type(z.type);
  const DoorAt* main = nullptr;
  auto pick = [&](auto pred) {
    for (const auto& d : here)
      if (!main && pred(d)) main = &d;
  };
  if (type == "sales_floor" || type == "dining_hall" || type == "lobby" || type == "reception" ||
      type == "security" || type == "concourse" || type == "ticket_hall" || type == "foyer" ||
      type == "main_hall" || type == "restaurant" || type == "mall_concourse" || type == "production_floor" ||
      type == "reading_room" || type == "assembly_seating")
    pick([](const DoorAt& d) { return d.exterior; });
  pick([](const DoorAt& d) { return !d.exterior && is_circulation_type(d.other_type); });
  pick([](const DoorAt&) { return true; });
  const int side = main ? nearest_side(box, main->centre) : 0;
  return Placer(z, Frame(box, side), here, out);
}

}  // namespace socsim::floorplan
