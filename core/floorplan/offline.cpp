#include "core/floorplan/offline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "core/common/rng.hpp"
#include "core/floorplan/features.hpp"
#include "core/floorplan/furnish.hpp"
#include "core/floorplan/rooms.hpp"
#include "core/geometry/planar.hpp"
#include "core/world/layout_check.hpp"

namespace socsim::floorplan {
namespace {

using knowledge::MergedConstraint;

// The layout works in integer centimetres so that coordinates are exact and the YAML is short.
int cm_up(double metres, int step = 5) {
  const int c = static_cast<int>(std::ceil(metres * 100.0 - 1e-6));
  return (c + step - 1) / step * step;
}
double m(int cm) {
  return cm / 100.0;
}

struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] int w() const { return x1 - x0; }
  [[nodiscard]] int h() const { return y1 - y0; }
};

// The wall two touching rectangles share: on x = c (vertical) or y = c (horizontal), from lo to hi.
struct Wall {
  bool vertical = false;
  int c = 0, lo = 0, hi = 0;
};

std::optional<Wall> shared_wall(const Rect& a, const Rect& b) {
  if (a.x1 == b.x0 || a.x0 == b.x1) {
    const int lo = std::max(a.y0, b.y0), hi = std::min(a.y1, b.y1);
    if (hi > lo) return Wall{true, a.x1 == b.x0 ? a.x1 : a.x0, lo, hi};
  }
  if (a.y1 == b.y0 || a.y0 == b.y1) {
    const int lo = std::max(a.x0, b.x0), hi = std::min(a.x1, b.x1);
    if (hi > lo) return Wall{false, a.y1 == b.y0 ? a.y1 : a.y0, lo, hi};
  }
  return std::nullopt;
}

// Parts of rect i's sides not shared with any other rectangle: the outside walls.
std::vector<Wall> outside_walls(const std::vector<Rect>& rects, std::size_t i) {
  const Rect& r = rects[i];
  std::vector<Wall> sides = {{false, r.y0, r.x0, r.x1},
                             {true, r.x1, r.y0, r.y1},
                             {false, r.y1, r.x0, r.x1},
                             {true, r.x0, r.y0, r.y1}};
  std::vector<Wall> out;
  for (const Wall& side : sides) {
    std::vector<std::pair<int, int>> free{{side.lo, side.hi}};
    for (std::size_t j = 0; j < rects.size(); ++j) {
      if (j == i) continue;
      const auto w = shared_wall(r, rects[j]);
      if (!w || w->vertical != side.vertical || w->c != side.c) continue;
      std::vector<std::pair<int, int>> next;
      for (auto [lo, hi] : free) {
        if (w->hi <= lo || w->lo >= hi) {
          next.emplace_back(lo, hi);
          continue;
        }
        if (w->lo > lo) next.emplace_back(lo, w->lo);
        if (w->hi < hi) next.emplace_back(w->hi, hi);
      }
      free = std::move(next);
    }
    for (auto [lo, hi] : free) out.push_back({side.vertical, side.c, lo, hi});
  }
  return out;
}

struct PlanRoom {
  std::string name;
  std::string type;
  double area = 0.0;  // target, m²
  int min_dim = 0;    // cm
  Rect rect;
  bool placed = false;
};

struct DoorDraft {
  std::string name;
  int x = 0, y = 0;  // cm
  bool vertical_wall = false;
  int width = 0;  // cm
  std::vector<std::string> connects;
};

struct DomainStyle {
  double depth_lo, depth_hi;  // band depth range, m
  const char* floor;
};

DomainStyle style_of(std::string_view domain) {
  if (domain == "residential") return {3.4, 4.6, "wood"};
  if (domain == "office") return {4.2, 6.0, "carpet"};
  if (domain == "hospital") return {4.2, 5.4, "vinyl"};
  if (domain == "school") return {6.4, 8.0, "linoleum"};
  if (domain == "warehouse") return {3.8, 5.6, "concrete"};
  if (domain == "airport") return {4.5, 6.5, "terrazzo"};
  if (domain == "train_station") return {5.0, 7.0, "terrazzo"};
  if (domain == "hotel") return {4.2, 5.6, "carpet"};
  if (domain == "care_home") return {4.2, 5.4, "vinyl"};
  if (domain == "library" || domain == "museum") return {4.5, 6.5, "oak_parquet"};
  if (domain == "theatre" || domain == "arena") return {4.0, 6.0, "carpet"};
  if (domain == "factory") return {4.0, 6.0, "concrete"};
  if (domain == "mall") return {5.0, 7.5, "terrazzo"};
  if (domain == "university") return {6.0, 8.0, "linoleum"};
  if (domain == "gym") return {4.5, 6.5, "sports_floor"};
  if (domain == "community_hall") return {3.8, 5.4, "wood"};
  return {3.6, 5.4, "vinyl"};  // canteen, retail, supermarket, restaurant
}

// Rooms that are nearer square than a band's slice (halls for an audience, a sport, a show).
bool stout_type(std::string_view type) {
  return type == "auditorium" || type == "arena_floor" || type == "sports_hall" || type == "lecture_hall" ||
         type == "food_court" || type == "fitness_room" || type == "gallery" || type == "day_room";
}
// Rooms that stand together along one side of the circulation (stout halls, platforms).
bool grouped_type(std::string_view type) {
  return stout_type(type) || type == "platform";
}
// Halls for an audience in rows facing a stage or screen: the auditorium family is laid out round them.
bool audience_type(std::string_view type) {
  return type == "auditorium" || type == "arena_floor";
}

// Corridor plans of this many rooms or more may be laid out in wings (half the seeds); from
// kAlwaysWingRooms on they always are.
constexpr std::size_t kWingRooms = 16;
constexpr std::size_t kAlwaysWingRooms = 24;
// A community hall is large (its main hall set out as an auditorium) from this many people in
// the scenario or a main hall given this many square metres.
constexpr int kAssemblyOccupants = 200;
constexpr double kAssemblyHallArea = 250.0;

std::string material_of(std::string_view domain, std::string_view type) {
  if (is_toilet_type(type) || type == "kitchen" || type == "kitchenette") return "ceramic_tile";
  if (domain == "hospital") return "washable_paint";
  if ((domain == "warehouse" || domain == "factory") && type != "private_office" && type != "break_room")
    return "concrete";
  if (domain == "care_home") return "washable_paint";
  if (type == "auditorium" || type == "lecture_hall") return "acoustic_panel";
  if (type == "platform") return "concrete";
  return "painted_plaster";
}

std::string circulation_for(std::string_view domain) {
  if (domain == "residential") return "hallway";  // small homes' programs have none (home_open_plan)
  return room_program(domain).rooms.front().type;
}

// Layout families (docs/worlds.md): how the rooms stand around the room everyone walks through.
enum class Family {
  kCorridorWithRooms,  // a corridor with bands of rooms along it and end rooms
  kHallWithRooms,      // a hall (concourse, sales floor …) with bands of rooms around it
  kOpenHall,      // one large hall divided into zones (check-outs, aisles, waiting …), rooms on one side
  kHomeOpenPlan,  // a home without a hallway: every room opens onto the living room (ProcTHOR-style)
  kAuditorium,    // audience halls side by side, stage end against their backstage, foyer along their backs
  kMultiWing,     // a large building: corridor wings with rooms on both sides, joined at a junction
  kEnSuite,       // galleries en suite are the circulation: an enfilade (two rows, a U or a ring)
                  // entered from the foyer, the other rooms in a band on the foyer's far side
};

std::string_view family_name(Family f) {
  switch (f) {
    case Family::kCorridorWithRooms:
      return "corridor_with_rooms";
    case Family::kHallWithRooms:
      return "hall_with_rooms";
    case Family::kOpenHall:
      return "open_hall_zones";
    case Family::kHomeOpenPlan:
      return "home_open_plan";
    case Family::kAuditorium:
      return "auditorium";
    case Family::kMultiWing:
      return "multi_wing";
    case Family::kEnSuite:
      return "rooms_en_suite";
  }
  return "";
}

// The zones an open hall of this type is divided into, with their share of its length; empty for
// halls that are not laid out as open halls (furnish_areas furnishes each zone by its type).
struct AreaShare {
  const char* type;
  double share;
};
std::vector<AreaShare> open_hall_areas(std::string_view hall, std::string_view domain) {
  if (hall == "sales_floor") return {{"checkout_zone", 0.35}, {"shelf_aisles", 0.65}};
  if (hall == "warehouse_floor") return {{"staging_area", 0.3}, {"rack_aisles", 0.7}};
  if (hall == "dining_hall") return {{"cafe", 0.35}, {"dining_area", 0.65}};
  if (hall == "concourse" && domain == "train_station") return {{"waiting_room", 0.5}, {"concourse", 0.5}};
  if (hall == "concourse") return {{"waiting_room", 0.4}, {"concourse", 0.3}, {"cafe", 0.3}};
  // A mall's walkway with a café court, a factory's goods-in area before its production lines, a
  // foyer's box office and bar beside a café, a restaurant's bar room beside its dining room.
  if (hall == "mall_concourse") return {{"mall_concourse", 0.6}, {"cafe", 0.4}};
  if (hall == "production_floor") return {{"staging_area", 0.3}, {"production_floor", 0.7}};
  if (hall == "foyer") return {{"foyer", 0.55}, {"cafe", 0.45}};
  if (hall == "restaurant") return {{"restaurant", 0.4}, {"dining_area", 0.6}};
  return {};
}

class Layout {
 public:
  Layout(const SceneGraph& graph, std::span<const MergedConstraint> constraints)
      : graph_(graph), constraints_(constraints), plan_(plan_requirement(constraints, graph.domain)) {}

