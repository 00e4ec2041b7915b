#include "core/interop/export_pedsim_scenario.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "core/crowd/scenario_runner.hpp"
#include "core/geometry/planar.hpp"
#include "core/interop/agent_routes.hpp"
#include "core/world/export_format.hpp"
#include "core/world/world_export.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::interop {

namespace {

using world::micro;
using world::Point;
using world::xml_escape;

bool attraction_kind(std::string_view kind) {
  return kind == "area" || kind == "seating_area" || kind == "waiting_zone";
}

struct Circle {
  Point center;
  double radius = 0.0;
};

// The circle through the most vertices of the ring (a waypoint's circle, possibly cut by walls,
// as import_pedsim made it); nullopt when fewer than four vertices share one circle.
std::optional<Circle> fitted_circle(const std::vector<Point>& ring) {
  const std::size_t n = ring.size();
  if (n > 64) return std::nullopt;  // import_pedsim's circles have 16 sides (fewer once cut)
  std::optional<Circle> best;
  std::size_t best_count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        const Point a = ring[i], b = ring[j], c = ring[k];
        const double d = 2.0 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
        if (std::abs(d) < 1e-12) continue;
        const double a2 = a.x * a.x + a.y * a.y, b2 = b.x * b.x + b.y * b.y, c2 = c.x * c.x + c.y * c.y;
        const Point o{(a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
                      (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d};
        const double r = geometry::distance(o, a);
        std::size_t count = 0;
        for (const Point& p : ring)
          count += std::abs(geometry::distance(o, p) - r) <= 1e-6 * std::max(1.0, r);
        if (count > best_count) {
          best_count = count;
          best = Circle{o, r};
        }
      }
    }
  }
  if (best_count < 4) return std::nullopt;
  return best;
}

int pedsim_type(std::string_view role, crowd::AgentKind kind) {
  if (kind == crowd::AgentKind::kRobot) return 2;
  if (role == "child") return 1;
  if (role == "elderly" || role == "elder") return 3;
  return 0;
}

class Writer {
 public:
  Writer(const world::World& w, const crowd::Program& p, crowd::ScenarioRunner& runner)
      : world_(w), program_(p), env_(runner.environment()), routes_(agent_routes(runner, p)) {}

