#pragma once
// The room vocabulary floor plans share: which zone types are circulation (corridors, halls),
// habitable rooms, bedrooms, which occupant-load use they have, and their typical sizes.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace socsim::floorplan {

enum class Circulation { kNone, kCorridor, kHall };

struct RoomType {
  std::string_view type;   // zone type, e.g. "patient_room"
  std::string_view label;  // words for people and prompts, e.g. "patient room"
  Circulation circulation = Circulation::kNone;
  bool habitable = false;     // a habitable room of a dwelling (IRC R304): living, sleeping, dining, study
  std::string_view load_use;  // occupant-load factor the room's area counts under ("business", "waiting" …);
                              // empty: accessory
  double area_lo = 0.0;  // typical net area (m²) of a generated room, before code minima
  double area_hi = 0.0;
};

std::span<const RoomType> room_types();
// By type name, case-insensitively, also accepting a few synonyms ("ward" → patient_room,
// "restroom" → toilet, "hall" → hallway …). nullptr for unknown types.
const RoomType* find_room_type(std::string_view type);
// The canonical type name for a known type or synonym; the lower-cased input otherwise.
std::string canonical_room_type(std::string_view type);

bool is_corridor_type(std::string_view type);  // corridor, hallway
bool is_hall_type(std::string_view type);      // dining_hall, sales_floor, warehouse_floor, concourse
inline bool is_circulation_type(std::string_view type) {
  return is_corridor_type(type) || is_hall_type(type);
}
bool is_bedroom_type(std::string_view type);  // bedroom (dwellings)
bool is_habitable_type(std::string_view type);
bool is_toilet_type(std::string_view type);  // toilet, bathroom

}  // namespace socsim::floorplan
