#include "core/household/house.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <queue>
#include <set>

#include "core/common/rng.hpp"

namespace socsim::household {
namespace {

struct Rect {
  double x0 = 0, z0 = 0, x1 = 0, z1 = 0;
  [[nodiscard]] double w() const { return x1 - x0; }
  [[nodiscard]] double d() const { return z1 - z0; }
};

double round_cm(double v) {
  return std::round(v * 100.0) / 100.0;
}

std::string fmt2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// Shared edge of two rectangles as a segment, when they touch along ≥ `min_len` metres.
std::optional<std::pair<FloorPoint, FloorPoint>> shared_edge(const Rect& a, const Rect& b, double min_len) {
  constexpr double eps = 1e-6;
  auto overlap = [&](double a0, double a1, double b0, double b1) {
    return std::pair{std::max(a0, b0), std::min(a1, b1)};
  };
  if (std::abs(a.x1 - b.x0) < eps || std::abs(b.x1 - a.x0) < eps) {
    const double x = std::abs(a.x1 - b.x0) < eps ? a.x1 : a.x0;
    auto [lo, hi] = overlap(a.z0, a.z1, b.z0, b.z1);
    if (hi - lo >= min_len) return std::pair{FloorPoint{x, lo}, FloorPoint{x, hi}};
  }
  if (std::abs(a.z1 - b.z0) < eps || std::abs(b.z1 - a.z0) < eps) {
    const double z = std::abs(a.z1 - b.z0) < eps ? a.z1 : a.z0;
    auto [lo, hi] = overlap(a.x0, a.x1, b.x0, b.x1);
    if (hi - lo >= min_len) return std::pair{FloorPoint{lo, z}, FloorPoint{hi, z}};
  }
  return std::nullopt;
}

void guillotine(const std::vector<int>& ids, const std::vector<double>& area, Rect r, std::vector<Rect>& out,
                Rng& rng) {
  if (ids.size() == 1) {
    out[static_cast<std::size_t>(ids[0])] = r;
    return;
  }
  double total = 0;
  for (int i : ids) total += area[static_cast<std::size_t>(i)];
  std::size_t best_k = 1;
  double best_diff = 1e18, acc = 0, best_acc = 0;
  for (std::size_t k = 1; k < ids.size(); ++k) {
    acc += area[static_cast<std::size_t>(ids[k - 1])];
    if (std::abs(acc - total / 2) < best_diff) {
      best_diff = std::abs(acc - total / 2);
      best_k = k;
      best_acc = acc;
    }
  }
  const double f = best_acc / total;
  std::vector<int> left(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(best_k));
  std::vector<int> right(ids.begin() + static_cast<std::ptrdiff_t>(best_k), ids.end());
  const bool across_x = (r.w() >= r.d()) != rng.chance(0.25);  // mostly cut the long side
  if (across_x) {
    const double cut = round_cm(r.x0 + f * r.w());
    guillotine(left, area, {r.x0, r.z0, cut, r.z1}, out, rng);
    guillotine(right, area, {cut, r.z0, r.x1, r.z1}, out, rng);
  } else {
    const double cut = round_cm(r.z0 + f * r.d());
    guillotine(left, area, {r.x0, r.z0, r.x1, cut}, out, rng);
    guillotine(right, area, {r.x0, cut, r.x1, r.z1}, out, rng);
  }
}

std::vector<RoomType> room_program(int n, std::optional<int> bedrooms, Rng& rng) {
  int bed = n <= 4   ? 1
            : n == 5 ? 2
            : n == 6 ? 2 + static_cast<int>(rng.chance(0.4))
            : n == 7 ? 3
            : n == 8 ? 3 + static_cast<int>(rng.chance(0.4))
            : n == 9 ? 4
                     : 4 + static_cast<int>(rng.chance(0.4));
  int bath = n < 3 ? 0 : n < 6 ? 1 : n < 10 ? 2 : 2 + static_cast<int>(rng.chance(0.4));
  const int kitchen = n >= 2 ? 1 : 0;
  if (bedrooms) bed = *bedrooms;
  int living = n - bed - bath - kitchen;
  while (living < (n >= 4 ? 1 : 0) && bath > (n >= 3 ? 1 : 0)) --bath, ++living;
  while (living < 0 && bath > 0) --bath, ++living;
  std::vector<RoomType> out;
  for (int i = 0; i < living; ++i) out.push_back(RoomType::kLivingRoom);
  for (int i = 0; i < kitchen; ++i) out.push_back(RoomType::kKitchen);
  for (int i = 0; i < bed; ++i) out.push_back(RoomType::kBedroom);
  for (int i = 0; i < bath; ++i) out.push_back(RoomType::kBathroom);
  return out;
}

std::string room_number(const Room& r) {
  const auto bar = r.id.find('|');
  return bar == std::string::npos ? r.id : r.id.substr(bar + 1);
}

}  // namespace

double polygon_area(const std::vector<FloorPoint>& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    s += a.x * b.z - b.x * a.z;
  }
  return std::abs(s) / 2.0;
}

