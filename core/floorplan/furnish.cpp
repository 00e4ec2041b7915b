#include "core/floorplan/furnish.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include "core/floorplan/rooms.hpp"
#include "core/geometry/geos.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/footprint.hpp"

namespace socsim::floorplan {
namespace {

using geometry::Box;
using geometry::MultiPolygon;
constexpr double kPi = std::numbers::pi;

double constraint(std::span<const knowledge::MergedConstraint> cs, std::string_view name) {
  for (const auto& c : cs)
    if (c.constraint.name == name) return c.constraint.value;
  return 0.0;
}

struct DoorAt {
  Point centre;
  double width = 0.0;
  bool exterior = false;
  std::string other_type;  // type of the zone on the other side ("" outside)
  std::string name;
};

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

// The largest axis-aligned box (of the bounding box's proportions, around a few candidate centres)
// inside the polygon; the bounding box itself for rectangles.
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

// A rectangle in room coordinates.
struct Area {
  double u0 = 0.0, v0 = 0.0, u1 = 0.0, v1 = 0.0;
};

// Where a counter and its queue lane went: counter at (u, v), the pair spans v_lo .. v_hi.
struct CounterPlace {
  double u = 0.0, v = 0.0, v_lo = 0.0, v_hi = 0.0;
};

// Room coordinates: u along the side with the main door, v from that side into the room.
struct Frame {
  Box box;
  int side = 0;  // 0 south, 1 east, 2 north, 3 west
  double len = 0.0;
  double depth = 0.0;

  Frame(Box b, int s) : box(b), side(s) {
    const bool horizontal = side == 0 || side == 2;
    len = horizontal ? b.width() : b.height();
    depth = horizontal ? b.height() : b.width();
  }
  [[nodiscard]] Point at(double u, double v) const {
    switch (side) {
      case 0:
        return {box.min.x + u, box.min.y + v};
      case 2:
        return {box.max.x - u, box.max.y - v};
      case 3:
        return {box.min.x + v, box.max.y - u};
      default:
        return {box.max.x - v, box.min.y + u};
    }
  }
  [[nodiscard]] Point local(Point p) const {
    switch (side) {
      case 0:
        return {p.x - box.min.x, p.y - box.min.y};
      case 2:
        return {box.max.x - p.x, box.max.y - p.y};
      case 3:
        return {box.max.y - p.y, p.x - box.min.x};
      default:
        return {p.y - box.min.y, box.max.x - p.x};
    }
  }
  // World yaw of a heading given relative to "into the room" (+v).
  [[nodiscard]] double yaw(double local) const {
    static constexpr double kBase[4] = {kPi / 2, kPi, -kPi / 2, 0.0};
    return wrap(kBase[side] + local);
  }
  [[nodiscard]] Polygon rect(double u0, double v0, double u1, double v1) const {
    std::vector<Point> ring{at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)};
    if (geometry::signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
    return Polygon{ring, {}};
  }
};

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

constexpr double kWallGap = 0.05;  // m between furniture and walls
constexpr double kDoorGap = 0.5;   // m kept free of furniture in front of a door opening
constexpr double kItemGap = 0.02;  // m between pieces of furniture (rows of seats touch)

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

// Places furniture of one room by footprint: inside the room's rectangle (clear of its walls),
// clear of its door openings, of the furniture already placed in it and of the areas that must
// stay free (queue lanes, aisles, entrances).
class Placer {
 public:
  Placer(const Zone& zone, const Frame& frame, std::vector<DoorAt> doors, Furnishing& out,
         std::size_t first_entity, std::size_t first_roi)
      : zone_(zone),
        f_(frame),
        doors_(std::move(doors)),
        out_(out),
        first_entity_(first_entity),
        first_roi_(first_roi) {
    for (const auto& d : doors_) {
      const int side = nearest_side(f_.box, d.centre);
      const bool horizontal = side == 0 || side == 2;
      const double h = d.width / 2;
      door_segments_.push_back(horizontal
                                   ? Segment{{d.centre.x - h, d.centre.y}, {d.centre.x + h, d.centre.y}}
                                   : Segment{{d.centre.x, d.centre.y - h}, {d.centre.x, d.centre.y + h}});
    }
  }

  [[nodiscard]] const Frame& frame() const { return f_; }
  [[nodiscard]] double len() const { return f_.len; }
  [[nodiscard]] double depth() const { return f_.depth; }
  [[nodiscard]] const Zone& zone() const { return zone_; }
  [[nodiscard]] std::size_t first_entity() const { return first_entity_; }

