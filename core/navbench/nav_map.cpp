#include "core/navbench/nav_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace socsim::navbench {
namespace {

using household::FloorPoint;
using household::House;

constexpr int kDx[kHeadings] = {1, 0, -1, 0};
constexpr int kDz[kHeadings] = {0, 1, 0, -1};
constexpr double kEps = 1e-12;
constexpr std::int64_t kMaxCells = 4'000'000;

double cross(FloorPoint o, FloorPoint a, FloorPoint b) {
  return (a.x - o.x) * (b.z - o.z) - (a.z - o.z) * (b.x - o.x);
}

bool within_box(FloorPoint p, FloorPoint a, FloorPoint b) {
  return p.x >= std::min(a.x, b.x) - 1e-12 && p.x <= std::max(a.x, b.x) + 1e-12 &&
         p.z >= std::min(a.z, b.z) - 1e-12 && p.z <= std::max(a.z, b.z) + 1e-12;
}

double distance_to_segment(FloorPoint p, FloorPoint a, FloorPoint b) {
  const double dx = b.x - a.x, dz = b.z - a.z;
  const double len2 = dx * dx + dz * dz;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.z - a.z) * dz) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.z - (a.z + t * dz));
}

// Walls minus door openings; open walls (`empty`) are left out entirely.
std::vector<WallPiece> solid_walls(const House& house) {
  std::unordered_map<std::string, const household::Wall*> by_id;
  for (const auto& w : house.walls) by_id.emplace(w.id, &w);
  std::vector<std::pair<FloorPoint, FloorPoint>> openings;
  for (const auto& d : house.doors) {
    auto it = by_id.find(d.wall0);
    if (it == by_id.end()) it = by_id.find(d.wall1);
    if (it == by_id.end()) continue;
    const auto& w = *it->second;
    const double len = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
    if (len <= 0) continue;
    const double ux = (w.b.x - w.a.x) / len, uz = (w.b.z - w.a.z) / len;
    openings.push_back({{w.a.x + ux * d.hole_min.x, w.a.z + uz * d.hole_min.x},
                        {w.a.x + ux * d.hole_max.x, w.a.z + uz * d.hole_max.x}});
  }
  std::vector<WallPiece> out;
  for (const auto& w : house.walls) {
    if (w.empty) continue;
    const double len = std::hypot(w.b.x - w.a.x, w.b.z - w.a.z);
    if (len <= 1e-9) continue;
    const double ux = (w.b.x - w.a.x) / len, uz = (w.b.z - w.a.z) / len;
    std::vector<std::pair<double, double>> solid = {{0.0, len}};
    for (const auto& [p0, p1] : openings) {
      if (std::abs(cross(w.a, w.b, p0)) / len > 1e-3 || std::abs(cross(w.a, w.b, p1)) / len > 1e-3) continue;
      const double t0 = (p0.x - w.a.x) * ux + (p0.z - w.a.z) * uz,
                   t1 = (p1.x - w.a.x) * ux + (p1.z - w.a.z) * uz;
      const double lo = std::min(t0, t1), hi = std::max(t0, t1);
      std::vector<std::pair<double, double>> next;
      for (auto [s, e] : solid) {
        if (hi <= s || lo >= e) {
          next.emplace_back(s, e);
          continue;
        }
        if (lo > s) next.emplace_back(s, lo);
        if (hi < e) next.emplace_back(hi, e);
      }
      solid = std::move(next);
    }
    for (auto [s, e] : solid)
      if (e - s > 1e-6) out.push_back({{w.a.x + ux * s, w.a.z + uz * s}, {w.a.x + ux * e, w.a.z + uz * e}});
  }
  return out;
}

}  // namespace

