#pragma once
// What the offline generator knows about a world: zones with their areas and neighbours through
// doors, places by kind and type, exits, queue lanes with their counters, reachability and how many
// people a region holds — read through the same BtEnvironment the behaviour nodes use, so a place
// the generator picks is a place the nodes resolve.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/crowd/bt_environment.hpp"
#include "core/world/world.hpp"

namespace socsim::scenario {

struct QueueLane {
  std::string name;           // queue_lane ROI
  std::string counter;        // the serving entity ("" when the lane has none)
  std::string zone;           // zone holding the lane
  crowd::Vec2 head, service;  // first place in line, where the head is served
  double length = 0.0;        // m along the lane axis
};

struct ExitPlace {
  std::string name;    // door to the outside or exit ROI (what Evacuate's exit port takes)
  std::string region;  // ROI just inside it (entrance/exit kind) or the zone it opens from
  crowd::Vec2 point;
};

class WorldProbe {
 public:
  explicit WorldProbe(const world::World& world);
  WorldProbe(const WorldProbe&) = delete;
  WorldProbe& operator=(const WorldProbe&) = delete;
  ~WorldProbe();

  [[nodiscard]] const world::World& world() const { return world_; }
  // Building type read from the zone types: hospital, office, residential, warehouse, canteen,
  // retail, school, airport or "generic".
  [[nodiscard]] const std::string& domain() const { return domain_; }

  [[nodiscard]] std::optional<crowd::Place> place(std::string_view name) const;
  [[nodiscard]] crowd::Vec2 point(std::string_view name) const;  // place's point; (0,0) if unknown
  // Name of the zone containing p ("" outside every zone).
  [[nodiscard]] std::string zone_at(crowd::Vec2 p) const;
  [[nodiscard]] double zone_area(std::string_view zone) const;
  [[nodiscard]] double region_area(std::string_view region) const;  // ROI or zone polygon
  // People that fit in a region for spawning (0.8 per m² of the area kept 0.35 m from its edges).
  [[nodiscard]] std::size_t capacity(std::string_view region) const;
  // Zones sharing a door with `zone`, by door name.
  [[nodiscard]] std::vector<std::pair<std::string, std::string>> neighbours(std::string_view zone) const;
  [[nodiscard]] bool is_circulation(std::string_view zone) const;
  [[nodiscard]] bool is_toilet(std::string_view zone) const;
  [[nodiscard]] std::vector<std::string> zones_of_type(std::initializer_list<std::string_view> types) const;
  [[nodiscard]] std::vector<std::string> entities_of_type(
      std::initializer_list<std::string_view> types) const;
  [[nodiscard]] std::vector<std::string> rois_of_kind(std::string_view kind) const;
  // Entities and ROIs whose point lies in the zone.
  [[nodiscard]] std::vector<std::string> entities_in(std::string_view zone) const;
  [[nodiscard]] std::vector<std::string> rois_in(std::string_view zone) const;

  [[nodiscard]] const std::vector<QueueLane>& queue_lanes() const { return lanes_; }
  [[nodiscard]] const std::vector<ExitPlace>& exits() const { return exits_; }
  // Walking distance (geodesic, +inf when unreachable).
  double walking_distance(crowd::Vec2 a, crowd::Vec2 b);

 private:
  const world::World& world_;
  std::string domain_;
  std::unique_ptr<crowd::CrowdSimulation> sim_;
  std::unique_ptr<crowd::BtEnvironment> env_;
  std::vector<QueueLane> lanes_;
  std::vector<ExitPlace> exits_;
};

}  // namespace socsim::scenario
