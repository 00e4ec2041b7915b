#pragma once
// Furniture placement inside one room, by footprint (core/world/footprint.hpp): in room
// coordinates (u along the side with the main door, v into the room), inside the room's
// rectangle clear of its walls and doors, of the furniture already there and of the areas that
// must stay free, and only where every door and piece of furniture stays reachable. Shared by
// room furnishing (furnish.cpp) and the features and objects a request asks for (features.cpp).
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/floorplan/furnish.hpp"
#include "core/geometry/planar.hpp"
#include "core/geometry/types.hpp"

namespace socsim::floorplan {

using geometry::Box;
inline constexpr double kPi = 3.14159265358979323846;

struct DoorAt {
  Point centre;
  double width = 0.0;
  bool exterior = false;
  std::string other_type;  // type of the zone on the other side ("" outside)
  std::string name;
};

bool axis_aligned_rectangle(const Polygon& p);

// The largest axis-aligned box (of the bounding box's proportions, around a few candidate centres)
// inside the polygon; the bounding box itself for rectangles.
Box inner_box(const Polygon& polygon);

double wrap(double a);

// A rectangle in room coordinates.
struct Area {
  double u0 = 0.0, v0 = 0.0, u1 = 0.0, v1 = 0.0;
};

// Where a counter and its queue lane went: counter at (u, v), the pair spans v_lo .. v_hi.
struct CounterPlace {
  double u = 0.0, v = 0.0, v_lo = 0.0, v_hi = 0.0;
};

// Room coordinates: u along the side with the main door, v from that side into the room.
struct Frame {
  Box box;
  int side = 0;  // 0 south, 1 east, 2 north, 3 west
  double len = 0.0;
  double depth = 0.0;

  Frame(Box b, int s) : box(b), side(s) {
    const bool horizontal = side == 0 || side == 2;
    len = horizontal ? b.width() : b.height();
    depth = horizontal ? b.height() : b.width();
  }
  [[nodiscard]] Point at(double u, double v) const {
    switch (side) {
      case 0:
        return {box.min.x + u, box.min.y + v};
      case 2:
        return {box.max.x - u, box.max.y - v};
      case 3:
        return {box.min.x + v, box.max.y - u};
      default:
        return {box.max.x - v, box.min.y + u};
    }
  }
  [[nodiscard]] Point local(Point p) const {
    switch (side) {
      case 0:
        return {p.x - box.min.x, p.y - box.min.y};
      case 2:
        return {box.max.x - p.x, box.max.y - p.y};
      case 3:
        return {box.max.y - p.y, p.x - box.min.x};
      default:
        return {p.y - box.min.y, box.max.x - p.x};
    }
  }
  // World yaw of a heading given relative to "into the room" (+v).
  [[nodiscard]] double yaw(double local) const {
    static constexpr double kBase[4] = {kPi / 2, kPi, -kPi / 2, 0.0};
    return wrap(kBase[side] + local);
  }
  [[nodiscard]] Polygon rect(double u0, double v0, double u1, double v1) const {
    std::vector<Point> ring{at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)};
    if (geometry::signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
    return Polygon{ring, {}};
  }
};

int nearest_side(const Box& b, Point p);

std::string numbered(const std::string& base, int i);

constexpr double kWallGap = 0.05;  // m between furniture and walls
constexpr double kDoorGap = 0.5;   // m kept free of furniture in front of a door opening
constexpr double kItemGap = 0.02;  // m between pieces of furniture (rows of seats touch)

bool overlaps(const Box& a, const Box& b, double gap);

double box_distance(const Box& b, const Segment& s);

Box footprint_box(const std::string& type, const Pose2& pose);

// Places furniture of one room by footprint: inside the room's rectangle (clear of its walls),
// clear of its door openings, of the furniture already placed in it and of the areas that must
// stay free (queue lanes, aisles, entrances).
class Placer {
 public:
  Placer(const Zone& zone, const Frame& frame, std::vector<DoorAt> doors, Furnishing& out);

  [[nodiscard]] const Frame& frame() const { return f_; }
  [[nodiscard]] double len() const { return f_.len; }
  [[nodiscard]] double depth() const { return f_.depth; }
  [[nodiscard]] const Zone& zone() const { return zone_; }
  // Everything furnished so far (all rooms): for a room that tries two arrangements.
  [[nodiscard]] Furnishing& furnishing() { return out_; }
  // Whether a box lies (partly) in this room: furniture and areas belong to the room they are in.
  [[nodiscard]] bool mine(const Box& b) const { return overlaps(f_.box, b, -0.01); }

  [[nodiscard]] bool clear(Point p, double radius) const;

  // Whether a box (world coordinates) keeps clear of the walls, the doors, the furniture of the
  // room (but `skip`) and the areas that must stay free.
  enum class Areas { kNone, kLanes, kAll };  // which kept-free areas a box must avoid
  [[nodiscard]] bool box_free(const Box& b, std::optional<std::size_t> skip = std::nullopt,
                              Areas areas = Areas::kAll) const;