bool segments_touch(FloorPoint a, FloorPoint b, FloorPoint c, FloorPoint d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  const bool straddle_ab = (d1 > kEps && d2 < -kEps) || (d1 < -kEps && d2 > kEps);
  const bool straddle_cd = (d3 > kEps && d4 < -kEps) || (d3 < -kEps && d4 > kEps);
  if (straddle_ab && straddle_cd) return true;
  if (std::abs(d1) <= kEps && within_box(a, c, d)) return true;
  if (std::abs(d2) <= kEps && within_box(b, c, d)) return true;
  if (std::abs(d3) <= kEps && within_box(c, a, b)) return true;
  if (std::abs(d4) <= kEps && within_box(d, a, b)) return true;
  return false;
}

std::vector<int> StepField::path_to(int pose) const {
  std::vector<int> path;
  if (pose < 0 || distance[static_cast<std::size_t>(pose)] < 0) return path;
  for (int p = pose; parent[static_cast<std::size_t>(p)] >= 0; p = parent[static_cast<std::size_t>(p)])
    path.push_back(p);
  std::reverse(path.begin(), path.end());
  return path;
}

int StepField::nearest(std::span<const int> poses) const {
  int best = -1, best_d = 0;
  for (int p : poses) {
    const int d = distance[static_cast<std::size_t>(p)];
    if (d < 0) continue;
    if (best < 0 || d < best_d || (d == best_d && p < best)) best = p, best_d = d;
  }
  return best;
}

int NavMap::free_cells() const {
  return static_cast<int>(std::count(free_.begin(), free_.end(), std::uint8_t{1}));
}

FloorPoint NavMap::center(int cell) const {
  return {origin_x_ + (cell % width_ + 0.5) * config_.cell, origin_z_ + (cell / width_ + 0.5) * config_.cell};
}

int NavMap::ahead(int cell, int heading) const {
  if ((moves_[static_cast<std::size_t>(cell)] >> heading & 1u) == 0) return -1;
  return cell + kDx[heading] + kDz[heading] * width_;
}

int NavMap::act(int pose, int action) const {
  const int cell = cell_of(pose), h = heading_of(pose);
  if (action == 1) return pose_of(cell, (h + 1) % kHeadings);
  if (action == 2) return pose_of(cell, (h + kHeadings - 1) % kHeadings);
  const int next = ahead(cell, h);
  return next < 0 ? pose : pose_of(next, h);
}

bool NavMap::line_of_sight(FloorPoint a, FloorPoint b) const {
  for (const auto& w : walls_)
    if (segments_touch(a, b, w.a, w.b)) return false;
  return true;
}

bool NavMap::sees(int pose, FloorPoint target) const {
  const FloorPoint from = center(cell_of(pose));
  const double vx = target.x - from.x, vz = target.z - from.z;
  const double dist = std::hypot(vx, vz);
  if (dist > config_.view_distance + 1e-9) return false;
  if (dist > 1e-9) {
    const int h = heading_of(pose);
    const double cos_angle = (vx * kDx[h] + vz * kDz[h]) / dist;
    if (cos_angle < std::cos(config_.field_of_view_deg / 2.0 * std::numbers::pi / 180.0) - 1e-9) return false;
  }
  return line_of_sight(from, target);
}

std::span<const int> NavMap::visible_from(int pose) const {
  const auto p = static_cast<std::size_t>(pose);
  return {visible_.data() + visible_offsets_[p], visible_offsets_[p + 1] - visible_offsets_[p]};
}

int NavMap::receptacle_of_entity(int entity) const {
  for (std::size_t i = 0; i < receptacles_.size(); ++i)
    if (receptacles_[i].entity == entity) return static_cast<int>(i);
  return -1;
}

StepField NavMap::steps_from(int pose) const {
  StepField f;
  f.distance.assign(static_cast<std::size_t>(poses()), -1);
  f.parent.assign(static_cast<std::size_t>(poses()), -1);
  if (pose < 0 || pose >= poses() || !free(cell_of(pose))) return f;
  std::vector<int> queue;
  queue.reserve(static_cast<std::size_t>(poses()));
  queue.push_back(pose);
  f.distance[static_cast<std::size_t>(pose)] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int p = queue[head];
    const int d = f.distance[static_cast<std::size_t>(p)];
    for (int action = 0; action < 3; ++action) {
      const int q = act(p, action);
      if (q == p || f.distance[static_cast<std::size_t>(q)] >= 0) continue;
      f.distance[static_cast<std::size_t>(q)] = d + 1;
      f.parent[static_cast<std::size_t>(q)] = p;
      queue.push_back(q);
    }
  }
  return f;
}

