#include "core/world/layout_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>

#include "core/geometry/planar.hpp"
#include "core/world/footprint.hpp"
#include "core/world/occupancy_grid.hpp"

namespace socsim::world {
namespace {

using geometry::Box;

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// Separating-axis test on convex point sets: how deep they overlap along their least axis
// (<= 0 when they are apart or only touch). Axes are the edge normals of both.
double overlap_depth(std::span<const Point> a, std::span<const Point> b) {
  double least = std::numeric_limits<double>::infinity();
  auto axes_of = [&](std::span<const Point> poly) {
    const std::size_t n = poly.size();
    const std::size_t edges = n == 2 ? 1 : n;
    for (std::size_t i = 0; i < edges; ++i) {
      const Point p = poly[i], q = poly[(i + 1) % n];
      const double len = std::hypot(q.x - p.x, q.y - p.y);
      if (len < 1e-12) continue;
      const Point axis{-(q.y - p.y) / len, (q.x - p.x) / len};
      double amin = std::numeric_limits<double>::infinity(), amax = -amin, bmin = amin, bmax = -amin;
      for (const Point& v : a) {
        const double t = v.x * axis.x + v.y * axis.y;
        amin = std::min(amin, t);
        amax = std::max(amax, t);
      }
      for (const Point& v : b) {
        const double t = v.x * axis.x + v.y * axis.y;
        bmin = std::min(bmin, t);
        bmax = std::max(bmax, t);
      }
      least = std::min(least, std::min(amax, bmax) - std::max(amin, bmin));
    }
  };
  axes_of(a);
  axes_of(b);
  return least;
}

// The convex quad with every side moved inwards by `by` (exact for rectangles).
std::vector<Point> shrunk(const Polygon& quad, double by) {
  const auto& c = quad.outer;
  const std::size_t n = c.size();
  std::vector<Point> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Point p = c[i], next = c[(i + 1) % n], prev = c[(i + n - 1) % n];
    const double ln = std::max(geometry::distance(p, next), 1e-12),
                 lp = std::max(geometry::distance(p, prev), 1e-12);
    out.push_back({p.x + by * ((next.x - p.x) / ln + (prev.x - p.x) / lp),
                   p.y + by * ((next.y - p.y) / ln + (prev.y - p.y) / lp)});
  }
  return out;
}

// Whether the segment passes through the quad deeper than `tol` (touching is not crossing).
bool crosses(const Polygon& quad, const Segment& s, double tol) {
  const Point seg[2] = {s.a, s.b};
  return overlap_depth(shrunk(quad, tol), seg) >= 0;
}

double distance_to_quad(const Polygon& quad, Point p) {
  if (geometry::contains(quad, p)) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (const auto& e : geometry::edges(quad.outer)) d = std::min(d, geometry::distance(e, p));
  return d;
}

double segment_to_quad(const Polygon& quad, const Segment& s) {
  const Point seg[2] = {s.a, s.b};
  if (overlap_depth(quad.outer, seg) > 0) return 0.0;
  double d = std::min(distance_to_quad(quad, s.a), distance_to_quad(quad, s.b));
  for (const Point& c : quad.outer) d = std::min(d, geometry::distance(s, c));
  return d;
}

bool boxes_meet(const Box& a, const Box& b, double margin) {
  return a.min.x < b.max.x + margin && b.min.x < a.max.x + margin && a.min.y < b.max.y + margin &&
         b.min.y < a.max.y + margin;
}

}  // namespace

std::size_t LayoutCheck::count(std::string_view kind) const {
  return static_cast<std::size_t>(std::count_if(findings.begin(), findings.end(),
                                                [&](const LayoutFinding& f) { return f.kind == kind; }));
}

std::string LayoutCheck::summary() const {
  std::string out;
  for (std::size_t i = 0; i < findings.size() && i < 20; ++i) out += findings[i].message + "\n";
  if (findings.size() > 20) out += "… and " + std::to_string(findings.size() - 20) + " more\n";
  return out;
}

