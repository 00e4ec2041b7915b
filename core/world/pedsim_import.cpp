#include "core/world/pedsim_import.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>

#include "core/geometry/geos.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::world {

namespace {

using geometry::MultiPolygon;

std::string num3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

class ElementReader {
 public:
  ElementReader(std::vector<FieldError>& errors, const XmlElement& e, std::string pointer)
      : errors_(errors), e_(e), ptr_(std::move(pointer)) {}

  void add(const std::string& message) {
    errors_.push_back(FieldError{ptr_, message, {}, e_.line, e_.column});
  }

  // Attributes this element may have; each other one is reported.
  void only(std::initializer_list<std::string_view> allowed) {
    for (const auto& [k, v] : e_.attributes) {
      bool ok = false;
      for (auto a : allowed) ok = ok || a == k;
      if (!ok) add("<" + e_.name + "> has unknown attribute '" + k + "'");
    }
  }

  double number(const char* key, bool required, double fallback = 0.0) {
    const std::string* v = e_.attribute(key);
    if (!v) {
      if (required) add("<" + e_.name + "> needs attribute '" + key + "'");
      return fallback;
    }
    double d = 0.0;
    const char* first = v->data() + (!v->empty() && (*v)[0] == '+' ? 1 : 0);
    auto [end, ec] = std::from_chars(first, v->data() + v->size(), d);
    if (ec != std::errc() || end != v->data() + v->size() || !std::isfinite(d)) {
      add("attribute " + std::string(key) + "=\"" + *v + "\" of <" + e_.name + "> is not a number");
      return fallback;
    }
    return d;
  }

  int integer(const char* key, bool required, int fallback, int lo, int hi) {
    const double d = number(key, required, fallback);
    if (d != std::floor(d) || d < lo || d > hi) {
      add("attribute " + std::string(key) + " of <" + e_.name + "> must be an integer from " +
          std::to_string(lo) + " to " + std::to_string(hi));
      return fallback;
    }
    return static_cast<int>(d);
  }

  std::string id() {
    const std::string* v = e_.attribute("id");
    if (!v || v->empty()) {
      add("<" + e_.name + "> needs attribute 'id'");
      return {};
    }
    return *v;
  }

 private:
  std::vector<FieldError>& errors_;
  const XmlElement& e_;
  std::string ptr_;
};

Polygon circle(Point c, double r, int sides = 16) {
  Polygon p;
  for (int i = 0; i < sides; ++i) {
    const double a = 2.0 * std::numbers::pi * i / sides;
    p.outer.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return p;
}

// The part of `shape` ∩ `area` that contains `anchor` (or the largest part), its ring
// starting at the vertex nearest the anchor (GEOS does not keep the input's first vertex).
std::optional<Polygon> clip(const geometry::Geos& geos, const Polygon& shape, const Polygon& area,
                            Point anchor) {
  const MultiPolygon parts = geos.intersection(MultiPolygon{shape}, MultiPolygon{area});
  const Polygon* best = nullptr;
  for (const auto& p : parts) {
    if (geometry::contains(p, anchor)) {
      best = &p;
      break;
    }
    if (!best || geometry::area(p) > geometry::area(*best)) best = &p;
  }
  if (!best || geometry::area(*best) < 1e-6) return std::nullopt;
  std::vector<Point> ring = best->outer;
  std::size_t first = 0;
  for (std::size_t i = 1; i < ring.size(); ++i) {
    if (geometry::distance(ring[i], anchor) < geometry::distance(ring[first], anchor)) first = i;
  }
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(first), ring.end());
  return Polygon{std::move(ring), {}};
}

}  // namespace

