#pragma once
// The compliance report of a world against the building-code constraints retrieved for its
// building type: every constraint with the measured value, the required value, pass/fail and
// the code entry (ref_id, section) it came from; plus what a generator must build to pass.
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/world/occupancy_grid.hpp"
#include "core/world/world.hpp"

namespace socsim::floorplan {

// Floor plans are built of the world model's types (World, Zone, Point, …).
using namespace socsim::world;

enum class CheckStatus {
  kPass,
  kFail,
  kAdvisory,       // a recommended value the plan does not reach (does not fail the report)
  kUsed,           // a design figure used by another check (occupant-load factors)
  kNotApplicable,  // the plan has nothing it applies to (no stairs, no bedrooms …)
  kNotChecked,     // the plan does not carry the quantity (window sills, WC clearances …)
};
std::string_view to_string(CheckStatus status);

struct ComplianceFinding {
  std::string element;  // zone, door or ROI name
  double value = 0.0;
};

// Clear widths and inscribed circles of outlines other than rectangles are measured with GEOS
// morphological openings, whose cost grows much faster than the vertex count. A report measures
// outlines of at most kMaxMeasuredVertices vertices, kMeasuredVertexBudget vertices in all; a check
// that needed an outline beyond these is not_checked (unless a measured element already fails it).
inline constexpr std::size_t kMaxMeasuredVertices = 64;
inline constexpr std::size_t kMeasuredVertexBudget = 1024;

struct ComplianceCheck {
  std::string name;  // constraint name, e.g. corridor_clear_width
  std::string applies_to;
  std::string type;       // min | max | recommended
  double required = 0.0;  // the constraint's value
  std::string unit;
  std::optional<double> value;  // the worst measured value (smallest for min, largest for max)
  std::string element;          // where that value was measured
  std::size_t checked = 0;      // elements measured
  std::size_t unmeasured = 0;   // elements too detailed to measure (see kMaxMeasuredVertices)
  std::vector<ComplianceFinding> failures;
  CheckStatus status = CheckStatus::kNotChecked;
  std::string detail;  // how it was measured, or why it was not
  std::string ref_id;
  std::string title;
  std::string section;  // the entry's source sections, "; "-joined
  std::string jurisdiction;
  double confidence = 1.0;
};

struct ComplianceReport {
  std::string building_type;
  bool passed = true;          // no check has status kFail
  double occupant_load = 0.0;  // persons: from the occupant-load factors, or the scenario's people when more
  double occupant_load_from_area = 0.0;      // persons, from the occupant-load factors alone
  std::optional<double> scenario_occupants;  // the people the scenario puts in the building, when given
  std::vector<ComplianceCheck> checks;
  [[nodiscard]] std::vector<const ComplianceCheck*> failures() const;
};

// Checks the world against every constraint (one check per constraint, in the given order).
// `occupants`: the people the scenario puts in the building; egress width and the number of
// exits are checked for them when they outnumber the occupant load of the floor areas.
// The building type a world is, classified from its zones' names and types (for worlds that do
// not say: posted world.yaml files, stored worlds without a domain).
std::string building_type_of(const World& world);

ComplianceReport check_compliance(const World& world, std::string_view building_type,
                                  std::span<const knowledge::MergedConstraint> constraints,
                                  std::optional<double> occupants = std::nullopt);

// What successive reports on the worlds of one plan share (a generator builds a plan again with
// more or wider exits, or with furniture left out): the travel-distance grid while the zones,
// walls and outline are the same, and each travel distance already measured from the same exit
// points. A report is the same with or without it; it only skips work.
struct ComplianceCache {
  std::vector<double> grid_of;  // the geometry the grid was rasterised from (zones, walls, outline)
  std::optional<OccupancyGrid> grid;
  // By the exit points the field was marched from: the longest distance and the zone where it is.
  std::map<std::vector<double>, std::pair<double, std::optional<std::uint32_t>>> travel;
};
ComplianceReport check_compliance(const World& world, std::string_view building_type,
                                  std::span<const knowledge::MergedConstraint> constraints,
                                  std::optional<double> occupants, ComplianceCache& cache);

// {building_type, passed, occupant_load, summary: {pass, fail, …}, checks: [...]}
Json to_json(const ComplianceReport& report);
Json to_json(const ComplianceCheck& check);

// What a generator must give a room of this type for check_compliance to pass (the main
// bedroom is the largest one, which the double-bedroom rules apply to).
struct RoomRequirement {
  double min_area = 0.0;       // m²
  double min_dimension = 0.0;  // m, narrowest clear width
};
RoomRequirement room_requirement(std::span<const knowledge::MergedConstraint> constraints,
                                 std::string_view room_type, bool main_bedroom);

struct PlanRequirement {
  double corridor_width = 0.0;     // m, clear
  double door_width = 0.0;         // m, every door
  double public_door_width = 0.0;  // m, entrances and doors onto circulation (non-dwellings)
  double walkway_width = 0.0;      // m, aisles between shelves or racks
  double queue_lane_width = 0.0;   // m, check-out aisles
  double turning_diameter = 0.0;   // m, every room
  double ceiling_height = 0.0;     // m, wall height
  double travel_distance = 0.0;    // m, to the nearest exit; 0 = no limit retrieved
};
PlanRequirement plan_requirement(std::span<const knowledge::MergedConstraint> constraints,
                                 std::string_view building_type);

// A dwelling's gross internal area and built-in storage minima for its bedrooms (areas in m²;
// a bedroom of at least the double-bedroom area sleeps two). Zero when no entry applies.
struct DwellingRequirement {
  double gross_internal_area = 0.0;
  double storage_area = 0.0;
};
DwellingRequirement dwelling_requirement(std::span<const knowledge::MergedConstraint> constraints,
                                         std::span<const double> bedroom_areas);

// Narrowest clear width of a polygon: the largest w such that every part of it lies in some
// w-wide disc that fits inside (exact for rectangles; GEOS morphological opening otherwise).
double clear_width(const Polygon& polygon);
// Diameter of the largest circle that fits inside the polygon.
double inscribed_diameter(const Polygon& polygon);

}  // namespace socsim::floorplan
