#pragma once
// Geometric quality of a world's layout beyond what WorldBuilder validates: every zone reachable
// from the outside by a person of a given width, doors on the walls they join, and every entity's
// footprint (footprint.hpp) inside its zone, clear of walls, door openings and other entities,
// with a free spot beside it that such a person can walk to.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/world/world.hpp"

namespace socsim::world {

struct LayoutFinding {
  // zone_unreachable, door_off_wall, entity_outside_zone, entity_on_wall, entity_overlap,
  // entity_blocks_door, entity_unreachable
  std::string kind;
  std::string element;  // zone, door or entity name
  std::string other;    // the second element of an overlap, the wall or door concerned
  std::string message;
};

struct LayoutCheck {
  std::vector<LayoutFinding> findings;
  std::size_t entities_checked = 0;
  std::size_t reachable_entities = 0;
  [[nodiscard]] bool ok() const { return findings.empty(); }
  [[nodiscard]] std::size_t count(std::string_view kind) const;
  [[nodiscard]] std::string summary() const;  // one line per finding (at most 20), for messages
};

struct LayoutCheckOptions {
  double person_width = 0.5;    // m: reachability is for a person this wide
  double resolution = 0.1;      // m per grid cell
  double reach = 0.4;           // m: a person's edge this close to an entity can use it
  double door_clearance = 0.3;  // m kept free of furniture in front of every door opening
  double tolerance = 0.01;      // m: touching is not overlapping
  std::size_t max_cells = 6'000'000;
};

LayoutCheck check_layout(const World& world, const LayoutCheckOptions& options = {});

}  // namespace socsim::world