std::vector<household::FloorPoint> top_grid(const household::Footprint& c, double spacing) {
  const double ux = c[1].x - c[0].x, uz = c[1].z - c[0].z, vx = c[3].x - c[0].x, vz = c[3].z - c[0].z;
  const double lu = std::hypot(ux, uz), lv = std::hypot(vx, vz);
  if (!(lu > 0.0) || !(lv > 0.0)) return {};
  const double mu = std::min(0.5, kTopMargin / lu), mv = std::min(0.5, kTopMargin / lv);
  const int nu = std::max(1, static_cast<int>(std::ceil((1.0 - 2.0 * mu) * lu / spacing - 1e-9)));
  const int nv = std::max(1, static_cast<int>(std::ceil((1.0 - 2.0 * mv) * lv / spacing - 1e-9)));
  std::vector<household::FloorPoint> out;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double a = mu + (1.0 - 2.0 * mu) * (i + 0.5) / nu, b = mv + (1.0 - 2.0 * mv) * (j + 0.5) / nv;
      out.push_back({c[0].x + a * ux + b * vx, c[0].z + a * uz + b * vz});
    }
  return out;
}

// Whether another piece rises above the sight line from the camera at `from` to a point at height
// `top` over `to`: the segment is clipped to each footprint (Cyrus–Beck); the line is lowest where
// it leaves the footprint on the target's side.
bool NavMap::occluded(FloorPoint from, FloorPoint to, double top, int self,
                      std::span<const FurnitureBox* const> near) const {
  const double dx = to.x - from.x, dz = to.z - from.z;
  for (const FurnitureBox* b : near) {
    if (b->entity == self || b->height <= top) continue;
    if (std::max(from.x, to.x) < b->x0 || std::min(from.x, to.x) > b->x1 || std::max(from.z, to.z) < b->z0 ||
        std::min(from.z, to.z) > b->z1)
      continue;
    double t0 = 0.0, t1 = 1.0;
    const auto& c = b->corners;
    const double orient = cross(c[0], c[1], c[2]) > 0 ? 1.0 : -1.0;
    bool out = false;
    for (std::size_t i = 0; i < 4 && !out; ++i) {
      const FloorPoint a = c[i], e = c[(i + 1) % 4];
      // Inside means orient · cross(a, e, p) ≥ 0; along the segment that is num + t · den ≥ 0.
      const double num = orient * ((e.x - a.x) * (from.z - a.z) - (e.z - a.z) * (from.x - a.x));
      const double den = orient * ((e.x - a.x) * dz - (e.z - a.z) * dx);
      if (std::abs(den) < kEps) {
        out = num < 0;
      } else if (den > 0) {
        t0 = std::max(t0, -num / den);
      } else {
        t1 = std::min(t1, -num / den);
      }
      out = out || t0 > t1;
    }
    if (out || t1 - t0 < 1e-6) continue;
    const double line = config_.eye_height + (top - config_.eye_height) * t1;
    if (b->height > line + 1e-9) return true;
  }
  return false;
}