  Status prepare() {
    // Circulation: the first corridor or hall of the graph, else one the domain needs.
    for (std::size_t i = 0; i < graph_.rooms.size(); ++i)
      if (!circ_ && is_circulation_type(graph_.rooms[i].type)) circ_ = i;
    // A home without a hallway keeps none: its rooms open onto the living room (ProcTHOR-style).
    if (!circ_ && graph_.domain == "residential")
      for (std::size_t i = 0; i < graph_.rooms.size(); ++i)
        if (!circ_ && canonical_room_type(graph_.rooms[i].type) == "living_room") {
          circ_ = i;
          home_open_plan_ = true;
        }
    if (!circ_) {
      const std::string type = circulation_for(graph_.domain);
      std::string name = type;
      for (int k = 2; std::any_of(graph_.rooms.begin(), graph_.rooms.end(),
                                  [&](const SceneRoom& r) { return r.name == name; });
           ++k)
        name = type + "_" + std::to_string(k);
      for (const auto& r : graph_.rooms) graph_.adjacency.emplace_back(name, r.name);
      graph_.rooms.push_back({name, type, std::nullopt});
      circ_ = graph_.rooms.size() - 1;
      notes_.push_back("added circulation room '" + name + "' (" + type + ") connected to every room");
    }
    const std::size_t n = graph_.rooms.size();
    index_.clear();
    for (std::size_t i = 0; i < n; ++i) index_[graph_.rooms[i].name] = i;
    if (graph_.entrance.empty()) graph_.entrance = graph_.rooms[*circ_].name;
    entrance_ = index_.at(graph_.entrance);
    neighbours_.assign(n, {});
    on_hub_.assign(n, false);
    for (const auto& [a, b] : graph_.adjacency) {
      if (a == graph_.rooms[*circ_].name) on_hub_[index_.at(b)] = true;
      if (b == graph_.rooms[*circ_].name) on_hub_[index_.at(a)] = true;
    }
    std::vector<FieldError> errors;
    std::vector<std::size_t> parent(n);
    for (std::size_t i = 0; i < n; ++i) parent[i] = i;
    auto root = [&](std::size_t x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (std::size_t e = 0; e < graph_.adjacency.size(); ++e) {
      const std::size_t a = index_.at(graph_.adjacency[e].first), b = index_.at(graph_.adjacency[e].second);
      if (a == *circ_ || b == *circ_) continue;
      const std::string ptr = "/adjacency/" + std::to_string(e);
      for (std::size_t r : {a, b})
        if (neighbours_[r].size() == 2) {
          errors.push_back({ptr, "room '" + graph_.rooms[r].name + "' must already share walls with '" +
                                     graph_.rooms[neighbours_[r][0]].name + "' and '" +
                                     graph_.rooms[neighbours_[r][1]].name +
                                     "'; the offline layout puts at most two rooms beside a room on the " +
                                     graph_.rooms[*circ_].type + " — connect the others through '" +
                                     graph_.rooms[*circ_].name + "'"});
        }
      if (!errors.empty()) break;
      if (root(a) == root(b)) {
        errors.push_back(
            {ptr, "rooms '" + graph_.rooms[a].name + "' and '" + graph_.rooms[b].name +
                      "' would close a ring of rooms, which the offline layout cannot place; connect one "
                      "of them through '" +
                      graph_.rooms[*circ_].name + "'"});
        break;
      }
      parent[root(a)] = root(b);
      neighbours_[a].push_back(b);
      neighbours_[b].push_back(a);
    }
    if (!errors.empty())
      return fail(ErrorCode::kValidation, "the scene graph cannot be laid out by the offline generator",
                  std::move(errors));
    // Chains: the paths of rooms that must stand side by side, in graph order.
    std::vector<bool> seen(n, false);
    seen[*circ_] = true;
    for (std::size_t i = 0; i < n; ++i) {
      if (seen[i] || neighbours_[i].size() == 2) continue;
      std::vector<std::size_t> chain{i};
      seen[i] = true;
      for (std::size_t cur = i;;) {
        std::optional<std::size_t> next;
        for (auto nb : neighbours_[cur])
          if (!seen[nb]) next = nb;
        if (!next) break;
        seen[*next] = true;
        chain.push_back(*next);
        cur = *next;
      }
      chains_.push_back(std::move(chain));
    }
    chain_of_.assign(n, 0);
    for (std::size_t c = 0; c < chains_.size(); ++c)
      for (auto r : chains_[c]) chain_of_[r] = c;
    return {};
  }

  // One layout; nullopt (with a reason) when this draw does not fit, e.g. a wall too short for its door.
  std::optional<std::string> attempt(Rng& rng, double scale) {
    const std::size_t n = graph_.rooms.size();
    rooms_.assign(n, {});
    doors_.clear();
    const DomainStyle style = style_of(graph_.domain);
    const bool dwelling = graph_.domain == "residential";
    door_w_ = cm_up(std::max(plan_.door_width, dwelling ? 0.85 : 0.9)) + 5 * static_cast<int>(rng.below(3));
    public_w_ = std::max(door_w_, cm_up(plan_.public_door_width));
    entrance_w_ = dwelling ? std::max(door_w_, cm_up(0.95))
                           : std::max(public_w_, 180 + 10 * static_cast<int>(rng.below(3)));

    // Target areas and narrowest dimensions.
    std::optional<std::size_t> main_bedroom;
    std::vector<double> bedroom_areas;
    for (std::size_t i = 0; i < n; ++i) {
      const SceneRoom& s = graph_.rooms[i];
      PlanRoom& r = rooms_[i];
      r.name = s.name;
      r.type = s.type;
      const RoomType* rt = find_room_type(s.type);
      const double lo = rt && rt->area_hi > 0 ? rt->area_lo : 10.0,
                   hi = rt && rt->area_hi > 0 ? rt->area_hi : 15.0;
      r.area = s.area ? *s.area : rng.uniform(lo, hi);
      const bool main = is_bedroom_type(s.type) && !main_bedroom;
      if (main) main_bedroom = i;
      const RoomRequirement req = room_requirement(constraints_, s.type, main);
      r.area = std::max(r.area, req.min_area * 1.03) * scale;
      r.min_dim = cm_up(std::max({req.min_dimension, m(door_w_) + 0.35, 1.2}));
      // Halls for an audience or a sport keep an aspect of at most 1.5; platforms are long and narrow.
      if (stout_type(s.type))
        r.min_dim = std::max(r.min_dim, cm_up(std::sqrt(r.area / rng.uniform(1.0, 1.5))));
      if (s.type == "platform") r.min_dim = std::max(r.min_dim, cm_up(rng.uniform(5.0, 7.0)));
    }
    bool grouped = false;
    for (std::size_t i = 0; i < n; ++i) grouped = grouped || (i != *circ_ && grouped_type(rooms_[i].type));
    if (main_bedroom) {
      double biggest = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (is_bedroom_type(rooms_[i].type) && i != *main_bedroom)
          biggest = std::max(biggest, rooms_[i].area);
      rooms_[*main_bedroom].area = std::max(rooms_[*main_bedroom].area, biggest + 0.5);
      for (const auto& r : rooms_)
        if (is_bedroom_type(r.type)) bedroom_areas.push_back(r.area);
      const DwellingRequirement dw = dwelling_requirement(constraints_, bedroom_areas);
      std::vector<std::size_t> stores;
      for (std::size_t i = 0; i < n; ++i)
        if (rooms_[i].type == "storage") stores.push_back(i);
      for (auto i : stores)
        rooms_[i].area =
            std::max(rooms_[i].area, dw.storage_area * 1.05 / static_cast<double>(stores.size()));
    }

    if (family_ == Family::kMultiWing) return lay_out_wings(rng, style);
    if (family_ == Family::kEnSuite) return lay_out_en_suite(rng, style, scale);

    // Caps at the ends of the circulation, bands of rooms along its sides.
    const bool corridor = is_corridor_type(rooms_[*circ_].type);
    // A hall entered from outside keeps one end free for its entrance, unless it is small (then
    // its rooms stand in one band and its other long side is outside).
    const bool small = !home_open_plan_ && n <= 6;
    const std::size_t max_caps = entrance_ == *circ_ && !small ? 1 : 2;
    std::vector<std::size_t> caps;
    auto try_cap = [&](std::size_t r, double p) {
      if (caps.size() >= max_caps || r == *circ_ || !rng.chance(p)) return;
      for (auto c : caps)
        if (c == r || chain_of_[c] == chain_of_[r]) return;
      caps.push_back(r);
    };
    try_cap(entrance_, 0.8);
    for (std::size_t i = 0; i < n; ++i) {
      const std::string& t = rooms_[i].type;
      if (t == "living_room" || t == "lobby" || t == "reception" || t == "waiting_room" || t == "security" ||
          t == "open_office" || t == "loading_bay" || t == "ticket_hall" || t == "food_court")
        try_cap(i, 0.45);
    }
    // A home without a hallway: any room may close an end of the living room. So may any room of a
    // small program (a hall and up to five rooms), whose few rooms otherwise stand in few ways.
    if (home_open_plan_ || small)
      for (std::size_t i = 0; i < n; ++i) try_cap(i, 0.3);
    // An auditorium's foyer may end in a service room (one that belongs to no hall).
    if (family_ == Family::kAuditorium)
      for (std::size_t i = 0; i < n; ++i) {
        const auto& chain = chains_[chain_of_[i]];
        if (i != *circ_ && std::none_of(chain.begin(), chain.end(),
                                        [&](std::size_t q) { return grouped_type(rooms_[q].type); }))
          try_cap(i, 0.45);
      }
    // Drawn from a stream of its own, so that larger programs keep their bytes.
    service_exit_ = small && rng.fork("service exit").chance(0.5);
    bool needs_two_bands = false;
    std::vector<std::vector<std::size_t>> pieces_of(caps.size());
    for (std::size_t k = 0; k < caps.size(); ++k) {
      const auto& chain = chains_[chain_of_[caps[k]]];
      const auto pos =
          static_cast<std::size_t>(std::find(chain.begin(), chain.end(), caps[k]) - chain.begin());
      std::vector<std::size_t> before(chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(pos));
      std::reverse(before.begin(), before.end());
      std::vector<std::size_t> after(chain.begin() + static_cast<std::ptrdiff_t>(pos) + 1, chain.end());
      if (!before.empty() && !after.empty()) needs_two_bands = true;
      pieces_of[k] = before.empty() ? after : before;
      if (!before.empty() && !after.empty()) {
        pieces_of[k] = before;
        second_piece_[k] = after;
      }
    }
    std::size_t band_rooms = n - 1 - caps.size();
    // An open hall keeps its rooms on one side (its other sides are outside walls and zones).
    const bool single =
        family_ == Family::kOpenHall
            ? !needs_two_bands && band_rooms <= 8u
            : family_ != Family::kAuditorium && !needs_two_bands && band_rooms <= (corridor ? 3u : 5u) &&
                  ((small && entrance_ == *circ_ && caps.size() == 2) || rng.chance(corridor ? 0.35 : 0.6));
    grouped_band_ = grouped ? static_cast<int>(rng.below(2)) : 0;
    // A large hall's rooms are dealt to both bands by area, a stout hall's band too (there they
    // keep a depth of their own): a food court does not leave fifty shops in one band.
    const bool spread = grouped && family_ == Family::kHallWithRooms && n >= kAlwaysWingRooms;
    std::vector<std::size_t> left[2], middle[2], right[2];
    const bool first_cap_left = rng.chance(0.5);
    std::vector<bool> used(n, false);
    used[*circ_] = true;
    for (std::size_t k = 0; k < caps.size(); ++k) {
      used[caps[k]] = true;
      cap_left_[caps[k]] = (k == 0) == first_cap_left;
      std::vector<std::vector<std::size_t>> pieces{pieces_of[k]};
      if (second_piece_.count(k)) pieces.push_back(second_piece_[k]);
      const int first_band = single ? 0 : static_cast<int>(rng.below(2));
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        if (pieces[p].empty()) continue;
        const int b = p == 0 ? first_band : 1 - first_band;
        auto& dst = cap_left_[caps[k]] ? left[b] : right[b];
        if (!dst.empty()) return "two end rooms want the same band end";
        dst = pieces[p];
        if (!cap_left_[caps[k]]) std::reverse(dst.begin(), dst.end());
        for (auto r : pieces[p]) used[r] = true;
      }
    }
    second_piece_.clear();
    std::vector<std::size_t> order(chains_.size());
    for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
    rng.shuffle(order);
    double load[2] = {0, 0};
    int halls_in[2] = {0, 0};  // auditorium: audience halls dealt to each band
    for (int b = 0; b < 2; ++b)
      for (auto* part : {&left[b], &right[b]})
        for (auto r : *part) load[b] += rooms_[r].area;
    for (auto c : order) {
      std::vector<std::size_t> chain;
      for (auto r : chains_[c])
        if (!used[r]) chain.push_back(r);
      if (chain.empty()) continue;
      if (rng.chance(0.5)) std::reverse(chain.begin(), chain.end());
      int b = load[0] <= load[1] ? 0 : 1;
      if (rng.chance(0.2)) b = 1 - b;
      // Stout halls and platforms on one side, the small rooms on the other (bands share a depth).
      if (grouped) {
        const bool stout = std::any_of(chain.begin(), chain.end(),
                                       [&](std::size_t r) { return grouped_type(rooms_[r].type); });
        if (stout || !spread) b = stout ? grouped_band_ : 1 - grouped_band_;
      }
      if (family_ == Family::kAuditorium) {
        const bool hall = std::any_of(chain.begin(), chain.end(),
                                      [&](std::size_t r) { return grouped_type(rooms_[r].type); });
        // A service room may stand beside the halls (shallower than they are), and a hall may
        // face the others across the foyer (a multiplex).
        if (!hall && rng.chance(0.5)) b = grouped_band_;
        if (hall && halls_in[grouped_band_] > 0 && rng.chance(0.35)) b = 1 - grouped_band_;
        if (hall) ++halls_in[b];
      }
      if (single) b = 0;
      for (auto r : chain) {
        middle[b].push_back(r);
        load[b] += rooms_[r].area;
        used[r] = true;
      }
    }

    // Band depths and room widths.
    int depth[2] = {0, 0};
    std::vector<std::size_t> band[2];
    // In a hall's plan, a room at the end of a chain that has no door onto the hall (a store behind
    // a kitchen, backstage behind an auditorium, the last gallery) may stand behind its neighbour
    // instead of beside it. Drawn from a stream of its own: plans without such a room keep their bytes.
    std::vector<std::pair<std::size_t, std::size_t>> behind;  // (room, the band room it stands behind)
    for (int b = 0; b < 2; ++b) {
      band[b] = left[b];
      band[b].insert(band[b].end(), middle[b].begin(), middle[b].end());
      band[b].insert(band[b].end(), right[b].begin(), right[b].end());
    }
    if (!corridor && !home_open_plan_) {
      Rng draw = rng.fork("behind");
      for (int b = 0; b < 2; ++b) {
        std::vector<std::size_t> kept;
        for (auto r : band[b]) {
          const bool end = neighbours_[r].size() == 1 && !on_hub_[r] && r != entrance_;
          const std::size_t q = end ? neighbours_[r][0] : r;
          const bool q_in_band = end && std::find(band[b].begin(), band[b].end(), q) != band[b].end() &&
                                 std::none_of(behind.begin(), behind.end(), [&](const auto& bq) {
                                   return bq.first == q || bq.second == q;
                                 });
          // An audience hall's backstage always stands behind it, at its stage end.
          if (q_in_band &&
              ((family_ == Family::kAuditorium && audience_type(rooms_[q].type)) || draw.chance(0.7))) {
            behind.emplace_back(r, q);
          } else {
            kept.push_back(r);
          }
        }
        band[b] = std::move(kept);
      }
    }
    for (int b = 0; b < 2; ++b) {
      depth[b] = cm_up(rng.uniform(style.depth_lo, style.depth_hi));
      for (auto r : band[b]) depth[b] = std::max(depth[b], rooms_[r].min_dim);
    }
    // A room beside an auditorium's halls that belongs to no hall keeps a depth of its own.
    std::vector<int> own(n, 0);
    bool hall_band[2] = {false, false};
    auto of_hall = [&](std::size_t r) {
      const auto& chain = chains_[chain_of_[r]];
      return std::any_of(chain.begin(), chain.end(),
                         [&](std::size_t q) { return grouped_type(rooms_[q].type); });
    };
    if (family_ == Family::kAuditorium || spread)
      for (int b = 0; b < 2; ++b) {
        hall_band[b] = std::any_of(band[b].begin(), band[b].end(), of_hall);
        if (!hall_band[b]) continue;
        for (auto r : band[b])
          if (!of_hall(r))
            own[r] = std::max(cm_up(rng.uniform(style.depth_lo, style.depth_hi)), rooms_[r].min_dim);
      }
    std::vector<int> width(n, 0);
    int length[2] = {0, 0};
    for (int b = 0; b < 2; ++b)
      for (auto r : band[b]) {
        width[r] = cm_up(std::max(rooms_[r].area / m(own[r] > 0 ? own[r] : depth[b]), m(rooms_[r].min_dim)));
        length[b] += width[r];
      }

    // The circulation: a corridor as long as the longer band, or a hall of its own area.
    PlanRoom& c = rooms_[*circ_];
    int L = 0, W = 0;
    if (corridor) {
      W = cm_up(std::max(plan_.corridor_width, m(std::max(door_w_, public_w_)) + 0.35) +
                rng.uniform(0.0, 0.3));
      // Never narrower than its own minimum dimension (the turning circle, 1.525 m in offices).
      W = std::max(W, c.min_dim);
      L = std::max({length[0], length[1], 300});
      // A corridor longer than the passing-space interval is as wide as a passing space all along.
      for (const auto& k : constraints_)
        if (k.constraint.name == "passing_space_width" && L > 6096)
          W = std::max(W, cm_up(k.constraint.value + 0.02));
    } else {
      const RoomType* rt = find_room_type(c.type);
      const double area =
          graph_.rooms[*circ_].area ? *graph_.rooms[*circ_].area : rng.uniform(rt->area_lo, rt->area_hi);
      // An open hall holds its zones (a third more floor); a living room hub keeps its own size.
      const double drawn = area * scale * (family_ == Family::kOpenHall ? 1.3 : 1.0);
      c.area = home_open_plan_ ? std::max(c.area, drawn) : drawn;
      L = std::max({length[0], length[1], cm_up(std::sqrt(c.area * rng.uniform(0.9, 1.7)))});
      W = cm_up(std::max({c.area / m(L), 4.0, m(c.min_dim)}));
    }
    // Bands shorter than the circulation: stretched when a little short, else they leave a gap.
    std::vector<int> x_of(n, 0);
    for (int b = 0; b < 2; ++b) {
      if (band[b].empty()) continue;
      const int gap = L - length[b];
      if (gap > 0 && corridor && gap * 100 <= L * 35) {
        int given = 0;
        for (std::size_t k = 0; k < band[b].size(); ++k) {
          const auto r = band[b][k];
          const int extra = k + 1 == band[b].size() ? gap - given : gap * width[r] / length[b] / 5 * 5;
          width[r] += extra;
          given += extra;
        }
        length[b] = L;
      }
      int x = 0;
      for (std::size_t k = 0; k < band[b].size(); ++k) {
        const auto r = band[b][k];
        const bool first_right = !right[b].empty() && r == right[b].front();
        if (first_right)
          x = L - [&] {
            int w = 0;
            for (auto q : right[b]) w += width[q];
            return w;
          }();
        x_of[r] = x;
        x += width[r];
      }
    }
    c.rect = {0, 0, L, W};
    c.placed = true;
    // An open hall's zones: strips across it along its longer side, in an order the seed draws.
    areas_.clear();
    if (family_ == Family::kOpenHall) {
      auto shares = open_hall_areas(canonical_room_type(c.type), graph_.domain);
      if (rng.chance(0.5)) std::reverse(shares.begin(), shares.end());
      // Along the longer side, or across a hall that is near square.
      const bool along_x = (L >= W) != (std::max(L, W) * 10 < std::min(L, W) * 16 && rng.chance(0.5));
      const int length_cm = along_x ? L : W, across = along_x ? W : L;
      int at = 0;
      for (std::size_t k = 0; k < shares.size(); ++k) {
        const int w = k + 1 == shares.size() ? length_cm - at : cm_up(m(length_cm) * shares[k].share);
        areas_.emplace_back(shares[k].type, along_x ? Rect{at, 0, at + w, W} : Rect{0, at, L, at + w});
        at += w;
        if (w < 300 || across < 300) areas_.clear();
        if (areas_.empty()) break;
      }
    }
    for (int b = 0; b < 2; ++b)
      for (auto r : band[b]) {
        const int d = own[r] > 0 ? own[r] : depth[b];
        rooms_[r].rect =
            b == 0 ? Rect{x_of[r], W, x_of[r] + width[r], W + d} : Rect{x_of[r], -d, x_of[r] + width[r], 0};
        rooms_[r].placed = true;
      }
    for (const auto& [r, q] : behind) {
      const Rect& in_front = rooms_[q].rect;
      const int d = cm_up(std::max(rooms_[r].area / m(in_front.x1 - in_front.x0), m(rooms_[r].min_dim)));
      const bool above = in_front.y0 >= W;  // band 0 stands above the hall, band 1 below it
      rooms_[r].rect = above ? Rect{in_front.x0, in_front.y1, in_front.x1, in_front.y1 + d}
                             : Rect{in_front.x0, in_front.y0 - d, in_front.x1, in_front.y0};
      rooms_[r].placed = true;
    }
    for (auto cap : caps) {
      int y0 = band[1].empty() ? 0 : -depth[1];
      int y1 = W + (band[0].empty() ? 0 : depth[0]);
      // An auditorium's end room closes the foyer and the service band, not a band of halls.
      if (hall_band[0]) y1 = W;
      if (hall_band[1]) y0 = 0;
      // Public entrance rooms are not left as a sliver across the building's end.
      const std::string& t = rooms_[cap].type;
      const double stout = t == "lobby" || t == "reception" || t == "security" ? 0.4 * m(y1 - y0) : 0.0;
      const int w = cm_up(std::max({rooms_[cap].area / m(y1 - y0), m(rooms_[cap].min_dim), 2.4, stout}));
      rooms_[cap].rect = cap_left_[cap] ? Rect{-w, y0, 0, y1} : Rect{L, y0, L + w, y1};
      rooms_[cap].placed = true;
    }
    cap_left_.clear();
    for (const auto& r : rooms_)
      if (!r.placed) return "room '" + r.name + "' was not placed";

    return doors_and_entrance(rng, dwelling);
  }

