#include "core/world/world_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "core/geometry/geos.hpp"
#include "core/geometry/planar.hpp"
#include "core/geometry/segment_index.hpp"
#include "core/world/occupancy_grid.hpp"

namespace socsim::world {

namespace {

using geometry::Geos;
using geometry::MultiPolygon;
using geometry::SegmentIndex;

constexpr std::size_t kMaxNameLength = 128;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string pt(Point p) {
  return "(" + num(p.x) + ", " + num(p.y) + ")";
}

bool coordinate(double v) {
  return std::isfinite(v) && std::abs(v) <= kMaxCoordinate;
}
// Finite and within ±kMaxCoordinate.
bool finite(Point p) {
  return coordinate(p.x) && coordinate(p.y);
}
bool finite(const Pose2& p) {
  return coordinate(p.x) && coordinate(p.y) && std::isfinite(p.yaw);
}
// Above this many vertices (two zones, or a zone and the plan), shared boundaries are computed
// from capsules instead of a GEOS buffer (see host_of in build).
constexpr std::size_t kExactBoundaryVertices = 2000;

const std::string kOutOfRange = "must be finite and within ±100000 m";

// Names are referenced from behaviour trees, XML and SVG ids: keep them to a safe alphabet.
std::optional<std::string> name_problem(const std::string& name) {
  if (name.empty()) return "must not be empty";
  if (name.size() > kMaxNameLength)
    return "must be at most " + std::to_string(kMaxNameLength) + " characters";
  for (const char ch : name) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                    ch == '_' || ch == '-' || ch == '.';
    if (!ok) return "'" + name + "' may only contain letters, digits, '_', '-' and '.'";
  }
  return std::nullopt;
}

// Free-text labels (types, materials, styles, affordances): printable, bounded.
std::optional<std::string> label_problem(const std::string& s, bool allow_empty) {
  if (s.empty()) return allow_empty ? std::nullopt : std::optional<std::string>("must not be empty");
  if (s.size() > kMaxNameLength) return "must be at most " + std::to_string(kMaxNameLength) + " characters";
  for (const char ch : s) {
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) return "must not contain control characters";
  }
  return std::nullopt;
}

double distance_to_boundary(const Polygon& poly, Point p) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& e : geometry::edges(poly.outer)) d = std::min(d, geometry::distance(e, p));
  for (const auto& h : poly.holes) {
    for (const auto& e : geometry::edges(h)) d = std::min(d, geometry::distance(e, p));
  }
  return d;
}

// Every zone edge in one spatial index: which zones' boundaries pass near a point, without
// comparing the point with every edge of every zone (quadratic for large worlds).
class ZoneBoundaries {
 public:
  explicit ZoneBoundaries(const std::vector<Zone>& zones) {
    std::vector<Segment> all;
    for (std::size_t z = 0; z < zones.size(); ++z) {
      auto add = [&](const std::vector<Point>& ring) {
        for (const auto& e : geometry::edges(ring)) {
          all.push_back(e);
          zone_.push_back(z);
        }
      };
      add(zones[z].polygon.outer);
      for (const auto& h : zones[z].polygon.holes) add(h);
    }
    index_ = SegmentIndex(std::move(all));
  }
  // (distance, zone) of every zone whose boundary is within `radius` of p, nearest first.
  [[nodiscard]] std::vector<std::pair<double, std::size_t>> within(Point p, double radius) const {
    std::map<std::size_t, double> best;
    for (std::size_t e : index_.within(p, radius)) {
      const double d = geometry::distance(index_.segment(e), p);
      auto [it, fresh] = best.emplace(zone_[e], d);
      if (!fresh) it->second = std::min(it->second, d);
    }
    std::vector<std::pair<double, std::size_t>> out;
    for (const auto& [z, d] : best) out.emplace_back(d, z);
    std::sort(out.begin(), out.end());
    return out;
  }
  // The first zone (lowest index) whose boundary is within `radius` of p.
  [[nodiscard]] std::optional<std::size_t> first_within(Point p, double radius) const {
    const auto edges = index_.within(p, radius);
    if (edges.empty()) return std::nullopt;
    return zone_[edges.front()];  // edges are numbered zone by zone
  }
  // (distance, zone) of the nearest zone boundary (the lowest zone among equals).
  [[nodiscard]] std::pair<double, std::size_t> nearest(Point p) const {
    const auto n = index_.nearest(p);
    if (!n) return {std::numeric_limits<double>::infinity(), 0};
    return {n->distance, zone_[n->index]};
  }

 private:
  SegmentIndex index_;
  std::vector<std::size_t> zone_;  // of each edge
};

class Validator {
 public:
  void add(std::string pointer, std::string message) {
    errors_.push_back(FieldError{std::move(pointer), std::move(message)});
  }
  [[nodiscard]] bool ok() const { return errors_.empty(); }
  [[nodiscard]] tl::unexpected<Error> failure() const {
    return fail(ErrorCode::kValidation,
                "the world is not valid (" + std::to_string(errors_.size()) + " problem" +
                    (errors_.size() == 1 ? "" : "s") + ")",
                errors_);
  }