bool point_in_polygon(const std::vector<FloorPoint>& p, double x, double z) {
  bool inside = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].z > z) != (p[j].z > z) && x < (p[j].x - p[i].x) * (z - p[i].z) / (p[j].z - p[i].z) + p[i].x)
      inside = !inside;
  }
  return inside;
}

FloorPoint local_to_world(const Entity& e, double lx, double lz) {
  const double yaw = e.rotation.y * std::numbers::pi / 180.0;
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {e.position.x + lx * c + lz * s, e.position.z - lx * s + lz * c};
}

Footprint footprint(const Entity& e) {
  const double hx = e.size_x / 2, hz = e.size_z / 2;
  return {local_to_world(e, -hx, -hz), local_to_world(e, hx, -hz), local_to_world(e, hx, hz),
          local_to_world(e, -hx, hz)};
}

bool footprints_overlap(const Footprint& a, const Footprint& b) {
  constexpr double eps = 1e-6;
  for (const Footprint* f : {&a, &b})
    for (std::size_t i = 0; i < 2; ++i) {
      const FloorPoint p = (*f)[i], q = (*f)[i + 1];
      const double ax = -(q.z - p.z), az = q.x - p.x;  // edge normal
      double amin = 1e18, amax = -1e18, bmin = 1e18, bmax = -1e18;
      for (const auto& v : a)
        amin = std::min(amin, v.x * ax + v.z * az), amax = std::max(amax, v.x * ax + v.z * az);
      for (const auto& v : b)
        bmin = std::min(bmin, v.x * ax + v.z * az), bmax = std::max(bmax, v.x * ax + v.z * az);
      const double len = std::hypot(ax, az);
      if (len < eps) continue;
      if (amax <= bmin + eps * len || bmax <= amin + eps * len) return false;
    }
  return true;
}

namespace {
bool segments_cross(FloorPoint a, FloorPoint b, FloorPoint c, FloorPoint d) {
  auto orient = [](FloorPoint p, FloorPoint q, FloorPoint r) {
    return (q.x - p.x) * (r.z - p.z) - (q.z - p.z) * (r.x - p.x);
  };
  const double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
  constexpr double eps = 1e-9;
  return ((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) &&
         ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps));
}
}  // namespace

bool footprint_inside(const std::vector<FloorPoint>& polygon, const Footprint& f) {
  for (const auto& c : f)
    if (!point_in_polygon(polygon, c.x, c.z)) return false;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    for (std::size_t j = 0; j < 4; ++j)
      if (segments_cross(polygon[i], polygon[(i + 1) % polygon.size()], f[j], f[(j + 1) % 4])) return false;
  return true;
}

std::vector<Footprint> door_clearances(const House& h, int room) {
  std::vector<Footprint> out;
  if (room < 0 || room >= static_cast<int>(h.rooms.size())) return out;
  const Room& r = h.rooms[static_cast<std::size_t>(room)];
  for (const auto& d : h.doors) {
    if (d.room0 != r.id && d.room1 != r.id) continue;
    const auto w =
        std::find_if(h.walls.begin(), h.walls.end(), [&](const Wall& x) { return x.id == d.wall0; });
    if (w == h.walls.end()) continue;
    const double len = std::hypot(w->b.x - w->a.x, w->b.z - w->a.z);
    if (len <= 0) continue;
    const double ux = (w->b.x - w->a.x) / len, uz = (w->b.z - w->a.z) / len;
    const double width = std::abs(d.hole_max.x - d.hole_min.x);
    const double lo = std::min(d.hole_min.x, d.hole_max.x) - 0.15,
                 hi = std::max(d.hole_min.x, d.hole_max.x) + 0.15;
    const FloorPoint p0{w->a.x + ux * lo, w->a.z + uz * lo}, p1{w->a.x + ux * hi, w->a.z + uz * hi};
    // The room's side of the wall: the normal whose probe point lies in the room.
    const double mid = (lo + hi) / 2;
    double nx = -uz, nz = ux;
    if (!point_in_polygon(r.floor, w->a.x + ux * mid + nx * 0.05, w->a.z + uz * mid + nz * 0.05))
      nx = -nx, nz = -nz;
    const double depth = width + 0.1;
    out.push_back({p0, p1, FloorPoint{p1.x + nx * depth, p1.z + nz * depth},
                   FloorPoint{p0.x + nx * depth, p0.z + nz * depth}});
  }
  return out;
}

