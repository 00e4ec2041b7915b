#pragma once
// The map-based setting of paper 000 §VI: reachable points on a 0.25 m grid built from a house's
// rooms, walls, doors and furniture footprints; an agent pose is (cell, heading) and a step is a
// 0.25 m move or a 90° turn; the agent sees a point within 1.5 m, in its field of view, with no
// wall in between. Receptacles are on the map (positions known); movable objects are not.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/household/house.hpp"

namespace socsim::navbench {

struct NavConfig {
  double cell = 0.25;               // grid spacing and forward step, metres
  double wall_clearance = 0.1;      // a reachable point keeps this far from walls (agent radius)
  double view_distance = 1.5;       // success and observation radius (paper 000 §VI-B)
  double field_of_view_deg = 90.0;  // AI2-THOR's default horizontal field of view
  // Furniture hides what lies behind it: a receptacle is seen only when no other piece's body
  // rises above the sight line from the camera (eye_height) to the top of the receptacle
  // (twice its centre height, as generated and ProcTHOR houses give centres), plus 5 cm for the
  // object lying there.
  bool furniture_occludes = true;
  double eye_height = 1.5;
  // The view distance counts from the camera to the object in 3D, as AI2-THOR's visibility
  // distance does, so a low top is seen from nearer than a high one.
  bool view_distance_from_camera = true;
};

// Headings in steps of 90°: 0 = +x, 1 = +z, 2 = −x, 3 = −z. A pose is cell · 4 + heading.
inline constexpr int kHeadings = 4;
inline int pose_of(int cell, int heading) {
  return cell * kHeadings + heading;
}
inline int cell_of(int pose) {
  return pose / kHeadings;
}
inline int heading_of(int pose) {
  return pose % kHeadings;
}

// A receptacle as the robot's map knows it. No object information lives on the map, so
// estimators that take only a NavMap cannot read where objects are.
struct MapReceptacle {
  int entity = -1;  // index into House::entities
  std::string id, type;
  int room = -1;
  household::RoomType room_type = household::RoomType::kLivingRoom;
  double x = 0.0, z = 0.0;
  double top = 0.05;                 // height of an object lying on it (its top plus 5 cm), metres
  household::Footprint footprint{};  // its top as an oriented rectangle (corners one way round)
  std::vector<int> views;            // poses that see its centre, sorted
  // Inspecting it means seeing all of its top: the views (sorted) of each spot of a grid of at most
  // kSpotSpacing over its top (inside kTopMargin of its edges); spots no pose sees are left out,
  // and a receptacle whose spots all go unseen keeps its centre's views as its one spot.
  std::vector<std::vector<int>> spots;
  std::vector<household::FloorPoint> spot_points;  // where each spot lies
  static constexpr double kSpotSpacing = 0.5;
};

// A piece of furniture as an obstacle to sight: footprint, bounding box and height.
struct FurnitureBox {
  double x0 = 0.0, z0 = 0.0, x1 = 0.0, z1 = 0.0;
  household::Footprint corners{};
  int entity = -1;
  double height = 0.0;
};

// A wall piece that blocks movement and sight (door openings and open walls removed).
struct WallPiece {
  household::FloorPoint a, b;
};

// Distances in steps from one pose to every pose (breadth-first search over the action model).
struct StepField {
  std::vector<int> distance;  // −1: unreachable
  std::vector<int> parent;    // previous pose on a shortest path, −1 at the source
  // Poses after each step from the source to `pose` (excluding the source).
  [[nodiscard]] std::vector<int> path_to(int pose) const;
  // The pose of `poses` nearest to the source (ties: the smaller pose), −1 when none is reachable.
  [[nodiscard]] int nearest(std::span<const int> poses) const;
};

class NavMap {
 public:
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int depth() const { return depth_; }
  [[nodiscard]] int cells() const { return width_ * depth_; }
  [[nodiscard]] int poses() const { return cells() * kHeadings; }
  [[nodiscard]] double cell_size() const { return config_.cell; }
  [[nodiscard]] double origin_x() const { return origin_x_; }
  [[nodiscard]] double origin_z() const { return origin_z_; }
  [[nodiscard]] const NavConfig& config() const { return config_; }
  [[nodiscard]] bool free(int cell) const { return free_[static_cast<std::size_t>(cell)] != 0; }
  [[nodiscard]] int free_cells() const;
  [[nodiscard]] household::FloorPoint center(int cell) const;
  // The cell one step ahead in `heading`, or −1 when the move is blocked.
  [[nodiscard]] int ahead(int cell, int heading) const;
  // One action from a pose: 0 = move ahead (stays put when blocked), 1 = turn left, 2 = turn right.
  [[nodiscard]] int act(int pose, int action) const;

  [[nodiscard]] bool line_of_sight(household::FloorPoint a, household::FloorPoint b) const;
  // Within view distance, inside the field of view and in line of sight.
  [[nodiscard]] bool sees(int pose, household::FloorPoint target) const;

  [[nodiscard]] const std::vector<MapReceptacle>& receptacles() const { return receptacles_; }
  // Receptacles (indices into receptacles()) seen from a pose.
  [[nodiscard]] std::span<const int> visible_from(int pose) const;
  // Map index of a receptacle entity, −1 when it is not on the map.
  [[nodiscard]] int receptacle_of_entity(int entity) const;
  [[nodiscard]] const std::vector<WallPiece>& walls() const { return walls_; }
  // Poses that see a point lying on a receptacle (an object put somewhere on its top), by the
  // same rules as the receptacle's own views (distance from the camera, field of view, walls,
  // other furniture); sorted. The receptacle's `views` are those of its centre.
  [[nodiscard]] std::vector<int> views_of_point(int receptacle, household::FloorPoint point) const;

  [[nodiscard]] StepField steps_from(int pose) const;

 private:
  friend Result<NavMap> build_nav_map(const household::House& house, const NavConfig& config);
  NavConfig config_;
  int width_ = 0, depth_ = 0;
  double origin_x_ = 0.0, origin_z_ = 0.0;
  std::vector<std::uint8_t> free_;
  std::vector<std::uint8_t> moves_;  // bit h: the move ahead in heading h is open
  std::vector<WallPiece> walls_;
  std::vector<MapReceptacle> receptacles_;
  std::vector<FurnitureBox> furniture_;
  [[nodiscard]] bool occluded(household::FloorPoint from, household::FloorPoint to, double top, int self,
                              std::span<const FurnitureBox* const> near) const;
  [[nodiscard]] std::vector<int> point_views(household::FloorPoint point, double top, int self) const;
  std::vector<std::uint32_t> visible_offsets_;  // CSR over poses
  std::vector<int> visible_;
};

// An object lies wholly on its receptacle's top: its centre keeps this far inside the edges.
inline constexpr double kTopMargin = 0.1;
// Centres of an n × m grid of cells of at most `spacing` over a top (corners one way round), kept
// kTopMargin inside its edges; empty for a degenerate footprint.
std::vector<household::FloorPoint> top_grid(const household::Footprint& corners, double spacing);

// Builds the grid (cell centres inside a room, clear of walls and furniture footprints; moves that
// cross no wall) and every receptacle's viewing poses. kValidation when the house has no rooms or
// the grid would exceed 4 million cells.
Result<NavMap> build_nav_map(const household::House& house, const NavConfig& config = {});

// Whether segment ab crosses or touches segment cd.
bool segments_touch(household::FloorPoint a, household::FloorPoint b, household::FloorPoint c,
                    household::FloorPoint d);

}  // namespace socsim::navbench
