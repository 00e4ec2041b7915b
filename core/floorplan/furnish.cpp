#include "core/floorplan/furnish.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include "core/floorplan/placer.hpp"
#include "core/floorplan/rooms.hpp"
#include "core/geometry/geos.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/footprint.hpp"

namespace socsim::floorplan {
namespace {

double constraint(std::span<const knowledge::MergedConstraint> cs, std::string_view name) {
  for (const auto& c : cs)
    if (c.constraint.name == name) return c.constraint.value;
  return 0.0;
}

void furnish_waiting(Placer& p, const std::string& type, const std::optional<CounterPlace>& counter) {
  const double L = p.len(), D = p.depth();
  const double cu = counter ? counter->u : L / 2;
  const bool on_left = cu > L / 2;
  std::vector<Area> areas{{on_left ? 0.3 : cu + 1.4, 1.6, on_left ? cu - 1.4 : L - 0.3, D - 0.4}};
  if (counter) {
    areas.push_back({0.3, 0.4, L - 0.3, counter->v_lo - 0.6});
    areas.push_back({0.3, counter->v_hi + 0.9, L - 0.3, D - 0.4});
  }
  const Area* best = nullptr;
  for (const auto& a : areas)
    if (a.u1 - a.u0 >= 1.4 && a.v1 - a.v0 >= 1.4 &&
        (!best || (a.u1 - a.u0) * (a.v1 - a.v0) > (best->u1 - best->u0) * (best->v1 - best->v0)))
      best = &a;
  if (type != "security" && best) {
    const bool cafe = type == "cafe";
    if (auto a = p.roi(cafe ? "seating_area" : "waiting_zone", cafe ? "seating" : "waiting", best->u0,
                       best->v0, best->u1, best->v1))
      p.grid(cafe ? "table" : "chair", cafe ? "table" : "chair", a->u0, a->v0, a->u1, a->v1, cafe ? 1.8 : 0.8,
             cafe ? 1.8 : 1.1, 24, 0,
             cafe ? std::vector<std::string>{"eat", "sit"} : std::vector<std::string>{"sit", "wait"});
  }
  if (type == "lobby" || type == "reception" || type == "concourse")
    p.entity("water_dispenser", "water_dispenser",
             {{on_left ? 0.4 : L - 0.4, D - 0.4}, {on_left ? 0.4 : L - 0.4, 1.2}}, 0, {"drink"});
}

// Rows of `type` facing +v (towards a screen or stage at the far wall) in [u0, u1] × [v0, v1]:
// blocks of at most `per_block` seats 0.55 m apart between aisles `aisle` m wide (one at each
// end), rows `pitch` m apart; a walkway ROI per aisle and a seating area per block. Seats are
// named <zone>_seat_rNN_MM. Returns the seats placed (all of them reachable).
int seat_rows(Placer& p, const std::string& type, double u0, double v0, double u1, double v1, double pitch,
              int per_block, double aisle, const std::vector<std::string>& affordances) {
  constexpr double kSeat = 0.55;
  const double width = u1 - u0;
  int blocks = 1, per = 0;
  for (; blocks <= 8; ++blocks) {
    per = static_cast<int>(std::floor((width - (blocks + 1) * aisle) / (blocks * kSeat) + 1e-9));
    if (per <= per_block) break;
  }
  if (per < 2) return 0;
  const int rows = static_cast<int>(std::floor((v1 - v0) / pitch + 1e-9));
  if (rows < 1) return 0;
  const double used = (blocks + 1) * aisle + blocks * per * kSeat;
  const double start = u0 + (width - used) / 2;
  Furnishing& out = p.furnishing();
  const std::size_t first = out.entities.size();
  const std::string& zone = p.zone().name;
  int placed = 0;
  for (int b = 0; b < blocks; ++b) {
    const double bu0 = start + aisle + b * (per * kSeat + aisle);
    p.roi("seating_area", numbered("seats", b + 1), bu0, v0, bu0 + per * kSeat, v0 + rows * pitch, true);
    for (int r = 0; r < rows; ++r)
      for (int k = 0; k < per; ++k) {
        const double u = bu0 + (k + 0.5) * kSeat, v = v0 + r * pitch + 0.3;
        const Point w = p.frame().at(u, v);
        const Pose2 pose{w.x, w.y, p.frame().yaw(0.0)};
        if (!p.box_free(footprint_box(type, pose), std::nullopt, Placer::Areas::kNone)) continue;
        char name[48];
        std::snprintf(name, sizeof name, "_seat_r%02d_%02d", r + 1, b * per + k + 1);
        out.entities.push_back({type, zone + name, pose, affordances});
        ++placed;
      }
  }
  for (int a = 0; a <= blocks; ++a) {
    const double au0 = start + a * (per * kSeat + aisle);
    p.roi("walkway", numbered("aisle", a + 1), au0, v0, au0 + aisle, v0 + rows * pitch, true);
  }
  p.keep_walkable(first);
  (void)placed;
  return static_cast<int>(out.entities.size() - first);
}

// Rows of shelves (or racks, machines) along u from v_start, walkway aisles between them.
void rows_of(Placer& p, const std::string& type, const std::string& base, double v_start, double item_depth,
             double walk, double pitch_u, int max_rows, const std::vector<std::string>& affordances,
             std::optional<double> v_end = std::nullopt) {
  const double L = p.len(), D = v_end.value_or(p.depth());
  int row = 0;
  for (double v = v_start; v + item_depth + walk <= D - 0.3 && row < max_rows; v += item_depth + walk) {
    ++row;
    p.roi("walkway", numbered("aisle", row), 0.6, v + item_depth, L - 0.6, v + item_depth + walk, true);
    p.grid(type, numbered(base, row), 1.0, v, L - 1.0, v + item_depth, pitch_u, item_depth, 30, 0,
           affordances);
  }
}

// A line of ticket-gate posts across the room at depth v, 0.9 m passages between them.
void gate_line(Placer& p, double v) {
  const double L = p.len();
  const int n = static_cast<int>(std::floor((L - 2.0) / 1.2)) + 1;
  if (n < 2) return;
  Furnishing& out = p.furnishing();
  const std::size_t first = out.entities.size();
  const double u0 = (L - (n - 1) * 1.2) / 2;
  for (int k = 0; k < n; ++k) {
    const auto at = p.fit("ticket_gate", u0 + k * 1.2, v, 0.0);
    if (!at || std::abs(at->x - (u0 + k * 1.2)) > 1e-9) continue;
    const Point w = p.frame().at(at->x, at->y);
    out.entities.push_back({"ticket_gate",
                            p.zone().name + "_" + numbered("gate", k + 1),
                            {w.x, w.y, p.frame().yaw(0.0)},
                            {"pass_gate"}});
  }
  p.keep_walkable(first);
}

// A counter against one of the room's side walls (either, at random first), else against its far
// wall: a bar in a foyer or restaurant, where the door wall and the queue lanes leave room.
void against_a_wall(Placer& p, Rng& rng, const std::string& type, const std::string& name,
                    const std::vector<std::string>& affordances) {
  const int first = rng.chance(0.5) ? 1 : 3;
  for (int turn : {first, 4 - first}) {
    Placer side = p.turned((p.side() + turn) % 4);
    if (side.entity(type, name, {{side.len() / 2, side.depth()}}, kPi, affordances)) return;
  }
  p.entity(type, name, {{p.len() / 2, p.depth()}}, kPi, affordances);
}

void furnish_venue_room(Placer& p, const std::string& type, const FurnishingRules& rules, Rng& rng) {
  const double L = p.len(), D = p.depth();
  const double left = rng.chance(0.5) ? 0.45 : L - 0.45;
  const double right = L - left;
  const double lane_w = rules.queue_lane_width;
  if (type == "ticket_hall") {
    p.counter_with_queue("counter", "ticket_counter", L * (rng.chance(0.5) ? 0.3 : 0.7), D - 1.0, 3.5, false,
                         lane_w, {"serve", "sell_ticket", "queue_target"});
    p.turned((p.side() + 1) % 4)
        .entity("ticket_machine", "ticket_machine_01", {{p.depth() / 2, L}}, kPi,
                {"buy_ticket", "queue_target"});
    p.turned((p.side() + 3) % 4)
        .entity("ticket_machine", "ticket_machine_02", {{p.depth() / 2, L}}, kPi,
                {"buy_ticket", "queue_target"});
    p.entity("info_board", "info_board", {{L / 2, D}}, kPi, {"read"});
    if (D >= 7.0) gate_line(p, D * 0.45);
  } else if (type == "platform") {
    // The far side is the track edge: people wait along it; benches down the middle.
    p.roi("waiting_zone", "edge", 0.6, D - 2.1, L - 0.6, D - 0.6, true);
    p.grid("bench", "bench", 1.0, D / 2 - 0.6, L - 1.0, D / 2 + 0.6, 6.0, 1.2, 20, 0, {"sit", "wait"});
    p.entity("info_board", "info_board", {{L / 2, 0.0}}, 0.0, {"read"});
  } else if (type == "hotel_room" || type == "resident_room") {
    p.entity("bed", "bed", {{L / 2, D - 1.1}, {L / 2, D / 2 + 0.3}}, kPi, {"lie", "sleep"});
    p.entity("wardrobe", "wardrobe", {{left, D - 0.4}, {right, D - 0.4}}, kPi, {"store"});
    if (type == "hotel_room") {
      p.entity("desk", "desk", {{right, 1.5}, {left, 1.5}}, kPi / 2, {"work", "sit"});
      p.entity("luggage_rack", "luggage_rack", {{left, 1.2}, {right, 1.2}}, 0, {"store"});
    } else {
      p.entity("armchair", "armchair", {{right, 1.4}, {left, 1.4}}, 0, {"sit", "rest"});
    }
  } else if (type == "day_room") {
    p.entity("tv", "tv", {{L / 2, D}}, kPi, {"watch"});
    if (auto a = p.roi("seating_area", "seating", 0.6, D * 0.45, L - 0.6, D - 1.0))
      p.grid("armchair", "armchair", a->u0, a->v0, a->u1, a->v1, 1.5, 1.7, 16, 0, {"sit", "rest", "watch"});
    p.grid("table", "table", 0.6, 1.4, L - 0.6, D * 0.45 - 0.2, 2.6, 2.4, 4, 0, {"eat", "sit"});
  } else if (type == "reading_room") {
    // Shelving along the far wall (a free-standing row would leave its walkway behind it).
    p.grid("bookshelf", "wall_shelf", 0.5, D - 0.5, L - 0.5, D - 0.05, 2.0, 0.45, 12, kPi,
           {"browse", "pick"});
    if (auto a = p.roi("seating_area", "reading", 0.8, 1.6, L - 0.8, D - 2.0))
      p.grid("reading_table", "table", a->u0, a->v0, a->u1, a->v1, 2.7, 2.4, 30, 0, {"read", "sit"});
  } else if (type == "library_stacks") {
    rows_of(p, "bookshelf", "shelf", 1.4, 0.4, std::max(1.0, rules.walkway_width), 1.9, 12,
            {"browse", "pick"});
  } else if (type == "study_room") {
    p.entity("reading_table", "table", {{L / 2, D / 2}}, 0, {"study", "sit"});
    p.entity("chair", "chair", {{L / 2 - 0.5, D / 2 + 0.8}, {L / 2, D / 2 + 0.8}}, kPi, {"sit"});
  } else if (type == "gallery") {
    for (int turn : {0, 1, 3})
      p.turned((p.side() + turn) % 4)
          .entity("painting", numbered("painting", turn + 1), {{0, 0}}, kPi, {"view"});
    p.grid("exhibit", "exhibit", 1.6, 2.0, L - 1.6, D - 1.6, 3.6, 3.6, 6, 0, {"view"});
    p.entity("bench", "bench", {{L / 2, D / 2}}, 0, {"sit", "view"});
    p.roi("goal_area", "view", L / 2 - 1.0, D / 2 - 2.0, L / 2 + 1.0, D / 2 - 0.8);
  } else if (type == "foyer") {
    p.counter_with_queue("counter", "box_office", L * (rng.chance(0.5) ? 0.25 : 0.75), D - 1.0, 3.5, false,
                         lane_w, {"serve", "sell_ticket", "queue_target"});
    against_a_wall(p, rng, "bar_counter", "bar", {"serve", "drink"});
    p.entity("water_dispenser", "water_dispenser", {{left, 0.4}, {right, 0.4}}, 0, {"drink"});
  } else if (type == "auditorium" || type == "lecture_hall") {
    // Screen or stage at the far wall, seats in rows facing it, cross aisle by the doors.
    const bool stage = type == "auditorium" && D >= 13.0 && L >= 8.0 && rng.chance(0.5);
    double front = D - 2.6;
    if (stage && p.entity("stage", "stage", {{L / 2, D}}, kPi, {"perform"})) front = D - 3.2 - 1.5;
    p.entity("screen", "screen", {{L / 2, D}}, kPi, {"watch"});
    if (type == "lecture_hall") p.entity("lectern", "lectern", {{L * 0.2, D - 1.4}}, kPi, {"present"});
    seat_rows(p, "seat", 0.3, 1.8, L - 0.3, front, 1.1, 14, std::max(1.1, rules.walkway_width),
              {"sit", "watch"});
  } else if (type == "arena_floor") {
    p.entity("stage", "stage", {{L / 2, D}}, kPi, {"perform"});
    p.roi("assembly_zone", "standing", 1.0, D * 0.45, L - 1.0, D - 4.6);
    seat_rows(p, "seat", 0.3, 1.8, L - 0.3, std::min(D * 0.45 - 0.5, 1.8 + 1.1 * 12), 1.1, 20,
              std::max(1.2, rules.walkway_width), {"sit", "watch"});
  } else if (type == "backstage") {
    p.entity("table", "table", {{L / 2, D / 2}}, 0, {"sit"});
    p.entity("wardrobe", "wardrobe", {{left, D - 0.4}, {right, D - 0.4}}, kPi, {"store"});
  } else if (type == "concession") {
    if (!p.counter_with_queue("counter", "counter", L / 2, D - 0.6, 3.0, false, lane_w,
                              {"serve", "queue_target"}))
      p.entity("counter", "counter", {{L / 2, D}}, kPi, {"serve"});
  } else if (type == "first_aid") {
    p.entity("exam_table", "bed", {{L / 2, D - 1.2}}, kPi, {"examine", "lie"});
    p.entity("desk", "desk", {{left, 1.0}, {right, 1.0}}, 0, {"work", "sit"});
    p.entity("sink", "sink", {{right, D - 0.3}, {left, D - 0.3}}, kPi, {"wash"});
  } else if (type == "seminar_room") {
    const int n = p.grid("desk", "desk", 1.0, 1.6, L - 1.0, D - 1.4, 1.6, 1.7, 40, 0, {"work", "sit"});
    if (n > 0) p.roi("work_area", "desks", 0.8, 1.5, L - 0.8, D - 1.2, true);
    p.entity("screen", "screen", {{L / 2, D}}, kPi, {"watch"});
  } else if (type == "production_floor") {
    p.roi("work_area", "staging", 0.8, 0.8, std::min(L - 0.8, 6.0), 3.0);
    p.entity("conveyor", "conveyor", {{L / 2, 4.0}}, 0, {"load", "pick"});
    rows_of(p, "machine", "machine", 5.4, 1.5, std::max(1.5, rules.walkway_width), 3.0, 8, {"operate"});
  } else if (type == "locker_room" || type == "changing_room") {
    p.grid("locker", "locker", 0.3, D - 0.6, L - 0.3, D - 0.05, 0.42, 0.55, 24, kPi, {"store"});
    p.entity("changing_bench", "bench", {{L / 2, D / 2}}, 0, {"sit", "change"});
  } else if (type == "mall_concourse") {
    p.grid("bench", "bench", 2.0, D / 2 - 0.6, L - 2.0, D / 2 + 0.6, 9.0, 1.2, 12, 0, {"sit", "rest"});
    p.entity("info_board", "info_board", {{L * 0.15, D / 2 + 2.0}}, 0, {"read"});
    p.entity("vending_machine", "vending_machine", {{left, D}, {right, D}}, kPi, {"buy"});
  } else if (type == "shop_unit") {
    const double lane = std::clamp(D * 0.3, 1.5, 3.0);
    p.counter_with_queue("counter", "checkout", L * (rng.chance(0.5) ? 0.3 : 0.7), 1.8, lane, true, lane_w,
                         {"pay", "queue_target"});
    // Shelving along the back wall, and free-standing rows between it and the queue where they fit.
    p.grid("shelf", "wall_shelf", 0.5, D - 0.6, L - 0.5, D - 0.05, 2.0, 0.55, 8, kPi, {"browse", "pick"});
    rows_of(p, "shelf", "shelf", 1.8 + 0.7 + lane + 0.6, 0.5, std::max(1.2, rules.walkway_width), 2.0, 6,
            {"browse", "pick"}, D - 0.6);
  } else if (type == "food_court") {
    int counters = 0;
    for (double frac : {0.2, 0.5, 0.8})
      counters += p.counter_with_queue("counter", numbered("food_counter", counters + 1), L * frac, D - 1.0,
                                       3.0, false, lane_w, {"serve", "queue_target"})
                      ? 1
                      : 0;
    if (auto a = p.roi("seating_area", "seating", 0.8, 1.6, L - 0.8, std::max(2.6, D - 5.6)))
      p.grid("table", "table", a->u0, a->v0, a->u1, a->v1, 2.2, 2.3, 40, 0, {"eat", "sit"});
  } else if (type == "restaurant") {
    against_a_wall(p, rng, "bar_counter", "bar", {"serve", "drink"});
    if (auto a = p.roi("seating_area", "seating", 0.8, 1.6, L - 0.8, D - 0.8))
      p.grid("table", "table", a->u0, a->v0, a->u1, a->v1, 2.2, 2.3, 40, 0, {"eat", "sit"});
  } else if (type == "sports_hall") {
    p.roi("assembly_zone", "court", 2.0, 2.0, L - 2.0, D - 2.0, true);
    p.grid("bench", "bench", 1.0, 0.3, L - 1.0, 1.3, 4.0, 1.0, 6, 0, {"sit", "watch"});
  } else if (type == "fitness_room") {
    p.grid("fitness_machine", "machine", 0.8, 1.6, L - 0.8, D - 0.8, 1.6, 2.6, 20, 0, {"exercise"});
    p.entity("water_dispenser", "water_dispenser", {{left, 0.4}, {right, 0.4}}, 0, {"drink"});
  } else if (type == "main_hall") {
    // A registration desk with its queue, voting booths along one wall, tables in the middle.
    p.counter_with_queue("counter", "registration", L * (rng.chance(0.5) ? 0.3 : 0.7), std::min(D - 1.0, 5.5),
                         3.5, false, lane_w, {"serve", "register", "queue_target"});
    Placer side = p.turned((p.side() + (rng.chance(0.5) ? 1 : 3)) % 4);
    side.grid("voting_booth", "booth", 1.0, side.depth() - 1.1, side.len() - 1.0, side.depth() - 0.1, 1.0,
              1.0, 8, kPi, {"vote"});
    if (auto a = p.roi("seating_area", "seating", 1.0, 1.6, L - 2.2, D - 2.2))
      p.grid("table", "table", a->u0, a->v0, a->u1, a->v1, 2.4, 2.4, 12, 0, {"sit", "meet"});
  }
}

void furnish_room(Placer& p, const std::string& type, const FurnishingRules& rules, Rng& rng, double area) {
  const double L = p.len(), D = p.depth();
  const double left = rng.chance(0.5) ? 0.45 : L - 0.45;  // corner for small appliances
  const double right = L - left;
  if (type == "bedroom") {
    p.entity("bed", "bed", {{L / 2, D - 1.1}, {L / 2, D / 2 + 0.3}}, kPi, {"lie", "sleep"});
    p.entity("wardrobe", "wardrobe", {{left, D - 0.4}, {right, D - 0.4}, {left, D / 2}}, kPi, {"store"});
  } else if (type == "living_room") {
    const auto sofa =
        p.entity("sofa", "sofa", {{L / 2, D - 0.6}, {L / 2, D / 2 + 0.5}}, kPi, {"sit", "rest"});
    if (sofa) {
      p.entity("coffee_table", "coffee_table", {{sofa->x, sofa->y - 1.0}}, 0, {"place"});
      p.roi("seating_area", "seating", sofa->x - 1.3, sofa->y - 1.6, sofa->x + 1.3, sofa->y + 0.5);
    }
    p.entity("tv", "tv", {{L / 2, 0.4}, {0.4, D / 2}, {L - 0.4, D / 2}}, 0, {"watch"});
  } else if (type == "kitchen" || type == "kitchenette" || type == "break_room" || type == "staff_room") {
    const bool cooking = type == "kitchen";
    p.entity("sink", "sink", {{L / 2, D - 0.4}, {0.4, D / 2}}, kPi, {"wash"});
    p.entity("fridge", "fridge", {{left, D - 0.4}, {right, D - 0.4}}, kPi, {"store_food"});
    if (cooking) {
      p.entity("stove", "stove", {{right, D - 0.4}, {left, D / 2}}, kPi, {"cook"});
      p.roi("work_area", "work_area", 0.2, D - 1.2, L - 0.2, D - 0.1);
    } else {
      p.entity("coffee_machine", "coffee_machine", {{right, D - 0.4}, {right, D / 2}}, kPi, {"drink"});
      p.entity("water_dispenser", "water_dispenser", {{left, D / 2}, {right, 0.9}}, 0, {"drink"});
    }
    if (area >= 9.0) p.entity("table", "table", {{L / 2, D / 2 - 0.3}, {L / 2, D / 2}}, 0, {"eat", "sit"});
  } else if (type == "bathroom" || type == "toilet") {
    p.entity("toilet", "toilet", {{left, D - 0.5}, {right, D - 0.5}}, kPi, {"use_toilet"});
    p.entity("sink", "sink", {{right, D - 0.35}, {left, D / 2}, {right, D / 2}}, kPi, {"wash"});
    if (type == "bathroom")
      p.entity("shower", "shower", {{right, 0.6}, {left, 0.6}, {L / 2, D - 0.6}}, 0, {"shower"});
  } else if (type == "storage") {
    p.grid("shelf", "shelf", 0.2, D - 0.8, L - 0.2, D - 0.1, 1.0, 0.7, 4, kPi, {"store", "pick"});
  } else if (type == "dining_room") {
    p.entity("dining_table", "dining_table", {{L / 2, D / 2}}, 0, {"eat", "sit"});
  } else if (type == "study") {
    p.entity("desk", "desk", {{L / 2, D - 0.8}}, kPi, {"work", "sit"});
  } else if (type == "open_office" || type == "classroom") {
    const int wanted = type == "open_office"
                           ? std::max(1, static_cast<int>(std::floor(area / rules.area_per_desk)))
                           : std::max(1, static_cast<int>(std::floor(area / 2.0)));
    const double du = type == "open_office" ? 1.8 : 1.3, dv = type == "open_office" ? 2.4 : 1.6;
    int n = p.grid("desk", "desk", 1.0, 1.4, L - 1.0, D - 1.0, du, dv, wanted, 0, {"work", "sit"});
    if (n > 0) p.roi("work_area", "desks", 0.8, 1.3, L - 0.8, D - 0.8, true);
    if (n == 0) {
      // A room too shallow for a row of desks facing its door (a long room entered from its long
      // side): the desks run along its length instead, seen from a side wall.
      Placer side = p.turned((p.side() + 1) % 4);
      const double sl = side.len(), sd = side.depth();
      n = side.grid("desk", "desk", 1.0, 1.4, sl - 1.0, sd - 1.0, du, dv, wanted, 0, {"work", "sit"});
      if (n > 0) side.roi("work_area", "desks", 0.8, 1.3, sl - 0.8, sd - 0.8, true);
    }
    if (type == "open_office") {
      p.entity("water_dispenser", "water_dispenser", {{left, 0.5}, {right, 0.5}, {left, D - 0.4}}, 0,
               {"drink"});
      p.entity("printer", "printer", {{right, D - 0.4}, {left, D - 0.4}}, kPi, {"print"});
    } else {
      p.entity("teacher_desk", "teacher_desk", {{L / 2, 0.9}, {L / 2, D - 0.7}}, 0, {"teach"});
    }
  } else if (type == "private_office") {
    p.entity("desk", "desk", {{L / 2, D - 1.1}, {L / 2, D / 2}}, kPi, {"work", "sit"});
  } else if (type == "meeting_room") {
    p.entity("meeting_table", "table", {{L / 2, D / 2 + 0.3}, {L / 2, D / 2}}, 0, {"meet", "sit"});
    p.entity("whiteboard", "whiteboard", {{L / 2, D - 0.15}, {0.15, D / 2}}, kPi, {"present"});
  } else if (type == "reception" || type == "lobby" || type == "security" || type == "gate_area" ||
             type == "concourse" || type == "cafe") {
    const bool gate = type == "gate_area";
    const std::string counter = type == "security"    ? "checkpoint"
                                : gate                ? "gate_counter"
                                : type == "cafe"      ? "counter"
                                : type == "concourse" ? "info_desk"
                                                      : "reception_counter";
    // The side with the main door first; a room too shallow for a queue there turns a quarter.
    const double frac = rng.chance(0.5) ? 0.68 : 0.32;
    std::optional<CounterPlace> at;
    for (int turn : {0, 1, 3, 2}) {
      Placer q = p.turned((p.side() + turn) % 4);
      at = q.counter_with_queue("counter", counter, q.len() * frac,
                                std::min(q.depth() - 0.8, std::max(3.2, q.depth() * 0.7)), 4.0, false,
                                rules.queue_lane_width, {"serve", "queue_target"});
      if (at) {
        furnish_waiting(q, type, at);
        return;
      }
    }
    furnish_waiting(p, type, std::nullopt);
  } else if (type == "waiting_room") {
    if (auto a = p.roi("waiting_zone", "waiting", 0.4, 1.4, L - 0.4, D - 0.4))
      p.grid("chair", "chair", a->u0, a->v0, a->u1, a->v1, 0.8, 1.1, 24, 0, {"sit", "wait"});
    p.entity("water_dispenser", "water_dispenser", {{left, 0.5}, {right, 0.5}}, 0, {"drink"});
  } else if (type == "patient_room" || type == "icu_room") {
    const auto bed = p.entity("bed", "bed", {{L / 2, D - 1.3}, {L / 2, D / 2 + 0.4}}, kPi, {"lie", "visit"});
    if (bed) p.entity("chair", "chair", {{bed->x + 1.4, bed->y}, {bed->x - 1.4, bed->y}}, 0, {"sit"});
    p.entity(type == "icu_room" ? "monitor" : "sink", type == "icu_room" ? "monitor" : "sink",
             {{left, 1.0}, {right, 1.0}, {left, D - 0.4}}, 0, {type == "icu_room" ? "observe" : "wash"});
  } else if (type == "nurse_station") {
    p.entity("counter", "counter", {{L / 2, D / 2}, {L / 2, D - 1.0}}, kPi, {"serve", "queue_target"});
    p.entity("desk", "desk", {{left, D - 0.6}, {right, D - 0.6}}, kPi, {"work", "sit"});
    p.entity("medication_cart", "medication_cart", {{right, D - 0.5}, {left, 1.0}}, 0, {"restock"});
  } else if (type == "treatment_room") {
    p.entity("exam_table", "exam_table", {{L / 2, D - 1.2}, {L / 2, D / 2}}, kPi, {"examine", "lie"});
    p.entity("desk", "desk", {{left, D / 2}, {right, D / 2}}, 0, {"work", "sit"});
    p.entity("sink", "sink", {{right, 0.9}, {left, 0.9}}, 0, {"wash"});
  } else if (type == "dining_hall") {
    // Serving counter at the far side, its queue towards the main door; tables on both sides of it.
    const double cu = L * (rng.chance(0.5) ? 0.3 : 0.7);
    auto at = p.counter_with_queue("counter", "serving_counter", cu, D - 1.0, 4.5, false,
                                   rules.queue_lane_width, {"serve", "queue_target"});
    // Pushed into the middle (an exit or door in the way): the other side may keep room for tables.
    if (at && std::abs(at->u - cu) > 0.6) {
      const Furnishing before = p.furnishing();
      p.furnishing().entities.pop_back();
      p.furnishing().rois.pop_back();
      const auto other = p.counter_with_queue("counter", "serving_counter", L - cu, D - 1.0, 4.5, false,
                                              rules.queue_lane_width, {"serve", "queue_target"});
      if (other && std::abs(other->u - (L - cu)) <= 0.6)
        at = other;
      else
        p.furnishing() = before;
    }
    const double gap = rules.queue_lane_width / 2 + 1.0;
    const double split = at ? at->u : -10.0;
    if (auto a = split - gap - 0.8 >= 2.0
                     ? p.roi("seating_area", "seating_01", 0.8, 1.6, split - gap, D - 0.6)
                     : std::nullopt)
      p.grid("table", "table_a", a->u0, a->v0, a->u1, a->v1, 2.0, 2.2, 40, 0, {"eat", "sit"});
    const double u0 = at ? split + gap : 0.8;
    if (auto a = L - 0.8 - u0 >= 2.0 ? p.roi("seating_area", "seating_02", u0, 1.6, L - 0.8, D - 0.6)
                                     : std::nullopt)
      p.grid("table", "table_b", a->u0, a->v0, a->u1, a->v1, 2.0, 2.2, 40, 0, {"eat", "sit"});
    p.entity("water_dispenser", "water_dispenser", {{0.5, D / 2}, {L - 0.5, D / 2}}, 0, {"drink"});
    p.entity("tray_return", "tray_return", {{L - 0.5, D * 0.3}, {0.5, D * 0.3}}, 0, {"return_tray"});
  } else if (type == "sales_floor" || type == "warehouse_floor" || type == "stock_room") {
    const bool shop = type == "sales_floor";
    double v_start = 1.4;
    if (shop) {
      const double lane = std::clamp(D * 0.3, 1.5, 3.5);
      p.counter_with_queue("counter", "checkout", L * (rng.chance(0.5) ? 0.3 : 0.7), 1.8, lane, true,
                           rules.queue_lane_width, {"pay", "queue_target"});
      v_start = 1.8 + 0.7 + lane + 0.6;
    } else if (type == "warehouse_floor") {
      p.roi("work_area", "staging", 0.8, 0.8, std::min(L - 0.8, 6.0), 3.0);
      v_start = 3.4;
    }
    // Rows of shelves or racks along u, walkway ROIs between them.
    const double shelf = type == "warehouse_floor" ? 1.1 : 0.6;
    const double walk = rules.walkway_width;
    int row = 0;
    for (double v = v_start; v + shelf + walk <= D - 0.3 && row < 12; v += shelf + walk) {
      ++row;
      p.roi("walkway", numbered("aisle", row), 0.6, v + shelf, L - 0.6, v + shelf + walk, true);
      p.grid(shop ? "shelf" : "rack", numbered(shop ? "shelf" : "rack", row), 1.0, v, L - 1.0, v + shelf, 2.0,
             shelf, 20, 0, {shop ? "browse" : "store", "pick"});
    }
  } else if (type == "loading_bay") {
    p.roi("work_area", "dock", 0.6, 0.6, L - 0.6, D - 0.6);
    p.grid("pallet", "pallet", 0.8, D - 2.0, L - 0.8, D - 0.6, 1.6, 1.4, 6, 0, {"pick", "store"});
  } else {
    furnish_venue_room(p, type, rules, rng);
  }
}

// One zone of an open hall (offline.cpp, family open_hall_zones) by its area type; area types
// that are also room types are furnished as those rooms are.
void furnish_area(Placer& p, const std::string& type, const FurnishingRules& rules, Rng& rng, double area) {
  const double L = p.len(), D = p.depth();
  if (type == "checkout_zone") {
    // A row of check-outs by the entrance side, each with its queue lane into the hall.
    // A row of check-outs with their queue lanes into the hall, from the main door's side, else
    // from another side of the zone (a narrow zone along the entrance wall).
    auto row = [&](Placer& q) {
      const double len = q.len(), depth = q.depth();
      const double lane = std::clamp(depth * 0.45, 1.5, 3.5);
      const int n = std::clamp(static_cast<int>((len - 1.0) / 2.8), 1, 6);
      int placed = 0;
      for (int k = 0; k < n; ++k)
        placed += q.counter_with_queue("counter", numbered("checkout", k + 1), (k + 0.5) * len / n, 1.8, lane,
                                       true, rules.queue_lane_width, {"pay", "queue_target"})
                      ? 1
                      : 0;
      return placed;
    };
    int placed = row(p);
    for (int turn = 1; turn < 4 && placed == 0; ++turn) {
      Placer q = p.turned((p.side() + turn) % 4);
      placed = row(q);
    }
  } else if (type == "shelf_aisles" || type == "rack_aisles") {
    const bool shop = type == "shelf_aisles";
    const double shelf = shop ? 0.6 : 1.1, walk = rules.walkway_width;
    int row = 0;
    for (double v = 1.4; v + shelf + walk <= D - 0.3 && row < 12; v += shelf + walk) {
      ++row;
      p.roi("walkway", numbered("aisle", row), 0.6, v + shelf, L - 0.6, v + shelf + walk, true);
      p.grid(shop ? "shelf" : "rack", numbered(shop ? "shelf" : "rack", row), 1.0, v, L - 1.0, v + shelf, 2.0,
             shelf, 20, 0, {shop ? "browse" : "store", "pick"});
    }
  } else if (type == "assembly_seating") {
    // A large community hall set out for an audience: a stage at a short wall (the rows run along
    // the hall's length; the other short wall, then the wall facing the entrance, when a door
    // leaves it no room), seat rows facing it in blocks between aisles, a cross aisle at the back.
    std::vector<Placer> frames;
    if (L > D) {
      const int turn = rng.chance(0.5) ? 1 : 3;
      frames.push_back(p.turned((p.side() + turn) % 4));
      frames.push_back(p.turned((p.side() + 4 - turn) % 4));
    }
    frames.push_back(p);
    const double aisle = std::max(1.1, rules.walkway_width);
    // A stage where one fits, else a screen on the wall (a hall whose short walls are all doors).
    std::optional<std::size_t> at;
    double gap = 0.0;  // m kept between the last row and the far wall
    for (const char* kind : {"stage", "screen"}) {
      for (std::size_t k = 0; k < frames.size() && !at; ++k) {
        Placer& q = frames[k];
        const std::vector<std::string> use{std::string(kind) == "stage" ? "perform" : "watch"};
        if (q.entity(kind, kind, {{q.len() / 2, q.depth()}}, kPi, use)) at = k;
      }
      if (at) {
        gap = std::string(kind) == "stage" ? 3.2 + 1.5 : 2.6;
        break;
      }
    }
    Placer& q = frames[at.value_or(0)];
    seat_rows(q, "seat", 0.3, 1.8, q.len() - 0.3, q.depth() - (at ? gap : 2.6), 1.1, 14, aisle,
              {"sit", "watch"});
  } else if (type == "dining_area") {
    if (auto a = p.roi("seating_area", "seating", 0.8, 1.6, L - 0.8, D - 0.6))
      p.grid("table", "table", a->u0, a->v0, a->u1, a->v1, 2.0, 2.2, 40, 0, {"eat", "sit"});
  } else if (type == "staging_area") {
    p.roi("work_area", "staging", 0.8, 0.8, L - 0.8, std::min(D - 0.8, 4.0));
    p.grid("pallet", "pallet", 0.8, std::min(D - 2.0, 4.4), L - 0.8, D - 0.6, 1.6, 1.4, 6, 0,
           {"pick", "store"});
  } else {
    furnish_room(p, type, rules, rng, area);
  }
}

}  // namespace

FurnishingRules furnishing_rules(std::span<const knowledge::MergedConstraint> constraints,
                                 const PlanRequirement& plan) {
  FurnishingRules r;
  r.walkway_width = std::max({1.2, plan.walkway_width + 0.2});
  r.queue_lane_width = std::max(1.0, plan.queue_lane_width + 0.05);
  const double per_person = constraint(constraints, "workspace_area_per_person");
  const double volume = constraint(constraints, "workroom_volume_per_person");
  const double height = plan.ceiling_height > 0 ? std::max(plan.ceiling_height, 3.0) : 3.0;
  r.area_per_desk = std::max({8.0, per_person, volume / height});
  return r;
}

namespace {
Furnishing furnish_zones(std::span<const Zone> zones, std::span<const DoorSpec> doors,
                         const FurnishingRules& rules, Rng& rng, std::span<const std::string> unfurnished,
                         FurnishingMemo* memo);
}  // namespace

Furnishing furnish(std::span<const Zone> zones, std::span<const DoorSpec> doors, const FurnishingRules& rules,
                   Rng& rng, std::span<const std::string> unfurnished) {
  return furnish_zones(zones, doors, rules, rng, unfurnished, nullptr);
}

Furnishing furnish(std::span<const Zone> zones, std::span<const DoorSpec> doors, const FurnishingRules& rules,
                   Rng& rng, std::span<const std::string> unfurnished, FurnishingMemo& memo) {
  return furnish_zones(zones, doors, rules, rng, unfurnished, &memo);
}

namespace {
Furnishing furnish_zones(std::span<const Zone> zones, std::span<const DoorSpec> doors,
                         const FurnishingRules& rules, Rng& rng, std::span<const std::string> unfurnished,
                         FurnishingMemo* memo) {
  Furnishing out;
  const bool named_entrance = std::any_of(doors.begin(), doors.end(), [](const DoorSpec& d) {
    return d.name == "main_entrance" && d.connects.size() == 1;
  });
  for (const auto& z : zones) {
    const std::string type = canonical_room_type(z.type);
    const std::vector<DoorAt> here = doors_of(z, zones, doors);
    if (is_circulation_type(type) && !is_hall_type(type)) {
      out.rois.push_back({z.name + "_walk", "corridor", z.polygon});
    }
    // Entrance ROI just inside every door to the outside: "<zone>_entrance" for the main entrance
    // (or, in a plan without one, the zone's first outside door), "<zone>_<door>" of kind exit
    // for further exits.
    bool has_entrance = named_entrance;
    for (const auto& d : here) {
      if (!d.exterior) continue;
      const bool entrance = d.name == "main_entrance" || !has_entrance;
      has_entrance = true;
      const auto ring = z.polygon.outer;
      double best = 1e18;
      Segment wall{};
      for (const auto& e : geometry::edges(ring)) {
        const double dist = geometry::distance(e, d.centre);
        if (dist < best) {
          best = dist;
          wall = e;
        }
      }
      const double len = geometry::length(wall);
      if (len <= 0) continue;
      const Point u{(wall.b.x - wall.a.x) / len, (wall.b.y - wall.a.y) / len};
      Point n{-u.y, u.x};
      const Point c = geometry::closest_point(wall, d.centre);
      if (!geometry::contains(z.polygon, {c.x + n.x * 0.1, c.y + n.y * 0.1})) n = {-n.x, -n.y};
      // Half as wide as the door plus 0.2 m each side, narrowed to the wall (a corridor's end).
      const double h =
          std::min(d.width / 2 + 0.2, std::min(geometry::distance(c, wall.a), geometry::distance(c, wall.b)));
      if (h < d.width / 2 - 1e-9) continue;
      std::vector<Point> r{{c.x - u.x * h, c.y - u.y * h},
                           {c.x + u.x * h, c.y + u.y * h},
                           {c.x + u.x * h + n.x * 1.0, c.y + u.y * h + n.y * 1.0},
                           {c.x - u.x * h + n.x * 1.0, c.y - u.y * h + n.y * 1.0}};
      if (geometry::signed_area(r) < 0) std::reverse(r.begin(), r.end());
      const Polygon poly{r, {}};
      bool inside = true;
      for (const auto& p : r) inside = inside && geometry::contains(z.polygon, p, 1e-6);
      if (inside)
        out.rois.push_back(
            {entrance ? z.name + "_entrance" : z.name + "_" + d.name, entrance ? "entrance" : "exit", poly});
    }
    if (!find_room_type(type) || is_corridor_type(type)) continue;
    if (std::find(unfurnished.begin(), unfurnished.end(), z.name) != unfurnished.end()) continue;
    std::vector<FurnishingMemo::Door> given;
    if (memo) {
      for (const auto& d : here)
        given.push_back({d.centre.x, d.centre.y, d.width, d.exterior, d.other_type, d.name});
      const auto hit = memo->rooms.find(z.name);
      if (hit != memo->rooms.end() && hit->second.polygon == z.polygon && hit->second.type == z.type &&
          hit->second.doors == given && hit->second.before == rng) {
        out.rois.insert(out.rois.end(), hit->second.rois.begin(), hit->second.rois.end());
        out.entities.insert(out.entities.end(), hit->second.entities.begin(), hit->second.entities.end());
        rng = hit->second.after;
        continue;
      }
    }
    const Rng before = rng;
    auto placer = placer_for(z, zones, doors, out);
    if (!placer) continue;
    const std::size_t first_entity = out.entities.size(), first_roi = out.rois.size();
    furnish_room(*placer, type, rules, rng, geometry::area(z.polygon));
    placer->poi_lanes(first_entity, first_roi, rules.queue_lane_width, 2.2);
    if (memo)
      memo->rooms.insert_or_assign(
          z.name,
          FurnishingMemo::Room{
              z.polygon,
              z.type,
              std::move(given),
              before,
              rng,
              {out.rois.begin() + static_cast<std::ptrdiff_t>(first_roi), out.rois.end()},
              {out.entities.begin() + static_cast<std::ptrdiff_t>(first_entity), out.entities.end()}});
  }
  return out;
}
}  // namespace

}  // namespace socsim::floorplan

namespace socsim::floorplan {

Furnishing furnish_areas(std::span<const Zone> areas, std::span<const DoorSpec> doors,
                         const FurnishingRules& rules, Rng& rng) {
  Furnishing out;
  for (const auto& z : areas) {
    auto placer = placer_for(z, areas, doors, out);
    if (!placer) continue;
    const std::size_t first_entity = out.entities.size(), first_roi = out.rois.size();
    furnish_area(*placer, z.type, rules, rng, geometry::area(z.polygon));
    placer->poi_lanes(first_entity, first_roi, rules.queue_lane_width, 2.2);
  }
  return out;
}

}  // namespace socsim::floorplan