  // Half extents along u and v of a footprint turned by `local_yaw` (quarter turns).
  [[nodiscard]] static std::pair<double, double> half_extents(const std::string& type, double local_yaw);

  [[nodiscard]] std::optional<Point> fit(const std::string& type, double u, double v, double local_yaw) const;

  [[nodiscard]] bool inside(double u, double v, double margin) const {
    return u >= margin && v >= margin && u <= f_.len - margin && v <= f_.depth - margin;
  }

  // The first candidate (u, v) where the footprint fits (moved off the walls); then positions
  // sliding along the first candidate's line. nullopt when nothing fits.
  std::optional<Point> entity(const std::string& type, const std::string& suffix,
                              std::initializer_list<std::pair<double, double>> candidates, double local_yaw,
                              std::vector<std::string> affordances);

  // Whether a person 0.5 m wide can still walk from each door of the room to every other door
  // and to every piece of furniture in it (within 0.4 m of its footprint). With `drop`, the
  // furniture placed since `from` that cannot be reached is listed instead of failing.
  bool walkable(std::size_t from = std::numeric_limits<std::size_t>::max(),
                std::vector<std::size_t>* drop = nullptr) const;

  // Removes the furniture placed since `from` that walls in a door or cannot be reached: the
  // unreachable pieces, then the last ones placed until the doors connect again.
  void keep_walkable(std::size_t from);

  // No furniture but entity `keep` within 0.5 m of the rectangle (1.3 m for serving furniture) and no area of
  // the room but corridors and work areas overlapping it (ROIs since `first_roi`).
  [[nodiscard]] bool lane_clear(double u0, double v0, double u1, double v1, std::size_t keep,
                                std::size_t first_roi) const;

  // A rectangular ROI in room coordinates, clamped inside and pulled back from the doors' swing
  // (the side that loses least is cut); dropped when it shrinks below 0.5 m.
  std::optional<Area> roi(const std::string& kind, const std::string& suffix, double u0, double v0, double u1,
                          double v1, bool may_touch_doors = false);

  // A queue lane in front of each water dispenser, coffee machine or vending machine furnished
  // since `first` (entities) where there is room: `length` m straight out from it (its facing
  // first, then sideways), clear of the other furniture, the doors and the room's areas; the
  // machine then takes queue_target so the lane's head is at it.
  void poi_lanes(std::size_t first, std::size_t first_roi, double width, double length);

  // The same room seen from another side.
  [[nodiscard]] Placer turned(int side) const { return Placer(zone_, Frame(f_.box, side), doors_, out_); }
  [[nodiscard]] int side() const { return f_.side; }

  // Items on a grid of cells (du × dv) inside [u0, u1] × [v0, v1], each where its footprint fits.
  int grid(const std::string& type, const std::string& base, double u0, double v0, double u1, double v1,
           double du, double dv, int max_items, double local_yaw,
           const std::vector<std::string>& affordances);

  // A counter at depth v with a queue lane of up to `lane` metres in front of it: towards the main
  // door (customers come in and queue towards a counter deeper in the room) or, when `inward`,
  // deeper into the room (a check-out by the door). Returns the u it was placed at.
  std::optional<CounterPlace> counter_with_queue(const std::string& type, const std::string& name, double u,
                                                 double v, double lane, bool inward, double lane_width,
                                                 std::vector<std::string> affordances);

 private:
  // The walkability grid of the last walkable() that passed: the footprints it blocked, the cells
  // blocked and reached. A call with one footprint more checks only around the new one when it
  // can prove the answer equal to a full flood fill (walkable_after_one()), else floods again.
  struct WalkGrid {
    std::vector<Box> boxes;  // the room's footprints, in furnishing order
    std::vector<std::uint8_t> blocked, reached;
  };
  [[nodiscard]] std::optional<bool> walkable_after_one(const std::vector<Box>& boxes) const;
  // The walkability grid cell just inside each door, where the flood fill starts.
  [[nodiscard]] std::vector<std::size_t> door_cells() const;

  const Zone& zone_;
  Frame f_;
  std::vector<DoorAt> doors_;
  std::vector<Segment> door_segments_;
  Furnishing& out_;
  mutable std::optional<WalkGrid> walk_;
};

// The doors of zone `z` as the placer sees them (centre, width, outside or the type beyond).
std::vector<DoorAt> doors_of(const Zone& z, std::span<const Zone> zones, std::span<const DoorSpec> doors);

// A placer for zone `z` in the largest rectangle inside it, facing its main door: the entrance
// of a shop, hall or lobby, else the door to circulation, else the first. nullopt for a room
// less than 1 m across.
std::optional<Placer> placer_for(const Zone& z, std::span<const Zone> zones, std::span<const DoorSpec> doors,
                                 Furnishing& out);

}  // namespace socsim::floorplan