  [[nodiscard]] bool clear(Point p, double radius) const {
    for (const auto& d : doors_)
      if (geometry::distance(p, d.centre) < d.width / 2 + 0.6 + radius) return false;
    return true;
  }

  // Whether a box (world coordinates) keeps clear of the walls, the doors, the furniture of the
  // room (but `skip`) and the areas that must stay free.
  enum class Areas { kNone, kLanes, kAll };  // which kept-free areas a box must avoid
  [[nodiscard]] bool box_free(const Box& b, std::optional<std::size_t> skip = std::nullopt,
                              Areas areas = Areas::kAll) const {
    if (b.min.x < f_.box.min.x + kWallGap - 1e-9 || b.min.y < f_.box.min.y + kWallGap - 1e-9 ||
        b.max.x > f_.box.max.x - kWallGap + 1e-9 || b.max.y > f_.box.max.y - kWallGap + 1e-9)
      return false;
    for (const auto& s : door_segments_)
      if (box_distance(b, s) < kDoorGap) return false;
    for (std::size_t k = first_entity_; k < out_.entities.size(); ++k) {
      if (skip && *skip == k) continue;
      const EntitySpec& e = out_.entities[k];
      if (overlaps(b, footprint_box(e.type, e.pose), kItemGap)) return false;
    }
    if (areas != Areas::kNone) {
      for (std::size_t k = first_roi_; k < out_.rois.size(); ++k) {
        const Roi& r = out_.rois[k];
        const bool lane = r.kind == "queue_lane" || r.kind == "walkway";
        if (!lane && (areas == Areas::kLanes || (r.kind != "entrance" && r.kind != "exit"))) continue;
        if (overlaps(b, geometry::bounds(r.polygon.outer), 0.0)) return false;
      }
    }
    return true;
  }

  // Half extents along u and v of a footprint turned by `local_yaw` (quarter turns).
  [[nodiscard]] static std::pair<double, double> half_extents(const std::string& type, double local_yaw) {
    const Footprint fp = footprint_of(type);
    const bool across = std::abs(std::sin(local_yaw)) > 0.5;  // facing along ±u
    return across ? std::pair{fp.depth / 2, fp.width / 2} : std::pair{fp.width / 2, fp.depth / 2};
  }

  [[nodiscard]] std::optional<Point> fit(const std::string& type, double u, double v,
                                         double local_yaw) const {
    const auto [hu, hv] = half_extents(type, local_yaw);
    if (2 * (hu + kWallGap) > f_.len || 2 * (hv + kWallGap) > f_.depth) return std::nullopt;
    u = std::clamp(u, hu + kWallGap, f_.len - hu - kWallGap);
    v = std::clamp(v, hv + kWallGap, f_.depth - hv - kWallGap);
    const Point p = f_.at(u, v);
    if (!box_free(footprint_box(type, {p.x, p.y, f_.yaw(local_yaw)}))) return std::nullopt;
    return Point{u, v};
  }

  [[nodiscard]] bool inside(double u, double v, double margin) const {
    return u >= margin && v >= margin && u <= f_.len - margin && v <= f_.depth - margin;
  }

