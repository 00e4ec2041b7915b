#pragma once
// Collects zones, walls, doors, ROIs and entities (from a file, an import or a floor-plan
// generator), validates them once and produces an immutable World. Errors carry JSON
// pointers into the world document (/zones/3/polygon), so a parser can add line numbers.
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/common/error.hpp"
#include "core/world/world.hpp"

namespace socsim::world {

// The largest |x| or |y| of any point of a world, in metres (100 km): far beyond any building,
// and small enough that areas, distances and the geometry library stay exact and finite
// (coordinates of 1e200 made GEOS fail on overflowing orientation tests).
inline constexpr double kMaxCoordinate = 1e5;

struct BuildOptions {
  double agent_radius = 0.25;        // m; every zone must be reachable for an agent this wide
  double boundary_tolerance = 0.01;  // m; points this close to a boundary lie on it
  double door_snap_distance = 0.25;  // m; a door centre may sit this far off the boundary (within the wall)
  double overlap_tolerance =
      1e-3;  // m²; zones may overlap by this much (rounding), ROIs leave zones by this much
  double default_wall_height = 3.0;          // m; for derived walls
  std::string default_wall_style = "plain";  // for derived walls of zones without a material
  double grid_resolution = 0.05;             // m; reachability grid (coarsened for very large worlds)
  bool check_reachability = true;
};

struct DoorSpec {
  std::string name;
  Pose2 pose;
  double width = 0.0;
  // Zone names: two for a door between zones, one for a door to the outside, none to let
  // the builder find the zones whose boundary the door lies on.
  std::vector<std::string> connects;
};

struct EntitySpec {
  std::string type;
  std::string name;
  Pose2 pose;
  std::vector<std::string> affordances;
};

// What build() works out from the zones alone — their overlaps, the plan's union and outline, the
// boundaries doors were found on, the dissolved boundaries walls are cut from — kept for the next
// build of the same zones (a floor plan built again with more exits or furniture left out). Read
// only when that build's zones and tolerances are equal to the ones it was filled from, so a
// world built with it is the world built without it.
struct BuildCache {
  std::vector<Zone> zones;
  double boundary_tolerance = -1.0, overlap_tolerance = -1.0;
  std::vector<std::tuple<std::size_t, std::size_t, double>> overlaps;  // (i, j, m²) over the tolerance
  geometry::MultiPolygon plan;
  std::vector<Segment> outline;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<Segment>> boundaries;
  std::vector<Segment> wall_lines;  // the zones' dissolved boundaries
};

class WorldBuilder {
 public:
  WorldBuilder& set_name(std::string name);
  WorldBuilder& set_origin(Pose2 origin);
  WorldBuilder& set_floor(Floor floor);
  // Elements are reported by their position in these lists (/zones/<i>, /doors/<i> …).
  // A zone with an empty polygon takes the region its walls enclose, or else the rectangle its
  // walls, doors, segmentation areas and entities span (paper 001, Fig. 3 names the zone only);
  // build() says so in a warning, or fails at /zones/<i>/polygon when nothing encloses it.
  ZoneId add_zone(Zone zone);
  WorldBuilder& add_wall(Wall wall);  // none added → walls are derived from zones and doors
  WorldBuilder& add_door(DoorSpec door);
  WorldBuilder& add_roi(Roi roi);
  WorldBuilder& add_entity(EntitySpec entity);

  [[nodiscard]] std::size_t zone_count() const { return zones_.size(); }

  // Validates everything and returns the World, or a kValidation error listing every
  // problem found (each with a JSON pointer and a message naming the elements involved).
  // What build() assumed (a zone region inferred, walls added to close it) is appended to
  // `warnings`, when given, with the pointer of the element concerned.
  // `cache`: what an earlier build of the same zones worked out (filled or refilled here).
  [[nodiscard]] Result<World> build(const BuildOptions& options = {},
                                    std::vector<FieldError>* warnings = nullptr,
                                    BuildCache* cache = nullptr) const;

 private:
  std::string name_;
  Pose2 origin_;
  Floor floor_;
  std::vector<Zone> zones_;
  std::vector<Wall> walls_;
  std::vector<DoorSpec> doors_;
  std::vector<Roi> rois_;
  std::vector<EntitySpec> entities_;
};

// Walls derived as the paper does: the dissolved zone boundaries minus the door openings.
// Each wall takes its style from the material of the first zone it bounds.
// `lines`: the zones' dissolved boundaries when already known (BuildCache::wall_lines).
std::vector<Wall> derive_walls(const std::vector<Zone>& zones, const std::vector<Door>& doors,
                               const BuildOptions& options, const std::vector<Segment>* lines = nullptr);

}  // namespace socsim::world
