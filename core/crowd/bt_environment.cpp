#include "core/crowd/bt_environment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/planar.hpp"

namespace socsim::crowd {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// m kept beyond the body's radius between the straight walk to a route waypoint and any wall, so
// that door jambs stay beside the walking line (the obstacle force then steers without braking).
constexpr double kRouteMargin = 0.05;

double dist(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}
world::Point pt(Vec2 v) {
  return {v.x, v.y};
}
Vec2 vec(world::Point p) {
  return {p.x, p.y};
}

// A point inside the polygon: the centroid when it lies inside, else the centre of the widest
// horizontal chord through the middle of the bounding box.
Vec2 interior_point(const geometry::Polygon& polygon) {
  const world::Point c = geometry::centroid(polygon.outer);
  if (geometry::contains(polygon, c)) return vec(c);
  const geometry::Box box = geometry::bounds(polygon.outer);
  const double y = (box.min.y + box.max.y) / 2.0;
  std::vector<double> xs;
  const auto n = polygon.outer.size();
  for (std::size_t i = 0; i < n; ++i) {
    const world::Point a = polygon.outer[i];
    const world::Point b = polygon.outer[(i + 1) % n];
    if ((a.y <= y) != (b.y <= y)) xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
  }
  std::sort(xs.begin(), xs.end());
  double best = -1.0;
  Vec2 out = vec(polygon.outer.front());
  for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
    if (xs[i + 1] - xs[i] > best) {
      best = xs[i + 1] - xs[i];
      out = {(xs[i] + xs[i + 1]) / 2.0, y};
    }
  }
  return out;
}

bool seat_like(const world::Entity& e) {
  if (std::find(e.affordances.begin(), e.affordances.end(), "sit") != e.affordances.end()) return true;
  return e.type == "chair" || e.type == "seat" || e.type == "bench" || e.type == "sofa" || e.type == "stool";
}

std::pair<std::int64_t, std::int64_t> seat_key(Vec2 p) {
  return {static_cast<std::int64_t>(std::llround(p.x * 100.0)),
          static_cast<std::int64_t>(std::llround(p.y * 100.0))};
}

}  // namespace

BtEnvironment::BtEnvironment(CrowdSimulation& sim, const world::World* world, EnvironmentOptions options)
    : sim_(sim), world_(world), options_(options) {
  if (world_ != nullptr) {
    grid_ = world::OccupancyGrid::rasterise(
        *world_, world::GridOptions{options_.navigation_resolution, options_.navigation_inflation,
                                    options_.navigation_max_cells});
    build_exits();
  }
  sync_agents();
}

void BtEnvironment::sync_agents() {
  while (agents_.size() < sim_.size()) {
    const AgentId id(static_cast<std::uint32_t>(agents_.size()));
    const PedestrianState s = sim_.state(id);
    AgentState a;
    a.base_speed = sim_.desired_speed(id);
    a.rng = Rng(s.metadata.seed ^ fnv1a64("behaviour"));
    a.group = s.group_id;
    agents_.push_back(std::move(a));
  }
}

void BtEnvironment::begin_tick(double now) {
  now_ = now;
  for (AgentState& a : agents_) a.leader.set = false;
}

void BtEnvironment::apply() {
  for (std::size_t i = 0; i < agents_.size(); ++i) {
    const AgentId id(static_cast<std::uint32_t>(i));
    AgentState& a = agents_[i];
    if (!sim_.active(id)) continue;
    Command cmd = a.leader.set ? a.leader : a.own;
    if (!cmd.set) continue;
    if (a.stopped) cmd.hold = true;
    if (cmd.hold) {
      if (sim_.current_goal(id)) (void)sim_.clear_goals(id);
    } else {
      const Vec2 p = sim_.position(id);
      const Vec2 waypoint = cmd.routing == Routing::kPath
                                ? route_waypoint(p, cmd.target, sim_.radius(id) + kRouteMargin)
                                : cmd.target;
      const bool final_leg = waypoint == cmd.target;
      (void)sim_.set_goal(id, Goal{waypoint, final_leg ? cmd.radius : 0.05});
      const double speed = std::clamp(cmd.speed, 0.0, kMaxAgentSpeed);
      if (speed != sim_.desired_speed(id) && !sim_.set_desired_speed(id, speed))
        (void)sim_.set_desired_speed(id, a.base_speed);
      if (cmd.radius > 0.1 && std::hypot(sim_.velocity(id).x, sim_.velocity(id).y) > 0.3) a.face.reset();
    }
    if (!a.applied || a.activity != cmd.activity) (void)sim_.set_activity(id, cmd.activity);
    a.activity = cmd.activity;
    a.applied = true;
  }
}