  // The first candidate (u, v) where the footprint fits (moved off the walls); then positions
  // sliding along the first candidate's line. nullopt when nothing fits.
  std::optional<Point> entity(const std::string& type, const std::string& suffix,
                              std::initializer_list<std::pair<double, double>> candidates, double local_yaw,
                              std::vector<std::string> affordances, double /*radius*/ = 0.4) {
    std::vector<std::pair<double, double>> tries(candidates);
    if (!tries.empty()) {
      const auto [u0, v0] = tries.front();
      for (int k = 1; k <= 40; ++k) {
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

  // Whether a person 0.5 m wide can still walk from each door of the room to every other door
  // and to every piece of furniture in it (within 0.4 m of its footprint). With `drop`, the
  // furniture placed since `from` that cannot be reached is listed instead of failing.
  bool walkable(std::size_t from = std::numeric_limits<std::size_t>::max(),
                std::vector<std::size_t>* drop = nullptr) const {
    constexpr double kRes = 0.1, kRadius = 0.25, kReach = 0.4;
    const Box& b = f_.box;
    const int nx = std::max(1, static_cast<int>(std::ceil(b.width() / kRes)));
    const int ny = std::max(1, static_cast<int>(std::ceil(b.height() / kRes)));
    auto centre = [&](int x, int y) { return Point{b.min.x + (x + 0.5) * kRes, b.min.y + (y + 0.5) * kRes}; };
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
    auto at = [&](int x, int y) {
      return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(x);
    };
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const Point c = centre(x, y);
        if (c.x - b.min.x < kRadius || b.max.x - c.x < kRadius || c.y - b.min.y < kRadius ||
            b.max.y - c.y < kRadius)
          blocked[at(x, y)] = 1;
      }
    std::vector<Box> boxes;
    for (std::size_t k = first_entity_; k < out_.entities.size(); ++k) {
      const EntitySpec& e = out_.entities[k];
      boxes.push_back(footprint_box(e.type, e.pose));
      const Box& fb = boxes.back();
      const int x0 = std::max(0, static_cast<int>(std::floor((fb.min.x - kRadius - b.min.x) / kRes)));
      const int x1 = std::min(nx - 1, static_cast<int>(std::floor((fb.max.x + kRadius - b.min.x) / kRes)));
      const int y0 = std::max(0, static_cast<int>(std::floor((fb.min.y - kRadius - b.min.y) / kRes)));
      const int y1 = std::min(ny - 1, static_cast<int>(std::floor((fb.max.y + kRadius - b.min.y) / kRes)));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const Point c = centre(x, y);
          const double dx = std::max({fb.min.x - c.x, 0.0, c.x - fb.max.x});
          const double dy = std::max({fb.min.y - c.y, 0.0, c.y - fb.max.y});
          if (std::hypot(dx, dy) < kRadius) blocked[at(x, y)] = 1;
        }
    }
    // Seeds just inside each door.
    std::vector<std::size_t> seeds;
    for (const auto& d : doors_) {
      const int side = nearest_side(b, d.centre);
      Point p = d.centre;
      const double in = kRadius + 0.1;
      if (side == 0) p.y = b.min.y + in;
      if (side == 1) p.x = b.max.x - in;
      if (side == 2) p.y = b.max.y - in;
      if (side == 3) p.x = b.min.x + in;
      const int x = std::clamp(static_cast<int>(std::floor((p.x - b.min.x) / kRes)), 0, nx - 1);
      const int y = std::clamp(static_cast<int>(std::floor((p.y - b.min.y) / kRes)), 0, ny - 1);
      if (blocked[at(x, y)]) return false;
      seeds.push_back(at(x, y));
    }
    if (seeds.empty()) return true;
    std::vector<std::uint8_t> reached(blocked.size(), 0);
    std::vector<std::size_t> queue{seeds.front()};
    reached[seeds.front()] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int x = static_cast<int>(queue[head] % static_cast<std::size_t>(nx));
      const int y = static_cast<int>(queue[head] / static_cast<std::size_t>(nx));
      const int next[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
      for (const auto& n : next) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= nx || n[1] >= ny) continue;
        const std::size_t k = at(n[0], n[1]);
        if (blocked[k] || reached[k]) continue;
        reached[k] = 1;
        queue.push_back(k);
      }
    }
    for (std::size_t s : seeds)
      if (!reached[s]) return false;
    bool ok = true;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      const Box& fb = boxes[k];
      bool near = false;
      const int x0 =
          std::max(0, static_cast<int>(std::floor((fb.min.x - kRadius - kReach - b.min.x) / kRes)));
      const int x1 =
          std::min(nx - 1, static_cast<int>(std::floor((fb.max.x + kRadius + kReach - b.min.x) / kRes)));
      const int y0 =
          std::max(0, static_cast<int>(std::floor((fb.min.y - kRadius - kReach - b.min.y) / kRes)));
      const int y1 =
          std::min(ny - 1, static_cast<int>(std::floor((fb.max.y + kRadius + kReach - b.min.y) / kRes)));
      for (int y = y0; y <= y1 && !near; ++y)
        for (int x = x0; x <= x1 && !near; ++x) {
          if (!reached[at(x, y)]) continue;
          const Point c = centre(x, y);
          const double dx = std::max({fb.min.x - c.x, 0.0, c.x - fb.max.x});
          const double dy = std::max({fb.min.y - c.y, 0.0, c.y - fb.max.y});
          near = std::hypot(dx, dy) <= kRadius + kReach - 0.05;
        }
      if (near) continue;
      const std::size_t index = first_entity_ + k;
      if (drop && index >= from) {
        drop->push_back(index);
      } else {
        ok = false;
      }
    }
    return ok;
  }