  // Widths (cm) of `rooms` stretched to `target` in all: the extra shared out by width (in 5 cm
  // steps), the last room taking the rest. Nothing changes when they are as long already.
  static void stretch(std::vector<int>& width, const std::vector<std::size_t>& rooms, int target) {
    int total = 0;
    for (auto r : rooms) total += width[r];
    const int gap = target - total;
    if (gap <= 0 || rooms.empty()) return;
    int given = 0;
    for (std::size_t k = 0; k < rooms.size(); ++k) {
      const auto r = rooms[k];
      const int extra = k + 1 == rooms.size() ? gap - given : gap * width[r] / total / 5 * 5;
      width[r] += extra;
      given += extra;
    }
  }
  static int total_of(const std::vector<int>& width, const std::vector<std::size_t>& rooms) {
    int total = 0;
    for (auto r : rooms) total += width[r];
    return total;
  }

  // Rooms en suite: the galleries are the circulation, each opening into the next, the first (and,
  // for a circuit, the last) onto the foyer. Laid out with the foyer along y = 0 .. W and one of
  //  - two rows: the galleries in an enfilade going out from the foyer and (a circuit) a second one
  //    beside it coming back, the two joined at their far end;
  //  - a U: the first and last gallery flank the foyer, the others a row across its back;
  //  - a ring: the first and last gallery rise from the foyer at its ends, the others a row across
  //    their tops, the space between them a core of service rooms that open onto the foyer.
  // The other rooms (chains of them) stand in a band along the foyer's other long side, leaving
  // room for its entrance. A chain without a way back to the foyer is a single enfilade.
  std::optional<std::string> lay_out_en_suite(Rng& rng, const DomainStyle& style, double scale) {
    const std::size_t n = rooms_.size();
    hub_pieces_.clear();
    areas_.clear();
    const std::vector<std::size_t>& gal = gallery_chain_;
    const std::size_t k = gal.size();
    std::vector<std::vector<std::size_t>> chains;
    for (std::size_t ch = 0; ch < chains_.size(); ++ch)
      if (ch != chain_of_[gal.front()]) chains.push_back(chains_[ch]);
    rng.shuffle(chains);
    for (auto& ch : chains)
      if (rng.chance(0.5)) std::reverse(ch.begin(), ch.end());
    enum Variant { kTwoRows, kU, kRing };
    Variant variant = kTwoRows;
    if (closed_chain_ && k >= 3) variant = static_cast<Variant>(rng.below(chains.empty() ? 2 : 3));
    // The band's depth and its rooms' widths. A ring's core is as deep as the galleries beside it:
    // it takes the largest chain and, on half the draws each, the others of rooms of 12 m² or more
    // (a café, a shop; toilets and stores would be slivers that deep).
    int band_depth = cm_up(rng.uniform(style.depth_lo, style.depth_hi));
    std::vector<std::size_t> core, band;
    std::size_t largest = 0;
    double largest_area = -1.0;
    for (std::size_t ch = 0; ch < chains.size(); ++ch) {
      double area = 0.0;
      for (auto r : chains[ch]) area += rooms_[r].area;
      if (area > largest_area) largest = ch, largest_area = area;
    }
    for (std::size_t ch = 0; ch < chains.size(); ++ch) {
      const bool roomy = std::all_of(chains[ch].begin(), chains[ch].end(),
                                     [&](std::size_t r) { return rooms_[r].area >= 12.0; });
      const bool in_core =
          variant == kRing && (ch == largest || (roomy && core.size() < 4 && rng.chance(0.5)));
      for (auto r : chains[ch]) (in_core ? core : band).push_back(r);
    }
    for (auto r : band) band_depth = std::max(band_depth, rooms_[r].min_dim);
    std::vector<int> width(n, 0);
    for (auto r : band) width[r] = cm_up(std::max(rooms_[r].area / m(band_depth), m(rooms_[r].min_dim)));
    const int band_length = total_of(width, band);
    // A row of galleries: its depth (their narrowest dimension at least) and their widths along it.
    auto row = [&](const std::vector<std::size_t>& rs, int extra_min = 0) {
      int d = std::max(cm_up(rng.uniform(style.depth_lo, style.depth_hi)), extra_min);
      for (auto r : rs) d = std::max(d, rooms_[r].min_dim);
      for (auto r : rs) width[r] = cm_up(std::max(rooms_[r].area / m(d), m(rooms_[r].min_dim)));
      return d;
    };
    PlanRoom& c = rooms_[*circ_];
    const RoomType* rt = find_room_type(c.type);
    const double drawn = graph_.rooms[*circ_].area ? *graph_.rooms[*circ_].area
                         : rt && rt->area_hi > 0   ? rng.uniform(rt->area_lo, rt->area_hi)
                                                   : rng.uniform(40.0, 80.0);
    c.area = std::max(c.area, drawn * scale);
    const int long_side = cm_up(std::sqrt(c.area * rng.uniform(0.9, 1.7)));
    int L = 0, W = 0;
    auto foyer_depth = [&](int length) { return cm_up(std::max({c.area / m(length), 4.0, m(c.min_dim)})); };
    auto place = [&](std::size_t r, int x0, int y0, int x1, int y1) {
      rooms_[r].rect = {x0, y0, x1, y1};
      rooms_[r].placed = true;
    };
    if (variant == kTwoRows) {
      // Out along one row, back along the other (a circuit); a single row when there is no way back.
      const std::size_t out = closed_chain_ ? std::clamp<std::size_t>((k + rng.below(2)) / 2, 1, k - 1) : k;
      std::vector<std::size_t> col[2];
      col[0].assign(gal.begin(), gal.begin() + static_cast<std::ptrdiff_t>(out));
      col[1].assign(gal.rbegin(), gal.rend() - static_cast<std::ptrdiff_t>(out));
      int d[2] = {0, 0}, h[2] = {0, 0};
      for (int s = 0; s < 2; ++s)
        if (!col[s].empty()) {
          d[s] = row(col[s]);
          // Along a column its rooms' widths are their lengths: swap the roles (depth across).
          h[s] = total_of(width, col[s]);
        }
      const int H = std::max(h[0], h[1]);
      for (int s = 0; s < 2; ++s) stretch(width, col[s], H);
      const int span = d[0] + d[1];
      L = std::max({span, band_length, long_side});
      W = foyer_depth(L);
      const int xg = L > span && rng.chance(0.5) ? (L - span) / 5 * 5 : 0;
      for (int s = 0; s < 2; ++s) {
        const int x0 = xg + (s == 0 ? 0 : d[0]);
        int y = W;
        for (auto r : col[s]) {
          place(r, x0, y, x0 + d[s], y + width[r]);
          y += width[r];
        }
      }
    } else {
      const std::size_t first = gal.front(), last = gal.back();
      std::vector<std::size_t> top(gal.begin() + 1, gal.end() - 1);
      const int top_depth = row(top);
      if (variant == kU) {
        // The foyer between the first and the last gallery, the others across its back.
        const int H = std::max({foyer_depth(long_side), rooms_[first].min_dim, rooms_[last].min_dim});
        const int c1 = cm_up(std::max(rooms_[first].area / m(H), m(rooms_[first].min_dim)));
        const int c2 = cm_up(std::max(rooms_[last].area / m(H), m(rooms_[last].min_dim)));
        L = std::max(
            {total_of(width, top) - c1 - c2, band_length + entrance_w_ + 90, cm_up(c.area / m(H)), 400});
        W = H;
        stretch(width, top, c1 + L + c2);
        place(first, -c1, 0, 0, H);
        place(last, L, 0, L + c2, H);
        int x = -c1;
        for (auto r : top) {
          place(r, x, H, x + width[r], H + top_depth);
          x += width[r];
        }
      } else {
        // A ring: the first and last gallery rise from the foyer's ends, a core of rooms between.
        int d = cm_up(rng.uniform(style.depth_lo, style.depth_hi));
        for (auto r : core) d = std::max(d, rooms_[r].min_dim);
        d = std::max({d, rooms_[first].min_dim, rooms_[last].min_dim});
        for (auto r : core) width[r] = cm_up(std::max(rooms_[r].area / m(d), m(rooms_[r].min_dim)));
        const int c1 = cm_up(std::max(rooms_[first].area / m(d), m(rooms_[first].min_dim)));
        const int c2 = cm_up(std::max(rooms_[last].area / m(d), m(rooms_[last].min_dim)));
        L = std::max({total_of(width, top), c1 + c2 + total_of(width, core), band_length, long_side});
        W = foyer_depth(L);
        stretch(width, top, L);
        stretch(width, core, L - c1 - c2);
        place(first, 0, W, c1, W + d);
        place(last, L - c2, W, L, W + d);
        int x = c1;
        for (auto r : core) {
          place(r, x, W, x + width[r], W + d);
          x += width[r];
        }
        x = 0;
        for (auto r : top) {
          place(r, x, W + d, x + width[r], W + d + top_depth);
          x += width[r];
        }
      }
    }
    c.rect = {0, 0, L, W};
    c.placed = true;
    // The band below the foyer, at one of its ends (the rest of that side outside).
    int x = rng.chance(0.5) ? 0 : L - band_length;
    for (auto r : band) {
      place(r, x, -band_depth, x + width[r], 0);
      x += width[r];
    }
    for (const auto& r : rooms_)
      if (!r.placed) return "room '" + r.name + "' was not placed";
    return doors_and_entrance(rng, false);
  }