// --- places ------------------------------------------------------------------------------------

std::optional<Place> BtEnvironment::place(std::string_view name) const {
  if (world_ == nullptr || name.empty()) return std::nullopt;
  if (auto r = world_->find_roi(name)) {
    const world::Roi& roi = world_->roi(*r);
    return Place{roi.name, Place::Kind::kRoi, roi.kind, interior_point(roi.polygon), &roi.polygon, {}};
  }
  if (auto e = world_->find_entity(name)) {
    const world::Entity& en = world_->entity(*e);
    return Place{en.name, Place::Kind::kEntity, en.type, {en.pose.x, en.pose.y}, nullptr, en.affordances};
  }
  if (auto d = world_->find_door(name)) {
    const world::Door& door = world_->door(*d);
    return Place{door.name, Place::Kind::kDoor, "door", {door.pose.x, door.pose.y}, nullptr, {}};
  }
  if (auto z = world_->find_zone(name)) {
    const world::Zone& zone = world_->zone(*z);
    return Place{zone.name, Place::Kind::kZone, zone.type, interior_point(zone.polygon), &zone.polygon, {}};
  }
  return std::nullopt;
}

std::optional<std::string> BtEnvironment::check_place(std::string_view name, std::string_view what) const {
  if (world_ == nullptr) return "'" + std::string(name) + "' cannot be resolved: the scenario has no world";
  const auto p = place(name);
  auto list = [&](auto&& pick) {
    std::string out;
    int shown = 0;
    auto add = [&](const std::string& n) {
      if (shown++ < 12) out += (out.empty() ? "" : ", ") + n;
    };
    pick(add);
    if (shown > 12) out += ", …";
    return out.empty() ? std::string("none") : out;
  };
  if (what == "queue") {
    if (p && p->kind == Place::Kind::kRoi && p->type == "queue_lane") return std::nullopt;
    return "no queue_lane ROI named '" + std::string(name) + "' (queue lanes: " + list([&](auto& add) {
             for (world::RoiId r : world_->rois_of_kind("queue_lane")) add(world_->roi(r).name);
           }) +
           ")";
  }
  if (what == "region") {
    if (p && p->region != nullptr) return std::nullopt;
    return "no ROI or zone named '" + std::string(name) + "' (ROIs: " + list([&](auto& add) {
             for (const world::Roi& r : world_->rois()) add(r.name);
           }) +
           ")";
  }
  if (what == "exit") {
    if (name.empty()) return std::nullopt;
    if (exit_index(name)) return std::nullopt;
    return "no exit named '" + std::string(name) +
           "' (exits: doors to the outside and ROIs of kind exit: " + list([&](auto& add) {
             for (const Exit& e : exits_) add(e.name);
           }) +
           ")";
  }
  if (p) return std::nullopt;
  return "no ROI, POI, door or zone named '" + std::string(name) +
         "' in the world (ROIs: " + list([&](auto& add) {
           for (const world::Roi& r : world_->rois()) add(r.name);
         }) +
         "; POIs: " + list([&](auto& add) {
           for (const world::Entity& e : world_->entities()) add(e.name);
         }) +
         ")";
}

bool BtEnvironment::inside(const Place& place, Vec2 p) const {
  if (place.region != nullptr) return geometry::contains(*place.region, pt(p));
  return dist(p, place.point) <= 0.5;
}

// --- goal lists --------------------------------------------------------------------------------

void BtEnvironment::set_goal_list(AgentId id, std::vector<Goal> goals, bool cyclic) {
  GoalList& g = agents_.at(id.value()).goals;
  g.goals = std::move(goals);
  g.index = 0;
  g.cyclic = cyclic;
  g.named.reset();
}

std::optional<Goal> BtEnvironment::current_goal(AgentId id) const {
  const GoalList& g = agents_.at(id.value()).goals;
  if (g.named) return g.named;
  if (g.index < g.goals.size()) return g.goals[g.index];
  return std::nullopt;
}

