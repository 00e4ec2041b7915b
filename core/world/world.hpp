#pragma once
// The semantic world (paper 001 §III-B): zones, walls, doors, floor, ROIs and entities in
// metres. Only WorldBuilder makes one, after validation; afterwards it never changes.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/types.hpp"
#include "core/world/ids.hpp"

namespace socsim::world {

using geometry::Point;
using geometry::Polygon;
using geometry::Pose2;
using geometry::Segment;

// A named region of the floor plan (a room, corridor, hall).
struct Zone {
  std::string name;
  std::string type;      // room type, e.g. "canteen", "patient_room", "corridor"
  std::string material;  // wall/finish convention of the room type; empty = unspecified
  Polygon polygon;
  friend bool operator==(const Zone&, const Zone&) = default;
};

struct Wall {
  Segment segment;  // start → end
  double height = 3.0;
  std::string style;
  friend bool operator==(const Wall&, const Wall&) = default;
};

// A navigable opening in a zone boundary; `other` is empty for a door to the outside.
struct Door {
  std::string name;
  Pose2 pose;  // centre of the opening as written; yaw is carried to exports
  double width = 0.0;
  ZoneId zone{0};
  std::optional<ZoneId> other;
  Segment opening;  // the opening on the boundary, computed by the builder
  friend bool operator==(const Door&, const Door&) = default;
};

// A segmentation region of interest that behaviours refer to (queue lane, seating area …).
struct Roi {
  std::string name;
  std::string kind;
  Polygon polygon;
  friend bool operator==(const Roi&, const Roi&) = default;
};

// A spawnable object or point of interest (counter, table, seat) with what agents can do there.
struct Entity {
  std::string type;
  std::string name;
  Pose2 pose;
  std::vector<std::string> affordances;
  ZoneId zone{0};  // the zone the entity stands in, found by the builder
  friend bool operator==(const Entity&, const Entity&) = default;
};

struct Floor {
  std::string material;
  friend bool operator==(const Floor&, const Floor&) = default;
};

// ROI kinds behaviours and generators know; world.yaml accepts only these.
std::span<const std::string_view> roi_kinds();
bool is_roi_kind(std::string_view kind);

class World {
 public:
  [[nodiscard]] const std::string& name() const { return name_; }
  // Pose of the world frame in the frame of exported maps and simulators.
  [[nodiscard]] const Pose2& origin() const { return origin_; }
  [[nodiscard]] const Floor& floor() const { return floor_; }

  [[nodiscard]] std::span<const Zone> zones() const { return zones_; }
  [[nodiscard]] std::span<const Wall> walls() const { return walls_; }
  [[nodiscard]] std::span<const Door> doors() const { return doors_; }
  [[nodiscard]] std::span<const Roi> rois() const { return rois_; }
  [[nodiscard]] std::span<const Entity> entities() const { return entities_; }

  [[nodiscard]] const Zone& zone(ZoneId id) const { return zones_.at(id.index()); }
  [[nodiscard]] const Wall& wall(WallId id) const { return walls_.at(id.index()); }
  [[nodiscard]] const Door& door(DoorId id) const { return doors_.at(id.index()); }
  [[nodiscard]] const Roi& roi(RoiId id) const { return rois_.at(id.index()); }
  [[nodiscard]] const Entity& entity(EntityId id) const { return entities_.at(id.index()); }

  [[nodiscard]] std::optional<ZoneId> find_zone(std::string_view name) const;
  [[nodiscard]] std::optional<DoorId> find_door(std::string_view name) const;
  [[nodiscard]] std::optional<RoiId> find_roi(std::string_view name) const;
  [[nodiscard]] std::optional<EntityId> find_entity(std::string_view name) const;
  // ROIs of one kind, in file order.
  [[nodiscard]] std::vector<RoiId> rois_of_kind(std::string_view kind) const;

  // The zone whose polygon covers p (the first one when p is on a shared boundary).
  [[nodiscard]] std::optional<ZoneId> zone_at(Point p) const;
  // Outline of the union of all zones: where the walkable plan ends.
  [[nodiscard]] std::span<const Segment> outline() const { return outline_; }
  // Bounding box of zones and walls.
  [[nodiscard]] geometry::Box bounds() const;
  [[nodiscard]] double area() const;  // sum of zone areas, m²

  friend bool operator==(const World&, const World&) = default;

 private:
  friend class WorldBuilder;
  World() = default;

  std::string name_;
  Pose2 origin_;
  Floor floor_;
  std::vector<Zone> zones_;
  std::vector<Wall> walls_;
  std::vector<Door> doors_;
  std::vector<Roi> rois_;
  std::vector<Entity> entities_;
  std::vector<Segment> outline_;
};

}  // namespace socsim::world