  Result<std::string> write(const PedsimExportOptions& options) {
    // Places that routes walk to: those ROIs must be waypoints even when they could be attractions.
    std::map<std::string, double> lingering;  // attraction → largest chance of lingering there
    for (const AgentRoute& r : routes_) {
      for (const RouteStop& s : r.stops) {
        if (s.kind == RouteStop::Kind::kWalk && !s.place.empty()) walked_.insert(s.place);
        if (s.kind == RouteStop::Kind::kLinger)
          lingering[s.place] = std::max(lingering[s.place], s.probability);
      }
    }
    // The world export names a waypoint, queue or attraction after every ROI and entity.
    for (const world::Roi& roi : world_.rois()) used_.insert(roi.name);
    for (const world::Entity& e : world_.entities()) used_.insert(e.name);

    std::ostringstream rois;
    std::ostringstream attractions;
    for (const world::Roi& roi : world_.rois()) {
      if (roi.kind == "queue_lane") continue;
      if (attraction_kind(roi.kind) && walked_.count(roi.name) == 0) {
        const geometry::Box b = geometry::bounds(roi.polygon.outer);
        const Point c = P({(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2});
        const auto l = lingering.find(roi.name);
        const double strength = l != lingering.end() ? l->second * options.attraction_scale
                                : roi.kind == "area" ? 0.0
                                                     : 1.0;
        attractions << "  <attraction id=\"" << xml_escape(roi.name) << "\" x=\"" << micro(c.x) << "\" y=\""
                    << micro(c.y) << "\" width=\"" << micro(b.width()) << "\" height=\"" << micro(b.height())
                    << "\" strength=\"" << micro(strength) << "\"/>\n";
        continue;
      }
      Circle circle{geometry::centroid(roi.polygon.outer),
                    std::sqrt(std::abs(geometry::area(roi.polygon)) / std::numbers::pi)};
      if (roi.kind == "waypoint")
        if (auto fit = fitted_circle(roi.polygon.outer)) circle = *fit;
      waypoint(rois, roi.name, circle.center, circle.radius);
      waypoint_ids_[roi.name] = roi.name;
    }
    for (const world::Entity& e : world_.entities()) {
      waypoint(rois, e.name, e.pose.position(), 1.0);
      waypoint_ids_[e.name] = e.name;
    }

    std::ostringstream agents;
    std::set<std::string> written;
    for (const AgentRoute& r : routes_) {
      if (!written.insert(r.pointer).second) continue;  // one <agent> per program entry
      agent(agents, rois, r);
    }

    std::ostringstream o;
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    o << "<!-- exported by socsim: world '" << xml_escape(world_.name()) << "', program '"
      << xml_escape(program_.name) << "', seed " << options.seed << " -->\n<scenario>\n";
    o << "  <!--Obstacles-->\n";
    for (const auto& w : world::pedsim_obstacles(world_)) o << world::pedsim_element(w);
    o << "  <!--Waypoints-->\n" << rois.str();
    o << "  <!--Queues-->\n";
    for (const auto& q : world::pedsim_queues(world_)) o << world::pedsim_element(q);
    o << "  <!--Attractions-->\n" << attractions.str();
    o << "  <!--Agents-->\n" << agents.str();
    o << "</scenario>\n";
    return o.str();
  }

 private:
  [[nodiscard]] Point P(Point p) const { return geometry::to_parent(world_.origin(), p); }

  void waypoint(std::ostringstream& o, const std::string& id, Point c, double r) {
    const Point p = P(c);
    o << "  <waypoint id=\"" << xml_escape(id) << "\" x=\"" << micro(p.x) << "\" y=\"" << micro(p.y)
      << "\" r=\"" << micro(std::max(r, 0.05)) << "\"/>\n";
    used_.insert(id);
  }

  // The waypoint id of a stop, adding a waypoint for places and points that have none yet.
  std::string stop_waypoint(std::ostringstream& rois, const RouteStop& s) {
    if (!s.place.empty()) {
      if (auto it = waypoint_ids_.find(s.place); it != waypoint_ids_.end()) return it->second;
    }
    const std::string wanted = s.place.empty() ? "goal_" + std::to_string(++points_) : s.place;
    std::string id = wanted;
    for (int k = 2; used_.count(id) != 0; ++k) id = wanted + "_" + std::to_string(k);
    waypoint(rois, id, {s.point.x, s.point.y}, std::max(s.radius, 0.3));
    if (!s.place.empty()) waypoint_ids_[s.place] = id;
    return id;
  }

  // Scatter box of a program entry: its spawn region's bounding box, else its position.
  geometry::Box box(const AgentRoute& r) const {
    std::vector<Point> pts;
    auto region = [&](const crowd::ProgramRegion& reg) {
      if (const auto* ring = std::get_if<std::vector<crowd::Vec2>>(&reg.where)) {
        for (const auto& v : *ring) pts.push_back({v.x, v.y});
      } else if (const auto place = env_.place(std::get<std::string>(reg.where)); place && place->region) {
        pts.insert(pts.end(), place->region->outer.begin(), place->region->outer.end());
      }
    };
    if (r.kind == crowd::AgentKind::kSpotlight && r.entry < program_.agents.size()) {
      const crowd::ProgramAgent& a = program_.agents[r.entry];
      if (!a.position && a.spawn) region(*a.spawn);
    } else if (r.kind == crowd::AgentKind::kAmbient && r.entry < program_.ambient_groups.size()) {
      for (const auto& reg : program_.ambient_groups[r.entry].start) region(reg);
    }
    if (pts.empty()) pts.push_back({r.start.x, r.start.y});
    return geometry::bounds(pts);
  }

  std::size_t count(const AgentRoute& r) const {
    if (r.kind == crowd::AgentKind::kSpotlight && r.entry < program_.agents.size())
      return program_.agents[r.entry].count;
    if (r.kind == crowd::AgentKind::kAmbient && r.entry < program_.ambient_groups.size())
      return program_.ambient_groups[r.entry].size;
    return 1;
  }

  void agent(std::ostringstream& o, std::ostringstream& rois, const AgentRoute& r) {
    const geometry::Box b = box(r);
    Point c{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2};
    // A scatter box whose centre is not walkable (an L-shaped region): centre on the first agent.
    if (!world_.zone_at(c)) c = {r.start.x, r.start.y};
    const Point p = P(c);
    o << "  <agent x=\"" << micro(p.x) << "\" y=\"" << micro(p.y) << "\" n=\"" << count(r) << "\" dx=\""
      << micro(b.width() / 2) << "\" dy=\"" << micro(b.height() / 2) << "\" type=\""
      << pedsim_type(r.role, r.kind) << "\"";
    std::string steps;
    for (const RouteStop& s : r.stops) {
      if (s.kind == RouteStop::Kind::kQueue) {
        steps += "    <addqueue id=\"" + xml_escape(s.place) + "\"/>\n";
        continue;
      }
      if (s.kind == RouteStop::Kind::kLinger && !s.place.empty()) {
        const auto roi = world_.find_roi(s.place);
        // Lingering in an attraction area is what the <attraction> element makes pedsim agents do.
        if (roi && attraction_kind(world_.roi(*roi).kind) && walked_.count(s.place) == 0) continue;
      }
      steps += "    <addwaypoint id=\"" + xml_escape(stop_waypoint(rois, s)) + "\"/>\n";
    }
    if (steps.empty()) {
      o << "/>\n";
      return;
    }
    o << ">\n" << steps << "  </agent>\n";
  }

  const world::World& world_;
  const crowd::Program& program_;
  crowd::BtEnvironment& env_;
  std::vector<AgentRoute> routes_;
  std::set<std::string> walked_;
  std::set<std::string> used_;
  std::map<std::string, std::string> waypoint_ids_;  // place name → waypoint id
  int points_ = 0;
};

}  // namespace

Result<std::string> export_pedsim_scenario(const world::World& world, const crowd::Program& program,
                                           const PedsimExportOptions& options) {
  crowd::RunnerOptions ro;
  ro.seed = options.seed;
  ro.record_metrics = false;
  auto runner = crowd::ScenarioRunner::create(&world, program, ro);
  if (!runner) return tl::unexpected(runner.error());
  return Writer(world, program, **runner).write(options);
}

}  // namespace socsim::interop