void BtEnvironment::advance_goal(AgentId id) {
  GoalList& g = agents_.at(id.value()).goals;
  if (g.named) {
    g.named.reset();
    return;
  }
  if (g.goals.empty()) return;
  ++g.index;
  if (g.index >= g.goals.size() && g.cyclic) g.index = 0;
}

// --- steering ----------------------------------------------------------------------------------

void BtEnvironment::move_to(AgentId id, Vec2 target, double radius, double speed, Activity activity,
                            Routing routing, Priority priority) {
  AgentState& a = agents_.at(id.value());
  Command& c = priority == Priority::kLeader ? a.leader : a.own;
  c = Command{true, false, target, radius, speed, activity, routing};
}

void BtEnvironment::hold(AgentId id, Activity activity, Priority priority) {
  AgentState& a = agents_.at(id.value());
  Command& c = priority == Priority::kLeader ? a.leader : a.own;
  c = Command{true, true, sim_.position(id), 0.3, 0.0, activity, Routing::kDirect};
}

void BtEnvironment::hold_at(AgentId id, Vec2 spot, Activity activity, Priority priority) {
  AgentState& a = agents_.at(id.value());
  Command& c = priority == Priority::kLeader ? a.leader : a.own;
  c = Command{true, false, spot, 0.1, std::min(0.6, a.base_speed), activity, Routing::kDirect};
}

void BtEnvironment::speak(AgentId id, std::string message) {
  AgentState& a = agents_.at(id.value());
  a.spoke_at = now_;
  a.message = std::move(message);
}

double BtEnvironment::heading(AgentId id) const {
  const AgentState& a = agents_.at(id.value());
  const Vec2 v = sim_.velocity(id);
  const bool staying = a.activity != Activity::kWalking && a.activity != Activity::kRunning &&
                       a.activity != Activity::kEvacuating;
  if (a.face && (staying || std::hypot(v.x, v.y) < 0.25)) {
    const Vec2 p = sim_.position(id);
    if (dist(*a.face, p) > 1e-6) return std::atan2(a.face->y - p.y, a.face->x - p.x);
  }
  return sim_.yaw(id);
}

PedestrianState BtEnvironment::state(AgentId id) const {
  PedestrianState s = sim_.state(id);
  if (id.value() >= agents_.size()) return s;
  const AgentState& a = agents_[id.value()];
  s.pose.yaw = heading(id);
  s.group_id = a.group;
  if (a.spoke_at && now_ - *a.spoke_at <= 3.0) s.metadata.tags.push_back("says:" + a.message);
  return s;
}

bool BtEnvironment::line_of_sight(Vec2 a, Vec2 b, double clearance) const {
  for (const WallSegment& w : sim_.walls())
    if (move_blocked(a, b, w.a, w.b)) return false;
  if (clearance <= 0.0) return true;
  const double len = dist(a, b);
  if (len < 1e-9) return true;
  const Vec2 side{-(b.y - a.y) / len * clearance, (b.x - a.x) / len * clearance};
  for (const double k : {1.0, -1.0}) {
    const Vec2 a2{a.x + k * side.x, a.y + k * side.y};
    const Vec2 b2{b.x + k * side.x, b.y + k * side.y};
    for (const WallSegment& w : sim_.walls())
      if (move_blocked(a2, b2, w.a, w.b)) return false;
  }
  return true;
}

// --- routing -----------------------------------------------------------------------------------

