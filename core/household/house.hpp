#pragma once
// Static houses in the style of ProcTHOR: rooms of four types with floor polygons (metres, x/z
// plane), walls, doors, receptacles and movable objects of AI2-THOR types on them. Generated
// procedurally with a seed (rectangles packed by guillotine cuts, doors on shared walls along
// a spanning tree, so every room is reachable) or imported from ProcTHOR JSON (procthor.hpp).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/household/knowledge.hpp"

namespace socsim::household {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};
struct FloorPoint {
  double x = 0.0, z = 0.0;
  friend bool operator==(const FloorPoint&, const FloorPoint&) = default;
};

struct Room {
  std::string id;
  RoomType type = RoomType::kLivingRoom;
  std::vector<FloorPoint> floor;  // simple polygon, may be non-convex
  Json extra = Json::object();    // ProcTHOR fields kept for export (materials, layer, …)
  friend bool operator==(const Room&, const Room&) = default;
};

struct Wall {
  std::string id;
  std::string room_id;  // "exterior" faces have the outside as their room
  FloorPoint a, b;
  double height = 2.5;
  bool empty = false;  // an open connection between rooms
  Json extra = Json::object();
  friend bool operator==(const Wall&, const Wall&) = default;
};

struct Door {
  std::string id, room0, room1, wall0, wall1, asset_id;
  Vec3 hole_min, hole_max;  // in wall0's local frame (x along the wall from its first point)
  Vec3 asset_position;
  bool openable = true;
  double openness = 1.0;
  Json extra = Json::object();
  friend bool operator==(const Door&, const Door&) = default;
};

enum class EntityKind : std::uint8_t { kReceptacle, kObject, kFixture };

// Anything placed in the house: receptacles (furniture), movable objects, fixtures.
struct Entity {
  std::string id;
  std::string type;  // AI2-THOR object type
  std::string asset_id;
  EntityKind kind = EntityKind::kFixture;
  int room = -1;    // index into House::rooms
  int parent = -1;  // index into House::entities (the receptacle it rests on), -1 on the floor
  Vec3 position;
  Vec3 rotation;
  double size_x = 0.3, size_z = 0.3;  // footprint in the entity's own frame (before yaw), metres
  bool synthetic = false;             // made on import (a room's Floor); not exported
  Json extra = Json::object();
  friend bool operator==(const Entity&, const Entity&) = default;
};

struct House {
  std::string id;
  std::vector<Room> rooms;
  std::vector<Wall> walls;
  std::vector<Door> doors;
  std::vector<Entity> entities;  // parents before their children
  Json windows = Json::array();  // kept as given, for export
  Json metadata = Json::object();
  Json procedural = Json::object();

  // Indices into entities, rebuilt by index().
  std::vector<int> receptacles;
  std::vector<int> objects;
  void index();

  [[nodiscard]] int room_index(std::string_view room_id) const;
  [[nodiscard]] int room_at(double x, double z) const;  // -1 when outside every room
  [[nodiscard]] std::vector<int> rooms_of(RoomType type) const;
  // Rooms reachable from each other through doors and open walls; true when all are.
  [[nodiscard]] bool connected() const;
  [[nodiscard]] std::vector<std::pair<int, int>> room_links() const;

  friend bool operator==(const House& a, const House& b) {
    return a.id == b.id && a.rooms == b.rooms && a.walls == b.walls && a.doors == b.doors &&
           a.entities == b.entities && a.windows == b.windows && a.metadata == b.metadata &&
           a.procedural == b.procedural;
  }
};

double polygon_area(const std::vector<FloorPoint>& polygon);
bool point_in_polygon(const std::vector<FloorPoint>& polygon, double x, double z);

// Footprints: an entity's size_x × size_z rectangle turned by its yaw (rotation.y, degrees, as
// in AI2-THOR: a local offset (lx, lz) lands at (lx·cos + lz·sin, −lx·sin + lz·cos)).
using Footprint = std::array<FloorPoint, 4>;
Footprint footprint(const Entity& e);
FloorPoint local_to_world(const Entity& e, double lx, double lz);
// Overlap of two convex quadrilaterals by separating axes; touching edges do not overlap.
bool footprints_overlap(const Footprint& a, const Footprint& b);
// Every corner inside the polygon and no polygon edge crossing the rectangle.
bool footprint_inside(const std::vector<FloorPoint>& polygon, const Footprint& f);
// Free floor to keep in front of each door of a room: the swing of a door leaf as wide as the
// opening, plus 0.15 m either side.
std::vector<Footprint> door_clearances(const House& house, int room);
// Objects counted as ProcTHOR counts them: every entity, furniture, fixtures and what stands on
// them (synthetic floors excluded).
int objects_with_children(const House& house);
// The range of objects with children in real ProcTHOR houses of that many rooms: the peer
// houses give 102–109 at 4 rooms and 124–166 at 8; linear between, extended with the 4→8 slope
// above 8, and proportional (0 rooms → 0) below 4.
std::pair<int, int> procthor_object_range(int rooms);

struct HouseRequest {
  int rooms = 4;                // 1 … 10
  std::optional<int> bedrooms;  // default: from the room count
  std::uint64_t seed = 0;
};

// A furnished house: room program by size, guillotine layout, doors on shared walls forming a
// spanning tree from the living room (or kitchen) plus a front door, windows on outside walls,
// receptacles from the room programs placed along walls or in the middle (inside the room, clear
// of door swings and each other), fixtures, and movable objects on receptacle tops until the
// house holds a count drawn inside procthor_object_range(rooms).
Result<House> generate_house(const HouseRequest& request, const HouseholdKnowledge& knowledge);

}  // namespace socsim::household
