#pragma once
// The floor area an entity takes, by type: a rectangle centred on its pose, `width` across its
// facing (yaw) and `depth` along it (a bed 1.0 × 2.0, a counter 1.8 × 0.7, a chair 0.5 × 0.5).
// Generators place furniture by these footprints and layout checks test them against walls and
// each other; types the table does not know take 0.6 × 0.6.
#include <span>
#include <string_view>

#include "core/geometry/types.hpp"

namespace socsim::world {

struct Footprint {
  double width = 0.6;  // m, across the facing
  double depth = 0.6;  // m, along the facing
};

struct EntityFootprint {
  std::string_view type;
  Footprint size;
};
std::span<const EntityFootprint> entity_footprints();

Footprint footprint_of(std::string_view entity_type);

// The four corners (counter-clockwise) of the footprint of an entity of `type` at `pose`.
geometry::Polygon footprint_polygon(std::string_view type, const geometry::Pose2& pose);
geometry::Polygon footprint_polygon(const Footprint& size, const geometry::Pose2& pose);

}  // namespace socsim::world