  void name(const std::string& ptr, const std::string& value, std::map<std::string, std::string>& seen) {
    if (auto p = name_problem(value)) {
      add(ptr, *p);
      return;
    }
    auto [it, inserted] = seen.emplace(value, ptr);
    if (!inserted) add(ptr, "duplicate name '" + value + "' (already used at " + it->second + ")");
  }
  void label(const std::string& ptr, const std::string& value, bool allow_empty) {
    if (auto p = label_problem(value, allow_empty)) add(ptr, *p);
  }
  bool polygon(const Geos& geos, const std::string& ptr, const Polygon& poly, const std::string& owner) {
    bool in_range = true;
    for (std::size_t i = 0; i < poly.outer.size(); ++i)
      if (!finite(poly.outer[i])) {
        add(ptr + "/" + std::to_string(i), owner + ": a vertex " + kOutOfRange);
        in_range = false;
        break;
      }
    for (const auto& hole : poly.holes)
      if (in_range && !std::all_of(hole.begin(), hole.end(), [](Point p) { return finite(p); })) {
        add(ptr, owner + ": a hole's vertex " + kOutOfRange);
        in_range = false;
      }
    if (!in_range) return false;
    const auto v = geos.validity(poly);
    if (!v.valid) {
      std::string msg = owner + " has an invalid polygon: " + v.reason;
      if (v.location) msg += " at " + pt(*v.location);
      add(ptr, msg);
      return false;
    }
    if (geometry::area(poly) <= 1e-9) {
      add(ptr, owner + " has a polygon of zero area");
      return false;
    }
    return true;
  }

 private:
  std::vector<FieldError> errors_;
};

std::string zone_ptr(std::size_t i) {
  return "/zones/" + std::to_string(i);
}
std::string door_ptr(std::size_t i) {
  return "/doors/" + std::to_string(i);
}

std::string box_text(const geometry::Box& b) {
  return "x " + num(b.min.x) + " .. " + num(b.max.x) + ", y " + num(b.min.y) + " .. " + num(b.max.y);
}

bool has_region(const Polygon& p) {
  return !p.outer.empty();
}

// The parts of `s` that no collinear segment of `cover` runs along.
std::vector<Segment> uncovered_parts(const Segment& s, std::span<const Wall> cover, double tol) {
  const double len = geometry::length(s);
  if (len <= tol) return {};
  const Point u{(s.b.x - s.a.x) / len, (s.b.y - s.a.y) / len};
  auto along = [&](Point p) { return (p.x - s.a.x) * u.x + (p.y - s.a.y) * u.y; };
  auto off = [&](Point p) { return std::abs((p.x - s.a.x) * u.y - (p.y - s.a.y) * u.x); };
  std::vector<std::pair<double, double>> covered;
  for (const auto& w : cover) {
    if (off(w.segment.a) > tol || off(w.segment.b) > tol) continue;
    // By value: minmax of two temporaries would return references to them.
    const auto [lo, hi] = std::minmax({along(w.segment.a), along(w.segment.b)});
    if (hi > tol && lo < len - tol) covered.emplace_back(std::max(lo, 0.0), std::min(hi, len));
  }
  std::sort(covered.begin(), covered.end());
  std::vector<Segment> out;
  double from = 0.0;
  auto at = [&](double t) {
    return t <= 0.0 ? s.a : t >= len ? s.b : Point{s.a.x + u.x * t, s.a.y + u.y * t};
  };
  for (const auto& [lo, hi] : covered) {
    if (lo - from > tol) out.push_back({at(from), at(lo)});
    from = std::max(from, hi);
  }
  if (len - from > tol) out.push_back({at(from), s.b});
  return out;
}