  // Removes the furniture placed since `from` that walls in a door or cannot be reached: the
  // unreachable pieces, then the last ones placed until the doors connect again.
  void keep_walkable(std::size_t from) {
    std::vector<std::size_t> drop;
    if (!walkable(from, &drop) && drop.empty()) {
      while (out_.entities.size() > from && !walkable()) out_.entities.pop_back();
      return;
    }
    for (auto it = drop.rbegin(); it != drop.rend(); ++it)
      out_.entities.erase(out_.entities.begin() + static_cast<std::ptrdiff_t>(*it));
    while (out_.entities.size() > from && !walkable()) out_.entities.pop_back();
  }

  // No furniture but entity `keep` within 0.5 m of the rectangle (1.3 m for serving furniture) and no area of
  // the room but corridors and work areas overlapping it (ROIs since `first_roi`).
  [[nodiscard]] bool lane_clear(double u0, double v0, double u1, double v1, std::size_t keep,
                                std::size_t first_roi) const {
    const Box lane = geometry::bounds(f_.rect(u0, v0, u1, v1).outer);
    for (std::size_t k = first_entity_; k < out_.entities.size(); ++k) {
      if (k == keep) continue;
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

  // A rectangular ROI in room coordinates, clamped inside and pulled back from the doors' swing
  // (the side that loses least is cut); dropped when it shrinks below 0.5 m.
  std::optional<Area> roi(const std::string& kind, const std::string& suffix, double u0, double v0, double u1,
                          double v1, bool may_touch_doors = false) {
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

  // A queue lane in front of each water dispenser, coffee machine or vending machine furnished
  // since `first` (entities) where there is room: `length` m straight out from it (its facing
  // first, then sideways), clear of the other furniture, the doors and the room's areas; the
  // machine then takes queue_target so the lane's head is at it.
  void poi_lanes(std::size_t first, std::size_t first_roi, double width, double length) {
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
        const auto lane =
            roi("queue_lane", poi.name.substr(zone_.name.size() + 1) + "_queue", u0, v0, u1, v1);
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

  // The same room seen from another side.
  [[nodiscard]] Placer turned(int side) const {
    return Placer(zone_, Frame(f_.box, side), doors_, out_, first_entity_, first_roi_);
  }
  [[nodiscard]] int side() const { return f_.side; }

  // Items on a grid of cells (du × dv) inside [u0, u1] × [v0, v1], each where its footprint fits.
  int grid(const std::string& type, const std::string& base, double u0, double v0, double u1, double v1,
           double du, double dv, int max_items, double local_yaw, const std::vector<std::string>& affordances,
           double /*radius*/ = 0.5) {
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
        out_.entities.push_back({type, zone_.name + "_" + numbered(base, placed + 1), pose, affordances});
        ++placed;
      }
    const std::size_t before = out_.entities.size();
    keep_walkable(before - static_cast<std::size_t>(placed));
    return placed - static_cast<int>(before - out_.entities.size());
  }

  // A counter at depth v with a queue lane of up to `lane` metres in front of it: towards the main
  // door (customers come in and queue towards a counter deeper in the room) or, when `inward`,
  // deeper into the room (a check-out by the door). Returns the u it was placed at.
  std::optional<CounterPlace> counter_with_queue(const std::string& type, const std::string& name, double u,
                                                 double v, double lane, bool inward, double lane_width,
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

 private:
  const Zone& zone_;
  Frame f_;
  std::vector<DoorAt> doors_;
  std::vector<Segment> door_segments_;
  Furnishing& out_;
  std::size_t first_entity_ = 0;
  std::size_t first_roi_ = 0;
};

// Waiting zone with chairs (tables in a cafe) on the half of the room away from the counter at u = cu.
// Waiting zone with chairs (tables in a cafe) in the largest part of the room the counter and its
// queue leave free: beside them, or before or beyond them.
void furnish_waiting(Placer& p, const std::string& type, const std::optional<CounterPlace>& counter) {
  const double L = p.len(), D = p.depth();
  const double cu = counter ? counter->u : L / 2;
  const bool on_left = cu > L / 2;
  std::vector<Area> areas{{on_left ? 0.3 : cu + 1.4, 1.6, on_left ? cu - 1.4 : L - 0.3, D - 0.4}};
  if (counter) {
    areas.push_back({0.3, 0.4, L - 0.3, counter->v_lo - 0.6});
    areas.push_back({0.3, counter->v_hi + 0.9, L - 0.3, D - 0.4});
  }
  const Area* best = nullptr;
  for (const auto& a : areas)
    if (a.u1 - a.u0 >= 1.4 && a.v1 - a.v0 >= 1.4 &&
        (!best || (a.u1 - a.u0) * (a.v1 - a.v0) > (best->u1 - best->u0) * (best->v1 - best->v0)))
      best = &a;
  if (type != "security" && best) {
    const bool cafe = type == "cafe";
    if (auto a = p.roi(cafe ? "seating_area" : "waiting_zone", cafe ? "seating" : "waiting", best->u0,
                       best->v0, best->u1, best->v1))
      p.grid(cafe ? "table" : "chair", cafe ? "table" : "chair", a->u0, a->v0, a->u1, a->v1, cafe ? 1.8 : 0.8,
             cafe ? 1.8 : 1.1, 24, 0,
             cafe ? std::vector<std::string>{"eat", "sit"} : std::vector<std::string>{"sit", "wait"},
             cafe ? 0.5 : 0.25);
  }
  if (type == "lobby" || type == "reception" || type == "concourse")
    p.entity("water_dispenser", "water_dispenser",
             {{on_left ? 0.4 : L - 0.4, D - 0.4}, {on_left ? 0.4 : L - 0.4, 1.2}}, 0, {"drink"}, 0.3);
}

void furnish_room(Placer& p, const std::string& type, const FurnishingRules& rules, Rng& rng, double area) {
  const double L = p.len(), D = p.depth();
  const double left = rng.chance(0.5) ? 0.45 : L - 0.45;  // corner for small appliances
  const double right = L - left;
  if (type == "bedroom") {
    p.entity("bed", "bed", {{L / 2, D - 1.1}, {L / 2, D / 2 + 0.3}}, kPi, {"lie", "sleep"}, 0.5);
    p.entity("wardrobe", "wardrobe", {{left, D - 0.4}, {right, D - 0.4}, {left, D / 2}}, kPi, {"store"}, 0.3);
  } else if (type == "living_room") {
    const auto sofa =
        p.entity("sofa", "sofa", {{L / 2, D - 0.6}, {L / 2, D / 2 + 0.5}}, kPi, {"sit", "rest"}, 0.5);
    if (sofa) {
      p.entity("coffee_table", "coffee_table", {{sofa->x, sofa->y - 1.0}}, 0, {"place"}, 0.3);
      p.roi("seating_area", "seating", sofa->x - 1.3, sofa->y - 1.6, sofa->x + 1.3, sofa->y + 0.5);
    }
    p.entity("tv", "tv", {{L / 2, 0.4}, {0.4, D / 2}, {L - 0.4, D / 2}}, 0, {"watch"}, 0.3);
  } else if (type == "kitchen" || type == "kitchenette" || type == "break_room" || type == "staff_room") {
    const bool cooking = type == "kitchen";
    p.entity("sink", "sink", {{L / 2, D - 0.4}, {0.4, D / 2}}, kPi, {"wash"}, 0.3);
    p.entity("fridge", "fridge", {{left, D - 0.4}, {right, D - 0.4}}, kPi, {"store_food"}, 0.3);
    if (cooking) {
      p.entity("stove", "stove", {{right, D - 0.4}, {left, D / 2}}, kPi, {"cook"}, 0.3);
      p.roi("work_area", "work_area", 0.2, D - 1.2, L - 0.2, D - 0.1);
    } else {
      p.entity("coffee_machine", "coffee_machine", {{right, D - 0.4}, {right, D / 2}}, kPi, {"drink"}, 0.3);
      p.entity("water_dispenser", "water_dispenser", {{left, D / 2}, {right, 0.9}}, 0, {"drink"}, 0.3);
    }
    if (area >= 9.0)
      p.entity("table", "table", {{L / 2, D / 2 - 0.3}, {L / 2, D / 2}}, 0, {"eat", "sit"}, 0.6);
  } else if (type == "bathroom" || type == "toilet") {
    p.entity("toilet", "toilet", {{left, D - 0.5}, {right, D - 0.5}}, kPi, {"use_toilet"}, 0.3);
    p.entity("sink", "sink", {{right, D - 0.35}, {left, D / 2}, {right, D / 2}}, kPi, {"wash"}, 0.25);
    if (type == "bathroom")
      p.entity("shower", "shower", {{right, 0.6}, {left, 0.6}, {L / 2, D - 0.6}}, 0, {"shower"}, 0.4);
  } else if (type == "storage") {
    p.grid("shelf", "shelf", 0.2, D - 0.8, L - 0.2, D - 0.1, 1.0, 0.7, 4, kPi, {"store", "pick"});
  } else if (type == "dining_room") {
    p.entity("dining_table", "dining_table", {{L / 2, D / 2}}, 0, {"eat", "sit"}, 0.7);
  } else if (type == "study") {
    p.entity("desk", "desk", {{L / 2, D - 0.8}}, kPi, {"work", "sit"}, 0.5);
  } else if (type == "open_office" || type == "classroom") {
    const int wanted = type == "open_office"
                           ? std::max(1, static_cast<int>(std::floor(area / rules.area_per_desk)))
                           : std::max(1, static_cast<int>(std::floor(area / 2.0)));
    const int n = p.grid("desk", "desk", 1.0, 1.4, L - 1.0, D - 1.0, type == "open_office" ? 1.8 : 1.3,
                         type == "open_office" ? 2.4 : 1.6, wanted, 0, {"work", "sit"});
    if (n > 0) p.roi("work_area", "desks", 0.8, 1.3, L - 0.8, D - 0.8, true);
    if (type == "open_office") {
      p.entity("water_dispenser", "water_dispenser", {{left, 0.5}, {right, 0.5}, {left, D - 0.4}}, 0,
               {"drink"}, 0.3);
      p.entity("printer", "printer", {{right, D - 0.4}, {left, D - 0.4}}, kPi, {"print"}, 0.3);
    } else {
      p.entity("teacher_desk", "teacher_desk", {{L / 2, 0.9}, {L / 2, D - 0.7}}, 0, {"teach"}, 0.5);
    }
  } else if (type == "private_office") {
    p.entity("desk", "desk", {{L / 2, D - 1.1}, {L / 2, D / 2}}, kPi, {"work", "sit"}, 0.5);
  } else if (type == "meeting_room") {
    p.entity("meeting_table", "table", {{L / 2, D / 2 + 0.3}, {L / 2, D / 2}}, 0, {"meet", "sit"}, 0.8);
    p.entity("whiteboard", "whiteboard", {{L / 2, D - 0.15}, {0.15, D / 2}}, kPi, {"present"}, 0.15);
  } else if (type == "reception" || type == "lobby" || type == "security" || type == "gate_area" ||
             type == "concourse" || type == "cafe") {
    const bool gate = type == "gate_area";
    const std::string counter = type == "security"    ? "checkpoint"
                                : gate                ? "gate_counter"
                                : type == "cafe"      ? "counter"
                                : type == "concourse" ? "info_desk"
                                                      : "reception_counter";
    // The side with the main door first; a room too shallow for a queue there turns a quarter.
    const double frac = rng.chance(0.5) ? 0.68 : 0.32;
    std::optional<CounterPlace> at;
    for (int turn : {0, 1, 3, 2}) {
      Placer q = p.turned((p.side() + turn) % 4);
      at = q.counter_with_queue("counter", counter, q.len() * frac,
                                std::min(q.depth() - 0.8, std::max(3.2, q.depth() * 0.7)), 4.0, false,
                                rules.queue_lane_width, {"serve", "queue_target"});
      if (at) {
        furnish_waiting(q, type, at);
        return;
      }
    }
    furnish_waiting(p, type, std::nullopt);
  } else if (type == "waiting_room") {
    if (auto a = p.roi("waiting_zone", "waiting", 0.4, 1.4, L - 0.4, D - 0.4))
      p.grid("chair", "chair", a->u0, a->v0, a->u1, a->v1, 0.8, 1.1, 24, 0, {"sit", "wait"}, 0.25);
    p.entity("water_dispenser", "water_dispenser", {{left, 0.5}, {right, 0.5}}, 0, {"drink"}, 0.3);
  } else if (type == "patient_room" || type == "icu_room") {
    const auto bed =
        p.entity("bed", "bed", {{L / 2, D - 1.3}, {L / 2, D / 2 + 0.4}}, kPi, {"lie", "visit"}, 0.6);
    if (bed) p.entity("chair", "chair", {{bed->x + 1.4, bed->y}, {bed->x - 1.4, bed->y}}, 0, {"sit"}, 0.3);
    p.entity(type == "icu_room" ? "monitor" : "sink", type == "icu_room" ? "monitor" : "sink",
             {{left, 1.0}, {right, 1.0}, {left, D - 0.4}}, 0, {type == "icu_room" ? "observe" : "wash"},
             0.25);
  } else if (type == "nurse_station") {
    p.entity("counter", "counter", {{L / 2, D / 2}, {L / 2, D - 1.0}}, kPi, {"serve", "queue_target"}, 0.6);
    p.entity("desk", "desk", {{left, D - 0.6}, {right, D - 0.6}}, kPi, {"work", "sit"}, 0.4);
    p.entity("medication_cart", "medication_cart", {{right, D - 0.5}, {left, 1.0}}, 0, {"restock"}, 0.3);
  } else if (type == "treatment_room") {
    p.entity("exam_table", "exam_table", {{L / 2, D - 1.2}, {L / 2, D / 2}}, kPi, {"examine", "lie"}, 0.5);
    p.entity("desk", "desk", {{left, D / 2}, {right, D / 2}}, 0, {"work", "sit"}, 0.4);
    p.entity("sink", "sink", {{right, 0.9}, {left, 0.9}}, 0, {"wash"}, 0.25);
  } else if (type == "dining_hall") {
    // Serving counter at the far side, its queue towards the main door; tables on both sides of it.
    const double cu = L * (rng.chance(0.5) ? 0.3 : 0.7);
    const auto at = p.counter_with_queue("counter", "serving_counter", cu, D - 1.0, 4.5, false,
                                         rules.queue_lane_width, {"serve", "queue_target"});
    const double gap = rules.queue_lane_width / 2 + 1.0;
    const double split = at ? at->u : -10.0;
    if (auto a = split - gap - 0.8 >= 2.0
                     ? p.roi("seating_area", "seating_01", 0.8, 1.6, split - gap, D - 0.6)
                     : std::nullopt)
      p.grid("table", "table_a", a->u0, a->v0, a->u1, a->v1, 2.0, 2.2, 40, 0, {"eat", "sit"});
    const double u0 = at ? split + gap : 0.8;
    if (auto a = L - 0.8 - u0 >= 2.0 ? p.roi("seating_area", "seating_02", u0, 1.6, L - 0.8, D - 0.6)
                                     : std::nullopt)
      p.grid("table", "table_b", a->u0, a->v0, a->u1, a->v1, 2.0, 2.2, 40, 0, {"eat", "sit"});
    p.entity("water_dispenser", "water_dispenser", {{0.5, D / 2}, {L - 0.5, D / 2}}, 0, {"drink"}, 0.3);
    p.entity("tray_return", "tray_return", {{L - 0.5, D * 0.3}, {0.5, D * 0.3}}, 0, {"return_tray"}, 0.3);
  } else if (type == "sales_floor" || type == "warehouse_floor" || type == "stock_room") {
    const bool shop = type == "sales_floor";
    double v_start = 1.4;
    if (shop) {
      const double lane = std::clamp(D * 0.3, 1.5, 3.5);
      p.counter_with_queue("counter", "checkout", L * (rng.chance(0.5) ? 0.3 : 0.7), 1.8, lane, true,
                           rules.queue_lane_width, {"pay", "queue_target"});
      v_start = 1.8 + 0.7 + lane + 0.6;
    } else if (type == "warehouse_floor") {
      p.roi("work_area", "staging", 0.8, 0.8, std::min(L - 0.8, 6.0), 3.0);
      v_start = 3.4;
    }
    // Rows of shelves or racks along u, walkway ROIs between them.
    const double shelf = type == "warehouse_floor" ? 1.1 : 0.6;
    const double walk = rules.walkway_width;
    int row = 0;
    for (double v = v_start; v + shelf + walk <= D - 0.3 && row < 12; v += shelf + walk) {
      ++row;
      p.roi("walkway", numbered("aisle", row), 0.6, v + shelf, L - 0.6, v + shelf + walk, true);
      p.grid(shop ? "shelf" : "rack", numbered(shop ? "shelf" : "rack", row), 1.0, v, L - 1.0, v + shelf, 2.0,
             shelf, 20, 0, {shop ? "browse" : "store", "pick"});
    }
  } else if (type == "loading_bay") {
    p.roi("work_area", "dock", 0.6, 0.6, L - 0.6, D - 0.6);
    p.grid("pallet", "pallet", 0.8, D - 2.0, L - 0.8, D - 0.6, 1.6, 1.4, 6, 0, {"pick", "store"});
  }
}

}  // namespace

FurnishingRules furnishing_rules(std::span<const knowledge::MergedConstraint> constraints,
                                 const PlanRequirement& plan) {
  FurnishingRules r;
  r.walkway_width = std::max({1.2, plan.walkway_width + 0.2});
  r.queue_lane_width = std::max(1.0, plan.queue_lane_width + 0.05);
  const double per_person = constraint(constraints, "workspace_area_per_person");
  const double volume = constraint(constraints, "workroom_volume_per_person");
  const double height = plan.ceiling_height > 0 ? std::max(plan.ceiling_height, 3.0) : 3.0;
  r.area_per_desk = std::max({8.0, per_person, volume / height});
  return r;
}

Furnishing furnish(std::span<const Zone> zones, std::span<const DoorSpec> doors, const FurnishingRules& rules,
                   Rng& rng) {
  Furnishing out;
  std::map<std::string, std::string> type_of;
  for (const auto& z : zones) type_of[z.name] = canonical_room_type(z.type);
  const bool named_entrance = std::any_of(doors.begin(), doors.end(), [](const DoorSpec& d) {
    return d.name == "main_entrance" && d.connects.size() == 1;
  });
  for (const auto& z : zones) {
    const std::string type = canonical_room_type(z.type);
    std::vector<DoorAt> here;
    for (const auto& d : doors) {
      const auto it = std::find(d.connects.begin(), d.connects.end(), z.name);
      if (it == d.connects.end()) continue;
      DoorAt a{d.pose.position(), d.width, d.connects.size() == 1, "", d.name};
      if (!a.exterior) a.other_type = type_of[d.connects[it == d.connects.begin() ? 1 : 0]];
      here.push_back(std::move(a));
    }
    const std::size_t zone_first_roi = out.rois.size();
    if (is_circulation_type(type) && !is_hall_type(type)) {
      out.rois.push_back({z.name + "_walk", "corridor", z.polygon});
    }
    // Entrance ROI just inside every door to the outside: "<zone>_entrance" for the main entrance
    // (or, in a plan without one, the zone's first outside door), "<zone>_<door>" of kind exit
    // for further exits.
    bool has_entrance = named_entrance;
    for (const auto& d : here) {
      if (!d.exterior) continue;
      const bool entrance = d.name == "main_entrance" || !has_entrance;
      has_entrance = true;
      const auto ring = z.polygon.outer;
      double best = 1e18;
      Segment wall{};
      for (const auto& e : geometry::edges(ring)) {
        const double dist = geometry::distance(e, d.centre);
        if (dist < best) {
          best = dist;
          wall = e;
        }
      }
      const double len = geometry::length(wall);
      if (len <= 0) continue;
      const Point u{(wall.b.x - wall.a.x) / len, (wall.b.y - wall.a.y) / len};
      Point n{-u.y, u.x};
      const Point c = geometry::closest_point(wall, d.centre);
      if (!geometry::contains(z.polygon, {c.x + n.x * 0.1, c.y + n.y * 0.1})) n = {-n.x, -n.y};
      // Half as wide as the door plus 0.2 m each side, narrowed to the wall (a corridor's end).
      const double h =
          std::min(d.width / 2 + 0.2, std::min(geometry::distance(c, wall.a), geometry::distance(c, wall.b)));
      if (h < d.width / 2 - 1e-9) continue;
      std::vector<Point> r{{c.x - u.x * h, c.y - u.y * h},
                           {c.x + u.x * h, c.y + u.y * h},
                           {c.x + u.x * h + n.x * 1.0, c.y + u.y * h + n.y * 1.0},
                           {c.x - u.x * h + n.x * 1.0, c.y - u.y * h + n.y * 1.0}};
      if (geometry::signed_area(r) < 0) std::reverse(r.begin(), r.end());
      const Polygon poly{r, {}};
      bool inside = true;
      for (const auto& p : r) inside = inside && geometry::contains(z.polygon, p, 1e-6);
      if (inside)
        out.rois.push_back(
            {entrance ? z.name + "_entrance" : z.name + "_" + d.name, entrance ? "entrance" : "exit", poly});
    }
    if (!find_room_type(type) || is_corridor_type(type)) continue;
    const Box box = inner_box(z.polygon);
    if (box.width() < 1.0 || box.height() < 1.0) continue;
    // Main door: the kitchen door of a dining hall, the entrance of a shop or lobby, else the door
    // to circulation, else the first.
    const DoorAt* main = nullptr;
    auto pick = [&](auto pred) {
      for (const auto& d : here)
        if (!main && pred(d)) main = &d;
    };
    if (type == "sales_floor" || type == "dining_hall" || type == "lobby" || type == "reception" ||
        type == "security" || type == "concourse")
      pick([](const DoorAt& d) { return d.exterior; });
    pick([](const DoorAt& d) { return !d.exterior && is_circulation_type(d.other_type); });
    pick([](const DoorAt&) { return true; });
    const int side = main ? nearest_side(box, main->centre) : 0;
    const std::size_t first_entity = out.entities.size(), first_roi = out.rois.size();
    Placer placer(z, Frame(box, side), here, out, first_entity, zone_first_roi);
    furnish_room(placer, type, rules, rng, geometry::area(z.polygon));
    placer.poi_lanes(first_entity, first_roi, rules.queue_lane_width, 2.2);
  }
  return out;
}

}  // namespace socsim::floorplan
