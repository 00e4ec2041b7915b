#include "core/world/world.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "core/geometry/planar.hpp"

namespace socsim::world {

namespace {
constexpr std::array<std::string_view, 14> kRoiKinds = {
    "area",       "assembly_zone", "corridor",   "counter_area", "entrance", "exit",     "goal_area",
    "queue_lane", "seating_area",  "spawn_area", "waiting_zone", "walkway",  "waypoint", "work_area"};

template <class T, class IdT>
std::optional<IdT> find_by_name(const std::vector<T>& items, std::string_view name) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == name) return IdT(static_cast<std::uint32_t>(i));
  }
  return std::nullopt;
}
}  // namespace

std::span<const std::string_view> roi_kinds() {
  return kRoiKinds;
}

bool is_roi_kind(std::string_view kind) {
  return std::find(kRoiKinds.begin(), kRoiKinds.end(), kind) != kRoiKinds.end();
}

std::optional<ZoneId> World::find_zone(std::string_view name) const {
  return find_by_name<Zone, ZoneId>(zones_, name);
}
std::optional<DoorId> World::find_door(std::string_view name) const {
  return find_by_name<Door, DoorId>(doors_, name);
}
std::optional<RoiId> World::find_roi(std::string_view name) const {
  return find_by_name<Roi, RoiId>(rois_, name);
}
std::optional<EntityId> World::find_entity(std::string_view name) const {
  return find_by_name<Entity, EntityId>(entities_, name);
}

std::vector<RoiId> World::rois_of_kind(std::string_view kind) const {
  std::vector<RoiId> out;
  for (std::size_t i = 0; i < rois_.size(); ++i) {
    if (rois_[i].kind == kind) out.emplace_back(static_cast<std::uint32_t>(i));
  }
  return out;
}

std::optional<ZoneId> World::zone_at(Point p) const {
  for (std::size_t i = 0; i < zones_.size(); ++i) {
    if (geometry::contains(zones_[i].polygon, p)) return ZoneId(static_cast<std::uint32_t>(i));
  }
  return std::nullopt;
}

geometry::Box World::bounds() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  geometry::Box b{{inf, inf}, {-inf, -inf}};
  auto grow = [&b](Point p) {
    b.min.x = std::min(b.min.x, p.x);
    b.min.y = std::min(b.min.y, p.y);
    b.max.x = std::max(b.max.x, p.x);
    b.max.y = std::max(b.max.y, p.y);
  };
  for (const auto& z : zones_) {
    for (const Point& p : z.polygon.outer) grow(p);
  }
  for (const auto& w : walls_) {
    grow(w.segment.a);
    grow(w.segment.b);
  }
  if (b.min.x > b.max.x) return {{0, 0}, {0, 0}};
  return b;
}

double World::area() const {
  double a = 0.0;
  for (const auto& z : zones_) a += geometry::area(z.polygon);
  return a;
}

}  // namespace socsim::world