// Regions for zones written by name only (paper 001, Fig. 3). The one such zone of a world
// takes what its walls (and door gaps) enclose, less the zones that have polygons; when the walls enclose
// nothing, the rectangle spanned by everything written (walls, door centres, segmentation
// areas, entities). Returns the index of the zone given a region.
std::optional<std::size_t> infer_zone_region(const Geos& geos, std::vector<Zone>& zones,
                                             const std::vector<Wall>& walls,
                                             const std::vector<DoorSpec>& doors, const std::vector<Roi>& rois,
                                             const std::vector<EntitySpec>& entities, const BuildOptions& opt,
                                             Validator& v, std::vector<FieldError>* warnings) {
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < zones.size(); ++i) {
    if (!has_region(zones[i].polygon)) open.push_back(i);
  }
  if (open.empty()) return std::nullopt;
  for (std::size_t k = 1; k < open.size(); ++k) {
    v.add(zone_ptr(open[k]) + "/polygon",
          "zone '" + zones[open[k]].name + "' has no polygon; only one zone of a world may take its region " +
              "from the walls (zone '" + zones[open[0]].name + "' at " + zone_ptr(open[0]) +
              " does), so give it a polygon");
  }
  const std::size_t z = open[0];
  const std::string ptr = zone_ptr(z) + "/polygon";
  const std::string who = "zone '" + zones[z].name + "' has no polygon";
  MultiPolygon given;
  for (const auto& other : zones) {
    if (has_region(other.polygon) && geos.validity(other.polygon).valid) given.push_back(other.polygon);
  }
  const double tol = opt.boundary_tolerance;
  auto without_given = [&](MultiPolygon region) {
    if (!given.empty()) region = geos.difference(region, geos.unite(given));
    MultiPolygon kept;
    for (auto& part : region) {
      if (geometry::area(part) > opt.overlap_tolerance) kept.push_back(std::move(part));
    }
    return kept;
  };

  std::vector<Segment> lines;
  for (const auto& w : walls) {
    if (finite(w.segment.a) && finite(w.segment.b) && geometry::length(w.segment) > tol)
      lines.push_back(w.segment);
  }
  // Walls are written with gaps where the doors are: a door closes the gap between two wall
  // ends its width apart around its centre.
  const std::size_t wall_lines = lines.size();
  for (const auto& d : doors) {
    if (!finite(d.pose) || !(d.width > 0)) continue;
    const Point c = d.pose.position();
    const double reach = d.width / 2 + opt.door_snap_distance;
    std::vector<Point> ends;
    for (std::size_t k = 0; k < wall_lines; ++k) {
      for (const Point& p : {lines[k].a, lines[k].b}) {
        if (geometry::distance(p, c) <= reach) ends.push_back(p);
      }
    }
    for (std::size_t a = 0; a < ends.size(); ++a) {
      for (std::size_t b = a + 1; b < ends.size(); ++b) {
        const Point mid{(ends[a].x + ends[b].x) / 2, (ends[a].y + ends[b].y) / 2};
        if (std::abs(geometry::distance(ends[a], ends[b]) - d.width) <= tol &&
            geometry::distance(mid, c) <= opt.door_snap_distance)
          lines.push_back({ends[a], ends[b]});
      }
    }
  }
  MultiPolygon enclosed = lines.empty() ? MultiPolygon{} : geos.polygonize(lines);
  if (!enclosed.empty()) enclosed = without_given(geos.unite(enclosed));
  if (enclosed.size() > 1) {
    v.add(ptr, who + " and the walls enclose " + std::to_string(enclosed.size()) + " separate regions (" +
                   box_text(geometry::bounds(enclosed)) + "); give the zone a polygon");
    return std::nullopt;
  }
  if (enclosed.size() == 1) {
    zones[z].polygon = enclosed[0];
    if (warnings) {
      warnings->push_back(FieldError{ptr, who + ": it takes the region its walls enclose, " +
                                              box_text(geometry::bounds(enclosed)) + " (" +
                                              num(geometry::area(enclosed[0])) + " m²)"});
    }
    return z;
  }

  // The walls close nothing: the rectangle spanned by what the file places in the zone.
  std::vector<Point> points;
  for (std::size_t k = 0; k < wall_lines; ++k) points.insert(points.end(), {lines[k].a, lines[k].b});
  for (const auto& r : rois) {
    for (const Point& p : r.polygon.outer) {
      if (finite(p)) points.push_back(p);
    }
  }
  if (rois.empty()) {
    v.add(ptr, who + ", its walls enclose no region and there are no segmentation areas to span one; " +
                   "give it a polygon or walls that close around it");
    return std::nullopt;
  }
  for (const auto& d : doors) {
    if (finite(d.pose)) points.push_back(d.pose.position());
  }
  for (const auto& e : entities) {
    if (finite(e.pose)) points.push_back(e.pose.position());
  }
  const geometry::Box box = geometry::bounds(points);
  const MultiPolygon region = without_given(MultiPolygon{Polygon{
      {{box.min.x, box.min.y}, {box.max.x, box.min.y}, {box.max.x, box.max.y}, {box.min.x, box.max.y}}, {}}});
  if (box.max.x - box.min.x <= tol || box.max.y - box.min.y <= tol || region.size() != 1) {
    v.add(ptr, who + ", its walls enclose no region and the rectangle its walls, doors, segmentation " +
                   "areas and entities span (" + box_text(box) + ") " +
                   (region.empty() ? "has no area outside the other zones" : "is not one region") +
                   "; give it a polygon");
    return std::nullopt;
  }
  zones[z].polygon = region[0];
  if (warnings) {
    warnings->push_back(
        FieldError{ptr, who + " and its walls enclose no region: it takes the rectangle " + box_text(box) +
                            " (" + num(geometry::area(region[0])) +
                            " m²) spanned by the walls, doors, segmentation areas and entities"});
  }
  return z;
}

}  // namespace

WorldBuilder& WorldBuilder::set_name(std::string name) {
  name_ = std::move(name);
  return *this;
}
WorldBuilder& WorldBuilder::set_origin(Pose2 origin) {
  origin_ = origin;
  return *this;
}
WorldBuilder& WorldBuilder::set_floor(Floor floor) {
  floor_ = std::move(floor);
  return *this;
}
ZoneId WorldBuilder::add_zone(Zone zone) {
  zones_.push_back(std::move(zone));
  return ZoneId(static_cast<std::uint32_t>(zones_.size() - 1));
}
WorldBuilder& WorldBuilder::add_wall(Wall wall) {
  walls_.push_back(std::move(wall));
  return *this;
}
WorldBuilder& WorldBuilder::add_door(DoorSpec door) {
  doors_.push_back(std::move(door));
  return *this;
}
WorldBuilder& WorldBuilder::add_roi(Roi roi) {
  rois_.push_back(std::move(roi));
  return *this;
}
WorldBuilder& WorldBuilder::add_entity(EntitySpec entity) {
  entities_.push_back(std::move(entity));
  return *this;
}