const world::GeodesicField* BtEnvironment::route_field(Vec2 target) {
  if (!grid_) return nullptr;
  const world::OccupancyGrid& g = *grid_;
  auto cell = g.cell_of(pt(target));
  if (!cell) return nullptr;
  // A target in a blocked cell (next to a wall, on a counter) is routed to the nearest free cell.
  if (g.blocked(*cell)) {
    std::optional<world::Cell> best;
    double best_d = kInf;
    for (int r = 1; r <= 12 && !best; ++r) {
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          if (std::max(std::abs(dx), std::abs(dy)) != r) continue;
          const world::Cell c{cell->x + dx, cell->y + dy};
          if (g.blocked(c)) continue;
          const double d = dist(vec(g.center(c)), target);
          if (d < best_d) {
            best_d = d;
            best = c;
          }
        }
      }
    }
    if (!best) return nullptr;
    cell = best;
  }
  const std::int64_t key = static_cast<std::int64_t>(g.index(*cell));
  for (auto it = routes_.begin(); it != routes_.end(); ++it) {
    if (it->first != key) continue;
    auto entry = *it;
    routes_.erase(it);
    routes_.push_back(entry);
    return routes_.back().second.get();
  }
  const world::Point source = g.blocked(*g.cell_of(pt(target))) ? g.center(*cell) : pt(target);
  auto field =
      std::make_shared<world::GeodesicField>(world::GeodesicField::from_points(g, std::span(&source, 1)));
  routes_.emplace_back(key, std::move(field));
  while (routes_.size() > options_.max_cached_routes) routes_.pop_front();
  return routes_.back().second.get();
}

namespace {

// Direction of descent at p, or towards the lowest finite neighbouring cell when p sits in a
// blocked cell (agents pressed against a wall).
std::optional<Vec2> descend(const world::GeodesicField& f, const world::OccupancyGrid& g, Vec2 p) {
  if (auto d = f.descent(pt(p))) return vec(*d);
  const auto cell = g.cell_of(pt(p));
  if (!cell) return std::nullopt;
  float best = std::numeric_limits<float>::infinity();
  std::optional<world::Cell> to;
  for (int dy = -3; dy <= 3; ++dy) {
    for (int dx = -3; dx <= 3; ++dx) {
      const world::Cell c{cell->x + dx, cell->y + dy};
      const float v = f.at(c);
      if (v < best) {
        best = v;
        to = c;
      }
    }
  }
  if (!to || (to->x == cell->x && to->y == cell->y)) return std::nullopt;
  const Vec2 c = vec(g.center(*to));
  const double len = dist(c, p);
  if (len < 1e-9) return std::nullopt;
  return Vec2{(c.x - p.x) / len, (c.y - p.y) / len};
}

}  // namespace

Vec2 BtEnvironment::route_waypoint(Vec2 from, Vec2 target, double clearance) {
  if (!grid_ || line_of_sight(from, target, clearance)) return target;
  const world::GeodesicField* f = route_field(target);
  if (f == nullptr || !f->has_source()) return target;
  const double step = std::max(0.1, 2.0 * grid_->resolution());
  const int steps = std::max(1, static_cast<int>(options_.lookahead / step));
  Vec2 q = from;
  Vec2 last_visible = from;
  for (int k = 0; k < steps; ++k) {
    const auto d = descend(*f, *grid_, q);
    if (!d) break;
    q = {q.x + d->x * step, q.y + d->y * step};
    if (!line_of_sight(from, q, clearance)) break;
    last_visible = q;
    if (dist(q, target) < step) return line_of_sight(from, target, clearance) ? target : q;
  }
  if (last_visible == from) {
    const auto d = descend(*f, *grid_, from);
    if (d) return {from.x + d->x * step, from.y + d->y * step};
    return target;
  }
  return last_visible;
}

double BtEnvironment::walking_distance(Vec2 p, Vec2 target) {
  if (!grid_) return dist(p, target);
  if (line_of_sight(p, target)) return dist(p, target);
  const world::GeodesicField* f = route_field(target);
  if (f == nullptr) return kInf;
  const auto d = f->distance(pt(p));
  return d ? *d : kInf;
}

// --- queues ------------------------------------------------------------------------------------

