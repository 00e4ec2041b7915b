#include "core/scenario/offline_world.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/floorplan/rooms.hpp"
#include "core/geometry/planar.hpp"

namespace socsim::scenario {

namespace {

std::string guess_domain(const world::World& w) {
  std::map<std::string, int> votes;
  for (const world::Zone& z : w.zones()) {
    const std::string t = floorplan::canonical_room_type(z.type);
    if (t == "patient_room" || t == "nurse_station" || t == "treatment_room" || t == "icu_room" ||
        t == "ward")
      ++votes["hospital"];
    else if (t == "open_office" || t == "meeting_room" || t == "private_office" || t == "kitchenette")
      ++votes["office"];
    else if (t == "living_room" || t == "bedroom" || t == "bathroom" || t == "kitchen")
      ++votes["residential"];
    else if (t == "warehouse_floor" || t == "loading_bay")
      ++votes["warehouse"];
    else if (t == "dining_hall")
      ++votes["canteen"];
    else if (t == "sales_floor" || t == "stock_room")
      ++votes["retail"];
    else if (t == "classroom")
      ++votes["school"];
    else if (t == "concourse" || t == "gate_area" || t == "security")
      ++votes["airport"];
  }
  std::string best = "generic";
  int n = 0;
  for (const auto& [d, v] : votes)
    if (v > n) {
      n = v;
      best = d;
    }
  return best;
}

}  // namespace

WorldProbe::WorldProbe(const world::World& world) : world_(world), domain_(guess_domain(world)) {
  auto sim = crowd::CrowdSimulation::create(crowd::SimulationConfig{});
  if (!sim) throw std::logic_error("default crowd simulation rejected: " + sim.error().detail);
  sim_ = std::make_unique<crowd::CrowdSimulation>(std::move(*sim));
  env_ = std::make_unique<crowd::BtEnvironment>(*sim_, &world_);
  for (world::RoiId r : world_.rois_of_kind("queue_lane")) {
    const world::Roi& roi = world_.roi(r);
    crowd::BtEnvironment::Queue* q = env_->queue(roi.name);
    if (q == nullptr) continue;
    QueueLane lane;
    lane.name = roi.name;
    lane.head = q->head;
    lane.service = q->service;
    const geometry::Box box = geometry::bounds(roi.polygon.outer);
    lane.length = std::max(box.width(), box.height());
    if (q->counter) {
      for (const world::Entity& e : world_.entities())
        if (crowd::distance({e.pose.x, e.pose.y}, *q->counter) < 1e-6) {
          lane.counter = e.name;
          break;
        }
    }
    lane.zone = zone_at(q->head);
    lanes_.push_back(std::move(lane));
  }
  for (const crowd::BtEnvironment::Exit& e : env_->exits()) {
    ExitPlace x;
    x.name = e.name;
    x.point = e.point;
    if (e.region != nullptr) {
      x.region = e.name;
    } else {
      // The entrance/exit ROI nearest the door (furnishing puts one just inside each outer door),
      // else the zone the door opens from.
      double best = 2.0;
      for (const world::Roi& r : world_.rois()) {
        if (r.kind != "entrance" && r.kind != "exit") continue;
        const world::Point c = geometry::centroid(r.polygon.outer);
        const double d = crowd::distance({c.x, c.y}, e.point);
        if (d < best) {
          best = d;
          x.region = r.name;
        }
      }
      if (x.region.empty()) {
        if (auto d = world_.find_door(e.name)) x.region = world_.zone(world_.door(*d).zone).name;
      }
    }
    exits_.push_back(std::move(x));
  }
}

WorldProbe::~WorldProbe() = default;

std::optional<crowd::Place> WorldProbe::place(std::string_view name) const {
  return env_->place(name);
}

crowd::Vec2 WorldProbe::point(std::string_view name) const {
  auto p = env_->place(name);
  return p ? p->point : crowd::Vec2{};
}

std::string WorldProbe::zone_at(crowd::Vec2 p) const {
  auto z = world_.zone_at({p.x, p.y});
  return z ? world_.zone(*z).name : std::string();
}

double WorldProbe::zone_area(std::string_view zone) const {
  auto z = world_.find_zone(zone);
  return z ? std::abs(geometry::area(world_.zone(*z).polygon)) : 0.0;
}

double WorldProbe::region_area(std::string_view region) const {
  auto p = env_->place(region);
  return p && p->region != nullptr ? std::abs(geometry::area(*p->region)) : 0.0;
}

std::size_t WorldProbe::capacity(std::string_view region) const {
  auto p = env_->place(region);
  if (!p || p->region == nullptr) return 0;
  const double area = std::abs(geometry::area(*p->region));
  double perimeter = 0.0;
  for (const world::Segment& e : geometry::edges(p->region->outer)) perimeter += geometry::length(e);
  const double usable = std::max(0.0, area - perimeter * 0.35);
  return static_cast<std::size_t>(std::floor(usable * 0.8));
}

std::vector<std::pair<std::string, std::string>> WorldProbe::neighbours(std::string_view zone) const {
  std::vector<std::pair<std::string, std::string>> out;
  const auto z = world_.find_zone(zone);
  if (!z) return out;
  for (const world::Door& d : world_.doors()) {
    if (!d.other) continue;
    if (d.zone == *z)
      out.emplace_back(world_.zone(*d.other).name, d.name);
    else if (*d.other == *z)
      out.emplace_back(world_.zone(d.zone).name, d.name);
  }
  return out;
}

bool WorldProbe::is_circulation(std::string_view zone) const {
  auto z = world_.find_zone(zone);
  return z && floorplan::is_circulation_type(floorplan::canonical_room_type(world_.zone(*z).type));
}

bool WorldProbe::is_toilet(std::string_view zone) const {
  auto z = world_.find_zone(zone);
  return z && floorplan::is_toilet_type(floorplan::canonical_room_type(world_.zone(*z).type));
}

std::vector<std::string> WorldProbe::zones_of_type(std::initializer_list<std::string_view> types) const {
  std::vector<std::string> out;
  for (std::string_view t : types)
    for (const world::Zone& z : world_.zones())
      if (floorplan::canonical_room_type(z.type) == t || z.type == t) out.push_back(z.name);
  return out;
}

std::vector<std::string> WorldProbe::entities_of_type(std::initializer_list<std::string_view> types) const {
  std::vector<std::string> out;
  for (std::string_view t : types)
    for (const world::Entity& e : world_.entities())
      if (e.type == t) out.push_back(e.name);
  return out;
}

std::vector<std::string> WorldProbe::rois_of_kind(std::string_view kind) const {
  std::vector<std::string> out;
  for (world::RoiId r : world_.rois_of_kind(kind)) out.push_back(world_.roi(r).name);
  return out;
}

std::vector<std::string> WorldProbe::entities_in(std::string_view zone) const {
  std::vector<std::string> out;
  for (const world::Entity& e : world_.entities())
    if (zone_at({e.pose.x, e.pose.y}) == zone) out.push_back(e.name);
  return out;
}

std::vector<std::string> WorldProbe::rois_in(std::string_view zone) const {
  std::vector<std::string> out;
  for (const world::Roi& r : world_.rois()) {
    auto p = env_->place(r.name);
    if (p && zone_at(p->point) == zone) out.push_back(r.name);
  }
  return out;
}

double WorldProbe::walking_distance(crowd::Vec2 a, crowd::Vec2 b) {
  return env_->walking_distance(a, b);
}

}  // namespace socsim::scenario