std::vector<Wall> derive_walls(const std::vector<Zone>& zones, const std::vector<Door>& doors,
                               const BuildOptions& options, const std::vector<Segment>* lines) {
  Geos geos;
  std::vector<Segment> own;
  if (lines == nullptr) {
    MultiPolygon polys;
    for (const auto& z : zones) polys.push_back(z.polygon);
    own = geos.boundary_segments(polys);
    lines = &own;
  }
  const double tol = options.boundary_tolerance;
  const ZoneBoundaries boundaries(zones);
  std::vector<Segment> openings;
  for (const auto& d : doors) openings.push_back(d.opening);
  const SegmentIndex door_index(std::move(openings));
  std::vector<Wall> walls;
  for (const Segment& s : *lines) {
    const double len = geometry::length(s);
    if (len <= tol) continue;
    const Point u{(s.b.x - s.a.x) / len, (s.b.y - s.a.y) / len};
    // Door openings collinear with this boundary piece, as intervals along it; the cut
    // points are the openings' own end points (no rounding drift from re-projection).
    struct Cut {
      double t0, t1;
      Point p0, p1;
    };
    std::vector<Cut> cuts;
    auto along = [&](Point p) { return (p.x - s.a.x) * u.x + (p.y - s.a.y) * u.y; };
    auto off = [&](Point p) { return std::abs((p.x - s.a.x) * u.y - (p.y - s.a.y) * u.x); };
    for (std::size_t k : door_index.within(s, tol)) {  // an opening on s lies within tol of it
      const Door& d = doors[k];
      if (off(d.opening.a) > tol || off(d.opening.b) > tol) continue;
      Cut c{along(d.opening.a), along(d.opening.b), d.opening.a, d.opening.b};
      if (c.t0 > c.t1) std::swap(c.t0, c.t1), std::swap(c.p0, c.p1);
      if (c.t0 <= 0.0) c.t0 = 0.0, c.p0 = s.a;
      if (c.t1 >= len) c.t1 = len, c.p1 = s.b;
      if (c.t1 - c.t0 > tol) cuts.push_back(c);
    }
    std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.t0 < y.t0; });
    std::vector<Cut> pieces;  // the parts that stay wall
    Cut from{0.0, 0.0, s.a, s.a};
    for (const auto& c : cuts) {
      if (c.t0 > from.t1) pieces.push_back(Cut{from.t1, c.t0, from.p1, c.p0});
      if (c.t1 > from.t1) from = Cut{0.0, c.t1, s.a, c.p1};
    }
    if (from.t1 < len) pieces.push_back(Cut{from.t1, len, from.p1, s.b});
    for (const auto& piece : pieces) {
      if (piece.t1 - piece.t0 <= tol) continue;
      const Point mid{(piece.p0.x + piece.p1.x) / 2, (piece.p0.y + piece.p1.y) / 2};
      std::string style = options.default_wall_style;
      if (auto z = boundaries.first_within(mid, tol); z && !zones[*z].material.empty())
        style = zones[*z].material;
      walls.push_back(Wall{{piece.p0, piece.p1}, options.default_wall_height, style});
    }
  }
  return walls;
}