int objects_with_children(const House& h) {
  int n = 0;
  for (const auto& e : h.entities) n += e.synthetic ? 0 : 1;
  return n;
}

std::pair<int, int> procthor_object_range(int rooms) {
  const double n = rooms;
  if (rooms <= 4)
    return {static_cast<int>(std::ceil(102.0 * n / 4)), static_cast<int>(std::floor(109.0 * n / 4))};
  return {static_cast<int>(std::ceil(102.0 + (124.0 - 102.0) * (n - 4) / 4)),
          static_cast<int>(std::floor(109.0 + (166.0 - 109.0) * (n - 4) / 4))};
}

void House::index() {
  receptacles.clear();
  objects.clear();
  for (std::size_t i = 0; i < entities.size(); ++i) {
    if (entities[i].kind == EntityKind::kReceptacle) receptacles.push_back(static_cast<int>(i));
    if (entities[i].kind == EntityKind::kObject) objects.push_back(static_cast<int>(i));
  }
}

int House::room_index(std::string_view room_id) const {
  for (std::size_t i = 0; i < rooms.size(); ++i)
    if (rooms[i].id == room_id) return static_cast<int>(i);
  return -1;
}

int House::room_at(double x, double z) const {
  for (std::size_t i = 0; i < rooms.size(); ++i)
    if (point_in_polygon(rooms[i].floor, x, z)) return static_cast<int>(i);
  return -1;
}

std::vector<int> House::rooms_of(RoomType type) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < rooms.size(); ++i)
    if (rooms[i].type == type) out.push_back(static_cast<int>(i));
  return out;
}