std::vector<int> NavMap::point_views(FloorPoint point, double top, int self) const {
  const NavConfig& config = config_;
  const double drop = config.eye_height - top;
  const double reach_2d = !config.view_distance_from_camera ? config.view_distance
                          : std::abs(drop) >= config.view_distance
                              ? 0.0
                              : std::sqrt(config.view_distance * config.view_distance - drop * drop);
  auto within = [&](FloorPoint p) { return std::hypot(p.x - point.x, p.z - point.z) <= reach_2d + 1e-9; };
  std::vector<const FurnitureBox*> near;
  if (config.furniture_occludes) {
    const double span = config.view_distance + config.cell;
    for (const auto& b : furniture_)
      if (b.x1 >= point.x - span && b.x0 <= point.x + span && b.z1 >= point.z - span &&
          b.z0 <= point.z + span)
        near.push_back(&b);
  }
  const int reach = static_cast<int>(std::ceil(config.view_distance / config.cell)) + 1;
  const int cx = static_cast<int>(std::floor((point.x - origin_x_) / config.cell)),
            cz = static_cast<int>(std::floor((point.z - origin_z_) / config.cell));
  std::vector<int> views;
  for (int iz = std::max(0, cz - reach); iz <= std::min(depth_ - 1, cz + reach); ++iz)
    for (int ix = std::max(0, cx - reach); ix <= std::min(width_ - 1, cx + reach); ++ix) {
      const int c = iz * width_ + ix;
      if (!free(c)) continue;
      for (int h = 0; h < kHeadings; ++h)
        if (sees(pose_of(c, h), point) && within(center(c)) && !occluded(center(c), point, top, self, near))
          views.push_back(pose_of(c, h));
    }
  std::sort(views.begin(), views.end());
  return views;
}

std::vector<int> NavMap::views_of_point(int receptacle, FloorPoint point) const {
  if (receptacle < 0 || receptacle >= static_cast<int>(receptacles_.size())) return {};
  const MapReceptacle& r = receptacles_[static_cast<std::size_t>(receptacle)];
  return point_views(point, r.top, r.entity);
}