  // A multi-wing plan: two to four wings (an L, a T or a cross), each a corridor with a band of
  // rooms on either side, joined at a square junction. The chains of rooms are dealt to the bands
  // by area (some at random), each band set back from the junction by the deepest band so that
  // neighbouring wings do not meet; the junction and the wing corridors are one zone, the hub.
  std::optional<std::string> lay_out_wings(Rng& rng, const DomainStyle& style) {
    const std::size_t n = rooms_.size();
    hub_pieces_.clear();
    hub_arms_ = {0, 0, 0, 0};
    areas_.clear();
    PlanRoom& c = rooms_[*circ_];
    int W =
        cm_up(std::max(plan_.corridor_width, m(std::max(door_w_, public_w_)) + 0.35) + rng.uniform(0.0, 0.3));
    W = std::max(W, c.min_dim);
    // Wings are long: as wide as a passing space all along.
    for (const auto& k : constraints_)
      if (k.constraint.name == "passing_space_width") W = std::max(W, cm_up(k.constraint.value + 0.02));
    const std::size_t most = std::clamp<std::size_t>((n - 1) / 4, 2, 4);
    const std::size_t wings = 2 + rng.below(static_cast<std::uint32_t>(most - 1));
    const std::size_t bands = 2 * wings;
    std::vector<std::vector<std::size_t>> band(bands);
    std::vector<double> load(bands, 0.0);
    std::vector<std::size_t> order(chains_.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    rng.shuffle(order);
    for (auto ch : order) {
      std::vector<std::size_t> chain = chains_[ch];
      if (rng.chance(0.5)) std::reverse(chain.begin(), chain.end());
      auto b = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
      if (rng.chance(0.25)) b = rng.below(static_cast<std::uint32_t>(bands));
      for (auto r : chain) {
        band[b].push_back(r);
        load[b] += rooms_[r].area;
      }
    }
    for (std::size_t w = 0; w < wings; ++w)
      if (band[2 * w].empty() && band[2 * w + 1].empty()) return "a wing without rooms";
    std::vector<int> depth(bands, 0);
    std::vector<int> width(n, 0);
    for (std::size_t b = 0; b < bands; ++b) {
      depth[b] = cm_up(rng.uniform(style.depth_lo, style.depth_hi));
      for (auto r : band[b]) depth[b] = std::max(depth[b], rooms_[r].min_dim);
      for (auto r : band[b]) width[r] = cm_up(std::max(rooms_[r].area / m(depth[b]), m(rooms_[r].min_dim)));
    }
    const int off = *std::max_element(depth.begin(), depth.end());
    // Laid out as a wing towards +x, then turned about the junction's centre to its side.
    auto turn = [W](Rect r, std::size_t quarters) {
      for (std::size_t k = 0; k < quarters; ++k) r = Rect{W - r.y1, r.x0, W - r.y0, r.x1};
      return r;
    };
    c.rect = {0, 0, W, W};
    c.placed = true;
    for (std::size_t w = 0; w < wings; ++w) {
      int length[2] = {0, 0};
      for (int s = 0; s < 2; ++s)
        for (auto r : band[2 * w + static_cast<std::size_t>(s)]) length[s] += width[r];
      const int L = off + std::max({length[0], length[1], 300});
      hub_arms_[w] = L;
      hub_pieces_.push_back(turn(Rect{W, 0, W + L, W}, w));
      for (int s = 0; s < 2; ++s) {
        const std::size_t b = 2 * w + static_cast<std::size_t>(s);
        int x = W + off;
        for (auto r : band[b]) {
          const Rect e =
              s == 0 ? Rect{x, W, x + width[r], W + depth[b]} : Rect{x, -depth[b], x + width[r], 0};
          rooms_[r].rect = turn(e, w);
          rooms_[r].placed = true;
          x += width[r];
        }
      }
    }
    for (const auto& r : rooms_)
      if (!r.placed) return "room '" + r.name + "' was not placed";
    return doors_and_entrance(rng, graph_.domain == "residential");
  }

  // The outline of a multi-wing hub (the junction and its wings), counter-clockwise from its
  // lowest corner, in world coordinates.
  [[nodiscard]] std::vector<Point> hub_ring() const {
    const Rect& j = rooms_[*circ_].rect;
    const auto& a = hub_arms_;
    std::vector<std::pair<int, int>> corners{{j.x0, j.y0}};
    if (a[3] > 0) corners.insert(corners.end(), {{j.x0, j.y0 - a[3]}, {j.x1, j.y0 - a[3]}});
    corners.emplace_back(j.x1, j.y0);
    if (a[0] > 0) corners.insert(corners.end(), {{j.x1 + a[0], j.y0}, {j.x1 + a[0], j.y1}});
    corners.emplace_back(j.x1, j.y1);
    if (a[1] > 0) corners.insert(corners.end(), {{j.x1, j.y1 + a[1]}, {j.x0, j.y1 + a[1]}});
    corners.emplace_back(j.x0, j.y1);
    if (a[2] > 0) corners.insert(corners.end(), {{j.x0 - a[2], j.y1}, {j.x0 - a[2], j.y0}});
    std::vector<Point> ring;
    const std::size_t k = corners.size();
    for (std::size_t i = 0; i < k; ++i) {
      const auto& p = corners[(i + k - 1) % k];
      const auto& q = corners[i];
      const auto& r = corners[(i + 1) % k];
      const long cross = static_cast<long>(q.first - p.first) * (r.second - q.second) -
                         static_cast<long>(q.second - p.second) * (r.first - q.first);
      if (cross != 0) ring.push_back(point_of(q.first, q.second));  // a corner, not a point on a side
    }
    if (geometry::signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
    const auto first = std::min_element(ring.begin(), ring.end(), [](const Point& p, const Point& q) {
      return p.y < q.y || (p.y == q.y && p.x < q.x);
    });
    std::rotate(ring.begin(), first, ring.end());
    return ring;
  }

  // Doors: one per edge on the shared wall, one to the outside; then the orientation.
  std::optional<std::string> doors_and_entrance(Rng& rng, bool dwelling) {
    const std::vector<Rect> rects = all_rects();
    std::set<std::string> names;
    for (const auto& [an, bn] : graph_.adjacency) {
      const std::size_t a = index_.at(an), b = index_.at(bn);
      const auto wall = a == *circ_   ? hub_wall(rects, b)
                        : b == *circ_ ? hub_wall(rects, a)
                                      : shared_wall(rects[a], rects[b]);
      if (!wall) return "rooms '" + an + "' and '" + bn + "' do not touch";
      const bool open = !dwelling && (is_public(a) || is_public(b));
      const int w = open ? public_w_ : door_w_;
      std::string name = "door_" + an + "_" + bn;
      for (int k = 2; names.count(name); ++k) name = "door_" + an + "_" + bn + "_" + std::to_string(k);
      names.insert(name);
      // Galleries en suite open into each other on their axis (an enfilade).
      const bool centred = family_ == Family::kEnSuite && (in_gallery_chain(a) || in_gallery_chain(b));
      if (!place_door(rng, name, *wall, w, {an, bn}, centred))
        return "the wall between '" + an + "' and '" + bn + "' is too short";
    }
    {
      auto walls = outside_of(rects, entrance_);
      std::vector<Wall> fit;
      for (const auto& wl : walls)
        if (wl.hi - wl.lo >= entrance_w_ + 60) fit.push_back(wl);
      if (fit.empty()) return "no outside wall of '" + rooms_[entrance_].name + "' takes the entrance";
      const Wall& wl = fit[rng.below(static_cast<std::uint32_t>(fit.size()))];
      place_door(rng, "main_entrance", wl, entrance_w_, {rooms_[entrance_].name});
    }

    // Orientation: a quarter turn or none, mirrored or not, then moved into the first quadrant.
    rotate_ = static_cast<int>(rng.below(4));
    mirror_ = rng.chance(0.5);
    return std::nullopt;
  }

  // The laid-out plan as WorldBuilder input (metres, first quadrant).
  void emit(WorldBuilder& builder, std::vector<Zone>& zones, std::vector<DoorSpec>& doors) const {
    const std::pair<int, int> min = origin();  // no structured binding: lambdas capture it (clang 14)
    auto point = [&](int x, int y) {
      auto [tx, ty] = turned(x, y);
      return Point{m(tx - min.first), m(ty - min.second)};
    };
    for (std::size_t i = 0; i < rooms_.size(); ++i) {
      const PlanRoom& r = rooms_[i];
      Zone z{r.name, r.type, material_of(graph_.domain, r.type),
             Polygon{i == *circ_ && !hub_pieces_.empty() ? hub_ring() : ring_of(r.rect), {}}};
      zones.push_back(z);
      builder.add_zone(std::move(z));
    }
    for (const auto& d : doors_) {
      const Point p = point(d.x, d.y);
      // The opening's normal: across a vertical wall it points along x, before the turn.
      bool along_x = d.vertical_wall;
      if (rotate_ % 2 == 1) along_x = !along_x;
      DoorSpec s{d.name, {p.x, p.y, along_x ? 0.0 : std::numbers::pi / 2}, m(d.width), d.connects};
      doors.push_back(s);
      builder.add_door(std::move(s));
    }
  }

  // A second door to the outside as far from the main entrance as the outside walls allow
  // (IBC 1007.1.1 wants at least half the building's diagonal): circulation and public rooms
  // first, then other rooms except toilets, bedrooms and stores; no randomness, so a plan that
  // needs no second exit is unchanged. False when no outside wall takes one.
  // `wide`: a double door (the egress width is short); `near`: a room the exit should open from
  // (the walk from it to an exit is too long), when it has an outside wall.
  std::optional<std::string> add_exit(bool wide = false, const std::string& near = "") {
    std::vector<const DoorDraft*> exits;
    for (const auto& d : doors_)
      if (d.connects.size() == 1) exits.push_back(&d);
    if (exits.empty()) return std::nullopt;
    const std::vector<Rect> rects = all_rects();
    // Squared distances in whole cm² (exact), one square root at the end: a large plan has
    // thousands of corner pairs and spots × doors, and hypot was a few ms of every exit round.
    auto square = [](long long dx, long long dy) { return dx * dx + dy * dy; };
    long long widest = 0;
    for (const Rect& a : rects)
      for (const Rect& b : rects)
        for (auto [ax, ay] : {std::pair{a.x0, a.y0}, {a.x1, a.y0}, {a.x1, a.y1}, {a.x0, a.y1}})
          for (auto [bx, by] : {std::pair{b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}})
            widest = std::max(widest, square(ax - bx, ay - by));
    const double diagonal = std::sqrt(static_cast<double>(widest));
    // The second exit half the diagonal from the first (IBC 1007.1.1); further exits spread out.
    const double apart =
        exits.size() == 1 ? diagonal / 2.0 : diagonal / (2.0 * static_cast<double>(exits.size()));
    const int w = wide ? std::max(public_w_, entrance_w_) : public_w_;
    bool near_has_wall = false;
    for (std::size_t r = 0; r < rooms_.size(); ++r)
      if (rooms_[r].name == near && !outside_of(rects, r).empty()) near_has_wall = true;
    auto base_tier = [&](std::size_t r) {
      const std::string& t = rooms_[r].type;
      if (near_has_wall) return rooms_[r].name == near ? 0 : 3;
      if (is_circulation_type(t)) return 0;
      // An audience hall is left straight from its side walls (IBC 1029: assembly seating).
      if (family_ == Family::kAuditorium && audience_type(t)) return 0;
      if (is_public(r) || t == "dining_hall" || t == "sales_floor" || t == "concourse" ||
          t == "open_office" || t == "warehouse_floor" || t == "loading_bay")
        return 1;
      if (is_toilet_type(t) || is_bedroom_type(t) || t == "storage") return 3;
      return 2;
    };
    // A service exit (kitchen, stock room, office) first when this attempt drew one.
    auto tier = [&](std::size_t r) {
      const int t = base_tier(r);
      if (!service_exit_ || near_has_wall) return t;
      return t == 2 ? 0 : t == 0 ? 1 : t;
    };
    struct Spot {
      std::size_t room;
      Wall wall;
      int at;
      double distance;
    };
    std::optional<Spot> best;
    int best_tier = 4;
    for (std::size_t r = 0; r < rooms_.size(); ++r) {
      const int t = tier(r);
      if (t == 3) continue;
      for (const Wall& wall : outside_of(rects, r)) {
        const int lo = wall.lo + 15 + (w + 1) / 2, hi = wall.hi - 15 - (w + 1) / 2;
        if (lo > hi) continue;
        for (int at : {lo, (lo + hi) / 2 / 5 * 5, hi, (3 * lo + hi) / 4 / 5 * 5, (lo + 3 * hi) / 4 / 5 * 5}) {
          const int x = wall.vertical ? wall.c : at, y = wall.vertical ? at : wall.c;
          bool clear = true;
          for (const DoorDraft& d : doors_) {
            const double reach = (d.width + w) / 2.0 + 30.0;
            if (static_cast<double>(square(d.x - x, d.y - y)) < reach * reach) clear = false;
          }
          if (!clear) continue;
          long long nearest = std::numeric_limits<long long>::max();
          for (const DoorDraft* e : exits) nearest = std::min(nearest, square(e->x - x, e->y - y));
          const double distance = std::sqrt(static_cast<double>(nearest));
          // A spot far enough apart in a better tier wins; within a tier, the farthest.
          const bool enough = distance >= apart;
          const int rank = enough ? t : t + 4;
          if (!best || rank < best_tier || (rank == best_tier && distance > best->distance)) {
            best = Spot{r, wall, at, distance};
            best_tier = rank;
          }
        }
      }
    }
    if (!best) return std::nullopt;
    DoorDraft d;
    d.name = exits.size() == 1 ? "emergency_exit" : "emergency_exit_" + std::to_string(exits.size());
    d.vertical_wall = best->wall.vertical;
    d.x = best->wall.vertical ? best->wall.c : best->at;
    d.y = best->wall.vertical ? best->at : best->wall.c;
    d.width = w;
    d.connects = {rooms_[best->room].name};
    const std::string name = d.name;
    doors_.push_back(std::move(d));
    char metres[32];
    std::snprintf(metres, sizeof metres, "%.1f", best->distance / 100.0);
    return "added '" + name + "' from '" + rooms_[best->room].name + "', " + metres + " m from " +
           (exits.size() == 1 ? std::string("the main entrance") : std::string("the nearest exit"));
  }

  // Layout coordinates (cm) turned and mirrored as the attempt drew, then moved into the first quadrant.
  [[nodiscard]] std::pair<int, int> turned(int x, int y) const {
    for (int k = 0; k < rotate_; ++k) {
      const int t = x;
      x = -y;
      y = t;
    }
    if (mirror_) x = -x;
    return {x, y};
  }
  [[nodiscard]] std::pair<int, int> origin() const {
    int min_x = INT32_MAX, min_y = INT32_MAX;
    for (const Rect& r : all_rects())
      for (auto [x, y] : {turned(r.x0, r.y0), turned(r.x1, r.y1)}) {
        min_x = std::min(min_x, x);
        min_y = std::min(min_y, y);
      }
    return {min_x, min_y};
  }
  [[nodiscard]] Point point_of(int x, int y) const {
    const auto [min_x, min_y] = origin();
    const auto [tx, ty] = turned(x, y);
    return {m(tx - min_x), m(ty - min_y)};
  }
  // A rectangle's outline in world coordinates, counter-clockwise from its lower-left corner
  // (stable text whatever the orientation).
  [[nodiscard]] std::vector<Point> ring_of(const Rect& r) const {
    std::vector<Point> ring{point_of(r.x0, r.y0), point_of(r.x1, r.y0), point_of(r.x1, r.y1),
                            point_of(r.x0, r.y1)};
    if (geometry::signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
    const auto first = std::min_element(ring.begin(), ring.end(), [](const Point& a, const Point& b) {
      return a.y < b.y || (a.y == b.y && a.x < b.x);
    });
    std::rotate(ring.begin(), first, ring.end());
    return ring;
  }

  // The layout family, chosen from the building type (the hub's type), the room count and the seed
  // (streams of their own, so that plans of the other families keep their bytes).
  void choose_family(std::uint64_t seed, const WorldRequirements& wants) {
    const std::string hub = canonical_room_type(graph_.rooms[*circ_].type);
    const std::size_t n = graph_.rooms.size();
    bool audience = false;  // a hall for an audience that opens onto the hub
    for (std::size_t i = 0; i < n; ++i)
      audience = audience || (on_hub_[i] && audience_type(graph_.rooms[i].type));
    if (home_open_plan_) {
      family_ = Family::kHomeOpenPlan;
    } else if (is_corridor_type(hub)) {
      family_ = Family::kCorridorWithRooms;
      // A large building: wings joined at a junction, always from kAlwaysWingRooms rooms on.
      if (n >= kWingRooms && (n >= kAlwaysWingRooms || Rng(seed, fnv1a64("multi_wing")).chance(0.5)))
        family_ = Family::kMultiWing;
    } else if (entrance_ == *circ_ && find_gallery_chain()) {
      // A museum: its galleries en suite are the way through it (every seed).
      family_ = Family::kEnSuite;
    } else if (hub == "main_hall" && assembly(wants)) {
      // A large community hall: its main hall, the hub, is set out for an audience (stage, seat rows).
      family_ = Family::kAuditorium;
      assembly_hub_ = true;
    } else if (audience && (n >= kAlwaysWingRooms || Rng(seed, fnv1a64("auditorium")).chance(0.6))) {
      // Theatres, cinemas, concert halls and arenas: the plan is laid out round their audience
      // halls (on 60 % of the seeds, every seed for a large venue; else a hall family, as before).
      family_ = Family::kAuditorium;
    } else {
      Rng pick(seed, fnv1a64("layout_family"));
      const bool open = !open_hall_areas(hub, graph_.domain).empty() && graph_.rooms.size() <= 24;
      family_ = open && pick.chance(0.5) ? Family::kOpenHall : Family::kHallWithRooms;
    }
  }
  [[nodiscard]] Family family() const { return family_; }
  [[nodiscard]] const std::string& hub_name() const { return graph_.rooms[*circ_].name; }
  // Whether a main hall is set out for an audience: many people (or a large hall given) and no
  // counters, tables or desks asked for (a polling station, a meeting at tables, a dinner).
  [[nodiscard]] bool assembly(const WorldRequirements& wants) const {
    const bool large = (wants.occupants && *wants.occupants >= kAssemblyOccupants) ||
                       graph_.rooms[*circ_].area.value_or(0.0) >= kAssemblyHallArea;
    return large && std::none_of(wants.features.begin(), wants.features.end(), [](const auto& f) {
             return f.feature == Feature::kCounter || f.feature == Feature::kTable ||
                    f.feature == Feature::kDesk;
           });
  }
  // Whether the hub itself is the audience hall (a large community hall's main hall).
  [[nodiscard]] bool assembly_hub() const { return assembly_hub_; }

  // The zones of an open hall as WorldBuilder would see rooms (for furnish_areas), with the hall's
  // doors on their edges and an opening between neighbours; nothing for the other families.
  void emit_areas(std::span<const DoorSpec> doors, std::vector<Zone>& areas,
                  std::vector<DoorSpec>& area_doors) const {
    if (areas_.empty()) return;
    const std::string& hub = graph_.rooms[*circ_].name;
    std::vector<Polygon> outlines;
    for (const auto& [type, r] : areas_) {
      Polygon poly{ring_of(r), {}};
      outlines.push_back(poly);
      areas.push_back({hub + "_" + type, type, "", std::move(poly)});
    }
    // Each door of the hall to the zones its opening reaches, as the part of it on their edge
    // (kept 0.35 m from the edge's ends, so that a person steps in from it inside the zone).
    for (const auto& d : doors) {
      if (std::find(d.connects.begin(), d.connects.end(), hub) == d.connects.end()) continue;
      const Point c = d.pose.position();
      for (std::size_t k = 0; k < areas.size(); ++k) {
        for (const auto& e : geometry::edges(outlines[k].outer)) {
          const double len = geometry::length(e);
          if (len < 1.0 || geometry::distance(e, c) > d.width / 2 + 0.011) continue;
          const Point u{(e.b.x - e.a.x) / len, (e.b.y - e.a.y) / len};
          const double off = (c.x - e.a.x) * u.y - (c.y - e.a.y) * u.x;
          if (std::abs(off) > 0.011) continue;
          const double t = (c.x - e.a.x) * u.x + (c.y - e.a.y) * u.y;
          const double lo = std::max(t - d.width / 2, 0.35), hi = std::min(t + d.width / 2, len - 0.35);
          if (hi - lo < 0.3) continue;
          DoorSpec copy = d;
          const double mid = (lo + hi) / 2;
          copy.pose.x = e.a.x + u.x * mid;
          copy.pose.y = e.a.y + u.y * mid;
          copy.width = hi - lo;
          for (auto& name : copy.connects)
            if (name == hub) name = areas[k].name;
          area_doors.push_back(std::move(copy));
          break;
        }
      }
    }
    // Openings between neighbouring zones (no wall there; the placer keeps them free).
    for (std::size_t k = 0; k + 1 < areas_.size(); ++k) {
      const Rect& a = areas_[k].second;
      const auto wall = shared_wall(a, areas_[k + 1].second);
      if (!wall) continue;
      const int mid = (wall->lo + wall->hi) / 2;
      const Point p = wall->vertical ? point_of(wall->c, mid) : point_of(mid, wall->c);
      bool along_x = wall->vertical;
      if (rotate_ % 2 == 1) along_x = !along_x;
      const double width = std::min(4.0, m(wall->hi - wall->lo) * 0.6);
      area_doors.push_back({hub + "_opening_" + std::to_string(k + 1),
                            {p.x, p.y, along_x ? 0.0 : std::numbers::pi / 2},
                            width,
                            {areas[k].name, areas[k + 1].name}});
    }
  }

  // Widens every exit (door to the outside) towards `each` cm on its outside wall: where it is
  // when the wall takes the width there, else moved along the wall to the widest free stretch
  // (15 cm from the wall's ends, 30 cm from the openings of doors near the wall's line). Returns
  // the exits' total width in cm; no randomness.
  int widen_exits(int each) {
    const std::vector<Rect> rects = all_rects();
    int total = 0;
    for (auto& d : doors_) {
      if (d.connects.size() != 1) continue;
      const auto room = index_.find(d.connects.front());
      const int c = d.vertical_wall ? d.x : d.y;
      int& at = d.vertical_wall ? d.y : d.x;
      std::optional<Wall> on;
      if (room != index_.end())
        for (const Wall& wall : outside_of(rects, room->second))
          if (wall.vertical == d.vertical_wall && wall.c == c && at >= wall.lo && at <= wall.hi) on = wall;
      if (!on || d.width >= each) {
        total += d.width;
        continue;
      }
      // Free stretches of the wall: its length less the openings of doors on or near its line.
      std::vector<std::pair<int, int>> free{{on->lo + 15, on->hi - 15}};
      for (const auto& o : doors_) {
        if (&o == &d) continue;
        const int oc = d.vertical_wall ? o.x : o.y, oat = d.vertical_wall ? o.y : o.x;
        const int reach = o.vertical_wall == d.vertical_wall ? o.width / 2 : 0;
        if (std::abs(oc - c) > 100) continue;
        const int margin = reach + 30 + (o.vertical_wall == d.vertical_wall ? 0 : 50);
        const int lo = oat - margin, hi = oat + margin;
        std::vector<std::pair<int, int>> next;
        for (auto [a, b] : free) {
          if (hi <= a || lo >= b) {
            next.emplace_back(a, b);
            continue;
          }
          if (lo > a) next.emplace_back(a, lo);
          if (hi < b) next.emplace_back(hi, b);
        }
        free = std::move(next);
      }
      std::optional<std::pair<int, int>> best;
      for (auto [a, b] : free) {
        const bool here = at >= a && at <= b;
        const int room_here = here ? 2 * std::min(at - a, b - at) : 0;
        if (here && room_here >= each) {
          best = {at, each};
          break;
        }
        const int w = std::min(each, b - a) / 5 * 5;
        if (!best || w > best->second) {
          // Centred in the stretch, or as near the old place as the width allows.
          const int centre = std::clamp(at, a + (w + 1) / 2, b - (w + 1) / 2);
          best = {centre, w};
        }
      }
      if (best && best->second > d.width) {
        at = best->first;
        d.width = best->second;
      }
      total += d.width;
    }
    return total;
  }

  [[nodiscard]] const SceneGraph& graph() const { return graph_; }
  [[nodiscard]] const std::vector<std::string>& notes() const { return notes_; }
  [[nodiscard]] const PlanRequirement& plan() const { return plan_; }

 private:
  // The rooms' rectangles, then the hub's further pieces (the wing corridors of a multi-wing plan).
  [[nodiscard]] std::vector<Rect> all_rects() const {
    std::vector<Rect> rects;
    rects.reserve(rooms_.size() + hub_pieces_.size());
    for (const auto& r : rooms_) rects.push_back(r.rect);
    rects.insert(rects.end(), hub_pieces_.begin(), hub_pieces_.end());
    return rects;
  }
  // Room r's outside walls (every piece of the hub's).
  [[nodiscard]] std::vector<Wall> outside_of(const std::vector<Rect>& rects, std::size_t r) const {
    std::vector<Wall> walls = outside_walls(rects, r);
    if (r == *circ_)
      for (std::size_t p = 0; p < hub_pieces_.size(); ++p)
        for (const Wall& w : outside_walls(rects, rooms_.size() + p)) walls.push_back(w);
    return walls;
  }
  // The longest wall room r shares with any piece of the hub.
  [[nodiscard]] std::optional<Wall> hub_wall(const std::vector<Rect>& rects, std::size_t r) const {
    std::optional<Wall> best = shared_wall(rects[*circ_], rects[r]);
    for (std::size_t p = 0; p < hub_pieces_.size(); ++p) {
      const auto w = shared_wall(rects[rooms_.size() + p], rects[r]);
      if (w && (!best || w->hi - w->lo > best->hi - best->lo)) best = w;
    }
    return best;
  }

  // The chain of two or more galleries en suite that the en-suite family is laid out round: its
  // first room (and its last, for a circuit) opens onto the hub, no room between does. Oriented
  // from the hub; false when the graph has none.
  bool find_gallery_chain() {
    for (const auto& chain : chains_) {
      if (chain.size() < 2) continue;
      const bool galleries = std::all_of(chain.begin(), chain.end(), [&](std::size_t r) {
        return canonical_room_type(graph_.rooms[r].type) == "gallery";
      });
      const bool inner_on_hub =
          std::any_of(chain.begin() + 1, chain.end() - 1, [&](std::size_t r) { return on_hub_[r]; });
      if (!galleries || inner_on_hub || (!on_hub_[chain.front()] && !on_hub_[chain.back()])) continue;
      gallery_chain_ = chain;
      if (!on_hub_[chain.front()]) std::reverse(gallery_chain_.begin(), gallery_chain_.end());
      closed_chain_ = on_hub_[chain.front()] && on_hub_[chain.back()];
      return true;
    }
    return false;
  }
  [[nodiscard]] bool in_gallery_chain(std::size_t r) const {
    return std::find(gallery_chain_.begin(), gallery_chain_.end(), r) != gallery_chain_.end();
  }

  bool is_public(std::size_t r) const {
    const std::string& t = rooms_[r].type;
    return is_circulation_type(t) || t == "lobby" || t == "reception" || t == "waiting_room" ||
           t == "ticket_hall";
  }

  bool place_door(Rng& rng, const std::string& name, const Wall& wall, int width,
                  std::vector<std::string> connects, bool centred = false) {
    const int margin = 15;
    const int lo = wall.lo + margin + (width + 1) / 2, hi = wall.hi - margin - (width + 1) / 2;
    if (lo > hi) return false;
    // Near one end or in the middle, as doors usually are (centred: in the middle).
    static constexpr double kAt[3] = {0.1, 0.5, 0.9};
    const double along = kAt[rng.below(3)];
    const int at = lo + static_cast<int>(std::lround((hi - lo) * (centred ? 0.5 : along)));
    DoorDraft d;
    d.name = name;
    d.vertical_wall = wall.vertical;
    d.x = wall.vertical ? wall.c : at;
    d.y = wall.vertical ? at : wall.c;
    d.width = width;
    d.connects = std::move(connects);
    doors_.push_back(std::move(d));
    return true;
  }

  SceneGraph graph_;
  std::span<const MergedConstraint> constraints_;
  PlanRequirement plan_;
  std::optional<std::size_t> circ_;
  std::size_t entrance_ = 0;
  std::map<std::string, std::size_t> index_;
  std::vector<std::vector<std::size_t>> neighbours_;  // rooms that must stand side by side
  std::vector<bool> on_hub_;                          // rooms with an edge to the hub
  std::vector<std::vector<std::size_t>> chains_;
  std::vector<std::size_t> chain_of_;
  std::vector<std::string> notes_;
  // Per attempt.
  std::vector<PlanRoom> rooms_;
  std::vector<DoorDraft> doors_;
  std::map<std::size_t, std::vector<std::size_t>> second_piece_;
  std::map<std::size_t, bool> cap_left_;
  int door_w_ = 90, public_w_ = 100, entrance_w_ = 100;
  int grouped_band_ = 0;         // the band stout halls and platforms go to
  bool home_open_plan_ = false;  // the living room is the hub (no hallway in the graph)
  bool service_exit_ = false;    // a small program's second exit from a service room (this attempt)
  bool assembly_hub_ = false;    // auditorium family: the hub is set out as the audience hall
  Family family_ = Family::kCorridorWithRooms;
  std::vector<std::size_t> gallery_chain_;           // en-suite family: the galleries, from the hub
  bool closed_chain_ = false;                        // its last gallery opens back onto the hub (a circuit)
  std::vector<std::pair<std::string, Rect>> areas_;  // open hall: its zones (type, rectangle)
  // Multi-wing plan: the hub's rect is the junction; these are its wing corridors, and hub_arms_
  // their lengths beyond the junction towards +x, +y, -x, -y (0: no wing there).
  std::vector<Rect> hub_pieces_;
  std::array<int, 4> hub_arms_{};
  int rotate_ = 0;
  bool mirror_ = false;
};

const char* floor_material(std::string_view domain) {
  return style_of(domain).floor;
}

}  // namespace

Json knowledge_provenance(std::span<const MergedConstraint> constraints) {
  std::map<std::string, Json> by_ref;
  std::vector<std::string> order;
  for (const auto& c : constraints) {
    auto it = by_ref.find(c.ref_id);
    if (it == by_ref.end()) {
      Json sources = Json::array();
      for (const auto& s : c.sources)
        sources.push_back({{"title", s.title}, {"url", s.url}, {"section", s.section}});
      it = by_ref
               .emplace(c.ref_id, Json{{"ref_id", c.ref_id},
                                       {"title", c.title},
                                       {"building_type", c.building_type},
                                       {"jurisdiction", c.jurisdiction},
                                       {"sources", std::move(sources)},
                                       {"constraints", Json::array()}})
               .first;
      order.push_back(c.ref_id);
    }
    it->second["constraints"].push_back(c.constraint.name);
  }
  Json out = Json::array();
  for (const auto& id : order) out.push_back(by_ref[id]);
  return out;
}

namespace {

// The exits the code asks for: the exit_count check's requirement (1 when there is none).
int code_exits(const ComplianceReport& report) {
  for (const auto& c : report.checks)
    if (c.name == "exit_count") return static_cast<int>(std::lround(c.required));
  return 1;
}

const ComplianceCheck* find_check(const ComplianceReport& report, std::string_view name) {
  for (const auto& c : report.checks)
    if (c.name == name) return &c;
  return nullptr;
}

// The widest exit the generator builds: a bank of three door leaves of the largest leaf the
// IBC allows (1010.1.1: 48 in, 1.22 m). The egress width of a large occupant load is given by
// widening the exits up to this before any exit beyond the asked and required count is added.
constexpr int kMaxExitWidthCm = 365;

std::string metres_text(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", metres);
  return text;
}

// Why the plan has the exits it has (asked for, required by the code's exit count, added for
// the egress width or the travel distance, widened), for its provenance.
struct ExitReasons {
  int added_for_count = 0;
  int added_for_width = 0;
  int added_for_travel = 0;
  bool widened = false;
};

Json exit_provenance(const World& world, const ComplianceReport& report, const WorldRequirements& wants,
                     int asked, const ExitReasons& why) {
  const ComplianceCheck* count = find_check(report, "exit_count");
  const ComplianceCheck* width = find_check(report, "egress_width_per_occupant");
  const int built = count_feature(world, Feature::kExit);
  double total = 0.0, widest = 0.0;
  Json widths = Json::array();
  for (const auto& d : world.doors())
    if (!d.other) {
      total += d.width;
      widest = std::max(widest, d.width);
      widths.push_back({{"door", d.name}, {"width_m", std::round(d.width * 100.0) / 100.0}});
    }
  const int required = count ? static_cast<int>(std::lround(count->required)) : 1;
  const std::string load =
      std::to_string(static_cast<long>(std::lround(report.occupant_load))) + " occupants";
  std::string text;
  std::string decided_by = "request";
  if (asked > 0)
    text = std::to_string(asked) + " exit" + (asked == 1 ? "" : "s") + " asked for";
  else
    text = "no exit count asked for";
  if (count) {
    text += "; " + std::to_string(required) + " required by " + count->ref_id + " (" + count->section +
            ") for " + load;
    if (required > asked) decided_by = count->ref_id;
  }
  if (width && width->value) {
    text += "; " + metres_text(width->required) + " m of exit width required by " + width->ref_id + " (" +
            width->section + ")";
    if (why.widened) text += ", given by exits up to " + metres_text(widest) + " m wide";
    if (why.widened && decided_by == "request") decided_by = width->ref_id + " (width only)";
  }
  if (why.added_for_width > 0) {
    text += "; " + std::to_string(why.added_for_width) + " exit" + (why.added_for_width == 1 ? "" : "s") +
            " added beyond that for the exit width (no exit is wider than " +
            metres_text(kMaxExitWidthCm / 100.0) + " m)";
    if (width) decided_by = width->ref_id;
  }
  if (why.added_for_travel > 0) {
    text += "; " + std::to_string(why.added_for_travel) + " exit" + (why.added_for_travel == 1 ? "" : "s") +
            " added for the travel distance";
    for (const auto& c : report.checks)
      if (c.name.rfind("exit_access_travel_distance", 0) == 0) decided_by = c.ref_id;
  }
  text += "; " + std::to_string(built) + " built";
  const FeatureCount* exit = wants.find(Feature::kExit);
  if (exit == nullptr) exit = wants.find(Feature::kEntrance);
  return {{"asked", asked},
          {"asked_exactly", exit != nullptr && !exit->at_least},
          {"required", required},
          {"required_by", count ? Json(count->ref_id + " (" + count->section + ")") : Json(nullptr)},
          {"occupant_load", report.occupant_load},
          {"width_required_m", width ? Json(std::round(width->required * 1000.0) / 1000.0) : Json(nullptr)},
          {"width_required_by", width ? Json(width->ref_id + " (" + width->section + ")") : Json(nullptr)},
          {"width_built_m", std::round(total * 100.0) / 100.0},
          {"added_for_count", why.added_for_count},
          {"added_for_width", why.added_for_width},
          {"added_for_travel", why.added_for_travel},
          {"widened", why.widened},
          {"built", built},
          {"widths", std::move(widths)},
          {"decided_by", decided_by},
          {"text", text}};
}

// The exits (doors to the outside) a request asks for, at least: the most of its exits,
// entrances and, when there are too few doors in all, doors.
int asked_exits(const WorldRequirements& r) {
  int n = 0;
  for (const auto& f : r.features)
    if (f.feature == Feature::kExit || f.feature == Feature::kEntrance) n = std::max(n, f.count);
  return n;
}

// What the world lacks of the request: "2 of the 3 exits" …; empty when it holds all of it.
std::vector<std::string> unmet(const World& world, const WorldRequirements& r, int code_needed) {
  std::vector<std::string> out;
  for (const auto& f : r.features) {
    int have = count_feature(world, f.feature);
    int want = f.count;
    bool exact = !f.at_least;
    if (f.feature == Feature::kExit || f.feature == Feature::kEntrance) {
      want = std::max(want, code_needed);  // the code may ask for more than the request
      if (f.count < code_needed) exact = false;
      if (f.count == 0) exact = false;  // a building keeps its entrance
    }
    if (f.feature == Feature::kDoor) exact = false;  // every room keeps its doors
    if (have < want || (exact && have > want))
      out.push_back(std::to_string(have) + " " + std::string(info(f.feature).plural) + " built, " +
                    std::to_string(want) + (exact ? "" : " or more") + " asked for");
  }
  for (const auto& room : r.rooms) {
    const std::string type = room_type_for(room);
    const auto have = std::count_if(world.zones().begin(), world.zones().end(), [&](const Zone& z) {
      return canonical_room_type(z.type) == type || z.name == type;
    });
    if (have < room.count)
      out.push_back("no room '" + room.name + "' (" + type + "): lay it out with apply_room_requirements");
  }
  return out;
}

}  // namespace

Result<FloorPlan> generate_floor_plan(const SceneGraph& graph, std::span<const MergedConstraint> constraints,
                                      const OfflineOptions& options) {
  if (graph.rooms.empty())
    return fail(ErrorCode::kValidation, "the scene graph has no rooms",
                {{"/rooms", "needs at least one room"}});
  Layout layout(graph, constraints);
  if (auto s = layout.prepare(); !s) return tl::unexpected(s.error());
  const WorldRequirements& wants = options.requirements;
  const std::optional<double> occupants =
      wants.occupants ? std::optional<double>(*wants.occupants) : std::nullopt;
  layout.choose_family(options.seed, wants);
  const FurnishingRules rules = furnishing_rules(constraints, layout.plan());
  const std::string& domain = layout.graph().domain;
  Rng rng(options.seed, fnv1a64("floorplan"));
  double scale = 1.0;
  std::vector<std::string> tried;
  std::optional<Error> last_error;
  std::optional<ComplianceReport> last_report;
  std::vector<std::string> last_unmet;
  const int attempts = std::max(1, options.max_attempts);
  for (int attempt = 0; attempt < attempts; ++attempt) {
    if (auto why = layout.attempt(rng, scale)) {
      tried.push_back(*why);
      continue;
    }
    const Rng furnishing_rng = rng.fork("furnish");
    ComplianceCache travel_cache;    // the worlds of this attempt share their travel-distance grid
    FurnishingMemo furnishing_memo;  // and the furnishing of rooms whose doors did not change
    BuildCache build_cache;          // and the geometry WorldBuilder works out from the zones alone
    std::set<std::string> dropped;   // furniture the layout check found in the way, left out
    FeatureOutcome outcome;
    // Worlds built again for more exits or with furniture left out are validated without the
    // reachability grid (the costliest part of a build); the plan returned is validated in full.
    bool validated = true;
    WorldBuilder last;  // the last world's input, validated in full at the end when it was not
    auto build = [&](bool reachability) {
      validated = reachability;
      WorldBuilder builder;
      builder.set_name(domain + "_plan_" + std::to_string(options.seed));
      builder.set_floor({floor_material(domain)});
      std::vector<Zone> zones;
      std::vector<DoorSpec> doors;
      layout.emit(builder, zones, doors);
      Rng furnishing = furnishing_rng;
      // An open hall is furnished zone by zone (each an ROI of kind "area" named after it).
      std::vector<Zone> areas;
      std::vector<DoorSpec> area_doors;
      layout.emit_areas(doors, areas, area_doors);
      std::vector<std::string> open_halls;
      if (!areas.empty() || layout.assembly_hub()) open_halls.push_back(layout.hub_name());
      Furnishing f = furnish(zones, doors, rules, furnishing, open_halls, furnishing_memo);
      if (layout.assembly_hub()) {
        // The hub set out for an audience: furnished as an area of its own kind (same zone name).
        for (const auto& z : zones)
          if (z.name == layout.hub_name()) {
            const std::vector<Zone> hall{{z.name, "assembly_seating", "", z.polygon}};
            Rng by_area = furnishing_rng.fork("assembly");
            Furnishing a = furnish_areas(hall, doors, rules, by_area);
            for (auto& r : a.rois) f.rois.push_back(std::move(r));
            for (auto& e : a.entities) f.entities.push_back(std::move(e));
          }
      }
      if (!areas.empty()) {
        Rng by_area = furnishing_rng.fork("areas");
        Furnishing a = furnish_areas(areas, area_doors, rules, by_area);
        for (const auto& z : areas) f.rois.push_back({z.name, "area", z.polygon});
        for (auto& r : a.rois) f.rois.push_back(std::move(r));
        for (auto& e : a.entities) f.entities.push_back(std::move(e));
      }
      outcome = furnish_requirements(zones, doors, wants, rules, f);
      for (auto& r : f.rois) builder.add_roi(std::move(r));
      for (auto& e : f.entities)
        if (!dropped.count(e.name)) builder.add_entity(std::move(e));
      BuildOptions build_options = options.build;
      build_options.check_reachability = build_options.check_reachability && reachability;
      if (!reachability) last = builder;
      return builder.build(build_options, nullptr, &build_cache);
    };
    // A large plan is almost always built again (more exits for its occupant load): its first
    // world is validated in full only if it turns out to be the last.
    auto world = build(layout.graph().rooms.size() <= 20);
    if (!world) {
      tried.push_back("the world did not validate: " + world.error().message());
      last_error = world.error();
      continue;
    }
    ComplianceReport report = check_compliance(*world, domain, constraints, occupants, travel_cache);
    // Exits: as many as the request asks for and the code requires (occupant load, travel
    // distance), each added as far from the others as the outside walls allow.
    // An exit count the request gives is a minimum: the code's exit count (IBC Table 1006.3.2)
    // may raise it; the egress width of the occupant load (IBC 1005.3.2) widens the exits first
    // (up to kMaxExitWidthCm each) and adds exits only when the widest exits cannot carry it.
    std::vector<std::string> exit_notes;
    ExitReasons why;
    bool exits_ok = true;
    for (int round = 0; round < 12 && world; ++round) {
      const int target = std::max({code_exits(report), asked_exits(wants), 1});
      const ComplianceCheck* egress = nullptr;
      std::string far_room;
      for (const auto& c : report.checks) {
        if (c.status != CheckStatus::kFail) continue;
        if (c.name == "egress_width_per_occupant") egress = &c;
        if (c.name.rfind("exit_access_travel_distance", 0) == 0) far_room = c.element;
      }
      const int have = count_feature(*world, Feature::kExit);
      if (have >= target && egress == nullptr && far_room.empty()) break;
      if (have >= target && far_room.empty()) {
        // The count is right, the width short: wider exits, when their walls take them.
        const int each = std::min(kMaxExitWidthCm, cm_up(egress->required / have + 0.005));
        const int before = static_cast<int>(std::lround(egress->value.value_or(0.0) * 100.0));
        if (layout.widen_exits(each) > before) {
          why.widened = true;
          world = build(false);
          if (world) report = check_compliance(*world, domain, constraints, occupants, travel_cache);
          continue;
        }
      }
      // The exits the count lacks are added together (one build and report for all of them).
      const bool for_width = have >= target && far_room.empty();
      for (int k = 0; k < std::max(1, target - have) && exits_ok; ++k) {
        auto note = k == 0 ? layout.add_exit(egress != nullptr, far_room) : layout.add_exit();
        if (!note) {
          exits_ok = false;
          break;
        }
        exit_notes.push_back(*note);
        if (have + k < target)
          ++why.added_for_count;
        else if (for_width)
          ++why.added_for_width;
        else
          ++why.added_for_travel;
      }
      if (!exits_ok) break;
      world = build(false);
      if (world) report = check_compliance(*world, domain, constraints, occupants, travel_cache);
    }
    if (!world) {
      tried.push_back("the world with more exits did not validate: " + world.error().message());
      last_error = world.error();
      continue;
    }
    if (!exits_ok) {
      tried.push_back("no outside wall takes another exit");
      scale *= 1.15;
      continue;
    }
    // Footprints clear of walls, doors and each other, every zone and piece of furniture
    // reachable by a person 0.5 m wide: furniture in the way is left out (and the plan built
    // again); a zone nobody can reach fails the attempt.
    if (report.passed) {
      LayoutCheck check = check_layout(*world);
      if (!check.ok()) {
        bool zones_ok = true;
        for (const auto& f : check.findings) {
          if (f.kind.rfind("entity_", 0) == 0) {
            dropped.insert(f.element);
            if (f.kind == "entity_overlap") dropped.insert(f.other);
          } else {
            zones_ok = false;
          }
        }
        if (zones_ok) {
          world = build(false);
          if (world) check = check_layout(*world);
        }
        if (!zones_ok || !world || !check.ok()) {
          tried.push_back("layout check: " + (world ? check.summary() : world.error().message()));
          continue;
        }
        report = check_compliance(*world, domain, constraints, occupants, travel_cache);
      }
    }
    if (!report.passed) {
      double grow = 1.1;
      for (const auto* c : report.failures())
        if (c->value && *c->value > 0 && c->type == "min" && c->name.rfind("exit_", 0) != 0)
          grow = std::max(grow, c->required / *c->value * 1.02);
      scale *= std::min(grow, 1.6);
      std::string what;
      for (const auto* c : report.failures())
        what += (what.empty() ? "" : ", ") + c->name + " at " + c->element;
      tried.push_back("not compliant: " + what);
      last_report = std::move(report);
      continue;
    }
    // Everything the request counts or names is there (furniture that did not fit: larger rooms).
    std::vector<std::string> lacking = outcome.missing;
    // Exits beyond the asked count are the code's (count, width, travel distance), not a miss.
    const int exits_by_code = why.added_for_width + why.added_for_travel > 0
                                  ? count_feature(*world, Feature::kExit)
                                  : code_exits(report);
    for (auto& u : unmet(*world, wants, exits_by_code)) lacking.push_back(std::move(u));
    if (!lacking.empty()) {
      std::string what;
      for (const auto& l : lacking) what += (what.empty() ? "" : "; ") + l;
      tried.push_back("the request is not met: " + what);
      last_unmet = std::move(lacking);
      scale *= 1.15;
      continue;
    }
    if (!validated) {
      world = last.build(options.build, nullptr, &build_cache);
      if (!world) {
        tried.push_back("the world did not validate: " + world.error().message());
        last_error = world.error();
        continue;
      }
    }
    FloorPlan plan{std::move(*world), std::move(report), layout.graph(), Json::object()};
    Json notes = layout.notes();
    for (const auto& n : exit_notes) notes.push_back(n);
    const int asked = asked_exits(wants);
    Json exits = exit_provenance(plan.world, plan.compliance, wants, asked, why);
    if (asked > 0 || why.widened || why.added_for_width + why.added_for_travel > 0)
      notes.push_back(exits["text"]);
    for (const auto& n : outcome.notes) notes.push_back(n);
    plan.provenance = {
        {"generator", "offline"},    {"layout_family", std::string(family_name(layout.family()))},
        {"seed", options.seed},      {"domain", domain},
        {"attempts", attempt + 1},   {"notes", std::move(notes)},
        {"exits", std::move(exits)}, {"knowledge", knowledge_provenance(constraints)}};
    if (!wants.empty()) {
      Json met = Json::array();
      for (const auto& f : wants.features)
        met.push_back({{"feature", std::string(to_string(f.feature))},
                       {"asked", f.count},
                       {"at_least", f.at_least},
                       {"built", count_feature(plan.world, f.feature)}});
      plan.provenance["requirements"] = to_json(wants);
      plan.provenance["requirements_met"] = std::move(met);
    }
    return plan;
  }
  std::vector<FieldError> errors;
  if (last_report)
    for (const auto* c : last_report->failures())
      errors.push_back({"", c->name + " (" + c->ref_id + "): " + c->element + " has " +
                                (c->value ? std::to_string(*c->value) : std::string("nothing")) + " " +
                                c->unit + ", required " + std::to_string(c->required)});
  for (const auto& u : last_unmet) errors.push_back({"/requirements", u});
  if (last_error)
    for (const auto& e : last_error->errors) errors.push_back(e);
  std::string detail = "no compliant plan after " + std::to_string(attempts) + " attempts";
  if (!tried.empty()) detail += " (last: " + tried.back() + ")";
  return fail(ErrorCode::kValidation, detail, std::move(errors));
}

}  // namespace socsim::floorplan
