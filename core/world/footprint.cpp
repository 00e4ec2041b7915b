#include "core/world/footprint.hpp"

#include <array>
#include <cmath>

namespace socsim::world {
namespace {

// Typical sizes (m) of the furniture and fittings generators place; width across the facing.
constexpr std::array<EntityFootprint, 64> kFootprints = {{
    {"armchair", {0.8, 0.8}},
    {"bar_counter", {3.0, 0.7}},
    {"bed", {1.0, 2.0}},
    {"bench", {1.5, 0.5}},
    {"bookshelf", {1.8, 0.4}},
    {"chair", {0.5, 0.5}},
    {"changing_bench", {1.6, 0.4}},
    {"checkout", {1.6, 0.8}},
    {"cinema_screen", {6.0, 0.2}},
    {"coffee_machine", {0.5, 0.5}},
    {"coffee_table", {1.0, 0.5}},
    {"conveyor", {6.0, 1.0}},
    {"counter", {1.8, 0.7}},
    {"desk", {1.4, 0.7}},
    {"dining_table", {1.6, 0.9}},
    {"display_case", {1.5, 0.6}},
    {"elevator", {1.6, 1.6}},
    {"escalator", {1.2, 8.0}},
    {"exam_table", {0.7, 1.9}},
    {"exhibit", {1.0, 1.0}},
    {"fitness_machine", {0.9, 1.8}},
    {"fridge", {0.7, 0.7}},
    {"hospital_bed", {1.0, 2.1}},
    {"info_board", {1.2, 0.3}},
    {"lectern", {0.6, 0.5}},
    {"locker", {0.4, 0.5}},
    {"luggage_rack", {0.8, 0.5}},
    {"machine", {2.0, 1.5}},
    {"medication_cart", {0.6, 0.5}},
    {"meeting_table", {2.4, 1.2}},
    {"monitor", {0.5, 0.4}},
    {"music_system", {0.6, 0.4}},
    {"painting", {1.5, 0.1}},
    {"pallet", {1.2, 1.0}},
    {"piano", {1.5, 0.6}},
    {"printer", {0.6, 0.6}},
    {"rack", {1.9, 1.0}},
    {"reading_table", {1.6, 0.9}},
    {"screen", {4.0, 0.2}},
    {"sculpture", {1.0, 1.0}},
    {"seat", {0.5, 0.5}},
    {"shelf", {1.9, 0.5}},
    {"shower", {0.9, 0.9}},
    {"sink", {0.6, 0.5}},
    {"sofa", {2.0, 0.9}},
    {"stage", {6.0, 3.0}},
    {"stairs", {1.4, 4.0}},
    {"stool", {0.4, 0.4}},
    {"stove", {0.6, 0.6}},
    {"table", {1.0, 1.0}},
    {"teacher_desk", {1.4, 0.7}},
    {"ticket_gate", {0.3, 1.4}},
    {"ticket_machine", {0.8, 0.5}},
    {"toilet", {0.4, 0.7}},
    {"tray_return", {1.2, 0.6}},
    {"tv", {1.0, 0.3}},
    {"vending_machine", {0.9, 0.8}},
    {"voting_booth", {0.9, 0.9}},
    {"wardrobe", {1.0, 0.6}},
    {"water_dispenser", {0.4, 0.4}},
    {"weight_bench", {0.6, 1.4}},
    {"whiteboard", {1.8, 0.1}},
    {"workbench", {1.8, 0.8}},
    {"workstation", {1.6, 0.8}},
}};

}  // namespace

std::span<const EntityFootprint> entity_footprints() {
  return kFootprints;
}

Footprint footprint_of(std::string_view entity_type) {
  for (const auto& f : kFootprints)
    if (f.type == entity_type) return f.size;
  return {};
}

geometry::Polygon footprint_polygon(const Footprint& size, const geometry::Pose2& pose) {
  // Facing along (cos yaw, sin yaw): depth along it, width across. Quarter turns are exact.
  double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const double q = pose.yaw / (std::acos(-1.0) / 2);
  if (std::abs(q - std::round(q)) < 1e-9) {
    static constexpr double kCos[4] = {1, 0, -1, 0}, kSin[4] = {0, 1, 0, -1};
    const int k = static_cast<int>((static_cast<long long>(std::llround(q)) % 4 + 4) % 4);
    c = kCos[k];
    s = kSin[k];
  }
  const double hd = size.depth / 2, hw = size.width / 2;
  const geometry::Point along{c * hd, s * hd}, across{-s * hw, c * hw};
  const geometry::Point o = pose.position();
  return geometry::Polygon{{{o.x - along.x - across.x, o.y - along.y - across.y},
                            {o.x + along.x - across.x, o.y + along.y - across.y},
                            {o.x + along.x + across.x, o.y + along.y + across.y},
                            {o.x - along.x + across.x, o.y - along.y + across.y}},
                           {}};
}

geometry::Polygon footprint_polygon(std::string_view type, const geometry::Pose2& pose) {
  return footprint_polygon(footprint_of(type), pose);
}

}  // namespace socsim::world