Result<PedsimScenario> import_pedsim(std::string_view xml, const PedsimImportOptions& options) {
  auto doc = parse_xml(xml);
  if (!doc) return tl::unexpected(doc.error());
  std::vector<FieldError> errors;
  if (doc->name != "scenario") {
    return fail(
        ErrorCode::kValidation, "not a pedsim scenario",
        {FieldError{
            "", "root element is <" + doc->name + ">, expected <scenario>", {}, doc->line, doc->column}});
  }

  std::vector<Segment> obstacles;
  std::vector<const XmlElement*> obstacle_elements;
  std::vector<PedsimWaypoint> waypoints;
  std::vector<PedsimQueue> queues;
  std::vector<PedsimAttraction> attractions;
  std::vector<PedsimAgentCluster> agents;
  std::map<std::string, std::string> ids;  // id → pointer of its first use

  auto claim = [&](ElementReader& r, const std::string& id, const std::string& ptr) {
    if (id.empty()) return;
    auto [it, inserted] = ids.emplace(id, ptr);
    if (!inserted) r.add("id '" + id + "' is already used at " + it->second);
  };

  for (const XmlElement& e : doc->children) {
    if (e.name == "obstacle") {
      const std::string ptr = "/obstacles/" + std::to_string(obstacles.size());
      ElementReader r(errors, e, ptr);
      r.only({"x1", "y1", "x2", "y2"});
      const Segment s{{r.number("x1", true), r.number("y1", true)},
                      {r.number("x2", true), r.number("y2", true)}};
      if (geometry::length(s) <= options.build.boundary_tolerance) r.add("obstacle has no length");
      obstacles.push_back(s);
      obstacle_elements.push_back(&e);
    } else if (e.name == "waypoint") {
      const std::string ptr = "/waypoints/" + std::to_string(waypoints.size());
      ElementReader r(errors, e, ptr);
      r.only({"id", "x", "y", "r", "b"});
      PedsimWaypoint w{r.id(),
                       {r.number("x", true), r.number("y", true)},
                       r.number("r", true, 1.0),
                       r.integer("b", false, 0, 0, 2),
                       e.line};
      if (!(w.radius > 0)) r.add("waypoint radius r must be positive");
      claim(r, w.id, ptr);
      waypoints.push_back(std::move(w));
    } else if (e.name == "queue") {
      const std::string ptr = "/queues/" + std::to_string(queues.size());
      ElementReader r(errors, e, ptr);
      r.only({"id", "x", "y", "direction"});
      PedsimQueue q{r.id(), {r.number("x", true), r.number("y", true)}, r.number("direction", true), e.line};
      claim(r, q.id, ptr);
      queues.push_back(std::move(q));
    } else if (e.name == "attraction") {
      const std::string ptr = "/attractions/" + std::to_string(attractions.size());
      ElementReader r(errors, e, ptr);
      r.only({"id", "x", "y", "width", "height", "strength"});
      PedsimAttraction a{r.id(),
                         {r.number("x", true), r.number("y", true)},
                         r.number("width", true, 1.0),
                         r.number("height", true, 1.0),
                         r.number("strength", false),
                         e.line};
      if (!(a.width > 0 && a.height > 0)) r.add("attraction width and height must be positive");
      claim(r, a.id, ptr);
      attractions.push_back(std::move(a));
    } else if (e.name == "agent" || e.name == "source") {
      const std::string ptr = "/agents/" + std::to_string(agents.size());
      ElementReader r(errors, e, ptr);
      r.only({"x", "y", "n", "dx", "dy", "type"});
      PedsimAgentCluster c;
      c.position = {r.number("x", true), r.number("y", true)};
      c.count = r.integer("n", true, 1, 0, 100000);
      c.dx = r.number("dx", false);
      c.dy = r.number("dy", false);
      c.type = r.integer("type", false, 0, 0, 3);
      c.source = e.name == "source";
      c.line = e.line;
      for (const XmlElement& step : e.children) {
        ElementReader sr(errors, step, ptr + "/route/" + std::to_string(c.route.size()));
        if (step.name != "addwaypoint" && step.name != "addqueue") {
          sr.add("unknown element <" + step.name + "> in <" + e.name + ">");
          continue;
        }
        sr.only({"id"});
        c.route.push_back(
            {step.name == "addqueue" ? PedsimRouteStep::Kind::kQueue : PedsimRouteStep::Kind::kWaypoint,
             sr.id()});
      }
      agents.push_back(std::move(c));
    } else {
      ElementReader(errors, e, "").add("unknown pedsim element <" + e.name + ">");
    }
  }
  // Routes must name existing waypoints / queues.
  std::set<std::string> waypoint_ids, queue_ids;
  for (const auto& w : waypoints) waypoint_ids.insert(w.id);
  for (const auto& q : queues) queue_ids.insert(q.id);
  for (std::size_t a = 0; a < agents.size(); ++a) {
    const XmlElement* agent_el = nullptr;
    std::size_t seen = 0;
    for (const XmlElement& e : doc->children) {
      if ((e.name == "agent" || e.name == "source") && seen++ == a) agent_el = &e;
    }
    for (std::size_t k = 0; k < agents[a].route.size(); ++k) {
      const auto& step = agents[a].route[k];
      const bool queue = step.kind == PedsimRouteStep::Kind::kQueue;
      if ((queue ? queue_ids : waypoint_ids).count(step.id) || step.id.empty()) continue;
      const XmlElement& step_el = agent_el->children[k];
      errors.push_back(FieldError{"/agents/" + std::to_string(a) + "/route/" + std::to_string(k),
                                  std::string(queue ? "<addqueue>" : "<addwaypoint>") + " names unknown " +
                                      (queue ? "queue" : "waypoint") + " '" + step.id + "'",
                                  {},
                                  step_el.line,
                                  step_el.column});
    }
  }
  if (obstacles.empty()) {
    errors.push_back(FieldError{"/obstacles", "the scenario has no <obstacle>", {}, doc->line, doc->column});
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "the pedsim scenario is not valid", errors);

  // The walkable area: the face the obstacles close around the whole scene, if they do;
  // otherwise the scene's bounding box with a margin.
  geometry::Geos geos;
  std::vector<Point> all_points;
  for (const auto& s : obstacles) all_points.insert(all_points.end(), {s.a, s.b});
  const geometry::Box obstacle_box = geometry::bounds(all_points);
  Polygon site;
  bool enclosed = false;
  for (const auto& face : geos.polygonize(obstacles)) {
    const geometry::Box b = geometry::bounds(face.outer);
    const double tol = options.build.boundary_tolerance;
    if (std::abs(b.min.x - obstacle_box.min.x) <= tol && std::abs(b.min.y - obstacle_box.min.y) <= tol &&
        std::abs(b.max.x - obstacle_box.max.x) <= tol && std::abs(b.max.y - obstacle_box.max.y) <= tol) {
      site = Polygon{face.outer, {}};
      enclosed = true;
      break;
    }
  }
  if (!enclosed) {
    for (const auto& w : waypoints) {
      all_points.push_back({w.position.x - w.radius, w.position.y - w.radius});
      all_points.push_back({w.position.x + w.radius, w.position.y + w.radius});
    }
    for (const auto& q : queues) all_points.push_back(q.position);
    for (const auto& a : attractions) {
      all_points.push_back({a.center.x - a.width / 2, a.center.y - a.height / 2});
      all_points.push_back({a.center.x + a.width / 2, a.center.y + a.height / 2});
    }
    for (const auto& c : agents) {
      all_points.push_back({c.position.x - c.dx, c.position.y - c.dy});
      all_points.push_back({c.position.x + c.dx, c.position.y + c.dy});
    }
    const geometry::Box b = geometry::bounds(all_points);
    const double m = options.margin;
    site = Polygon{{{b.min.x - m, b.min.y - m},
                    {b.max.x + m, b.min.y - m},
                    {b.max.x + m, b.max.y + m},
                    {b.min.x - m, b.max.y + m}},
                   {}};
  }
  const geometry::Box sb = geometry::bounds(site.outer);
  const std::string walls_text = "the obstacles enclose x " + num3(sb.min.x) + " .. " + num3(sb.max.x) +
                                 ", y " + num3(sb.min.y) + " .. " + num3(sb.max.y);
  auto inside = [&](Point p) { return geometry::contains(site, p, options.build.boundary_tolerance); };
  auto outside_error = [&](const std::string& ptr, const std::string& what, Point p, int line) {
    errors.push_back(FieldError{
        ptr,
        what + " at (" + num3(p.x) + ", " + num3(p.y) + ") lies outside the walls (" + walls_text + ")",
        {},
        line,
        1});
  };

  WorldBuilder b;
  b.set_name(options.name);
  b.add_zone(Zone{"site", "pedsim_area", "", site});
  for (const auto& s : obstacles)
    b.add_wall(Wall{s, options.build.default_wall_height, options.build.default_wall_style});
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const auto& w = waypoints[i];
    if (!inside(w.position)) {
      outside_error("/waypoints/" + std::to_string(i), "waypoint '" + w.id + "'", w.position, w.line);
      continue;
    }
    if (auto poly = clip(geos, circle(w.position, w.radius), site, w.position))
      b.add_roi(Roi{w.id, "waypoint", *poly});
  }
  for (std::size_t i = 0; i < queues.size(); ++i) {
    const auto& q = queues[i];
    if (!inside(q.position)) {
      outside_error("/queues/" + std::to_string(i), "queue '" + q.id + "'", q.position, q.line);
      continue;
    }
    const double a = q.direction_deg * std::numbers::pi / 180.0;
    const Point u{std::cos(a), std::sin(a)};
    const Point n{-u.y * options.queue_width / 2, u.x * options.queue_width / 2};
    const Point h = q.position;
    const Point t{h.x + u.x * options.queue_length, h.y + u.y * options.queue_length};
    // Head edge first: export_pedsim takes the end nearest the first vertex as the head.
    const Polygon lane{
        {{h.x + n.x, h.y + n.y}, {h.x - n.x, h.y - n.y}, {t.x - n.x, t.y - n.y}, {t.x + n.x, t.y + n.y}}, {}};
    if (auto poly = clip(geos, lane, site, h)) b.add_roi(Roi{q.id, "queue_lane", *poly});
  }
  for (std::size_t i = 0; i < attractions.size(); ++i) {
    const auto& at = attractions[i];
    if (!inside(at.center)) {
      outside_error("/attractions/" + std::to_string(i), "attraction '" + at.id + "'", at.center, at.line);
      continue;
    }
    const Point c = at.center;
    const Polygon rect{{{c.x - at.width / 2, c.y - at.height / 2},
                        {c.x + at.width / 2, c.y - at.height / 2},
                        {c.x + at.width / 2, c.y + at.height / 2},
                        {c.x - at.width / 2, c.y + at.height / 2}},
                       {}};
    if (auto poly = clip(geos, rect, site, c)) b.add_roi(Roi{at.id, "area", *poly});
  }
  for (std::size_t i = 0; i < agents.size(); ++i) {
    if (!inside(agents[i].position)) {
      outside_error("/agents/" + std::to_string(i),
                    std::string(agents[i].type == 2 ? "robot" : "agent cluster"), agents[i].position,
                    agents[i].line);
    }
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "the pedsim scenario is not valid", errors);

  auto world = b.build(options.build);
  if (!world) {
    // Map builder pointers back to the XML elements they came from.
    Error e = world.error();
    for (auto& fe : e.errors) {
      if (fe.pointer.rfind("/walls/", 0) == 0) {
        const std::size_t k = std::stoul(fe.pointer.substr(7));
        if (k < obstacle_elements.size()) {
          fe.line = obstacle_elements[k]->line;
          fe.column = obstacle_elements[k]->column;
          fe.pointer = "/obstacles/" + std::to_string(k);
        }
      }
    }
    return tl::unexpected(std::move(e));
  }
  return PedsimScenario{std::move(*world),      enclosed,         std::move(waypoints), std::move(queues),
                        std::move(attractions), std::move(agents)};
}

}  // namespace socsim::world
