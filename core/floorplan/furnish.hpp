#pragma once
// ROIs, POIs and entities placed by room type, as the floor-plan generators need them: a
// reception counter with its queue lane and a waiting zone in a lobby, tables and a serving
// counter in a dining hall, desks in offices, beds in patient rooms, a sofa in a living room,
// water dispensers and coffee machines where they fit, corridor and entrance ROIs.
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/common/rng.hpp"
#include "core/floorplan/compliance.hpp"
#include "core/world/world_builder.hpp"

namespace socsim::floorplan {

// Floor plans are built of the world model's types (World, Zone, Point, …).
using namespace socsim::world;

struct FurnishingRules {
  double walkway_width = 1.2;     // m, aisles between shelves and racks (at least the code's aisle width)
  double queue_lane_width = 1.0;  // m
  double area_per_desk = 10.0;    // m² of work room per desk
};

// Rules that satisfy the retrieved constraints (aisle widths, workspace per person).
FurnishingRules furnishing_rules(std::span<const knowledge::MergedConstraint> constraints,
                                 const PlanRequirement& plan);

struct Furnishing {
  std::vector<Roi> rois;
  std::vector<EntitySpec> entities;
};

// Furnishes every zone of a known type inside the largest axis-aligned rectangle of its polygon,
// facing the room's main door and keeping the doors clear. Zones and doors are those handed to
// WorldBuilder; the names made are "<zone>_<item>[_NN]". Deterministic for a given rng state.
// Zones named in `unfurnished` get only their entrance ROIs (an open hall furnished by its areas).
Furnishing furnish(std::span<const Zone> zones, std::span<const DoorSpec> doors, const FurnishingRules& rules,
                   Rng& rng, std::span<const std::string> unfurnished = {});

// What furnishing the worlds of one plan again (more or wider exits) can re-use: per room, what it
// was given (zone, its doors, the random stream's state) and what it made (things, areas, the
// stream's state after). A room's furnishing depends on nothing else (the placer ignores other
// rooms' things), so a room given the same again gets the same, without placing it again.
struct FurnishingMemo {
  struct Door {
    double x = 0, y = 0, width = 0;
    bool exterior = false;
    std::string other_type, name;
    friend bool operator==(const Door&, const Door&) = default;
  };
  struct Room {
    Polygon polygon;
    std::string type;
    std::vector<Door> doors;
    Rng before{0}, after{0};
    std::vector<Roi> rois;
    std::vector<EntitySpec> entities;
  };
  std::map<std::string, Room> rooms;  // by zone name
};
Furnishing furnish(std::span<const Zone> zones, std::span<const DoorSpec> doors, const FurnishingRules& rules,
                   Rng& rng, std::span<const std::string> unfurnished, FurnishingMemo& memo);

// Furnishes the zones of an open hall: rectangles inside one room with no walls between them,
// each typed by what happens there — checkout_zone (a row of check-outs with queue lanes),
// shelf_aisles and rack_aisles (rows with walkways), dining_area (tables), staging_area (a work
// area and pallets), or a room type furnished as that room (waiting_room, cafe, concourse …).
// `doors` are the hall's doors on each area's edges and the openings between areas, each naming
// the areas it joins; names made are "<area>_<item>[_NN]".
Furnishing furnish_areas(std::span<const Zone> areas, std::span<const DoorSpec> doors,
                         const FurnishingRules& rules, Rng& rng);

}  // namespace socsim::floorplan