std::vector<std::pair<int, int>> House::room_links() const {
  std::vector<std::pair<int, int>> links;
  for (const auto& d : doors) {
    const int a = room_index(d.room0), b = room_index(d.room1);
    if (a >= 0 && b >= 0 && a != b) links.emplace_back(std::min(a, b), std::max(a, b));
  }
  // Open walls: two rooms' walls over the same segment, both marked empty.
  for (std::size_t i = 0; i < walls.size(); ++i) {
    if (!walls[i].empty) continue;
    for (std::size_t j = i + 1; j < walls.size(); ++j) {
      if (!walls[j].empty || walls[j].room_id == walls[i].room_id) continue;
      const bool same = (walls[i].a == walls[j].a && walls[i].b == walls[j].b) ||
                        (walls[i].a == walls[j].b && walls[i].b == walls[j].a);
      const int a = room_index(walls[i].room_id), b = room_index(walls[j].room_id);
      if (same && a >= 0 && b >= 0) links.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  return links;
}

bool House::connected() const {
  if (rooms.empty()) return false;
  std::vector<std::vector<int>> adj(rooms.size());
  for (auto [a, b] : room_links()) {
    adj[static_cast<std::size_t>(a)].push_back(b);
    adj[static_cast<std::size_t>(b)].push_back(a);
  }
  std::vector<bool> seen(rooms.size(), false);
  std::vector<int> stack = {0};
  seen[0] = true;
  std::size_t count = 1;
  while (!stack.empty()) {
    const int r = stack.back();
    stack.pop_back();
    for (int n : adj[static_cast<std::size_t>(r)])
      if (!seen[static_cast<std::size_t>(n)]) {
        seen[static_cast<std::size_t>(n)] = true;
        ++count;
        stack.push_back(n);
      }
  }
  return count == rooms.size();
}

Result<House> generate_house(const HouseRequest& req, const HouseholdKnowledge& k) {
  if (req.rooms < 1 || req.rooms > 10)
    return fail(ErrorCode::kValidation, "a house has 1 to 10 rooms",
                {FieldError{"/rooms", "must be between 1 and 10"}});
  if (req.bedrooms && (*req.bedrooms < 1 || *req.bedrooms > req.rooms - (req.rooms >= 2 ? 1 : 0)))
    return fail(ErrorCode::kValidation, "bedrooms do not fit the rooms",
                {FieldError{"/bedrooms", "must be between 1 and rooms − 1 (the kitchen)"}});
  Rng rng(req.seed, fnv1a64("house"));
  const auto types = room_program(req.rooms, req.bedrooms, rng);
  const std::size_t n = types.size();
  std::vector<double> area(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& prog = k.room_programs[index_of(types[i])];
    area[i] = rng.uniform(prog.min_area, prog.max_area);
  }
  double total = 0;
  for (double a : area) total += a;

  // Layout: retry the order until rooms are well shaped and the shared walls connect them all.
  std::vector<Rect> rects(n);
  std::vector<std::vector<std::pair<std::size_t, std::pair<FloorPoint, FloorPoint>>>> adj;
  bool ok = false;
  for (int attempt = 0; attempt < 300 && !ok; ++attempt) {
    if (attempt > 0 && attempt % 20 == 0) {  // this set of sizes does not pack well: draw new ones
      total = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto& prog = k.room_programs[index_of(types[i])];
        area[i] = rng.uniform(prog.min_area, prog.max_area);
        total += area[i];
      }
    }
    std::vector<int> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
    rng.shuffle(order);
    const double aspect = rng.uniform(1.0, 1.6);
    const double width = round_cm(std::sqrt(total * aspect)), depth = round_cm(total / width);
    guillotine(order, area, {0, 0, width, depth}, rects, rng);
    ok = true;
    for (const auto& r : rects)
      ok = ok && std::min(r.w(), r.d()) >= 1.9 && std::max(r.w(), r.d()) / std::min(r.w(), r.d()) <= 3.2;
    adj.assign(n, {});
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (auto e = shared_edge(rects[i], rects[j], 1.0)) {
          adj[i].push_back({j, *e});
          adj[j].push_back({i, *e});
        }
    // Connected?
    std::vector<bool> seen(n, false);
    std::vector<std::size_t> st = {0};
    seen[0] = true;
    std::size_t c = 1;
    while (!st.empty()) {
      auto r = st.back();
      st.pop_back();
      for (auto& [m, e] : adj[r])
        if (!seen[m]) seen[m] = true, ++c, st.push_back(m);
    }
    ok = ok && c == n;
  }
  if (!ok)
    return fail(ErrorCode::kInternal,
                "could not lay out " + std::to_string(n) + " rooms (seed " + std::to_string(req.seed) + ")");

  House h;
  h.id = "house-" + std::to_string(req.seed) + "-" + std::to_string(req.rooms);
  for (std::size_t i = 0; i < n; ++i) {
    Room r;
    r.id = "room|" + std::to_string(i + 2);
    r.type = types[i];
    const Rect& q = rects[i];
    r.floor = {{q.x0, q.z0}, {q.x0, q.z1}, {q.x1, q.z1}, {q.x1, q.z0}};
    h.rooms.push_back(std::move(r));
  }
  h.metadata = {{"schema", "1.0.0"}, {"generator", "socsim offline"}, {"seed", req.seed}};

  // Walls: each room edge split wherever another room's corner lies on it.
  constexpr double kHeight = 2.6;
  std::map<std::pair<std::size_t, int>, std::vector<std::pair<FloorPoint, FloorPoint>>>
      segments;  // (room, edge) → segments
  for (std::size_t i = 0; i < n; ++i) {
    const auto& f = h.rooms[i].floor;
    for (int e = 0; e < 4; ++e) {
      const FloorPoint a = f[static_cast<std::size_t>(e)], b = f[static_cast<std::size_t>((e + 1) % 4)];
      const bool vertical = std::abs(a.x - b.x) < 1e-9;
      std::set<double> cuts = {vertical ? a.z : a.x, vertical ? b.z : b.x};
      for (std::size_t j = 0; j < n; ++j)
        for (const auto& p : h.rooms[j].floor) {
          const double along = vertical ? p.z : p.x, across = vertical ? p.x : p.z,
                       line = vertical ? a.x : a.z;
          if (std::abs(across - line) < 1e-9 &&
              along > std::min(vertical ? a.z : a.x, vertical ? b.z : b.x) &&
              along < std::max(vertical ? a.z : a.x, vertical ? b.z : b.x))
            cuts.insert(along);
        }
      std::vector<double> cv(cuts.begin(), cuts.end());
      const bool forward = vertical ? b.z > a.z : b.x > a.x;
      if (!forward) std::reverse(cv.begin(), cv.end());
      for (std::size_t c = 0; c + 1 < cv.size(); ++c) {
        FloorPoint p0 = vertical ? FloorPoint{a.x, cv[c]} : FloorPoint{cv[c], a.z};
        FloorPoint p1 = vertical ? FloorPoint{a.x, cv[c + 1]} : FloorPoint{cv[c + 1], a.z};
        segments[{i, e}].push_back({p0, p1});
      }
    }
  }
  auto wall_id = [](const std::string& owner, FloorPoint p0, FloorPoint p1) {
    if (p1.x < p0.x || (p1.x == p0.x && p1.z < p0.z)) std::swap(p0, p1);
    return "wall|" + owner + "|" + fmt2(p0.x) + "|" + fmt2(p0.z) + "|" + fmt2(p1.x) + "|" + fmt2(p1.z);
  };
  auto on_segment = [](FloorPoint p, FloorPoint a, FloorPoint b) {
    const double cross = (b.x - a.x) * (p.z - a.z) - (b.z - a.z) * (p.x - a.x);
    return std::abs(cross) < 1e-6 && p.x >= std::min(a.x, b.x) - 1e-9 && p.x <= std::max(a.x, b.x) + 1e-9 &&
           p.z >= std::min(a.z, b.z) - 1e-9 && p.z <= std::max(a.z, b.z) + 1e-9;
  };
  std::vector<Wall> exterior;
  for (const auto& [key, segs] : segments) {
    const Room& room = h.rooms[key.first];
    for (const auto& [p0, p1] : segs) {
      h.walls.push_back(
          {wall_id(room_number(room), p0, p1), room.id, p0, p1, kHeight, false, Json::object()});
      const FloorPoint mid{(p0.x + p1.x) / 2, (p0.z + p1.z) / 2};
      bool shared = false;
      for (std::size_t j = 0; j < n && !shared; ++j) {
        if (j == key.first) continue;
        const auto& f = h.rooms[j].floor;
        for (std::size_t e = 0; e < 4 && !shared; ++e) shared = on_segment(mid, f[e], f[(e + 1) % 4]);
      }
      if (!shared)
        exterior.push_back({wall_id("exterior", p0, p1), room.id, p1, p0, kHeight, false, Json::object()});
    }
  }
  h.walls.insert(h.walls.end(), exterior.begin(), exterior.end());
  auto find_wall = [&](const std::string& room_id, FloorPoint a, FloorPoint b, bool ext) -> const Wall* {
    const FloorPoint mid{(a.x + b.x) / 2, (a.z + b.z) / 2};
    for (const auto& w : h.walls) {
      if (w.room_id != room_id || (w.id.find("|exterior|") != std::string::npos) != ext) continue;
      if (on_segment(mid, w.a, w.b)) return &w;
    }
    return nullptr;
  };

  // Doors: a spanning tree grown from the hub, private rooms reached last.
  std::size_t hub = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (types[i] == RoomType::kLivingRoom) {
      hub = i;
      break;
    } else if (types[i] == RoomType::kKitchen && types[hub] != RoomType::kKitchen) {
      hub = i;
    }
  auto is_private = [&](std::size_t r) {
    return types[r] == RoomType::kBedroom || types[r] == RoomType::kBathroom;
  };
  using Edge = std::tuple<double, std::size_t, std::size_t>;
  std::priority_queue<Edge, std::vector<Edge>, std::greater<>> frontier;
  std::vector<bool> in(n, false);
  in[hub] = true;
  auto push_edges = [&](std::size_t r) {
    for (auto& [m, e] : adj[r])
      if (!in[m]) frontier.push({(is_private(r) ? 10.0 : 0.0) + rng.uniform(), r, m});
  };
  push_edges(hub);
  auto add_door = [&](std::size_t r0, std::size_t r1, FloorPoint a, FloorPoint b) {
    const Room& ra = h.rooms[r0];
    const Room& rb = h.rooms[r1];
    // The longest piece of r0's wall inside the shared edge (corners of other rooms may split it).
    const Wall* w0 = nullptr;
    double longest = 0.0;
    for (const auto& w : h.walls) {
      if (w.room_id != ra.id || w.id.find("|exterior|") != std::string::npos) continue;
      if (!on_segment(w.a, a, b) || !on_segment(w.b, a, b)) continue;
      const double l = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
      if (l > longest) longest = l, w0 = &w;
    }
    if (!w0) return;
    const Wall* w1 = r0 == r1 ? find_wall(ra.id, w0->a, w0->b, true) : find_wall(rb.id, w0->a, w0->b, false);
    if (!w1 || longest < 0.8) return;
    const double len = std::hypot(w0->b.x - w0->a.x, w0->b.z - w0->a.z);
    const double width = std::min(0.9, len - 0.2);
    const double start = round_cm((len - width) / 2);
    Door d;
    d.id = "door|" + room_number(ra) + "|" + room_number(rb);
    d.room0 = ra.id;
    d.room1 = rb.id;
    d.wall0 = w0->id;
    d.wall1 = w1->id;
    d.asset_id = "socsim/Doorway";
    d.hole_min = {start, 0, 0};
    d.hole_max = {round_cm(start + width), 2.1, 0};
    d.asset_position = {round_cm(start + width / 2), 1.05, 0};
    h.doors.push_back(std::move(d));
  };
  while (!frontier.empty()) {
    auto [cost, from, to] = frontier.top();
    frontier.pop();
    if (in[to]) continue;
    in[to] = true;
    for (auto& [m, e] : adj[from])
      if (m == to) add_door(from, to, e.first, e.second);
    push_edges(to);
  }
  // Front door on the longest outside wall of the hub, else of another public room, else of any room.
  {
    std::vector<std::size_t> candidates = {hub};
    for (std::size_t i = 0; i < n; ++i)
      if (i != hub && !is_private(i)) candidates.push_back(i);
    for (std::size_t i = 0; i < n; ++i)
      if (i != hub && is_private(i)) candidates.push_back(i);
    const std::size_t doors_before = h.doors.size();
    for (std::size_t c : candidates) {
      const Wall* best = nullptr;
      double best_len = 1.2;
      for (const auto& w : h.walls)
        if (w.room_id == h.rooms[c].id && w.id.find("|exterior|") != std::string::npos) {
          const double len = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
          if (len > best_len) best_len = len, best = &w;
        }
      if (best) add_door(c, c, best->a, best->b);
      if (h.doors.size() > doors_before) break;
    }
  }

  // Windows: on outside walls long enough, away from the front door; at least one per house.
  {
    int windows = 0;
    std::vector<std::pair<const Wall*, const Wall*>> candidates;  // (inside, outside) faces
    auto add_window = [&](const Room& room, const Wall& inside, const Wall& outside, int attempts) {
      const double len = std::hypot(inside.b.x - inside.a.x, inside.b.z - inside.a.z);
      double door_lo = 1e18, door_hi = -1e18;
      for (const auto& d : h.doors)
        if (d.wall0 == inside.id) door_lo = d.hole_min.x - 0.3, door_hi = d.hole_max.x + 0.3;
      for (int attempt = 0; attempt < attempts; ++attempt) {
        const double width = round_cm(rng.uniform(0.8, std::min(1.6, len - 0.6)));
        const double start = round_cm(rng.uniform(0.3, len - 0.3 - width));
        if (start < door_hi && start + width > door_lo) continue;
        const double sill = rng.chance(0.5) ? 0.9 : 1.0;
        h.windows.push_back(
            {{"id", "window|" + room_number(room) + "|" + std::to_string(windows)},
             {"assetId", "socsim/Window"},
             {"room0", room.id},
             {"room1", room.id},
             {"wall0", inside.id},
             {"wall1", outside.id},
             {"holePolygon", Json::array({{{"x", start}, {"y", sill}, {"z", 0}},
                                          {{"x", round_cm(start + width)}, {"y", 2.1}, {"z", 0}}})},
             {"assetPosition", {{"x", round_cm(start + width / 2)}, {"y", (sill + 2.1) / 2}, {"z", 0}}}});
        ++windows;
        return true;
      }
      return false;
    };
    for (std::size_t i = 0; i < n; ++i) {
      int in_room = 0;
      for (const auto& w : h.walls) {
        if (w.room_id != h.rooms[i].id || w.id.find("|exterior|") == std::string::npos) continue;
        const Wall* inside = find_wall(h.rooms[i].id, w.a, w.b, false);
        const double len = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
        if (!inside || len < 1.5) continue;
        candidates.emplace_back(inside, &w);
        if (in_room < 2 && rng.chance(0.6)) in_room += add_window(h.rooms[i], *inside, w, 4) ? 1 : 0;
      }
    }
    for (std::size_t c = 0; c < candidates.size() && windows == 0; ++c) {
      const Room& room = h.rooms[static_cast<std::size_t>(h.room_index(candidates[c].first->room_id))];
      add_window(room, *candidates[c].first, *candidates[c].second, 16);
    }
  }

  // Furniture: footprints (local size turned by yaw) inside the room, clear of door swings, with
  // 0.5 m of free floor between pieces so every piece stays reachable.
  auto place_on_top = [&](const Entity& rec, double height, double margin) {
    const double hx = std::max(0.0, rec.size_x / 2 - margin), hz = std::max(0.0, rec.size_z / 2 - margin);
    const FloorPoint p = local_to_world(rec, rng.uniform(-hx, hx), rng.uniform(-hz, hz));
    return Vec3{round_cm(p.x), round_cm(height), round_cm(p.z)};
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Room& room = h.rooms[i];
    const Rect& q = rects[i];
    const auto& prog = k.room_programs[index_of(room.type)];
    const std::vector<Footprint> blocked = door_clearances(h, static_cast<int>(i));
    std::vector<Footprint> halos;  // placed pieces grown by 0.25 m each side
    int counter = 0;
    for (const auto& rule : prog.furniture) {
      const auto* spec = k.receptacle(rule.type);
      if (!spec || !rng.chance(rule.p)) continue;
      const int count = rule.max_count <= 1 ? 1 : static_cast<int>(rng.between(1, rule.max_count));
      for (int c = 0; c < count; ++c) {
        bool placed = false;
        for (int attempt = 0; attempt < 24 && !placed; ++attempt) {
          Entity e;
          e.size_x = spec->size_x;
          e.size_z = spec->size_z;
          double cx, cz, yaw;
          if (spec->middle) {
            yaw = (attempt % 2) * 90.0;
            const double ex = yaw == 0 ? e.size_x : e.size_z, ez = yaw == 0 ? e.size_z : e.size_x;
            cx = rng.uniform(q.x0 + 0.6 + ex / 2, q.x1 - 0.6 - ex / 2);
            cz = rng.uniform(q.z0 + 0.6 + ez / 2, q.z1 - 0.6 - ez / 2);
            if (attempt < 4) cx = (q.x0 + q.x1) / 2, cz = (q.z0 + q.z1) / 2 + (attempt - 1.5) * 0.6;
          } else {
            // Back to the wall, facing into the room: side 0 is the z0 wall (yaw 0 faces +z).
            const int side = static_cast<int>(rng.below(4));
            yaw = side * 90.0;
            const double ex = side % 2 == 0 ? e.size_x : e.size_z, ez = side % 2 == 0 ? e.size_z : e.size_x;
            if (side % 2 == 0) {
              cx = rng.uniform(q.x0 + ex / 2 + 0.05, q.x1 - ex / 2 - 0.05);
              cz = side == 0 ? q.z0 + ez / 2 + 0.02 : q.z1 - ez / 2 - 0.02;
            } else {
              cz = rng.uniform(q.z0 + ez / 2 + 0.05, q.z1 - ez / 2 - 0.05);
              cx = side == 1 ? q.x0 + ex / 2 + 0.02 : q.x1 - ex / 2 - 0.02;
            }
          }
          e.position = {round_cm(cx), round_cm(spec->height / 2), round_cm(cz)};
          e.rotation = {0, yaw, 0};
          const Footprint fp = footprint(e);
          if (!footprint_inside(room.floor, fp)) continue;
          bool clash = false;
          for (const auto& b : blocked) clash = clash || footprints_overlap(fp, b);
          for (const auto& t : halos) clash = clash || footprints_overlap(fp, t);
          if (clash) continue;
          Entity halo = e;
          halo.size_x += 0.5;
          halo.size_z += 0.5;
          halos.push_back(footprint(halo));
          e.kind = EntityKind::kReceptacle;
          e.type = spec->type;
          e.id = spec->type + "|" + room_number(room) + "|" + std::to_string(counter++);
          e.asset_id = "socsim/" + spec->type;
          e.room = static_cast<int>(i);
          h.entities.push_back(std::move(e));
          placed = true;
        }
      }
    }
  }
  const std::size_t furniture = h.entities.size();

  // Fixtures: hung on the room's inside walls (away from doors and windows) or standing on a
  // receptacle of the named type (one fixture per receptacle).
  std::vector<bool> carries_fixture(furniture, false);
  for (std::size_t i = 0; i < n; ++i) {
    const Room& room = h.rooms[i];
    const auto& prog = k.room_programs[index_of(room.type)];
    std::vector<const Wall*> room_walls;
    for (const auto& w : h.walls)
      if (w.room_id == room.id && w.id.find("|exterior|") == std::string::npos &&
          std::hypot(w.b.x - w.a.x, w.b.z - w.a.z) >= 1.2)
        room_walls.push_back(&w);
    // Centres of every door and window (world coordinates, from the wall their hole is measured
    // on): hung fixtures keep 1 m from them, on either side of the wall.
    std::vector<FloorPoint> openings;
    auto centre_on = [&](const std::string& on_wall, double along) {
      for (const auto& w : h.walls)
        if (w.id == on_wall) {
          const double len = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
          if (len > 0)
            openings.push_back(
                {w.a.x + (w.b.x - w.a.x) * along / len, w.a.z + (w.b.z - w.a.z) * along / len});
          return;
        }
    };
    for (const auto& d : h.doors) centre_on(d.wall0, (d.hole_min.x + d.hole_max.x) / 2);
    for (const auto& win : h.windows)
      centre_on(win["wall0"].get<std::string>(), win["assetPosition"]["x"].get<double>());
    std::map<std::string, int> counters;
    for (const auto& rule : prog.fixtures) {
      if (!rng.chance(rule.p)) continue;
      const int count = rule.max_count <= 1 ? 1 : static_cast<int>(rng.between(1, rule.max_count));
      for (int c = 0; c < count; ++c) {
        Entity f;
        f.kind = EntityKind::kFixture;
        f.type = rule.type;
        f.asset_id = "socsim/" + rule.type;
        f.room = static_cast<int>(i);
        f.size_x = 0.1;
        f.size_z = 0.1;
        bool placed = false;
        if (rule.on == "wall") {
          for (int attempt = 0; attempt < 8 && !placed && !room_walls.empty(); ++attempt) {
            const Wall& w = *room_walls[rng.below(static_cast<std::uint32_t>(room_walls.size()))];
            const double len = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
            const double ux = (w.b.x - w.a.x) / len, uz = (w.b.z - w.a.z) / len;
            const double t = rng.uniform(0.4, len - 0.4);
            FloorPoint p{w.a.x + ux * t, w.a.z + uz * t};
            bool near = false;
            for (const auto& o : openings) near = near || std::hypot(o.x - p.x, o.z - p.z) < 1.0;
            if (near) continue;
            double nx = -uz, nz = ux;
            if (!point_in_polygon(room.floor, p.x + nx * 0.05, p.z + nz * 0.05)) nx = -nx, nz = -nz;
            openings.push_back(p);  // keep the next fixture on this wall apart from this one
            f.position = {round_cm(p.x + nx * 0.03), rule.type == "LightSwitch" ? 1.2 : 1.5,
                          round_cm(p.z + nz * 0.03)};
            // Facing into the room: yaw whose forward (sin, cos) is the inward normal.
            f.rotation = {0, std::fmod(std::atan2(nx, nz) * 180.0 / std::numbers::pi + 360.0, 360.0), 0};
            f.size_x = rule.type == "LightSwitch" ? 0.1 : rule.type == "Mirror" ? 0.7 : 0.6;
            f.size_z = 0.04;
            placed = true;
          }
        } else {
          std::vector<std::size_t> hosts;
          for (std::size_t r = 0; r < furniture; ++r)
            if (h.entities[r].room == static_cast<int>(i) && h.entities[r].type == rule.on &&
                !carries_fixture[r])
              hosts.push_back(r);
          if (!hosts.empty()) {
            const std::size_t r = hosts[rng.below(static_cast<std::uint32_t>(hosts.size()))];
            carries_fixture[r] = true;
            const Entity& rec = h.entities[r];
            const auto* spec = k.receptacle(rec.type);
            f.parent = static_cast<int>(r);
            f.position = place_on_top(rec, spec->height + 0.15, 0.15);
            f.rotation = rec.rotation;
            f.size_x = f.size_z = 0.25;
            placed = true;
          }
        }
        if (!placed) continue;
        f.id = rule.type + "|" + room_number(room) + "|" + std::to_string(counters[rule.type]++);
        h.entities.push_back(std::move(f));
      }
    }
  }

  // Movable objects on receptacle tops (appended after furniture; parents come first): as many as
  // bring the house to a count drawn inside ProcTHOR's range for its size, spread over the
  // receptacles by their usual load and capped by their top area.
  const auto [lo, hi] = procthor_object_range(static_cast<int>(n));
  const int target = static_cast<int>(rng.between(lo, hi));
  const int wanted = std::max(0, target - static_cast<int>(h.entities.size()));
  std::vector<std::size_t> hosts;
  std::vector<double> load;
  std::vector<int> capacity;
  int total_capacity = 0;
  for (std::size_t r = 0; r < furniture; ++r) {
    const auto* spec = k.receptacle(h.entities[r].type);
    if (!spec || spec->contents.empty() || spec->mean_objects <= 0) continue;
    hosts.push_back(r);
    load.push_back(spec->mean_objects);
    capacity.push_back(std::max(1, static_cast<int>(h.entities[r].size_x * h.entities[r].size_z / 0.06)));
    total_capacity += capacity.back();
  }
  if (!hosts.empty())
    while (total_capacity < wanted) {  // small houses with few surfaces: allow denser tops
      total_capacity = 0;
      for (auto& c : capacity) c *= 2, total_capacity += c;
    }
  std::map<int, int> per_room_counter;
  for (int c = 0; c < wanted && !hosts.empty(); ++c) {
    std::vector<double> w(hosts.size());
    for (std::size_t j = 0; j < hosts.size(); ++j) w[j] = capacity[j] > 0 ? load[j] : 0.0;
    const std::size_t j = rng.weighted(w);
    --capacity[j];
    const Entity& rec = h.entities[hosts[j]];
    const auto* spec = k.receptacle(rec.type);
    std::vector<double> cw;
    for (const auto& [t, x] : spec->contents) cw.push_back(x);
    const auto& type = spec->contents[rng.weighted(cw)].first;
    Entity o;
    o.kind = EntityKind::kObject;
    o.type = type;
    o.id = type + "|surface|" + room_number(h.rooms[static_cast<std::size_t>(rec.room)]) + "|" +
           std::to_string(per_room_counter[rec.room]++);
    o.asset_id = "socsim/" + type;
    o.room = rec.room;
    o.parent = static_cast<int>(hosts[j]);
    o.position = place_on_top(rec, spec->height + 0.05, 0.08);
    o.size_x = o.size_z = 0.15;
    h.entities.push_back(std::move(o));
  }
  h.index();
  if (!h.connected()) return fail(ErrorCode::kInternal, "generated house " + h.id + " has unreachable rooms");
  return h;
}

}  // namespace socsim::household