LayoutCheck check_layout(const World& world, const LayoutCheckOptions& opt) {
  LayoutCheck out;
  const double tol = opt.tolerance;
  auto add = [&](std::string kind, std::string element, std::string other, std::string message) {
    out.findings.push_back({std::move(kind), std::move(element), std::move(other), std::move(message)});
  };

  // Doors on the walls they join: the opening lies on the boundary of each of its zones.
  for (const Door& d : world.doors()) {
    for (auto z : {std::optional<ZoneId>(d.zone), d.other}) {
      if (!z) continue;
      const Polygon& poly = world.zone(*z).polygon;
      double worst = 0.0;
      for (const Point& p : {d.opening.a, d.opening.b}) {
        double best = std::numeric_limits<double>::infinity();
        for (const auto& e : geometry::edges(poly.outer)) best = std::min(best, geometry::distance(e, p));
        worst = std::max(worst, best);
      }
      if (worst > tol)
        add("door_off_wall", d.name, world.zone(*z).name,
            "door '" + d.name + "' is " + metres(worst) + " m off the wall of zone '" + world.zone(*z).name +
                "'");
    }
  }

  // Entities: footprints inside their zone, clear of walls, door openings and each other.
  const auto entities = world.entities();
  std::vector<Polygon> quads;
  std::vector<Box> boxes;
  for (const Entity& e : entities) {
    quads.push_back(footprint_polygon(e.type, e.pose));
    boxes.push_back(geometry::bounds(quads.back().outer));
  }
  out.entities_checked = entities.size();
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const Entity& e = entities[i];
    const Polygon& q = quads[i];
    const Zone& zone = world.zone(e.zone);
    bool inside = true;
    for (const Point& c : q.outer) inside = inside && geometry::contains(zone.polygon, c, tol);
    if (inside) {
      auto crossed = [&](std::span<const Point> ring) {
        for (const auto& edge : geometry::edges(ring))
          if (crosses(q, edge, tol)) return true;
        return false;
      };
      inside = !crossed(zone.polygon.outer);
      for (const auto& h : zone.polygon.holes) inside = inside && !crossed(h);
    }
    if (!inside)
      add("entity_outside_zone", e.name, zone.name,
          "entity '" + e.name + "' (" + e.type + ") does not fit inside zone '" + zone.name + "'");
    for (const Wall& w : world.walls()) {
      const Box wb = geometry::bounds(std::vector<Point>{w.segment.a, w.segment.b});
      if (!boxes_meet(boxes[i], wb, 0.0)) continue;
      if (crosses(q, w.segment, tol)) {
        add("entity_on_wall", e.name, "",
            "entity '" + e.name + "' (" + e.type + ") stands on the wall from (" + metres(w.segment.a.x) +
                ", " + metres(w.segment.a.y) + ") to (" + metres(w.segment.b.x) + ", " +
                metres(w.segment.b.y) + ")");
        break;
      }
    }
    for (const Door& d : world.doors()) {
      const Box db = geometry::bounds(std::vector<Point>{d.opening.a, d.opening.b});
      if (!boxes_meet(boxes[i], db, opt.door_clearance)) continue;
      const double gap = segment_to_quad(q, d.opening);
      if (gap < opt.door_clearance - tol) {
        add("entity_blocks_door", e.name, d.name,
            "entity '" + e.name + "' (" + e.type + ") is " + metres(gap) + " m from door '" + d.name + "' (" +
                metres(opt.door_clearance) + " m kept free)");
        break;
      }
    }
  }
  // Pairs: sweep along x.
  std::vector<std::size_t> order(entities.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].min.x < boxes[b].min.x || (boxes[a].min.x == boxes[b].min.x && a < b);
  });
  for (std::size_t x = 0; x < order.size(); ++x) {
    const std::size_t i = order[x];
    for (std::size_t y = x + 1; y < order.size(); ++y) {
      const std::size_t j = order[y];
      if (boxes[j].min.x >= boxes[i].max.x - tol) break;
      if (!boxes_meet(boxes[i], boxes[j], -tol)) continue;
      const double depth = overlap_depth(quads[i].outer, quads[j].outer);
      if (depth > tol) {
        const std::size_t a = std::min(i, j), b = std::max(i, j);
        add("entity_overlap", entities[a].name, entities[b].name,
            "entities '" + entities[a].name + "' (" + entities[a].type + ") and '" + entities[b].name +
                "' (" + entities[b].type + ") overlap by " + metres(depth) + " m");
      }
    }
  }

  // Reachability for a person of the given width: walls, the outline and every footprint
  // inflated by half that width; flooded from just inside the doors to the outside.
  const double radius = opt.person_width / 2;
  const OccupancyGrid grid =
      OccupancyGrid::rasterise(world, GridOptions{opt.resolution, radius, opt.max_cells});
  std::vector<std::uint8_t> blocked(grid.blocked_cells().begin(), grid.blocked_cells().end());
  const double res = grid.resolution();
  auto cells_near = [&](const Box& b, double margin, auto&& fn) {
    const int x0 = std::max(0, static_cast<int>(std::floor((b.min.x - margin - grid.origin().x) / res)));
    const int x1 =
        std::min(grid.width() - 1, static_cast<int>(std::floor((b.max.x + margin - grid.origin().x) / res)));
    const int y0 = std::max(0, static_cast<int>(std::floor((b.min.y - margin - grid.origin().y) / res)));
    const int y1 =
        std::min(grid.height() - 1, static_cast<int>(std::floor((b.max.y + margin - grid.origin().y) / res)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) fn(Cell{x, y});
  };
  for (std::size_t i = 0; i < entities.size(); ++i) {
    cells_near(boxes[i], radius, [&](Cell c) {
      if (distance_to_quad(quads[i], grid.center(c)) < radius) blocked[grid.index(c)] = 1;
    });
  }
  std::vector<std::uint8_t> reached(blocked.size(), 0);
  std::deque<Cell> queue;
  auto seed = [&](Point p) {
    const auto c = grid.cell_of(p);
    if (!c || blocked[grid.index(*c)] || reached[grid.index(*c)]) return;
    reached[grid.index(*c)] = 1;
    queue.push_back(*c);
  };
  bool any_exterior = false;
  for (const Door& d : world.doors()) {
    if (d.other) continue;
    any_exterior = true;
    const Point a = d.opening.a, b = d.opening.b;
    const Point mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
    const double len = std::max(geometry::distance(a, b), 1e-9);
    const Point n{-(b.y - a.y) / len, (b.x - a.x) / len};
    for (double s : {radius + 0.15, -(radius + 0.15), radius + 0.3, -(radius + 0.3)}) {
      const Point p{mid.x + n.x * s, mid.y + n.y * s};
      if (geometry::contains(world.zone(d.zone).polygon, p)) seed(p);
    }
  }
  if (!any_exterior && !world.zones().empty()) {
    // A world without a door to the outside: flood from the first zone's free cells.
    for (int y = 0; y < grid.height(); ++y)
      for (int x = 0; x < grid.width(); ++x) {
        const Cell c{x, y};
        const auto z = grid.zone_of(c);
        if (z && z->index() == 0 && !blocked[grid.index(c)] && !reached[grid.index(c)]) {
          reached[grid.index(c)] = 1;
          queue.push_back(c);
        }
      }
  }
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    const Cell next[4] = {{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}};
    for (const Cell& m : next) {
      if (!grid.in_bounds(m)) continue;
      const std::size_t k = grid.index(m);
      if (blocked[k] || reached[k]) continue;
      reached[k] = 1;
      queue.push_back(m);
    }
  }
  std::vector<bool> zone_reached(world.zones().size(), false);
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x) {
      const Cell c{x, y};
      if (!reached[grid.index(c)]) continue;
      if (const auto z = grid.zone_of(c)) zone_reached[z->index()] = true;
    }
  for (std::size_t z = 0; z < zone_reached.size(); ++z) {
    if (!zone_reached[z])
      add("zone_unreachable", world.zones()[z].name, "",
          "zone '" + world.zones()[z].name + "' cannot be reached from outside by a person " +
              metres(opt.person_width) + " m wide");
  }
  for (std::size_t i = 0; i < entities.size(); ++i) {
    bool ok = false;
    cells_near(boxes[i], radius + opt.reach, [&](Cell c) {
      if (!ok && reached[grid.index(c)] && distance_to_quad(quads[i], grid.center(c)) <= radius + opt.reach)
        ok = true;
    });
    if (ok) {
      ++out.reachable_entities;
    } else {
      add("entity_unreachable", entities[i].name, "",
          "entity '" + entities[i].name + "' (" + entities[i].type + ") cannot be reached by a person " +
              metres(opt.person_width) + " m wide");
    }
  }
  return out;
}

}  // namespace socsim::world
