#include <cmath>
#include <numbers>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "core/geometry/planar.hpp"
#include "core/world/export_format.hpp"
#include "core/world/world_export.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::world {

namespace {

struct Lane {
  Point head;
  Point tail;
};

// The lane's long axis (principal axis of its vertices). The head is the end nearest an
// entity within one lane length of it (the counter being queued for); without one, the end
// nearest the polygon's first vertex.
Lane lane_axis(const World& world, const Polygon& poly) {
  const Point c = geometry::centroid(poly.outer);
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const Point& p : poly.outer) {
    const Eigen::Vector2d d(p.x - c.x, p.y - c.y);
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  const Eigen::Vector2d axis = eig.eigenvectors().col(1);  // largest eigenvalue last
  double lo = 0.0;
  double hi = 0.0;
  for (const Point& p : poly.outer) {
    const double t = (p.x - c.x) * axis.x() + (p.y - c.y) * axis.y();
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  const Point a{c.x + axis.x() * lo, c.y + axis.y() * lo};
  const Point b{c.x + axis.x() * hi, c.y + axis.y() * hi};
  const double reach = hi - lo;
  double da = INFINITY;
  double db = INFINITY;
  for (const auto& e : world.entities()) {
    da = std::min(da, geometry::distance(a, e.pose.position()));
    db = std::min(db, geometry::distance(b, e.pose.position()));
  }
  if (std::min(da, db) > reach) {
    da = geometry::distance(a, poly.outer.front());
    db = geometry::distance(b, poly.outer.front());
  }
  return db < da ? Lane{b, a} : Lane{a, b};
}

}  // namespace

std::vector<PedsimObstacle> pedsim_obstacles(const World& world) {
  std::vector<PedsimObstacle> out;
  out.reserve(world.walls().size());
  for (const auto& w : world.walls())
    out.push_back(
        {geometry::to_parent(world.origin(), w.segment.a), geometry::to_parent(world.origin(), w.segment.b)});
  return out;
}

std::vector<PedsimQueue> pedsim_queues(const World& world) {
  std::vector<PedsimQueue> out;
  for (const auto& r : world.rois()) {
    if (r.kind != "queue_lane") continue;
    const Lane lane = lane_axis(world, r.polygon);
    const Point head = geometry::to_parent(world.origin(), lane.head);
    const Point tail = geometry::to_parent(world.origin(), lane.tail);
    double deg = std::atan2(tail.y - head.y, tail.x - head.x) * 180.0 / std::numbers::pi;
    if (deg < 0) deg += 360.0;
    out.push_back({r.name, head, deg, 0});
  }
  return out;
}

std::string pedsim_element(const PedsimObstacle& o) {
  return "  <obstacle x1=\"" + micro(o.a.x) + "\" y1=\"" + micro(o.a.y) + "\" x2=\"" + micro(o.b.x) +
         "\" y2=\"" + micro(o.b.y) + "\"/>\n";
}

std::string pedsim_element(const PedsimQueue& q) {
  return "  <queue id=\"" + xml_escape(q.id) + "\" x=\"" + micro(q.position.x) + "\" y=\"" +
         micro(q.position.y) + "\" direction=\"" + micro(q.direction_deg) + "\"/>\n";
}

std::string export_pedsim(const World& world) {
  const Pose2& origin = world.origin();
  auto P = [&](Point p) { return geometry::to_parent(origin, p); };
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o << "<!-- exported by socsim from world '" << xml_escape(world.name()) << "' -->\n<scenario>\n";
  o << "  <!--Obstacles-->\n";
  for (const PedsimObstacle& w : pedsim_obstacles(world)) o << pedsim_element(w);
  o << "  <!--Waypoints-->\n";
  for (const auto& r : world.rois()) {
    // Queue lanes are queues and seating or waiting areas attractions (one element per id, as
    // pedsim_ros and the importer want).
    if (r.kind == "queue_lane" || r.kind == "seating_area" || r.kind == "waiting_zone") continue;
    const Point c = P(geometry::centroid(r.polygon.outer));
    const double radius = std::sqrt(geometry::area(r.polygon) / std::numbers::pi);
    o << "  <waypoint id=\"" << xml_escape(r.name) << "\" x=\"" << micro(c.x) << "\" y=\"" << micro(c.y)
      << "\" r=\"" << micro(radius) << "\"/>\n";
  }
  for (const auto& e : world.entities()) {
    const Point c = P(e.pose.position());
    o << "  <waypoint id=\"" << xml_escape(e.name) << "\" x=\"" << micro(c.x) << "\" y=\"" << micro(c.y)
      << "\" r=\"1\"/>\n";
  }
  o << "  <!--Queues-->\n";
  for (const PedsimQueue& q : pedsim_queues(world)) o << pedsim_element(q);
  o << "  <!--Attractions-->\n";
  for (const auto& r : world.rois()) {
    if (r.kind != "seating_area" && r.kind != "waiting_zone") continue;
    const geometry::Box b = geometry::bounds(r.polygon.outer);
    const Point c = P({(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2});
    o << "  <attraction id=\"" << xml_escape(r.name) << "\" x=\"" << micro(c.x) << "\" y=\"" << micro(c.y)
      << "\" width=\"" << micro(b.width()) << "\" height=\"" << micro(b.height()) << "\" strength=\"1\"/>\n";
  }
  o << "</scenario>\n";
  return o.str();
}

}  // namespace socsim::world