Result<World> WorldBuilder::build(const BuildOptions& opt, std::vector<FieldError>* warnings,
                                  BuildCache* cache) const {
  Validator v;
  if (!(opt.agent_radius >= 0 && std::isfinite(opt.agent_radius)) || !(opt.boundary_tolerance > 0) ||
      !(opt.door_snap_distance >= 0) || !(opt.overlap_tolerance >= 0) || !(opt.grid_resolution > 0) ||
      !(opt.default_wall_height > 0)) {
    return fail(
        ErrorCode::kValidation, "world build options out of range",
        {FieldError{"",
                    "agent_radius, tolerances, grid_resolution and default_wall_height must be positive"}});
  }
  Geos geos;
  std::map<std::string, std::string> names;
  std::vector<Zone> zones = zones_;
  std::vector<FieldError> notes;
  std::optional<std::size_t> inferred;
  try {
    inferred = infer_zone_region(geos, zones, walls_, doors_, rois_, entities_, opt, v, &notes);
  } catch (const geometry::GeosError& e) {
    return fail(ErrorCode::kValidation, std::string("geometry check failed: ") + e.what());
  }

  // 1. Each element on its own: names, labels, numbers, polygon validity.
  if (auto p = label_problem(name_, true)) v.add("/name", *p);
  bool out_of_range = false;
  const auto check_point = [&](const std::string& ptr, bool ok) {
    if (!ok) v.add(ptr, kOutOfRange);
    out_of_range = out_of_range || !ok;
  };
  check_point("/origin", finite(origin_));
  v.label("/floor/material", floor_.material, true);
  std::vector<bool> zone_ok(zones.size(), false);
  for (std::size_t i = 0; i < zones.size(); ++i) {
    const auto& z = zones[i];
    const std::string ptr = zone_ptr(i);
    v.name(ptr + "/name", z.name, names);
    v.label(ptr + "/type", z.type, false);
    v.label(ptr + "/material", z.material, true);
    // A zone whose region could not be inferred has its error already.
    zone_ok[i] =
        has_region(z.polygon) && v.polygon(geos, ptr + "/polygon", z.polygon, "zone '" + z.name + "'");
  }
  if (zones.empty()) v.add("/zones", "a world needs at least one zone");
  for (std::size_t i = 0; i < walls_.size(); ++i) {
    const auto& w = walls_[i];
    const std::string ptr = "/walls/" + std::to_string(i);
    check_point(ptr + "/start", finite(w.segment.a));
    check_point(ptr + "/end", finite(w.segment.b));
    if (finite(w.segment.a) && finite(w.segment.b) && geometry::length(w.segment) <= opt.boundary_tolerance) {
      v.add(ptr + "/end", "wall from " + pt(w.segment.a) + " to " + pt(w.segment.b) + " has no length");
    }
    if (!(w.height > 0 && std::isfinite(w.height)))
      v.add(ptr + "/height", "must be a positive number of metres");
    v.label(ptr + "/style", w.style, true);
  }
  for (std::size_t i = 0; i < doors_.size(); ++i) {
    const auto& d = doors_[i];
    const std::string ptr = door_ptr(i);
    v.name(ptr + "/name", d.name, names);
    check_point(ptr + "/pose", finite(d.pose));
    if (!(d.width > 0 && d.width <= kMaxCoordinate)) {
      v.add(ptr + "/width", "must be a positive number of metres, at most 100000");
      out_of_range = true;
    } else if (d.width < 2 * opt.agent_radius) {
      v.add(ptr + "/width", "door '" + d.name + "' is " + num(d.width) +
                                " m wide, narrower than an agent of radius " + num(opt.agent_radius) + " m");
    }
    if (d.connects.size() > 2) {
      v.add(ptr + "/connects", "lists " + std::to_string(d.connects.size()) +
                                   " zones; a door connects two zones, or one zone and the outside");
    }
  }
  std::vector<bool> roi_ok(rois_.size(), false);
  for (std::size_t i = 0; i < rois_.size(); ++i) {
    const auto& r = rois_[i];
    const std::string ptr = "/segmentation/" + std::to_string(i);
    v.name(ptr + "/name", r.name, names);
    if (!is_roi_kind(r.kind)) {
      std::string known;
      for (auto k : roi_kinds()) {
        if (!known.empty()) known += ", ";
        known += k;
      }
      v.add(ptr + "/kind", "unknown ROI kind '" + r.kind + "' (known: " + known + ")");
    }
    roi_ok[i] = v.polygon(geos, ptr + "/polygon", r.polygon, "ROI '" + r.name + "'");
  }
  for (std::size_t i = 0; i < entities_.size(); ++i) {
    const auto& e = entities_[i];
    const std::string ptr = "/entities/" + std::to_string(i);
    v.name(ptr + "/name", e.name, names);
    v.label(ptr + "/type", e.type, false);
    check_point(ptr + "/pose", finite(e.pose));
    std::set<std::string> seen;
    for (std::size_t k = 0; k < e.affordances.size(); ++k) {
      const std::string aptr = ptr + "/affordances/" + std::to_string(k);
      v.label(aptr, e.affordances[k], false);
      if (!seen.insert(e.affordances[k]).second)
        v.add(aptr, "duplicate affordance '" + e.affordances[k] + "'");
    }
  }
  if (std::find(zone_ok.begin(), zone_ok.end(), false) != zone_ok.end() || zones.empty() || out_of_range)
    return v.failure();

  try {
    // 2. Zones against each other.
    const double tol = opt.boundary_tolerance;
    std::vector<geometry::Box> boxes;
    for (const auto& z : zones) boxes.push_back(geometry::bounds(z.polygon.outer));
    const bool cached = cache != nullptr && cache->boundary_tolerance == tol &&
                        cache->overlap_tolerance == opt.overlap_tolerance && cache->zones == zones;
    BuildCache fresh;
    BuildCache& known = cache != nullptr ? *cache : fresh;
    if (!cached) {
      known = BuildCache{};
      for (std::size_t j = 0; j < zones.size(); ++j) {
        for (std::size_t i = 0; i < j; ++i) {
          const auto& a = boxes[i];
          const auto& b = boxes[j];
          if (a.max.x <= b.min.x || b.max.x <= a.min.x || a.max.y <= b.min.y || b.max.y <= a.min.y) continue;
          const double overlap =
              geos.area(geos.intersection(MultiPolygon{zones[i].polygon}, MultiPolygon{zones[j].polygon}));
          if (overlap > opt.overlap_tolerance) known.overlaps.emplace_back(i, j, overlap);
        }
      }
      MultiPolygon all;
      for (const auto& z : zones) all.push_back(z.polygon);
      known.plan = geos.unite(all);
      known.outline = geos.boundary_segments(known.plan);
      // The key last: a build that throws above leaves a cache that matches nothing.
      known.zones = zones;
      known.boundary_tolerance = tol;
      known.overlap_tolerance = opt.overlap_tolerance;
    }
    for (const auto& [i, j, overlap] : known.overlaps)
      v.add(zone_ptr(j) + "/polygon", "zone '" + zones[j].name + "' overlaps zone '" + zones[i].name + "' (" +
                                          zone_ptr(i) + ") by " + num(overlap) + " m²");
    const MultiPolygon& plan = known.plan;
    std::vector<Segment> outline = known.outline;

    // 3. Doors: find their zones and their opening on the shared (or outside) boundary.
    // Boundaries are computed once per zone pair (or zone and outside) and indexed, so each door
    // costs a few index queries, not a pass over every edge.
    std::vector<Door> doors;
    const ZoneBoundaries boundaries(zones);
    std::map<std::string, std::size_t> zone_index;
    for (std::size_t z = 0; z < zones.size(); ++z) zone_index[zones[z].name] = z;
    constexpr std::size_t kOutside = std::numeric_limits<std::size_t>::max();
    std::map<std::pair<std::size_t, std::size_t>, SegmentIndex> host_cache;
    std::optional<SegmentIndex> outline_index;
    const auto vertices = [](const Polygon& p) {
      std::size_t n = p.outer.size();
      for (const auto& h : p.holes) n += h.size();
      return n;
    };
    const auto rings = [](const Polygon& p) {
      std::vector<std::vector<Point>> r{p.outer};
      r.insert(r.end(), p.holes.begin(), p.holes.end());
      return r;
    };
    std::size_t plan_vertices = 0;
    for (const auto& part : plan) plan_vertices += vertices(part);
    // The boundary shared by zones a and b, or (b == kOutside) the part of a's that is the outline.
    // Small boundaries go through GEOS as they always did (the same bits, so stored scenarios
    // replay identically); large ones through exact capsules, since GEOS's buffer of a boundary
    // with features finer than the tolerance grows without bound (8 GB for a 10k-vertex sawtooth).
    auto host_of = [&](std::size_t a, std::size_t b) -> const SegmentIndex& {
      const std::pair<std::size_t, std::size_t> key =
          b == kOutside ? std::make_pair(a, b) : std::make_pair(std::min(a, b), std::max(a, b));
      auto it = host_cache.find(key);
      if (it == host_cache.end()) {
        if (auto seen = known.boundaries.find(key); seen != known.boundaries.end())
          return host_cache.emplace(key, SegmentIndex(seen->second)).first->second;
        std::vector<Segment> segs;
        if (b == kOutside && vertices(zones[a].polygon) + plan_vertices <= kExactBoundaryVertices) {
          for (const auto& part : plan) {
            const auto pieces = geos.shared_boundary(zones[a].polygon, part, tol);
            segs.insert(segs.end(), pieces.begin(), pieces.end());
          }
        } else if (b == kOutside) {
          if (!outline_index) outline_index.emplace(outline);
          segs = geometry::pieces_near(rings(zones[a].polygon), *outline_index, tol);
        } else if (vertices(zones[a].polygon) + vertices(zones[b].polygon) <= kExactBoundaryVertices) {
          segs = geos.shared_boundary(zones[key.first].polygon, zones[key.second].polygon, tol);
        } else {
          std::vector<Segment> other_edges;
          for (const auto& ring : rings(zones[key.second].polygon))
            for (const auto& e : geometry::edges(ring)) other_edges.push_back(e);
          segs = geometry::pieces_near(rings(zones[key.first].polygon), SegmentIndex(std::move(other_edges)),
                                       tol);
        }
        known.boundaries.emplace(key, segs);
        it = host_cache.emplace(key, SegmentIndex(std::move(segs))).first;
      }
      return it->second;
    };
    SegmentIndex accepted_openings;  // of `doors`, in order
    for (std::size_t i = 0; i < doors_.size(); ++i) {
      const auto& spec = doors_[i];
      const std::string ptr = door_ptr(i);
      if (!finite(spec.pose) || !(spec.width > 0) || spec.connects.size() > 2) continue;
      const Point c = spec.pose.position();
      std::vector<std::size_t> ends;
      bool resolved = true;
      for (std::size_t k = 0; k < spec.connects.size(); ++k) {
        auto found = zone_index.find(spec.connects[k]);
        if (found == zone_index.end()) {
          v.add(ptr + "/connects/" + std::to_string(k), "unknown zone '" + spec.connects[k] + "'");
          resolved = false;
        } else {
          ends.push_back(found->second);
        }
      }
      if (!resolved) continue;
      if (ends.size() == 2 && ends[0] == ends[1]) {
        v.add(ptr + "/connects",
              "door '" + spec.name + "' connects zone '" + zones[ends[0]].name + "' with itself");
        continue;
      }
      if (ends.empty()) {
        // Infer: the zones whose boundary passes by the door.
        const auto near = boundaries.within(c, opt.door_snap_distance);
        if (near.empty()) {
          const auto [best, bz] = boundaries.nearest(c);
          v.add(ptr + "/pose", "door '" + spec.name + "' at " + pt(c) +
                                   " is on no zone boundary (nearest is zone '" + zones[bz].name + "', " +
                                   num(best) + " m away; at most " + num(opt.door_snap_distance) +
                                   " m allowed)");
          continue;
        }
        for (std::size_t x = 0; x < near.size() && ends.empty(); ++x) {
          for (std::size_t y = x + 1; y < near.size() && ends.empty(); ++y) {
            const auto n = host_of(near[x].second, near[y].second).nearest(c);
            if (n && n->distance <= opt.door_snap_distance) {
              ends = {std::min(near[x].second, near[y].second), std::max(near[x].second, near[y].second)};
            }
          }
        }
        if (ends.empty()) ends = {near[0].second};
      }
      const Zone& za = zones[ends[0]];
      const SegmentIndex& host = host_of(ends[0], ends.size() == 2 ? ends[1] : kOutside);
      if (ends.size() == 2 && host.size() == 0) {
        v.add(ptr + "/connects", "zones '" + za.name + "' and '" + zones[ends[1]].name +
                                     "' share no boundary, so door '" + spec.name + "' cannot connect them");
        continue;
      }
      const auto nh = host.nearest(c);
      if (!nh || nh->distance > opt.door_snap_distance) {
        const std::string where = ends.size() == 2 ? "the boundary shared by zones '" + za.name + "' and '" +
                                                         zones[ends[1]].name + "'"
                                                   : "the outside boundary of zone '" + za.name + "'";
        std::string msg = "door '" + spec.name + "' at " + pt(c) + " is not on " + where;
        if (nh)
          msg += " (" + num(nh->distance) + " m away; at most " + num(opt.door_snap_distance) + " m allowed)";
        v.add(ptr + "/pose", msg);
        continue;
      }
      const Segment& s = host.segment(nh->index);
      const double len = geometry::length(s);
      const Point u{(s.b.x - s.a.x) / len, (s.b.y - s.a.y) / len};
      const double t = (c.x - s.a.x) * u.x + (c.y - s.a.y) * u.y;
      const double half = spec.width / 2;
      if (t - half < -tol || t + half > len + tol) {
        const double over = std::max(-(t - half), t + half - len);
        v.add(ptr + "/width", "door '" + spec.name + "' (" + num(spec.width) +
                                  " m) does not fit on its boundary from " + pt(s.a) + " to " + pt(s.b) +
                                  "; the opening runs " + num(over) + " m past its end");
        continue;
      }
      Door d;
      d.name = spec.name;
      d.pose = spec.pose;
      d.width = spec.width;
      d.zone = ZoneId(static_cast<std::uint32_t>(ends[0]));
      if (ends.size() == 2) d.other = ZoneId(static_cast<std::uint32_t>(ends[1]));
      // From the projected centre, so that round numbers stay round (2 ± 0.6, not 10 − 7.4).
      const Point mid{s.a.x + u.x * t, s.a.y + u.y * t};
      d.opening = {{mid.x - u.x * half, mid.y - u.y * half}, {mid.x + u.x * half, mid.y + u.y * half}};
      // Two doors in one opening would double-count it (an overlapping opening lies within tol).
      for (std::size_t k : accepted_openings.within(d.opening, tol)) {
        const Door& other = doors[k];
        const Segment& o = other.opening;
        auto off = [&](Point p) {
          return std::abs((p.x - d.opening.a.x) * u.y - (p.y - d.opening.a.y) * u.x);
        };
        if (off(o.a) > tol || off(o.b) > tol) continue;
        auto along = [&](Point p) { return (p.x - d.opening.a.x) * u.x + (p.y - d.opening.a.y) * u.y; };
        const double lo = std::max(0.0, std::min(along(o.a), along(o.b)));
        const double hi = std::min(spec.width, std::max(along(o.a), along(o.b)));
        if (hi - lo > tol)
          v.add(ptr + "/pose", "door '" + spec.name + "' overlaps door '" + other.name + "'");
      }
      accepted_openings.insert(d.opening);
      doors.push_back(std::move(d));
    }

    // 4. Walls: as written, or derived from the zone boundaries minus the door openings.
    std::vector<Wall> walls = walls_;
    if (walls.empty()) {
      if (known.wall_lines.empty()) {
        MultiPolygon polys;
        for (const auto& z : zones) polys.push_back(z.polygon);
        known.wall_lines = geos.boundary_segments(polys);
      }
      walls = derive_walls(zones, doors, opt, &known.wall_lines);
    } else {
      std::vector<Segment> inner_openings;
      for (const auto& d : doors) {
        const double len = geometry::length(d.opening);
        const double cut = std::min(2 * tol, len / 4);
        const Point u{(d.opening.b.x - d.opening.a.x) / len, (d.opening.b.y - d.opening.a.y) / len};
        inner_openings.push_back({{d.opening.a.x + u.x * cut, d.opening.a.y + u.y * cut},
                                  {d.opening.b.x - u.x * cut, d.opening.b.y - u.y * cut}});
      }
      const SegmentIndex inner_index(std::move(inner_openings));
      for (std::size_t k = 0; k < walls.size(); ++k) {
        for (std::size_t di : inner_index.within(walls[k].segment, tol)) {
          if (geometry::distance(walls[k].segment, inner_index.segment(di)) < tol) {
            v.add("/walls/" + std::to_string(k), "wall from " + pt(walls[k].segment.a) + " to " +
                                                     pt(walls[k].segment.b) + " blocks door '" +
                                                     doors[di].name + "'");
          }
        }
      }
    }

    if (inferred && !walls_.empty()) {
      // The written walls need not close the zone whose region was inferred: close it where
      // they leave it open (less its doors), like the written walls when they agree on a style.
      Wall like{{}, opt.default_wall_height, opt.default_wall_style};
      if (std::all_of(walls_.begin(), walls_.end(), [&](const Wall& w) {
            return w.style == walls_[0].style && w.height == walls_[0].height;
          })) {
        like = Wall{{}, walls_[0].height, walls_[0].style};
      }
      double added = 0.0;
      std::size_t count = 0;
      for (const Wall& piece : derive_walls(zones, doors, opt)) {
        const Point mid{(piece.segment.a.x + piece.segment.b.x) / 2,
                        (piece.segment.a.y + piece.segment.b.y) / 2};
        if (distance_to_boundary(zones[*inferred].polygon, mid) > tol) continue;
        for (const Segment& part : uncovered_parts(piece.segment, walls_, tol)) {
          walls.push_back(Wall{part, like.height, like.style});
          added += geometry::length(part);
          ++count;
        }
      }
      if (count > 0) {
        notes.push_back(FieldError{"/walls", "the walls written leave zone '" + zones[*inferred].name +
                                                 "' open: " + std::to_string(count) + " wall" +
                                                 (count == 1 ? "" : "s") + " (" + num(added) +
                                                 " m) added along its boundary, doors left open"});
      }
    }

    // 5. ROIs inside the zones; entities standing in a zone. A ROI whose bounds lie in a zone that
    // is an axis-aligned rectangle has nothing outside (no GEOS difference with the whole plan).
    std::vector<bool> rectangle(zones.size(), false);
    for (std::size_t z = 0; z < zones.size(); ++z) {
      const auto& ring = zones[z].polygon.outer;
      bool axis =
          zones[z].polygon.holes.empty() && (ring.size() == 4 || (ring.size() == 5 && ring[0] == ring[4]));
      for (std::size_t k = 0; axis && k < 4; ++k) {
        const Point a = ring[k], b = ring[(k + 1) % 4];
        axis = a.x == b.x || a.y == b.y;
      }
      rectangle[z] = axis;
    }
    for (std::size_t i = 0; i < rois_.size(); ++i) {
      if (!roi_ok[i]) continue;
      const geometry::Box rb = geometry::bounds(rois_[i].polygon.outer);
      bool inside = false;
      for (std::size_t z = 0; z < zones.size() && !inside; ++z) {
        const auto& b = boxes[z];
        inside = rectangle[z] && rb.min.x >= b.min.x && rb.max.x <= b.max.x && rb.min.y >= b.min.y &&
                 rb.max.y <= b.max.y;
      }
      if (inside) continue;
      const MultiPolygon roi{rois_[i].polygon};
      const double outside = geos.area(geos.difference(roi, plan));
      if (outside > opt.overlap_tolerance) {
        const double total = geometry::area(rois_[i].polygon);
        const std::string ptr = "/segmentation/" + std::to_string(i) + "/polygon";
        if (outside >= total - opt.overlap_tolerance) {
          v.add(ptr, "ROI '" + rois_[i].name + "' lies outside every zone");
        } else {
          v.add(ptr, "ROI '" + rois_[i].name + "' extends " + num(outside) + " m² (of " + num(total) +
                         " m²) outside the zones");
        }
      }
    }
    std::vector<Entity> entities;
    for (std::size_t i = 0; i < entities_.size(); ++i) {
      const auto& e = entities_[i];
      if (!finite(e.pose)) continue;
      std::optional<std::size_t> in;
      const Point p = e.pose.position();
      for (std::size_t z = 0; z < zones.size() && !in; ++z) {
        const auto& b = boxes[z];
        if (p.x < b.min.x - tol || p.x > b.max.x + tol || p.y < b.min.y - tol || p.y > b.max.y + tol)
          continue;
        if (geometry::contains(zones[z].polygon, p, tol)) in = z;
      }
      if (!in) {
        v.add("/entities/" + std::to_string(i) + "/pose",
              "entity '" + e.name + "' at " + pt(e.pose.position()) + " is outside every zone");
        continue;
      }
      entities.push_back(
          Entity{e.type, e.name, e.pose, e.affordances, ZoneId(static_cast<std::uint32_t>(*in))});
    }
    if (!v.ok()) return v.failure();

    World w;
    w.name_ = name_;
    w.origin_ = origin_;
    w.floor_ = floor_;
    w.zones_ = zones;
    w.walls_ = std::move(walls);
    w.doors_ = std::move(doors);
    w.rois_ = rois_;
    w.entities_ = std::move(entities);
    w.outline_ = std::move(outline);

    // 6. Every zone reachable from every other for an agent of the given radius.
    if (opt.check_reachability && zones.size() > 1) {
      const auto grid =
          OccupancyGrid::rasterise(w, GridOptions{opt.grid_resolution, opt.agent_radius, 4'000'000});
      const auto label = grid.components();
      std::vector<std::map<int, std::size_t>> counts(zones.size());
      // Neighbouring cells mostly share zone and component: one map lookup per run of them.
      std::size_t* run = nullptr;
      std::size_t run_zone = 0;
      int run_label = -1;
      const auto zone_of = grid.zone_cells();
      for (std::size_t i = 0; i < label.size(); ++i) {
        const int l = label[i];
        if (l < 0 || zone_of[i] < 0) continue;
        const auto z = static_cast<std::size_t>(zone_of[i]);
        if (run == nullptr || run_zone != z || run_label != l) {
          run_zone = z;
          run_label = l;
          run = &counts[run_zone][l];
        }
        ++*run;
      }
      std::vector<int> main(zones.size(), -1);
      std::map<int, std::size_t> votes;
      for (std::size_t z = 0; z < zones.size(); ++z) {
        if (counts[z].empty()) {
          v.add(zone_ptr(z) + "/polygon", "zone '" + zones[z].name +
                                              "' has no free space for an agent of radius " +
                                              num(opt.agent_radius) + " m");
          continue;
        }
        main[z] = std::max_element(counts[z].begin(), counts[z].end(), [](const auto& a, const auto& b) {
                    return a.second < b.second || (a.second == b.second && a.first > b.first);
                  })->first;
        ++votes[main[z]];
      }
      if (!votes.empty()) {
        const int ref = std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) {
                          return a.second < b.second;
                        })->first;
        std::size_t ref_zone = 0;
        while (main[ref_zone] != ref) ++ref_zone;
        for (std::size_t z = 0; z < zones.size(); ++z) {
          if (main[z] < 0 || main[z] == ref) continue;
          std::string doors_of;
          for (const auto& d : w.doors_) {
            if (d.zone.index() == z || (d.other && d.other->index() == z)) {
              if (!doors_of.empty()) doors_of += ", ";
              doors_of += d.name;
              doors_of += " (" + num(d.width) + " m)";
            }
          }
          v.add(zone_ptr(z), "zone '" + zones[z].name + "' cannot be reached from zone '" +
                                 zones[ref_zone].name + "' by an agent of radius " + num(opt.agent_radius) +
                                 " m; " + (doors_of.empty() ? "it has no door" : "its doors: " + doors_of));
        }
      }
      if (!v.ok()) return v.failure();
    }
    if (warnings) warnings->insert(warnings->end(), notes.begin(), notes.end());
    return w;
  } catch (const geometry::GeosError& e) {
    return fail(ErrorCode::kValidation, std::string("geometry check failed: ") + e.what());
  }
}

}  // namespace socsim::world