BtEnvironment::Queue* BtEnvironment::queue(std::string_view name) {
  if (auto it = queues_.find(name); it != queues_.end()) return &it->second;
  if (world_ == nullptr) return nullptr;
  const auto r = world_->find_roi(name);
  if (!r || world_->roi(*r).kind != "queue_lane") return nullptr;
  const geometry::Polygon& poly = world_->roi(*r).polygon;
  // Lane axis: the direction of the longest edge; the lane spans the vertices' projections.
  Vec2 axis{1.0, 0.0};
  double longest = -1.0;
  const auto n = poly.outer.size();
  for (std::size_t i = 0; i < n; ++i) {
    const world::Point a = poly.outer[i];
    const world::Point b = poly.outer[(i + 1) % n];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    if (len > longest) {
      longest = len;
      axis = {(b.x - a.x) / len, (b.y - a.y) / len};
    }
  }
  const world::Point c = geometry::centroid(poly.outer);
  double tmin = kInf;
  double tmax = -kInf;
  for (const world::Point& v : poly.outer) {
    const double t = (v.x - c.x) * axis.x + (v.y - c.y) * axis.y;
    tmin = std::min(tmin, t);
    tmax = std::max(tmax, t);
  }
  const double inset = std::min(0.35, (tmax - tmin) / 4.0);
  const Vec2 end_a{c.x + axis.x * (tmin + inset), c.y + axis.y * (tmin + inset)};
  const Vec2 end_b{c.x + axis.x * (tmax - inset), c.y + axis.y * (tmax - inset)};
  // The head is the end nearest the counter: the nearest serving entity within a lane length.
  const double lane = tmax - tmin;
  std::optional<Vec2> counter;
  double best = kInf;
  for (const world::Entity& e : world_->entities()) {
    const bool serves =
        e.type == "counter" || e.type == "desk" || e.type == "reception" ||
        std::find(e.affordances.begin(), e.affordances.end(), "serve") != e.affordances.end() ||
        std::find(e.affordances.begin(), e.affordances.end(), "queue_target") != e.affordances.end();
    if (!serves) continue;
    const Vec2 p{e.pose.x, e.pose.y};
    const double d = std::min(dist(p, end_a), dist(p, end_b));
    if (d <= lane && d < best) {
      best = d;
      counter = p;
    }
  }
  Vec2 head = end_b;
  Vec2 tail = end_a;
  if (counter) {
    if (dist(*counter, end_a) < dist(*counter, end_b)) std::swap(head, tail);
  } else {
    const Vec2 first = vec(poly.outer.front());
    if (dist(first, end_a) < dist(first, end_b)) std::swap(head, tail);
  }
  Queue q;
  q.name = std::string(name);
  q.head = head;
  const double hl = std::max(dist(head, tail), 1e-9);
  q.to_tail = {(tail.x - head.x) / hl, (tail.y - head.y) / hl};
  q.counter = counter;
  if (counter) {
    const double d = dist(*counter, head);
    const double back = std::min(0.55, d / 2.0);
    q.service = d > 1e-9 ? Vec2{counter->x + (head.x - counter->x) / d * back,
                                counter->y + (head.y - counter->y) / d * back}
                         : head;
  } else {
    q.service = {head.x - q.to_tail.x * 0.8, head.y - q.to_tail.y * 0.8};
  }
  return &queues_.emplace(q.name, std::move(q)).first->second;
}

Vec2 BtEnvironment::queue_place(const Queue& q, std::size_t index) const {
  const double s = q.spacing * static_cast<double>(index);
  return {q.head.x + q.to_tail.x * s, q.head.y + q.to_tail.y * s};
}

std::optional<std::size_t> BtEnvironment::queue_index(const Queue& q, AgentId id) const {
  for (std::size_t i = 0; i < q.members.size(); ++i)
    if (q.members[i] == id) return i;
  return std::nullopt;
}

void BtEnvironment::join_queue(Queue& q, AgentId id) {
  if (queue_index(q, id)) return;
  q.members.push_back(id);
  if (q.members.size() == 1) q.head_since = now_;
}

void BtEnvironment::leave_queue(Queue& q, AgentId id) {
  const auto i = queue_index(q, id);
  if (!i) return;
  q.members.erase(q.members.begin() + static_cast<std::ptrdiff_t>(*i));
  if (*i == 0) q.head_since = now_;
}

// --- seats -------------------------------------------------------------------------------------