Result<NavMap> build_nav_map(const House& house, const NavConfig& config) {
  if (house.rooms.empty())
    return fail(ErrorCode::kValidation, "a navigation map needs a house with rooms",
                {FieldError{"/rooms", "is empty"}});
  if (!(config.cell > 0.01) || !(config.view_distance > 0) ||
      !(config.field_of_view_deg > 0 && config.field_of_view_deg <= 360))
    return fail(ErrorCode::kValidation, "bad navigation map configuration");
  double x0 = 1e300, z0 = 1e300, x1 = -1e300, z1 = -1e300;
  for (const auto& r : house.rooms)
    for (const auto& p : r.floor)
      x0 = std::min(x0, p.x), z0 = std::min(z0, p.z), x1 = std::max(x1, p.x), z1 = std::max(z1, p.z);
  if (!(x1 > x0) || !(z1 > z0))
    return fail(ErrorCode::kValidation, "the house's rooms have no area",
                {FieldError{"/rooms", "floor polygons are empty"}});
  const double w = std::ceil((x1 - x0) / config.cell), d = std::ceil((z1 - z0) / config.cell);
  if (w * d > static_cast<double>(kMaxCells))
    return fail(ErrorCode::kValidation, "the house is too large for the navigation grid",
                {FieldError{"/rooms", "spans more than 4 million grid cells"}});

  NavMap m;
  m.config_ = config;
  m.origin_x_ = x0;
  m.origin_z_ = z0;
  m.width_ = static_cast<int>(w);
  m.depth_ = static_cast<int>(d);
  m.walls_ = solid_walls(house);
  // Receptacle footprints as oriented rectangles (size in the piece's own frame, turned by yaw),
  // with their bounding boxes to skip most cells quickly.
  using Box = FurnitureBox;
  std::vector<Box>& furniture = m.furniture_;
  for (int idx : house.receptacles) {
    const auto& e = house.entities[static_cast<std::size_t>(idx)];
    if (e.synthetic) continue;
    Box b{1e18, 1e18, -1e18, -1e18, household::footprint(e), idx, std::max(0.0, 2.0 * e.position.y)};
    for (const auto& c : b.corners)
      b.x0 = std::min(b.x0, c.x), b.z0 = std::min(b.z0, c.z), b.x1 = std::max(b.x1, c.x),
      b.z1 = std::max(b.z1, c.z);
    furniture.push_back(b);
  }
  auto inside = [](const Box& b, const FloorPoint& p) {
    if (p.x < b.x0 || p.x > b.x1 || p.z < b.z0 || p.z > b.z1) return false;
    for (std::size_t i = 0; i < 4; ++i) {  // same side of every edge (corners run one way round)
      const auto& a = b.corners[i];
      const auto& c = b.corners[(i + 1) % 4];
      const auto& e = b.corners[(i + 2) % 4];
      const double side = (c.x - a.x) * (p.z - a.z) - (c.z - a.z) * (p.x - a.x);
      const double ref = (c.x - a.x) * (e.z - a.z) - (c.z - a.z) * (e.x - a.x);
      if (side * ref < -1e-12) return false;
    }
    return true;
  };
  const auto n = static_cast<std::size_t>(m.cells());
  m.free_.assign(n, 0);
  for (int c = 0; c < m.cells(); ++c) {
    const FloorPoint p = m.center(c);
    if (house.room_at(p.x, p.z) < 0) continue;
    bool blocked = false;
    for (const auto& b : furniture) blocked = blocked || inside(b, p);
    for (std::size_t i = 0; i < m.walls_.size() && !blocked; ++i)
      blocked = distance_to_segment(p, m.walls_[i].a, m.walls_[i].b) < config.wall_clearance;
    m.free_[static_cast<std::size_t>(c)] = blocked ? 0 : 1;
  }
  m.moves_.assign(n, 0);
  for (int c = 0; c < m.cells(); ++c) {
    if (!m.free(c)) continue;
    const int cx = c % m.width_, cz = c / m.width_;
    for (int h = 0; h < kHeadings; ++h) {
      const int nx = cx + kDx[h], nz = cz + kDz[h];
      if (nx < 0 || nz < 0 || nx >= m.width_ || nz >= m.depth_) continue;
      const int next = nz * m.width_ + nx;
      if (!m.free(next) || !m.line_of_sight(m.center(c), m.center(next))) continue;
      m.moves_[static_cast<std::size_t>(c)] =
          static_cast<std::uint8_t>(m.moves_[static_cast<std::size_t>(c)] | (1u << h));
    }
  }
  // Receptacles and the poses that see them.
  std::vector<std::vector<int>> seen_by(static_cast<std::size_t>(m.poses()));
  for (int idx : house.receptacles) {
    const auto& e = house.entities[static_cast<std::size_t>(idx)];
    MapReceptacle r;
    r.entity = idx;
    r.id = e.id;
    r.type = e.type;
    r.room = e.room;
    if (e.room >= 0) r.room_type = house.rooms[static_cast<std::size_t>(e.room)].type;
    r.x = e.position.x;
    r.z = e.position.z;
    const auto index = static_cast<int>(m.receptacles_.size());
    r.top = (e.synthetic ? 0.0 : std::max(0.0, 2.0 * e.position.y)) + 0.05;
    r.footprint = household::footprint(e);
    r.views = m.point_views({r.x, r.z}, r.top, idx);
    for (const household::FloorPoint& spot : top_grid(r.footprint, MapReceptacle::kSpotSpacing))
      if (auto v = m.point_views(spot, r.top, idx); !v.empty()) {
        r.spots.push_back(std::move(v));
        r.spot_points.push_back(spot);
      }
    if (r.spots.empty() && !r.views.empty()) {
      r.spots.push_back(r.views);
      r.spot_points.push_back({r.x, r.z});
    }
    for (int v : r.views) seen_by[static_cast<std::size_t>(v)].push_back(index);
    m.receptacles_.push_back(std::move(r));
  }
  m.visible_offsets_.assign(static_cast<std::size_t>(m.poses()) + 1, 0);
  for (std::size_t p = 0; p < seen_by.size(); ++p) {
    m.visible_offsets_[p + 1] = m.visible_offsets_[p] + static_cast<std::uint32_t>(seen_by[p].size());
    m.visible_.insert(m.visible_.end(), seen_by[p].begin(), seen_by[p].end());
  }
  return m;
}

}  // namespace socsim::navbench