std::optional<Vec2> BtEnvironment::reserve_seat(const Place& place, AgentId id, Vec2 from) {
  auto it = seats_.find(place.name);
  if (it == seats_.end()) {
    std::vector<Vec2> seats;
    if (place.region == nullptr) {
      seats.push_back(place.point);
    } else {
      if (world_ != nullptr)
        for (const world::Entity& e : world_->entities())
          if (seat_like(e) && geometry::contains(*place.region, {e.pose.x, e.pose.y}))
            seats.push_back({e.pose.x, e.pose.y});
      if (seats.empty()) {
        // No seat entities: a 0.8 m grid of places inside the region, 0.4 m from its edges.
        const geometry::Box box = geometry::bounds(place.region->outer);
        for (double y = box.min.y + 0.4; y <= box.max.y - 0.4 + 1e-9; y += 0.8) {
          for (double x = box.min.x + 0.4; x <= box.max.x - 0.4 + 1e-9; x += 0.8) {
            const Vec2 p{x, y};
            if (!geometry::contains(*place.region, pt(p))) continue;
            if (grid_) {
              const auto c = grid_->cell_of(pt(p));
              if (!c || grid_->blocked(*c)) continue;
            }
            seats.push_back(p);
          }
        }
      }
    }
    it = seats_.emplace(place.name, std::move(seats)).first;
  }
  release_seat(id);
  std::optional<Vec2> best;
  double best_d = kInf;
  for (const Vec2& s : it->second) {
    if (seat_taken_.count(seat_key(s)) != 0) continue;
    const double d = dist(s, from);
    if (d < best_d) {
      best_d = d;
      best = s;
    }
  }
  if (!best) return std::nullopt;
  seat_taken_.emplace(seat_key(*best), id);
  agents_.at(id.value()).seat = best;
  return best;
}

void BtEnvironment::release_seat(AgentId id) {
  AgentState& a = agents_.at(id.value());
  if (!a.seat) return;
  seat_taken_.erase(seat_key(*a.seat));
  a.seat.reset();
}

// --- fields and exits --------------------------------------------------------------------------

void BtEnvironment::add_velocity_field(std::string name, VelocityField field,
                                       std::vector<geometry::Polygon> goal_regions) {
  fields_.insert_or_assign(std::move(name), FieldEntry{std::move(field), std::move(goal_regions)});
}

const BtEnvironment::FieldEntry* BtEnvironment::velocity_field(std::string_view name) const {
  auto it = fields_.find(name);
  return it == fields_.end() ? nullptr : &it->second;
}

void BtEnvironment::build_exits() {
  for (const world::Door& d : world_->doors()) {
    if (d.other) continue;
    const Vec2 c{d.pose.x, d.pose.y};
    const double ux = d.opening.b.x - d.opening.a.x;
    const double uy = d.opening.b.y - d.opening.a.y;
    const double len = std::hypot(ux, uy);
    Vec2 normal{std::cos(d.pose.yaw), std::sin(d.pose.yaw)};
    if (len > 1e-9) normal = {-uy / len, ux / len};
    Vec2 beyond{c.x + normal.x * 1.0, c.y + normal.y * 1.0};
    if (world_->zone_at(pt(beyond))) beyond = {c.x - normal.x * 1.0, c.y - normal.y * 1.0};
    exits_.push_back(Exit{d.name, c, beyond, nullptr, {ux / 2.0, uy / 2.0}});
  }
  for (world::RoiId r : world_->rois_of_kind("exit")) {
    const world::Roi& roi = world_->roi(r);
    exits_.push_back(Exit{roi.name, interior_point(roi.polygon), std::nullopt, &roi.polygon, {}});
  }
  exit_fields_.resize(exits_.size());
}

std::optional<std::size_t> BtEnvironment::exit_index(std::string_view name) const {
  for (std::size_t i = 0; i < exits_.size(); ++i)
    if (exits_[i].name == name) return i;
  return std::nullopt;
}

std::optional<std::size_t> BtEnvironment::nearest_exit(Vec2 p) {
  if (!grid_) return std::nullopt;
  std::optional<std::size_t> best;
  double best_d = kInf;
  for (std::size_t i = 0; i < exits_.size(); ++i) {
    if (!exit_fields_[i]) {
      if (exits_[i].region != nullptr) {
        exit_fields_[i] = std::make_shared<world::GeodesicField>(
            world::GeodesicField::from_region(*grid_, *exits_[i].region));
      } else {
        const world::GeodesicField* f = route_field(exits_[i].point);
        exit_fields_[i] = f != nullptr ? std::make_shared<world::GeodesicField>(*f)
                                       : std::make_shared<world::GeodesicField>();
      }
    }
    const auto d = exit_fields_[i]->distance(pt(p));
    if (d && *d < best_d) {
      best_d = *d;
      best = i;
    }
  }
  return best;
}

bool BtEnvironment::outside(Vec2 p) const {
  return world_ != nullptr && !world_->zone_at(pt(p));
}

}  // namespace socsim::crowd
