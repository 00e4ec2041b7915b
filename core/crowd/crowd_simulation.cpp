#include "core/crowd/crowd_simulation.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <span>
#include <vector>

#include "core/common/rng.hpp"
#include "core/crowd/fast_math.hpp"
#include "core/crowd/neighbour_gather.hpp"
#include "core/crowd/social_kernel.hpp"

namespace socsim::crowd {

// Agents sorted by grid cell (counting sort, stable), with their frozen state copied into
// contiguous arrays so a neighbour scan reads memory in order.
struct CrowdSimulation::CellIndex {
  double origin_x = 0.0;
  double origin_y = 0.0;
  double cell = 1.0;
  double inv_cell = 1.0;
  std::int64_t nx = 0;
  std::int64_t ny = 0;
  std::vector<std::uint32_t> start;  // nx*ny + 1 offsets into the sorted arrays
  // Entries: every active agent, then (periodic boundary) the images of those near either end.
  std::vector<std::uint32_t> entry_agent;
  std::vector<double> entry_x;
  std::vector<std::uint32_t> entry_cell;
  // build_cells' lists of entries (the agents part by part, then their images part by part).
  struct Part {
    std::array<double, 4> box{1e300, 1e300, -1e300, -1e300};
    std::size_t count = 0;  // entries of this list
    std::size_t first = 0;  // its first entry
  };
  std::vector<Part> parts;
  std::vector<std::uint32_t> list_cell;  // per list and cell: a count, then a sorted position
  std::vector<std::uint32_t> order;      // sorted position -> entry (periodic boundary only)
  std::vector<std::uint32_t> agents;     // the active agents in sorted order (no images)
  // For the scan agent by agent only (step_pairs reads `inputs`): agent index -> sorted position
  // of its own entry (kNoCell when inactive), and the entries' state in double precision.
  std::vector<std::uint32_t> cell_of;
  std::vector<double> x, y, vx, vy, r;
  // The same positions and velocities in single precision, for the gather (kGatherSlack inert
  // entries past the end: far away, never within the cut-off).
  std::vector<float> fx, fy, fvx, fvy;
  std::vector<std::int32_t> group;  // (the scan agent by agent only)
  std::vector<std::uint32_t> id;
  LargeVector<AgentInputs> inputs;  // the entries' agents' inputs (step_pairs: no images)
};

struct CrowdSimulation::Images {
  std::vector<double> x, y, vx, vy, r;
  std::vector<float> fx, fy, fvx, fvy;  // as CellIndex's
  std::vector<std::int32_t> group;
  std::vector<std::uint32_t> id;
  std::vector<std::uint8_t> active;
};

struct CrowdSimulation::AgentMeta {
  Activity activity = Activity::kWalking;
  Intent intent;
  std::vector<std::string> tags;
  std::string bt_node;
  std::uint64_t seed = 0;
  std::int64_t group_id = -1;
  std::vector<Goal> goals;
  std::size_t goal_index = 0;
  bool cyclic = false;
};

// A neighbour within touching distance + margin: its agent id, the unit direction n to it, the
// gap between the bodies (negative: overlap) and its frozen velocity.
struct BodyContact {
  std::uint32_t who;
  double nx, ny, gap, vx, vy;
};

// What an agent's step needs before its neighbours (prepare_agent).
struct CrowdSimulation::AgentPrep {
  double ex = 0.0;  // the unit walking direction, (0, 0) without a goal (or once reached)
  double ey = 0.0;
  bool heading = false;
  unsigned wall_sides = 0;  // walls abreast within zipper_reach: 1 left, 2 right, 3 both
  Vec2 obstacle;            // the walls' force
  // The squared distance to the nearest wall of wall_grid_.near(x, y) (+inf: none): walls
  // farther than one step's move can neither block it nor limit the velocity (finish_agent).
  double wall_d2 = std::numeric_limits<double>::infinity();
};

// The neighbours' sums for one agent.
struct CrowdSimulation::NeighbourTotals {
  double speed_cap = std::numeric_limits<double>::infinity();
  Vec2 social, repulsion, body;
};

// The pair step's scratch (step_pairs), kept between steps.
struct CrowdSimulation::PairState {
  // One agent's sums from the pairs a thread computed (integers: exact, in any order): the social
  // force, side pushes and headway caps, which every pair adds to (32 bytes, no branch).
  struct Social {
    std::int64_t x, y, side_push;
    std::int32_t cap;  // the bits of the smallest headway cap (those of +inf: none)
  };
  // The touching-pair terms, which only the few pairs in touch add to: kept as records rather
  // than as an array over all agents that would be emptied and read whole each step.
  struct Sums {
    std::int64_t repulsion_x, repulsion_y, body_x, body_y;
  };
  struct Touch {
    std::uint32_t to;  // the sorted position of the agent the terms belong to
    Sums terms;
  };
  // A contact: the sorted positions of the agent it belongs to and of the neighbour. Its
  // direction, gap and the neighbour's velocity are computed where it is used (step_pairs' last
  // pass) from the same inputs the close pair read: 8 bytes to write and sort instead of 56.
  struct Record {
    std::uint32_t to;
    std::uint32_t other;
  };
  static constexpr unsigned kContactShift = 7;  // blocks of 128 agents
  static constexpr std::size_t kContactBlock = std::size_t{1} << kContactShift;
  // One thread's records of one kind, then the same by block of kContactBlock sorted positions
  // (each thread sorts its own, in parallel; stable): those of block b are
  // sorted[start[b] .. [b + 1]).
  template <class R>
  struct Bucketed {
    LargeVector<R> records;
    std::vector<std::uint32_t> start;
    LargeVector<R> sorted;
    void sort(std::size_t blocks) {
      start.assign(blocks + 1, 0);
      for (const R& r : records) ++start[(r.to >> kContactShift) + 1];
      for (std::size_t b = 0; b < blocks; ++b) start[b + 1] += start[b];
      sorted.resize(start[blocks]);
      for (const R& r : records) sorted[start[r.to >> kContactShift]++] = r;
      for (std::size_t b = blocks; b > 0; --b) start[b] = start[b - 1];  // back to each block's start
      start[0] = 0;
    }
    // Each record for the positions [begin, end), in order.
    template <class Visit>
    void each(std::size_t begin, std::size_t end, const Visit& visit) const {
      for (std::size_t b = begin >> kContactShift; b <= (end - 1) >> kContactShift; ++b)
        for (std::uint32_t q = start[b]; q < start[b + 1]; ++q)
          if (sorted[q].to >= begin && sorted[q].to < end) visit(sorted[q]);
    }
  };
  struct Thread {
    // By sorted position: emptied by the thread itself when it takes its first range of the
    // pairs (so the lines it adds to are in its own cache, not the other core's), and read only
    // when `round` is the step's (a thread that took no range has stale sums).
    LargeVector<Social> social;
    std::uint64_t round = 0;
    Bucketed<Record> contacts;
    Bucketed<Touch> touches;
  };
  std::vector<Thread> threads;
  std::uint64_t round = 0;  // step_pairs' calls
  // By sorted position: prepare_agent's results, the kernel's inputs of each agent (walking
  // direction, v·e, headway band; 0 for a driven one). (The contact margin is recomputed from
  // the inputs the close pairs read anyway: an array of its own cost a load from another line.)
  LargeVector<AgentPrep> prep;
  LargeVector<float> heading;  // 4 per agent: ex, ey, along, band (fill_pair_sides)
};

namespace {

constexpr std::uint32_t kNoCell = UINT32_MAX;
constexpr double kMaxCoordinate = 1.0e6;  // m; keeps every product far from overflow
constexpr double kTiny2 = 1e-18;          // squared lengths below this count as zero
// The gap the crowd leaves between a body and a wall's inside when it presses the body against it
// (m): the velocity limit and the separation passes stop a body this far from the wall. (It was a
// 0.1 m squeeze — shoulders turned — but then a body's disc could end up to 0.1 m into a wall in a
// dense crowd round a corner, RiMEA 15, depending on the run.) Wall ends (door jambs) are exempt:
// people squeeze past them.
constexpr double kWallClearance = 0.01;
// Narrow passages (the zipper, Hoogendoorn & Daamen 2005; Seyfried et al. 2009): between the
// insides of two walls closer together than kNarrowTo (m, centre to wall on the left plus on the
// right, both abreast within zipper_reach), the walls' push across the walking direction fades
// linearly to nothing at kNarrowFrom, so people walk staggered near the walls instead of being
// held on the middle line in single file; the hard contact keeps them kWallClearance off the walls,
// and the push along the walking direction (braking before a wall ahead) is kept. Door jambs (wall
// ends) keep their push. With LightSFM's full push a 4 m passage passed 1.09–1.15 /s at 0.8 m
// and 1.36–1.58 /s at 1.0 m, under Seyfried's data; now 1.29–1.48 and 1.62–1.75 (docs/crowd.md).
constexpr double kNarrowFrom = 0.8;
constexpr double kNarrowTo = 1.3;

// Whether two roles' pair terms agree (then every pair's social force is antisymmetric and the
// ahead terms use the same parameters on both sides).
bool same_pair_terms(const ForceParameters& a, const ForceParameters& b) {
  return a.lambda == b.lambda && a.gamma == b.gamma && a.n == b.n && a.n_prime == b.n_prime &&
         a.social_factor == b.social_factor && a.headway_distance == b.headway_distance &&
         a.headway_time == b.headway_time && a.headway_anticipation == b.headway_anticipation &&
         a.side_factor == b.side_factor && a.side_range == b.side_range && a.side_bias == b.side_bias &&
         a.side_band == b.side_band && a.group_repulsion_factor == b.group_repulsion_factor;
}

bool finite_in_range(double v, double limit) {
  return std::isfinite(v) && std::abs(v) <= limit;
}

double wrap_angle(double a) {
  while (a > std::numbers::pi) a -= 2.0 * std::numbers::pi;
  while (a <= -std::numbers::pi) a += 2.0 * std::numbers::pi;
  return a;
}

// Separation direction for two agents at the same point: fixed per pair and antisymmetric
// (agent i gets u, agent j gets -u), so coincident agents part deterministically.
Vec2 tie_break_direction(std::uint32_t i, std::uint32_t j) {
  static constexpr std::array<Vec2, 8> kDirs = {{{1.0, 0.0},
                                                 {0.70710678118654752, 0.70710678118654752},
                                                 {0.0, 1.0},
                                                 {-0.70710678118654752, 0.70710678118654752},
                                                 {-1.0, 0.0},
                                                 {-0.70710678118654752, -0.70710678118654752},
                                                 {0.0, -1.0},
                                                 {0.70710678118654752, -0.70710678118654752}}};
  const std::uint32_t lo = std::min(i, j);
  const std::uint32_t hi = std::max(i, j);
  const Vec2 u = kDirs[((lo * 2654435761u) ^ (hi * 40503u)) >> 29u];
  return i < j ? u : Vec2{-u.x, -u.y};
}

// Distance between agents i and j and the unit vector from i towards j (dx, dy: j − i; d2 its
// squared length); coincident agents get distance 0 and their fixed per-pair direction.
struct Separation {
  double d, x, y;
};
Separation separation(double dx, double dy, double d2, std::uint32_t i, std::uint32_t j) {
  if (d2 > kTiny2) {
    const double d = std::sqrt(d2);
    return {d, dx / d, dy / d};
  }
  const Vec2 u = tie_break_direction(i, j);
  return {0.0, u.x, u.y};
}

// Where along from→to the move meets the wall's line (0..1).
double hit_parameter(Vec2 from, Vec2 to, const WallSegment& w) {
  const double o1 = orient(w.a, w.b, from);
  const double o2 = orient(w.a, w.b, to);
  if (o1 == o2) return 0.0;
  return std::clamp(o1 / (o1 - o2), 0.0, 1.0);
}

int first_blocking_wall(Vec2 from, Vec2 to, std::span<const std::uint32_t> near,
                        const std::vector<WallSegment>& walls, double* t_hit) {
  int best = -1;
  double best_t = 2.0;
  for (std::uint32_t w : near) {
    const WallSegment& s = walls[w];
    if (!move_blocked(from, to, s.a, s.b)) continue;
    const double t = hit_parameter(from, to, s);
    if (t < best_t) {
      best_t = t;
      best = static_cast<int>(w);
    }
  }
  *t_hit = best_t;
  return best;
}

// The wall guard: returns where an agent moving p→q may end so that the straight move from p
// crosses no wall. Blocked moves stop just before the first wall hit and slide along it; up to
// three walls (corners) are handled, otherwise the agent keeps the last legal stop.
Vec2 guard_move(Vec2 p, Vec2 q, std::span<const std::uint32_t> near, const std::vector<WallSegment>& walls) {
  constexpr double kGap = 1e-6;  // m kept between the stop point and the wall along the move
  Vec2 target = q;
  Vec2 safe = p;
  for (int attempt = 0; attempt < 3; ++attempt) {
    double t = 0.0;
    const int w = first_blocking_wall(p, target, near, walls, &t);
    if (w < 0) return target;
    const double dx = target.x - p.x;
    const double dy = target.y - p.y;
    const double len = std::sqrt(dx * dx + dy * dy);
    const double t_stop = len > 0.0 ? std::max(0.0, t - kGap / len) : 0.0;
    Vec2 stop{p.x + dx * t_stop, p.y + dy * t_stop};
    double unused = 0.0;
    if (first_blocking_wall(p, stop, near, walls, &unused) >= 0) stop = p;
    safe = stop;
    const WallSegment& s = walls[static_cast<std::size_t>(w)];
    const double ux = s.b.x - s.a.x;
    const double uy = s.b.y - s.a.y;
    const double ulen2 = ux * ux + uy * uy;
    const double along = ((target.x - stop.x) * ux + (target.y - stop.y) * uy) / ulen2;
    target = {stop.x + ux * along, stop.y + uy * along};
  }
  double unused = 0.0;
  return first_blocking_wall(p, target, near, walls, &unused) < 0 ? target : safe;
}

// The nearest point of wall s to p; *interior: whether it lies strictly between the wall's ends.
Vec2 nearest_on_wall(Vec2 p, const WallSegment& s, bool* interior) {
  const double ux = s.b.x - s.a.x;
  const double uy = s.b.y - s.a.y;
  const double len2 = ux * ux + uy * uy;
  double t = 0.0;
  if (len2 > 0.0) t = std::clamp(((p.x - s.a.x) * ux + (p.y - s.a.y) * uy) / len2, 0.0, 1.0);
  *interior = t > 0.0 && t < 1.0;
  return {s.a.x + t * ux, s.a.y + t * uy};
}

// A separation shift cur → to, projected so that the body (radius r) ends no closer to any wall
// than min(r + kWallClearance, its distance from that wall at cur): where `to` is too close, it is
// moved straight away from the wall's nearest point. Only where that point lies inside the wall:
// a wall end (a door jamb, a corner seen from outside) is left to the wall guard, as people
// squeeze past jambs. Walls are taken in the order of `near` (deterministic).
Vec2 keep_off_walls(Vec2 cur, Vec2 to, double r, std::span<const std::uint32_t> near,
                    const std::vector<WallSegment>& walls) {
  for (std::uint32_t w : near) {
    const WallSegment& s = walls[w];
    bool interior = false;
    const Vec2 qc = nearest_on_wall(cur, s, &interior);
    const double dc = std::hypot(cur.x - qc.x, cur.y - qc.y);
    const double limit = std::min(r + kWallClearance, dc);
    const Vec2 q = nearest_on_wall(to, s, &interior);
    if (!interior) continue;  // a wall end (a door jamb): people squeeze past it
    const double dx = to.x - q.x;
    const double dy = to.y - q.y;
    const double d = std::sqrt(dx * dx + dy * dy);
    if (d >= limit) continue;
    if (d > 1e-9) {
      to = {q.x + dx * (limit / d), q.y + dy * (limit / d)};
    } else if (dc > 1e-9) {
      to = {qc.x + (cur.x - qc.x) * (limit / dc), qc.y + (cur.y - qc.y) * (limit / dc)};
    } else {
      to = cur;
    }
  }
  return to;
}

// Whether a body of radius r walking straight from p along the unit direction e for `len` metres
// stays at least r away from the wall [a, b]: the segments do not cross, and no end point of
// either lies within r of the other.
bool walk_clears(Vec2 p, Vec2 e, double len, Vec2 a, Vec2 b, double r) {
  const Vec2 q{p.x + e.x * len, p.y + e.y * len};
  // Boxes farther apart than r (with 1e-9 m to spare for rounding) along x or y: every point of
  // one segment is farther than r from every point of the other, so the exact test below would
  // say the same (most walls near an agent are not on its way).
  const double gap = r + 1e-9;
  if (std::min(a.x, b.x) - std::max(p.x, q.x) > gap || std::min(p.x, q.x) - std::max(a.x, b.x) > gap ||
      std::min(a.y, b.y) - std::max(p.y, q.y) > gap || std::min(p.y, q.y) - std::max(a.y, b.y) > gap)
    return true;
  const double o1 = orient(a, b, p);
  const double o2 = orient(a, b, q);
  const double o3 = orient(p, q, a);
  const double o4 = orient(p, q, b);
  if (((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
      ((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0)))
    return false;
  return point_segment_distance(a, p, q) >= r && point_segment_distance(b, p, q) >= r &&
         point_segment_distance(p, a, b) >= r && point_segment_distance(q, a, b) >= r;
}

// Whether v, a point of wall o (usually one of its ends), is o's nearest point to p. An end of a
// wall that touches other walls pushes only when it is the nearest point of all of them: then a
// polyline — a wall cut into segments, a circle of many sides — pushes from its nearest point
// like one smooth wall, not once more from every vertex in reach; a corner seen from outside still
// pushes (once).
bool nearest_point_is(Vec2 p, Vec2 v, const WallSegment& o) {
  const double da = (v.x - o.a.x) * (v.x - o.a.x) + (v.y - o.a.y) * (v.y - o.a.y);
  const double db = (v.x - o.b.x) * (v.x - o.b.x) + (v.y - o.b.y) * (v.y - o.b.y);
  const Vec2 end = da <= db ? o.a : o.b;
  const Vec2 other = da <= db ? o.b : o.a;
  if (std::min(da, db) > 1e-18) return false;  // v inside o (a T-junction): o's own point is nearer
  return (p.x - end.x) * (other.x - end.x) + (p.y - end.y) * (other.y - end.y) <= 0.0;
}

// Touching-pair forces (group repulsion, body force) are summed in 64-bit fixed point (2^-32 m/s²
// resolution), like the quantised social forces: integer addition is associative, so the sum
// does not depend on the order neighbours are visited in, and the cell-list step and the O(N²)
// reference give bit-identical results. Each term is bounded to ±2^30 (no overflow).
class FixedSum {
 public:
  void add(double v) { sum_ += term(v); }
  void add_term(std::int64_t t) { sum_ += t; }
  [[nodiscard]] double value() const { return to_double(sum_); }
  // What add(v) adds, and the value of a sum of such terms.
  static std::int64_t term(double v) {
    constexpr double kLimit = 1073741824.0;  // 2^30 m/s²
    const double clamped = v > kLimit ? kLimit : (v < -kLimit ? -kLimit : v);
    return static_cast<std::int64_t>(clamped * 4294967296.0);
  }
  static double to_double(std::int64_t sum) { return static_cast<double>(sum) * 0x1.0p-32; }

 private:
  std::int64_t sum_ = 0;
};

// The forces between touching agents on `self` from `other`, at (dx, dy) = other − self with d2
// from the batch's single-precision offsets (reach: the sum of the radii), as FixedSum terms:
// LightSFM's group repulsion Σ (p_i − p_j) when both are in one group, and the body force.
// NeighbourSums adds them for its agent; the pair step for both agents of a pair.
struct TouchTerms {
  std::int64_t repulsion_x = 0, repulsion_y = 0, body_x = 0, body_y = 0;
};
TouchTerms touch_terms(double dx, double dy, double d2, double reach, bool same_group, double repulsion,
                       double stiffness, std::uint32_t self, std::uint32_t other) {
  TouchTerms t;
  if (same_group) {
    t.repulsion_x = FixedSum::term(-repulsion * dx);
    t.repulsion_y = FixedSum::term(-repulsion * dy);
  }
  if (stiffness > 0.0) {
    const Separation n = separation(dx, dy, d2, self, other);
    t.body_x = FixedSum::term(-stiffness * (reach - n.d) * n.x);
    t.body_y = FixedSum::term(-stiffness * (reach - n.d) * n.y);
  }
  return t;
}

// The social force from the kernel's integer sums and the side push, which pushes along the
// right-hand direction (e_y, −e_x) of the walking direction e.
Vec2 social_total(std::int64_t social_x, std::int64_t social_y, std::int64_t side_push, float ex, float ey) {
  const double side = static_cast<double>(side_push) / kForceQuantum;
  return {static_cast<double>(social_x) / kForceQuantum + side * static_cast<double>(ey),
          static_cast<double>(social_y) / kForceQuantum - side * static_cast<double>(ex)};
}

// v_j·e below −kOncoming (m/s along the walking direction e) is walking towards the agent.
constexpr float kOncoming = 0.1f;

// Frozen state of the candidate neighbours, in the order a scan visits them; positions and
// velocities also in single precision (the gather's).
struct NeighbourArrays {
  const double *x, *y, *vx, *vy, *r;
  const float *fx, *fy, *fvx, *fvy;
  const std::int32_t* group;
  const std::uint32_t* id;     // agent index of each entry (nullptr: the entry index is the agent)
  const std::uint8_t* active;  // nullptr: all entries are active
  std::uint32_t readable;      // entries of fx, fy, fvx, fvy that may be read (see GatherQuery)
};

// Collects the neighbours of one agent within the cut-off, runs the kernel batch by batch and
// sums the quantised forces exactly (core/crowd/neighbour_gather.hpp fills the batch). Group
// repulsion and the body force act only between touching agents — the few candidates the gather
// lists as close — and are computed in double precision.
class NeighbourSums {
 public:
  // `max_radius` bounds every neighbour's radius: only candidates closer than r + max_radius can
  // touch, and only those are re-examined in double precision by flush().
  // (ex, ey): the unit walking direction, (0, 0) without a goal; it defines the band in which
  // speed_cap() looks for the people ahead; `band` is that band's half-width.
  // Neighbours closer than their touching distance + `contact_margin` are listed as contacts
  // (contacts(), for the hard-contact limit); 0 lists none.
  NeighbourSums(std::uint32_t id, double x, double y, double vx, double vy, double r, std::int32_t group,
                double cutoff, double max_radius, const ForceParameters& fp, double body_stiffness, double ex,
                double ey, double contact_margin, double band)
      : id_(id),
        x_(x),
        y_(y),
        vx_(vx),
        vy_(vy),
        r_(r),
        group_(group),
        cutoff2_(cutoff * cutoff),
        // Widened by 1e-5 (relative) so the float-rounded offsets flush() tests can never exceed it.
        close2_((r + max_radius + contact_margin) * (r + max_radius + contact_margin) * (1.0 + 1e-5) +
                2.0 * kTiny2),
        contact_margin_(contact_margin),
        repulsion_factor_(fp.group_repulsion_factor),
        body_stiffness_(body_stiffness),
        ex_(static_cast<float>(ex)),
        ey_(static_cast<float>(ey)),
        heading_(ex != 0.0 || ey != 0.0),
        speed_along_(static_cast<float>(vx * ex + vy * ey)),
        band_(static_cast<float>(band)),
        params_{static_cast<float>(fp.lambda),      static_cast<float>(fp.gamma),
                static_cast<float>(1.0 / fp.gamma), static_cast<float>(fp.n),
                static_cast<float>(fp.n_prime),     static_cast<float>(fp.social_factor)},
        headway_distance_(static_cast<float>(fp.headway_distance)),
        headway_inv_time_(static_cast<float>(fp.headway_time > 0.0 ? 1.0 / fp.headway_time : 0.0)),
        headway_anticipation_(static_cast<float>(fp.headway_anticipation)),
        side_factor_(static_cast<float>(fp.side_factor)),
        side_inv_range_(static_cast<float>(1.0 / fp.side_range)),
        side_bias_(static_cast<float>(fp.side_bias)),
        side_band_(static_cast<float>(fp.side_band)),
        headway_on_(fp.headway_time > 0.0) {}

  [[nodiscard]] std::uint32_t id() const { return id_; }

  // Visits the candidate ranges of `a` in order; `self` is the owner's own entry, which is skipped.
  void scan(const NeighbourArrays& a, GatherRange* ranges, int count, std::uint32_t self) {
    arrays_ = &a;
    const GatherQuery q{a.fx,
                        a.fy,
                        a.fvx,
                        a.fvy,
                        static_cast<float>(x_),
                        static_cast<float>(y_),
                        static_cast<float>(vx_),
                        static_cast<float>(vy_),
                        static_cast<float>(cutoff2_),
                        static_cast<float>(close2_),
                        self,
                        a.active,
                        a.readable};
    GatherBatch b{batch_.dx, batch_.dy, batch_.dvx, batch_.dvy, slot_, close_, kBatch, count_, close_count_};
    int done = 0;
    while (true) {
      done += gather_neighbours(q, ranges + done, count - done, b);
      count_ = b.count;
      close_count_ = b.close_count;
      if (done == count) break;
      flush();  // the batch is full
      b.count = b.close_count = 0;
    }
  }

  void flush() {
    if (count_ == 0) return;
    const NeighbourArrays& a = *arrays_;
    bool tied = false;  // a coincident pair needs a tie direction (else the kernel reads zeros)
    for (int c = 0; c < close_count_; ++c) {
      const int m = close_[c];
      // From the single-precision offsets: the same in the grid and the reference scan.
      const double fdx = batch_.dx[m];
      const double fdy = batch_.dy[m];
      const double d2 = fdx * fdx + fdy * fdy;
      const std::uint32_t k = slot_[m];
      const double reach = r_ + a.r[k];
      const std::uint32_t who = a.id != nullptr ? a.id[k] : k;
      if (contact_margin_ > 0.0 && d2 < (reach + contact_margin_) * (reach + contact_margin_))
        add_contact(who, fdx, fdy, d2, reach, a.vx[k], a.vy[k]);
      if (d2 >= reach * reach) continue;
      if (d2 <= kTiny2) {  // coincident: part along a fixed per-pair direction
        if (!tied) {
          std::fill(std::begin(batch_.tie_x), std::end(batch_.tie_x), 0.0f);
          std::fill(std::begin(batch_.tie_y), std::end(batch_.tie_y), 0.0f);
          tied = true;
        }
        const Vec2 u = tie_break_direction(id_, who);
        batch_.dx[m] = 0.0f;
        batch_.dy[m] = 0.0f;
        batch_.tie_x[m] = static_cast<float>(u.x);
        batch_.tie_y[m] = static_cast<float>(u.y);
      }
      touching(a.x[k] - x_, a.y[k] - y_, d2, reach, a.group[k], who);
    }
    // Pad to whole vectors with inert entries (all zero: the kernels return 0 for them and count
    // them neither ahead nor oncoming, (dx, dy)·e = 0), so no kernel runs a scalar tail.
    const int padded = (count_ + kBatchLanes - 1) / kBatchLanes * kBatchLanes;
    for (int m = count_; m < padded; ++m) batch_.dx[m] = batch_.dy[m] = batch_.dvx[m] = batch_.dvy[m] = 0.0f;
    static constexpr float kNoTies[kBatch] = {};
    const float* tie_x = tied ? batch_.tie_x : kNoTies;
    const float* tie_y = tied ? batch_.tie_y : kNoTies;
    const AheadParams ahead{ex_,
                            ey_,
                            speed_along_,
                            kOncoming,
                            band_,
                            headway_distance_,
                            headway_inv_time_,
                            headway_anticipation_,
                            side_band_,
                            side_bias_,
                            side_factor_,
                            side_inv_range_};
    // The social force, its sum and the terms of the people ahead in one pass over the batch.
    const BatchTotals totals =
        social_kernel_with_ahead(params_, heading_ ? &ahead : nullptr, speed_cap_, padded, batch_.dx,
                                 batch_.dy, batch_.dvx, batch_.dvy, tie_x, tie_y, batch_.fx, batch_.fy);
    if (heading_ && headway_on_) speed_cap_ = totals.ahead.speed_cap;
    side_push_ += totals.ahead.side_push;  // 0 when side_factor is 0 or without a heading
    social_x_ += totals.fx;
    social_y_ += totals.fy;
    close_count_ = 0;
    count_ = 0;
  }

  [[nodiscard]] Vec2 social() const { return social_total(social_x_, social_y_, side_push_, ex_, ey_); }

  // The speed–headway cap: the smallest (s − ℓ + τ·(v_j − v_i)·e)/T over the people ahead in the
  // walking band (band_) who do not come towards the agent; +inf when there is none within the
  // cut-off. A minimum, so independent of the order neighbours are visited in.
  [[nodiscard]] double speed_cap() const { return static_cast<double>(speed_cap_); }

  FixedSum repulsion_x, repulsion_y;
  FixedSum body_x, body_y;

  using Contact = BodyContact;
  static constexpr int kMaxContacts = 32;
  // Sorted by agent id, so the list (and what is done with it) does not depend on the order
  // neighbours were visited in; beyond kMaxContacts (bodies piled up) the highest ids are dropped.
  [[nodiscard]] std::span<const Contact> contacts() const { return {contacts_.data(), contact_count_}; }

 private:
  void add_contact(std::uint32_t who, double dx, double dy, double d2, double reach, double vx, double vy) {
    const Separation n = separation(dx, dy, d2, id_, who);
    Contact c{who, n.x, n.y, n.d - reach, vx, vy};
    std::size_t pos = contact_count_;
    while (pos > 0 && contacts_[pos - 1].who > who) --pos;
    if (pos >= contacts_.size()) return;
    const std::size_t last = std::min(contact_count_, contacts_.size() - 1);
    for (std::size_t k = last; k > pos; --k) contacts_[k] = contacts_[k - 1];
    contacts_[pos] = c;
    contact_count_ = std::min(contact_count_ + 1, contacts_.size());
  }

  void touching(double dx, double dy, double d2, double reach, std::int32_t gj, std::uint32_t idj) {
    const TouchTerms t = touch_terms(dx, dy, d2, reach, group_ >= 0 && gj == group_, repulsion_factor_,
                                     body_stiffness_, id_, idj);
    repulsion_x.add_term(t.repulsion_x);
    repulsion_y.add_term(t.repulsion_y);
    body_x.add_term(t.body_x);
    body_y.add_term(t.body_y);
  }

  std::uint32_t id_;
  double x_, y_, vx_, vy_, r_;
  std::int32_t group_;
  double cutoff2_, close2_, contact_margin_, repulsion_factor_, body_stiffness_;
  std::array<Contact, kMaxContacts>
      contacts_;  // the first contact_count_ are set (no zeroing: 1.5 kB per agent)
  std::size_t contact_count_ = 0;
  float ex_, ey_;
  bool heading_;
  float speed_along_;
  // Someone counts as ahead when their centre is within headway_band × the agent's radius of its
  // walking line (1.5 radii: for equal bodies, when they overlap by more than a quarter of their
  // widths). People offset by more pass by turning their shoulders (staggered rows); the social
  // force keeps them apart.
  float band_;
  float speed_cap_ = std::numeric_limits<float>::infinity();
  SocialParams params_;
  float headway_distance_, headway_inv_time_, headway_anticipation_;
  float side_factor_, side_inv_range_, side_bias_, side_band_;
  bool headway_on_;
  const NeighbourArrays* arrays_ = nullptr;
  int count_ = 0;
  int close_count_ = 0;  // batch entries that may touch the agent (listed in close_)
  std::int64_t social_x_ = 0;
  std::int64_t social_y_ = 0;
  std::int64_t side_push_ = 0;
  std::uint32_t slot_[kBatch];
  std::uint8_t close_[kBatch];
  PairBatch batch_;
};

}  // namespace

Status validate(const SimulationConfig& c) {
  std::vector<FieldError> errors;
  if (!(std::isfinite(c.dt) && c.dt > 0.0 && c.dt <= 0.2))
    errors.push_back(
        FieldError("/dt", "must be in (0, 0.2] s: larger steps make the force integration unstable"));
  if (!(std::isfinite(c.neighbor_cutoff) && c.neighbor_cutoff >= 0.5 && c.neighbor_cutoff <= 20.0))
    errors.push_back(FieldError("/neighbor_cutoff", "must be in [0.5, 20] m"));
  if (!(std::isfinite(c.wall_cutoff) && c.wall_cutoff >= 0.5 && c.wall_cutoff <= 20.0))
    errors.push_back(FieldError("/wall_cutoff", "must be in [0.5, 20] m"));
  if (c.threads < 1 || c.threads > 256) errors.push_back(FieldError("/threads", "must be in [1, 256]"));
  if (!(std::isfinite(c.body_stiffness) && c.body_stiffness >= 0.0 && c.body_stiffness <= 1000.0))
    errors.push_back(
        FieldError("/body_stiffness", "must be in [0, 1000] 1/s² (stiffer contact is unstable at this dt)"));
  if (!(std::isfinite(c.periodic_length) && c.periodic_length >= 0.0 && c.periodic_length <= kMaxCoordinate))
    errors.push_back(FieldError("/periodic_length", "must be 0 (no periodic boundary) or a length in m"));
  else if (c.periodic_length > 0.0 && !(c.periodic_length >= 2.0 * c.neighbor_cutoff + 0.5))
    errors.push_back(FieldError("/periodic_length", "must be at least twice the neighbour cut-off + 0.5 m"));
  if (!finite_in_range(c.periodic_origin, kMaxCoordinate))
    errors.push_back(FieldError("/periodic_origin", "must be finite and within ±1e6 m"));
  if (errors.empty() && kMaxAgentSpeed * c.dt >= c.wall_cutoff)
    errors.push_back(FieldError("/dt", "the fastest agent must move less than wall_cutoff in one step"));
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "invalid simulation configuration", std::move(errors));
  return {};
}

CrowdSimulation::CrowdSimulation(const SimulationConfig& config, RoleTable roles)
    : config_(config),
      roles_(std::move(roles)),
      pool_(std::make_unique<WorkerPool>(config.threads)),
      cells_(std::make_unique<CellIndex>()) {}

CrowdSimulation::CrowdSimulation(CrowdSimulation&&) noexcept = default;
CrowdSimulation& CrowdSimulation::operator=(CrowdSimulation&&) noexcept = default;
CrowdSimulation::~CrowdSimulation() = default;

Result<CrowdSimulation> CrowdSimulation::create(const SimulationConfig& config, RoleTable roles) {
  if (auto ok = validate(config); !ok) return tl::unexpected(ok.error());
  if (!roles.index_of("adult"))
    return fail(ErrorCode::kValidation, "role table has no 'adult' role",
                {FieldError("/roles", "needs an 'adult' role")});
  return CrowdSimulation(config, std::move(roles));
}

Status CrowdSimulation::check_id(AgentId id, const char* what) const {
  if (id.value() >= size())
    return fail(ErrorCode::kNotFound, std::string(what) + ": no agent with id " + std::to_string(id.value()),
                {FieldError("/agent_id", "unknown agent " + std::to_string(id.value()))});
  return {};
}

Result<AgentId> CrowdSimulation::add_agent(const AgentSpec& spec) {
  std::vector<FieldError> errors;
  const auto role_index = roles_.index_of(spec.role);
  if (!role_index) {
    std::string known;
    for (const std::string& n : roles_.names()) known += (known.empty() ? "" : ", ") + n;
    errors.push_back(FieldError("/role", "unknown role '" + spec.role + "' (known: " + known + ")"));
  }
  if (!finite_in_range(spec.position.x, kMaxCoordinate) || !finite_in_range(spec.position.y, kMaxCoordinate))
    errors.push_back(FieldError("/position", "must be finite and within ±1e6 m"));
  if (!finite_in_range(spec.velocity.x, kMaxAgentSpeed) || !finite_in_range(spec.velocity.y, kMaxAgentSpeed))
    errors.push_back(FieldError("/velocity", "components must be finite and within ±8 m/s"));
  if (spec.yaw && !std::isfinite(*spec.yaw)) errors.push_back(FieldError("/yaw", "must be finite"));
  if (spec.desired_speed && !(std::isfinite(*spec.desired_speed) && *spec.desired_speed >= 0.0 &&
                              *spec.desired_speed <= kMaxAgentSpeed))
    errors.push_back(FieldError("/desired_speed", "must be in [0, 8] m/s"));
  if (spec.radius && !(std::isfinite(*spec.radius) && *spec.radius >= 0.05 && *spec.radius <= 1.5))
    errors.push_back(FieldError("/radius", "must be in [0.05, 1.5] m"));
  if (spec.group_id < -1)
    errors.push_back(FieldError("/group_id", "must be -1 (no group) or a non-negative id"));
  if (size() >= UINT32_MAX - 1) errors.push_back(FieldError("", "too many agents"));
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid agent", std::move(errors));

  const RoleParameters& role = roles_.at(*role_index);
  const auto index = static_cast<std::uint32_t>(size());
  AgentMeta meta;
  meta.seed = config_.seed ^ fnv1a64("agent:" + std::to_string(index));
  Rng rng(meta.seed);
  double v0 = spec.desired_speed
                  ? *spec.desired_speed
                  : std::clamp(rng.normal(role.speed.mean, role.speed.sd), role.speed.min, role.speed.max);
  const double vmax = v0 * role.max_speed_factor;
  if (vmax * config_.dt >= config_.wall_cutoff)
    return fail(ErrorCode::kValidation, "invalid agent",
                {FieldError("/desired_speed", "too fast for dt and wall_cutoff")});

  const std::int32_t group = group_slot(spec.group_id);
  meta.activity = spec.activity;
  meta.intent = spec.intent;
  meta.tags = spec.tags;
  meta.group_id = spec.group_id;

  px_.push_back(wrap_x(spec.position.x));
  py_.push_back(spec.position.y);
  // Start no faster than the agent may go.
  double vx = spec.velocity.x;
  double vy = spec.velocity.y;
  const double s = std::sqrt(vx * vx + vy * vy);
  if (s > vmax) {
    vx = s > 0.0 ? vx * vmax / s : 0.0;
    vy = s > 0.0 ? vy * vmax / s : 0.0;
  }
  vx_.push_back(vx);
  vy_.push_back(vy);
  yaw_.push_back(spec.yaw ? wrap_angle(*spec.yaw) : (vx * vx + vy * vy > kTiny2 ? std::atan2(vy, vx) : 0.0));
  omega_.push_back(0.0);
  next_.push_back({0.0, 0.0, 0.0, 0.0});
  radius_.push_back(spec.radius ? *spec.radius : role.radius);
  v0_.push_back(v0);
  vmax_.push_back(vmax);
  maxima_dirty_ = true;
  // Whether every agent's role shares the pair terms with the first one's (pairs_once()).
  if (!role_.empty() && !same_pair_terms(roles_.at(role_.front()).forces, roles_.at(*role_index).forces))
    mixed_pair_terms_ = true;
  role_.push_back(static_cast<std::uint16_t>(*role_index));
  group_.push_back(group);
  groups_dirty_ = groups_dirty_ || group >= 0;
  active_.push_back(spec.activity == Activity::kExited ? 0 : 1);
  driven_.push_back(kNotDriven);
  has_goal_.push_back(0);
  gx_.push_back(0.0);
  gy_.push_back(0.0);
  gr_.push_back(0.0);
  meta_.push_back(std::move(meta));
  return AgentId(index);
}

Status CrowdSimulation::add_wall(Vec2 a, Vec2 b) {
  std::vector<FieldError> errors;
  if (!finite_in_range(a.x, kMaxCoordinate) || !finite_in_range(a.y, kMaxCoordinate))
    errors.push_back(FieldError("/a", "must be finite and within ±1e6 m"));
  if (!finite_in_range(b.x, kMaxCoordinate) || !finite_in_range(b.y, kMaxCoordinate))
    errors.push_back(FieldError("/b", "must be finite and within ±1e6 m"));
  if (walls_.size() >= UINT32_MAX / 2) errors.push_back(FieldError("", "too many walls"));
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid wall", std::move(errors));
  walls_.push_back({a, b});
  walls_dirty_ = true;
  return {};
}

Status CrowdSimulation::add_polyline(std::span<const Vec2> points, bool closed) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2& p = points[i];
    if (!finite_in_range(p.x, kMaxCoordinate) || !finite_in_range(p.y, kMaxCoordinate))
      return fail(ErrorCode::kValidation, "invalid polyline",
                  {FieldError("/points/" + std::to_string(i), "must be finite and within ±1e6 m")});
  }
  for (std::size_t i = 0; i + 1 < points.size(); ++i) (void)add_wall(points[i], points[i + 1]);
  if (closed && points.size() > 2) (void)add_wall(points.back(), points.front());
  if (points.size() == 1) (void)add_wall(points[0], points[0]);
  return {};
}

Status CrowdSimulation::set_goals(AgentId id, std::vector<Goal> goals, bool cyclic) {
  if (auto ok = check_id(id, "set_goals"); !ok) return ok;
  std::vector<FieldError> errors;
  for (std::size_t k = 0; k < goals.size(); ++k) {
    const Goal& g = goals[k];
    if (!finite_in_range(g.position.x, kMaxCoordinate) || !finite_in_range(g.position.y, kMaxCoordinate))
      errors.push_back(
          FieldError("/goals/" + std::to_string(k) + "/position", "must be finite and within ±1e6 m"));
    if (!(std::isfinite(g.radius) && g.radius >= 0.0 && g.radius <= 1000.0))
      errors.push_back(FieldError("/goals/" + std::to_string(k) + "/radius", "must be in [0, 1000] m"));
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid goals", std::move(errors));
  const std::uint32_t i = id.value();
  AgentMeta& m = meta_[i];
  m.goals = std::move(goals);
  m.goal_index = 0;
  m.cyclic = cyclic;
  has_goal_[i] = m.goals.empty() ? 0 : 1;
  if (has_goal_[i]) {
    gx_[i] = m.goals[0].position.x;
    gy_[i] = m.goals[0].position.y;
    gr_[i] = m.goals[0].radius;
  }
  m.intent.goal_id = has_goal_[i] ? 0 : -1;
  return {};
}

Status CrowdSimulation::set_desired_speed(AgentId id, double speed) {
  if (auto ok = check_id(id, "set_desired_speed"); !ok) return ok;
  const double factor = roles_.at(role_[id.value()]).max_speed_factor;
  if (!(std::isfinite(speed) && speed >= 0.0 && speed <= kMaxAgentSpeed) ||
      speed * factor * config_.dt >= config_.wall_cutoff)
    return fail(ErrorCode::kValidation, "invalid desired speed",
                {FieldError("/desired_speed", "must be in [0, 8] m/s")});
  v0_[id.value()] = speed;
  vmax_[id.value()] = speed * factor;
  maxima_dirty_ = true;
  return {};
}

Status CrowdSimulation::set_activity(AgentId id, Activity activity) {
  if (auto ok = check_id(id, "set_activity"); !ok) return ok;
  meta_[id.value()].activity = activity;
  if (activity == Activity::kExited) active_[id.value()] = 0;
  maxima_dirty_ = true;
  return {};
}

Status CrowdSimulation::set_intent(AgentId id, Intent intent) {
  if (auto ok = check_id(id, "set_intent"); !ok) return ok;
  meta_[id.value()].intent = std::move(intent);
  return {};
}

Status CrowdSimulation::set_bt_node(AgentId id, std::string node) {
  if (auto ok = check_id(id, "set_bt_node"); !ok) return ok;
  meta_[id.value()].bt_node = std::move(node);
  return {};
}

Status CrowdSimulation::set_active(AgentId id, bool active) {
  if (auto ok = check_id(id, "set_active"); !ok) return ok;
  active_[id.value()] = active ? 1 : 0;
  maxima_dirty_ = true;
  if (!active) {
    vx_[id.value()] = 0.0;
    vy_[id.value()] = 0.0;
  }
  return {};
}

Status CrowdSimulation::set_driven(AgentId id, Presence presence) {
  if (auto ok = check_id(id, "set_driven"); !ok) return ok;
  const std::uint32_t i = id.value();
  driven_[i] = static_cast<std::uint8_t>(1 + static_cast<std::uint8_t>(presence));
  has_goal_[i] = 0;
  meta_[i].goals.clear();
  meta_[i].intent.goal_id = -1;
  return {};
}

Status CrowdSimulation::set_driven_state(AgentId id, Pose2 pose, Twist2 twist) {
  if (auto ok = check_id(id, "set_driven_state"); !ok) return ok;
  const std::uint32_t i = id.value();
  std::vector<FieldError> errors;
  if (driven_[i] == kNotDriven) errors.push_back(FieldError("/agent_id", "agent is not driven"));
  if (!finite_in_range(pose.x, kMaxCoordinate) || !finite_in_range(pose.y, kMaxCoordinate))
    errors.push_back(FieldError("/pose", "must be finite and within ±1e6 m"));
  if (!std::isfinite(pose.yaw)) errors.push_back(FieldError("/pose/yaw", "must be finite"));
  const double speed = std::hypot(twist.vx, twist.vy);
  if (!(std::isfinite(speed) && speed <= kMaxAgentSpeed))
    errors.push_back(FieldError("/twist", "speed must be finite and at most 8 m/s"));
  if (!finite_in_range(twist.omega, 20.0))
    errors.push_back(FieldError("/twist/omega", "must be within ±20 rad/s"));
  if (!errors.empty()) return fail(ErrorCode::kValidation, "invalid driven state", std::move(errors));
  px_[i] = wrap_x(pose.x);
  py_[i] = pose.y;
  yaw_[i] = wrap_angle(pose.yaw);
  vx_[i] = twist.vx;
  vy_[i] = twist.vy;
  omega_[i] = twist.omega;
  // The contact margin of the others assumes no one is faster than the fastest speed limit.
  vmax_[i] = std::max(vmax_[i], speed);
  maxima_dirty_ = true;
  return {};
}

std::int32_t CrowdSimulation::group_slot(std::int64_t group_id) {
  if (group_id < 0) return -1;
  auto [it, inserted] = group_index_.try_emplace(group_id, static_cast<std::int32_t>(group_ids_.size()));
  if (inserted) {
    group_ids_.push_back(group_id);
    group_cx_.push_back(0.0);
    group_cy_.push_back(0.0);
    group_size_.push_back(0);
  }
  return it->second;
}

Status CrowdSimulation::set_group(AgentId id, std::int64_t group_id) {
  if (auto ok = check_id(id, "set_group"); !ok) return ok;
  if (group_id < -1)
    return fail(ErrorCode::kValidation, "invalid group",
                {FieldError("/group_id", "must be -1 (no group) or a non-negative id")});
  group_[id.value()] = group_slot(group_id);
  meta_[id.value()].group_id = group_id;
  groups_dirty_ = true;
  return {};
}

std::optional<Goal> CrowdSimulation::current_goal(AgentId id) const {
  const std::uint32_t i = id.value();
  if (i >= size() || !has_goal_[i]) return std::nullopt;
  return Goal{{gx_[i], gy_[i]}, gr_[i]};
}

PedestrianState CrowdSimulation::state(AgentId id) const {
  const std::uint32_t i = id.value();
  const AgentMeta& m = meta_.at(i);
  PedestrianState s;
  s.id = id;
  s.pose = {px_[i], py_[i], yaw_[i]};
  s.twist = {vx_[i], vy_[i], omega_[i]};
  s.activity = m.activity;
  s.role = roles_.at(role_[i]).name;
  s.intent = m.intent;
  s.group_id = m.group_id;
  s.proxemics = roles_.at(role_[i]).proxemics;
  s.metadata.seed = m.seed;
  s.metadata.bt_node = m.bt_node;
  s.metadata.tags = m.tags;
  return s;
}

void CrowdSimulation::prepare_step() {
  if (walls_dirty_) {
    wall_grid_ = WallGrid(walls_, config_.wall_cutoff);
    wall_link_start_.assign(1, 0);
    wall_links_.clear();
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      for (const Vec2 end : {walls_[w].a, walls_[w].b}) {
        for (std::uint32_t o : wall_grid_.near(end.x, end.y))
          if (o != w && point_segment_distance(end, walls_[o].a, walls_[o].b) <= 1e-9)
            wall_links_.push_back(o);
        wall_link_start_.push_back(static_cast<std::uint32_t>(wall_links_.size()));
      }
    }
    walls_dirty_ = false;
  }
  if (config_.hard_contact) {
    contact_ids_.resize(size() * kStoredContacts);
    // Not emptied: the step writes the count of every agent separate_bodies() reads one of
    // (active and not driven), and emptying 10,000 counts the other thread had just written cost
    // 10–20 µs of serial time a step.
    contact_count_.resize(size(), 0);
    moved_.resize(size(), 0);
  }
  // Every agent's inputs to its step in one record (the passes over the agents in the cells'
  // order read one or two cache lines of an agent instead of one of each of 14 arrays).
  // Each group's members in agent order (counting sort by group), rebuilt when one changed.
  const std::size_t groups = group_size_.size();
  if (groups_dirty_) {
    group_member_start_.assign(groups + 1, 0);
    for (const std::int32_t g : group_)
      if (g >= 0) ++group_member_start_[static_cast<std::size_t>(g) + 1];
    for (std::size_t g = 0; g < groups; ++g) group_member_start_[g + 1] += group_member_start_[g];
    group_members_.resize(group_member_start_[groups]);
    std::vector<std::uint32_t> next(group_member_start_.begin(), group_member_start_.end() - 1);
    for (std::size_t i = 0; i < size(); ++i)
      if (group_[i] >= 0)
        group_members_[next[static_cast<std::size_t>(group_[i])]++] = static_cast<std::uint32_t>(i);
    groups_dirty_ = false;
  }
  // The largest radius and speed limit of the active agents (exact in any order), recomputed
  // only after one of them may have changed.
  if (maxima_dirty_) {
    max_radius_ = 0.0;
    max_vmax_ = 0.0;
    for (std::size_t i = 0; i < size(); ++i) {
      if (!active_[i]) continue;
      max_radius_ = std::max(max_radius_, radius_[i]);
      max_vmax_ = std::max(max_vmax_, vmax_[i]);
    }
    maxima_dirty_ = false;
  }
  // Each group's centre: its active members' positions summed in agent order (the same bits as
  // one pass over all agents), groups in parallel.
  pool_->parallel_for(groups, 256, [&](std::size_t begin, std::size_t end) {
    for (std::size_t g = begin; g < end; ++g) {
      double sx = 0.0;
      double sy = 0.0;
      std::uint32_t count = 0;
      for (std::uint32_t m = group_member_start_[g]; m < group_member_start_[g + 1]; ++m) {
        const std::uint32_t i = group_members_[m];
        if (!active_[i]) continue;
        sx += px_[i];
        sy += py_[i];
        ++count;
      }
      group_size_[g] = count;
      group_cx_[g] = count == 0 ? sx : sx / static_cast<double>(count);
      group_cy_[g] = count == 0 ? sy : sy / static_cast<double>(count);
    }
  });
}

double CrowdSimulation::wrap_x(double x) const {
  const double length = config_.periodic_length;
  if (length <= 0.0) return x;
  const double lo = config_.periodic_origin;
  if (x >= lo + length) {
    x -= length;
  } else if (x < lo) {
    x += length;
  }
  if (x < lo || x >= lo + length) {  // more than one period away (only when agents are added)
    x = lo + std::fmod(x - lo, length);
    if (x < lo) x += length;
    if (x >= lo + length) x = lo;
  }
  return x;
}

// An agent this close to one end of the period has an image beyond the other end that someone
// may see within the cut-off (1e-6 m of slack: an image too many is filtered by the cut-off).
bool CrowdSimulation::near_low_end(double x) const {
  return config_.periodic_length > 0.0 && x < config_.periodic_origin + config_.neighbor_cutoff + 1e-6;
}

bool CrowdSimulation::near_high_end(double x) const {
  return config_.periodic_length > 0.0 &&
         x >= config_.periodic_origin + config_.periodic_length - config_.neighbor_cutoff - 1e-6;
}

void CrowdSimulation::build_images(Images& m) const {
  m.x = px_;
  m.y = py_;
  m.vx = vx_;
  m.vy = vy_;
  m.r = radius_;
  m.group = group_;
  m.active.resize(size());
  m.id.resize(size());
  for (std::uint32_t i = 0; i < size(); ++i) {
    m.id[i] = i;
    m.active[i] = seen(i) ? 1 : 0;
  }
  const double length = config_.periodic_length;
  for (std::uint32_t i = 0; i < size(); ++i) {
    if (!seen(i)) continue;
    double x = 0.0;
    if (near_low_end(px_[i])) {
      x = px_[i] + length;
    } else if (near_high_end(px_[i])) {
      x = px_[i] - length;
    } else {
      continue;
    }
    m.x.push_back(x);
    m.y.push_back(py_[i]);
    m.vx.push_back(vx_[i]);
    m.vy.push_back(vy_[i]);
    m.r.push_back(radius_[i]);
    m.group.push_back(group_[i]);
    m.active.push_back(1);
    m.id.push_back(i);
  }
  const std::size_t entries = m.x.size();
  for (std::vector<float>* v : {&m.fx, &m.fy, &m.fvx, &m.fvy}) v->assign(entries + kGatherSlack, 0.0f);
  for (std::size_t k = 0; k < entries; ++k) {
    m.fx[k] = static_cast<float>(m.x[k]);
    m.fy[k] = static_cast<float>(m.y[k]);
    m.fvx[k] = static_cast<float>(m.vx[k]);
    m.fvy[k] = static_cast<float>(m.vy[k]);
  }
  for (std::size_t k = entries; k < entries + kGatherSlack; ++k) m.fx[k] = m.fy[k] = 1e30f;
}

void CrowdSimulation::build_cells() {
  CellIndex& c = *cells_;
  const std::size_t n = size();
  const double length = config_.periodic_length;
  // The agents in `parts` fixed ranges, one per thread: each part's seen agents become entries in
  // agent order, and (periodic boundary) its agents' images a part of their own after all agents.
  // Every pass below runs part by part in parallel; the results do not depend on which thread
  // runs which part, and the counting sort keeps the entries' order within a cell (stable), as
  // one serial pass over the entries would.
  const std::size_t parts = std::max<std::size_t>(1, std::min<std::size_t>(pool_->threads(), n / 256));
  const std::size_t per_part = (n + parts - 1) / std::max<std::size_t>(parts, 1);
  const auto part_begin = [&](std::size_t p) { return std::min(n, p * per_part); };
  const bool periodic = length > 0.0;
  const bool pairs = pairs_once();  // step_pairs reads neither cell_of nor the double copies
  const std::size_t lists = periodic ? 2 * parts : parts;  // agents' parts, then images' parts
  c.cell_of.resize(n);
  c.parts.assign(lists, CellIndex::Part{});
  auto& list = c.parts;
  // Pass 1: each part's entries and bounding box (kept in registers: the parts' slots share
  // cache lines).
  pool_->parallel_for(parts, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t p = begin; p < end; ++p) {
      double bx0 = 1e300, by0 = 1e300, bx1 = -1e300, by1 = -1e300;
      std::size_t count = 0;
      std::size_t images = 0;
      for (std::size_t i = part_begin(p); i < part_begin(p + 1); ++i) {
        if (!pairs) c.cell_of[i] = kNoCell;
        if (!seen(i)) continue;
        ++count;
        const double x = px_[i];
        const double y = py_[i];
        by0 = std::min(by0, y);
        by1 = std::max(by1, y);
        bx0 = std::min(bx0, x);
        bx1 = std::max(bx1, x);
        if (!periodic) continue;
        double image = x;
        if (near_low_end(x)) {
          image = x + length;
        } else if (near_high_end(x)) {
          image = x - length;
        } else {
          continue;
        }
        ++images;
        bx0 = std::min(bx0, image);
        bx1 = std::max(bx1, image);
      }
      list[p].count = count;
      list[p].box = {bx0, by0, bx1, by1};
      if (periodic) {
        list[parts + p].count = images;
        list[parts + p].box = {bx0, by0, bx1, by1};
      }
    }
  });
  std::array<double, 4> box{1e300, 1e300, -1e300, -1e300};
  std::size_t entries = 0;
  for (CellIndex::Part& l : list) {
    l.first = entries;
    entries += l.count;
    box[0] = std::min(box[0], l.box[0]);
    box[1] = std::min(box[1], l.box[1]);
    box[2] = std::max(box[2], l.box[2]);
    box[3] = std::max(box[3], l.box[3]);
  }
  const std::size_t active = periodic ? list[parts].first : entries;
  const double x0 = box[0], y0 = box[1], x1 = box[2], y1 = box[3];
  c.order.resize(entries);
  c.agents.resize(active);
  if (active == 0) {
    c.nx = c.ny = 0;
    c.start.assign(1, 0);
    return;
  }
  // Cells a third of the cut-off wide, so the scanned cells hug the cut-off disc; in sparse or
  // spread-out crowds the cells grow to keep at most ~2 cells per agent.
  const double max_cells = std::max(1024.0, 2.0 * static_cast<double>(entries));
  auto cells_for = [&](double size) {
    return (std::floor((x1 - x0) / size) + 1.0) * (std::floor((y1 - y0) / size) + 1.0);
  };
  double cell = config_.neighbor_cutoff / 3.0;
  while (cells_for(cell) > max_cells) cell *= 1.25;
  c.cell = cell;
  c.origin_x = x0;
  c.origin_y = y0;
  c.inv_cell = 1.0 / cell;
  c.nx = static_cast<std::int64_t>((x1 - x0) * c.inv_cell) + 1;
  c.ny = static_cast<std::int64_t>((y1 - y0) * c.inv_cell) + 1;
  const auto cells = static_cast<std::size_t>(c.nx * c.ny);
  c.entry_agent.resize(entries);
  c.entry_x.resize(entries);
  c.entry_cell.resize(entries);
  // Per list and cell, its entries' count, then the sorted position of its first entry there.
  c.list_cell.resize(lists * cells);
  // Pass 2: the entries, their cells and the counts.
  pool_->parallel_for(parts, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t p = begin; p < end; ++p) {
      std::uint32_t* counts = c.list_cell.data() + p * cells;
      std::uint32_t* image_counts = periodic ? c.list_cell.data() + (parts + p) * cells : nullptr;
      std::fill(counts, counts + cells, 0u);
      if (periodic) std::fill(image_counts, image_counts + cells, 0u);
      std::size_t e = list[p].first;
      std::size_t image = periodic ? list[parts + p].first : 0;
      const auto place = [&](std::size_t at, std::uint32_t i, double x, std::uint32_t* count) {
        const auto cx = std::min(static_cast<std::int64_t>((x - x0) * c.inv_cell), c.nx - 1);
        const auto cy = std::min(static_cast<std::int64_t>((py_[i] - y0) * c.inv_cell), c.ny - 1);
        const auto k = static_cast<std::uint32_t>(cy * c.nx + cx);
        c.entry_agent[at] = i;
        c.entry_x[at] = x;
        c.entry_cell[at] = k;
        ++count[k];
      };
      for (std::size_t i = part_begin(p); i < part_begin(p + 1); ++i) {
        if (!seen(i)) continue;
        const auto agent = static_cast<std::uint32_t>(i);
        place(e++, agent, px_[i], counts);
        if (!periodic) continue;
        if (near_low_end(px_[i])) {
          place(image++, agent, px_[i] + length, image_counts);
        } else if (near_high_end(px_[i])) {
          place(image++, agent, px_[i] - length, image_counts);
        }
      }
    }
  });
  // Cell by cell, the lists in order: each entry's sorted position is its cell's start plus the
  // entries of earlier lists there plus those before it in its own list.
  c.start.resize(cells + 1);
  std::uint32_t running = 0;
  for (std::size_t k = 0; k < cells; ++k) {
    c.start[k] = running;
    for (std::size_t l = 0; l < lists; ++l) {
      std::uint32_t& slot = c.list_cell[l * cells + k];
      const std::uint32_t count = slot;
      slot = running;
      running += count;
    }
  }
  c.start[cells] = running;
  // Three inert entries past the end (far away, never within the cut-off) so the vector gather
  // may read whole groups of four.
  c.x.resize(entries);
  c.y.resize(entries);
  c.vx.resize(entries);
  c.vy.resize(entries);
  for (std::vector<float>* v : {&c.fx, &c.fy, &c.fvx, &c.fvy}) v->resize(entries + kGatherSlack);
  for (std::size_t k = entries; k < entries + kGatherSlack; ++k) {
    c.fx[k] = c.fy[k] = 1e30f;
    c.fvx[k] = c.fvy[k] = 0.0f;
  }
  c.r.resize(entries);
  c.inputs.resize(entries);
  c.group.resize(entries);
  c.id.resize(entries);
  // Pass 3: each entry to its sorted position, with its copies.
  pool_->parallel_for(lists, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t l = begin; l < end; ++l) {
      std::uint32_t* next = c.list_cell.data() + l * cells;
      for (std::size_t e = list[l].first; e < list[l].first + list[l].count; ++e) {
        const std::uint32_t k = next[c.entry_cell[e]]++;
        const std::uint32_t i = c.entry_agent[e];
        const AgentInputs in = inputs_of(i);
        c.inputs[k] = in;
        c.id[k] = i;
        // step_pairs fills the single-precision copies and c.agents from c.inputs and c.id in its
        // first pass, which reads the inputs in sorted order anyway (≈ 1.5 % less time per step
        // than writing all seven arrays here).
        if (pairs) continue;  // (no periodic boundary: entries = agents)
        if (periodic) c.order[k] = static_cast<std::uint32_t>(e);
        if (e < active) c.cell_of[i] = k;  // the agent's position in the sorted arrays
        if (!periodic) c.agents[k] = i;
        c.fx[k] = static_cast<float>(c.entry_x[e]);
        c.fy[k] = static_cast<float>(in.y);
        c.fvx[k] = static_cast<float>(in.vx);
        c.fvy[k] = static_cast<float>(in.vy);
        // The scan agent by agent reads these too.
        c.x[k] = c.entry_x[e];
        c.y[k] = in.y;
        c.vx[k] = in.vx;
        c.vy[k] = in.vy;
        c.r[k] = in.r;
        c.group[k] = in.group;
      }
    }
  });
  if (periodic) {  // the agents in sorted order, without the images
    std::size_t a = 0;
    for (std::size_t k = 0; k < entries; ++k)
      if (c.order[k] < active) c.agents[a++] = c.entry_agent[c.order[k]];
  }
}

inline CrowdSimulation::AgentInputs CrowdSimulation::inputs_of(std::uint32_t i) const {
  return {px_[i], py_[i], vx_[i], vy_[i],    radius_[i], v0_[i],     vmax_[i],
          gx_[i], gy_[i], gr_[i], group_[i], role_[i],   driven_[i], has_goal_[i]};
}

namespace {

// Neighbour scans: both visit candidate agents in a fixed order; NeighbourSums applies the cut-off.
// The grid scan visits, row by row, only the cells that can hold an agent within the cut-off
// (each row's x-range shrinks with its distance from the agent), widened by 1e-9 m so rounding
// can never hide a neighbour.
struct GridScan {
  const std::vector<std::uint32_t>& start;
  const std::vector<std::uint32_t>& position_of;  // agent -> its entry in the sorted arrays
  double origin_x, origin_y, cell, inv_cell, cutoff;
  std::int64_t nx, ny;
  NeighbourArrays arrays;

  void operator()(NeighbourSums& s, double x, double y) const {
    const std::uint32_t self = position_of[s.id()];
    GatherRange ranges[kMaxGridRows];
    const GridQuery q{start.data(), origin_x, origin_y, cell, inv_cell, cutoff + 1e-9, nx, ny, x, y};
    const int count = grid_ranges(q, ranges);
    s.scan(arrays, ranges, count, self);
  }
};

struct FullScan {
  std::uint32_t n;
  NeighbourArrays arrays;
  void operator()(NeighbourSums& s, double /*x*/, double /*y*/) const {
    GatherRange all{0, n};
    s.scan(arrays, &all, 1, s.id());
  }
};

// The O(N²) scan over every agent and its periodic images (step_reference, forces).
template <class ImagesT>
FullScan full_scan(const ImagesT& m) {
  const auto entries = static_cast<std::uint32_t>(m.x.size());
  return {
      entries,
      {m.x.data(), m.y.data(), m.vx.data(), m.vy.data(), m.r.data(), m.fx.data(), m.fy.data(), m.fvx.data(),
       m.fvy.data(), m.group.data(), m.id.data(), m.active.data(), static_cast<std::uint32_t>(m.fx.size())}};
}

}  // namespace

template <class Neighbours>
void CrowdSimulation::advance_agent(std::uint32_t i, const AgentInputs& in, const Neighbours& neighbours,
                                    ForceBreakdown* breakdown) {
  if (in.driven != kNotDriven) {  // moved from outside: stays where it was put
    hold_driven(i, in, breakdown);
    return;
  }
  const AgentPrep prep = prepare_agent(in);
  // Social, group-repulsion and body forces from neighbours within the cut-off.
  const ForceParameters& fp = roles_.at(in.role).forces;
  thread_local std::vector<BodyContact> contacts;  // (finish_agent may reorder them)
  NeighbourTotals t;
  {
    NeighbourSums sums(i, in.x, in.y, in.vx, in.vy, in.r, in.group, config_.neighbor_cutoff, max_radius_, fp,
                       config_.body_stiffness, prep.ex, prep.ey, contact_margin(in),
                       (prep.wall_sides == 3u ? fp.zipper_band : fp.headway_band) * in.r);
    neighbours(sums, in.x, in.y);
    sums.flush();
    t.speed_cap = sums.speed_cap();
    t.social = sums.social();
    t.repulsion = {sums.repulsion_x.value(), sums.repulsion_y.value()};
    t.body = {sums.body_x.value(), sums.body_y.value()};
    contacts.assign(sums.contacts().begin(), sums.contacts().end());
  }
  finish_agent(i, in, prep, t, contacts, breakdown);
}

void CrowdSimulation::hold_driven(std::uint32_t i, const AgentInputs& in, ForceBreakdown* breakdown) {
  if (breakdown != nullptr) *breakdown = ForceBreakdown{};
  next_[i] = {in.x, in.y, in.vx, in.vy};
  if (config_.hard_contact) contact_count_[i] = 0;
}

double CrowdSimulation::contact_margin(const AgentInputs& in) const {
  // Neighbours the two bodies could reach within one step (with 0.05 m to spare) are contacts.
  return config_.hard_contact ? config_.dt * (in.vmax + max_vmax_) + 0.05 : 0.0;
}

CrowdSimulation::AgentPrep CrowdSimulation::prepare_agent(const AgentInputs& in) const {
  const RoleParameters& role = roles_.at(in.role);
  const ForceParameters& fp = role.forces;
  const double x = in.x;
  const double y = in.y;
  const double vx = in.vx;
  const double vy = in.vy;
  const double r = in.r;
  AgentPrep prep;
  ForceBreakdown f;
  // Desired force (computed after the neighbour scan): relax towards the desired speed along the
  // goal direction (LightSFM computeDesiredForce); brake with −v/τ when there is no goal or it is
  // reached.
  double ex = 0.0;
  double ey = 0.0;
  double goal_distance = 0.0;
  bool heading = false;
  if (in.has_goal) {
    const double dx = in.gx - x;
    const double dy = in.gy - y;
    const double dist2 = dx * dx + dy * dy;
    if (dist2 > in.gr * in.gr && dist2 > kTiny2) {
      const double dist = std::sqrt(dist2);
      goal_distance = dist;
      ex = dx / dist;
      ey = dy / dist;
      heading = true;
    }
  }
  // Obstacle force: the nearest point of every wall within the cut-off pushes with
  // A·exp(−(d − r)/σ). An end shared with other walls pushes (once) only where it is the nearest
  // point of all of them (nearest_point_is). When the nearest point is a wall end — a free end (a
  // door jamb in a thin wall) or a corner seen from outside (a jamb in a thick wall) — and the body
  // clears every wall meeting there walking straight to its goal, the end only pushes across the
  // walking direction: it steers, it does not brake (nor push from behind once passed). See
  // docs/crowd.md, "doorways".
  const std::span<const std::uint32_t> near_walls = wall_grid_.near(x, y);
  // Walls within zipper_reach, abreast: bit 1 on the left of the walking line, bit 2 on its right
  // (both: the agent is in or just before a narrow opening, or faces a wall's corner or a pillar
  // head-on, where the narrower band changes little).
  unsigned wall_sides = 0;
  unsigned inside_sides = 0;   // the same, from walls' insides only (a passage, not a door's jambs)
  double inside_left = 1e300;  // and the distances to the nearest such wall on each side
  double inside_right = 1e300;
  {
    const double wc2 = config_.wall_cutoff * config_.wall_cutoff;
    const double sweep = std::min(goal_distance, config_.wall_cutoff);
    // Wall ends already applied (at most 8 kept); not zeroed, only the first vertex_count are read
    // (zeroing them cost 2 % of a step).
    double vertex_x[8];
    double vertex_y[8];
    std::size_t vertex_count = 0;
    const double zr2 = fp.zipper_reach * fp.zipper_reach;
    double side_x = 0.0;  // the pushes of walls' insides, summed apart
    double side_y = 0.0;
    // A wall whose bounding box is farther than √skip2 is beyond the cut-off and beyond both
    // distances finish_agent compares wall_d2 with — one step's reach, r + dt·kMaxAgentSpeed, and
    // one step's move, less than wall_cutoff (validated) — so its exact distance (a division)
    // would change nothing: skipped. The 2 % covers rounding, even at the 10^6 m coordinate bound.
    const double reach = r + config_.dt * kMaxAgentSpeed;
    const double skip2 = std::max(wc2, reach * reach) * 1.02 + 1e-9;
    for (std::uint32_t w : near_walls) {
      const WallSegment& s = walls_[w];
      const double box_x = std::max({std::min(s.a.x, s.b.x) - x, x - std::max(s.a.x, s.b.x), 0.0});
      const double box_y = std::max({std::min(s.a.y, s.b.y) - y, y - std::max(s.a.y, s.b.y), 0.0});
      if (box_x * box_x + box_y * box_y > skip2) continue;
      const double ux = s.b.x - s.a.x;
      const double uy = s.b.y - s.a.y;
      const double len2 = ux * ux + uy * uy;
      double t = 0.0;
      if (len2 > 0.0) t = std::clamp(((x - s.a.x) * ux + (y - s.a.y) * uy) / len2, 0.0, 1.0);
      const Vec2 q{s.a.x + t * ux, s.a.y + t * uy};
      const double dx = x - q.x;
      const double dy = y - q.y;
      const double d2 = dx * dx + dy * dy;
      prep.wall_d2 = std::min(prep.wall_d2, d2);
      if (d2 > wc2) continue;
      const unsigned end_bit = t == 0.0 ? 1u : (t == 1.0 ? 2u : 0u);  // nearest point at an end
      if (heading && d2 <= zr2) {  // walls beside the walking line, abreast of the agent (zipper)
        const double ahead = -(dx * ex + dy * ey);
        const double left = -(ex * dy - ey * dx);  // > 0: the wall point is left of the line
        const unsigned side = left > 0.0 ? 1u : (left < 0.0 ? 2u : 0u);
        if (std::abs(ahead) <= fp.zipper_reach) {
          wall_sides |= side;
          if (end_bit == 0) {
            inside_sides |= side;
            double& nearest = side == 1u ? inside_left : inside_right;
            nearest = std::min(nearest, std::sqrt(d2));
          }
        }
      }
      // With end_bit: the wall end's index into wall_link_start_ (2w for end a, 2w + 1 for end b).
      const std::size_t end = 2 * static_cast<std::size_t>(w) + (end_bit == 2u ? 1 : 0);
      if (end_bit != 0) {
        const Vec2 v = t == 0.0 ? s.a : s.b;
        bool hidden = false;
        for (std::uint32_t k = wall_link_start_[end]; k < wall_link_start_[end + 1] && !hidden; ++k)
          hidden = !nearest_point_is({x, y}, v, walls_[wall_links_[k]]);
        if (hidden) continue;
        bool seen = false;
        for (std::size_t k = 0; k < vertex_count; ++k)
          seen = seen || (vertex_x[k] == v.x && vertex_y[k] == v.y);
        if (seen) continue;
        if (vertex_count < std::size(vertex_x)) {
          vertex_x[vertex_count] = v.x;
          vertex_y[vertex_count++] = v.y;
        }
      }
      double nx = 0.0;
      double ny = 0.0;
      double d = 0.0;
      if (d2 > kTiny2) {
        d = std::sqrt(d2);
        nx = dx / d;
        ny = dy / d;
      } else if (len2 > 0.0) {
        // Standing on the wall: push along the wall normal, against the current velocity.
        const double len = std::sqrt(len2);
        nx = -uy / len;
        ny = ux / len;
        if (nx * vx + ny * vy > 0.0) {
          nx = -nx;
          ny = -ny;
        }
      }
      const double magnitude = fp.obstacle_factor * fast_exp(-(d - r) / fp.obstacle_sigma);
      double fx = magnitude * nx;
      double fy = magnitude * ny;
      const double along = nx * ex + ny * ey;  // component along the walking direction (0 without a goal)
      if (end_bit != 0 && along != 0.0) {
        // A wall end (a free end, or a corner seen from outside) that the straight walk passes.
        bool clears = walk_clears({x, y}, {ex, ey}, sweep, s.a, s.b, r);
        for (std::uint32_t k = wall_link_start_[end]; k < wall_link_start_[end + 1] && clears; ++k)
          clears =
              walk_clears({x, y}, {ex, ey}, sweep, walls_[wall_links_[k]].a, walls_[wall_links_[k]].b, r);
        if (clears) {
          fx -= magnitude * along * ex;
          fy -= magnitude * along * ey;
        }
      }
      if (end_bit == 0) {  // the inside of a wall (narrow passages: below)
        side_x += fx;
        side_y += fy;
      } else {
        f.obstacle.x += fx;
        f.obstacle.y += fy;
      }
    }
    // In a narrow passage the insides' push across the walking direction fades (kNarrowFrom).
    double across = 1.0;
    if (inside_sides == 3u)
      across = std::clamp((inside_left + inside_right - kNarrowFrom) / (kNarrowTo - kNarrowFrom), 0.0, 1.0);
    const double along = side_x * ex + side_y * ey;
    f.obstacle.x += along * ex + across * (side_x - along * ex);
    f.obstacle.y += along * ey + across * (side_y - along * ey);
  }

  prep.ex = ex;
  prep.ey = ey;
  prep.heading = heading;
  prep.wall_sides = wall_sides;
  prep.obstacle = f.obstacle;
  return prep;
}

void CrowdSimulation::finish_agent(std::uint32_t i, const AgentInputs& in, const AgentPrep& prep,
                                   const NeighbourTotals& t, std::span<BodyContact> contacts,
                                   ForceBreakdown* breakdown) {
  const ForceParameters& fp = roles_.at(in.role).forces;
  const double x = in.x;
  const double y = in.y;
  const double vx = in.vx;
  const double vy = in.vy;
  const double r = in.r;
  const double dt = config_.dt;
  const double ex = prep.ex;
  const double ey = prep.ey;
  const bool heading = prep.heading;
  const std::int32_t g = in.group;
  ForceBreakdown f;
  f.obstacle = prep.obstacle;
  if (heading) {
    // The desired speed, capped by the headway to the person ahead (speed–headway adaptation).
    double v0 = in.v0;
    if (fp.headway_time > 0.0) v0 = std::min(v0, t.speed_cap);
    f.desired = {fp.desired_factor * (ex * v0 - vx) / fp.relaxation_time,
                 fp.desired_factor * (ey * v0 - vy) / fp.relaxation_time};
  } else {
    f.desired = {-vx / fp.relaxation_time, -vy / fp.relaxation_time};
  }
  f.social = t.social;
  f.group = t.repulsion;
  f.body = t.body;
  // Walls beyond one step's reach (prep.wall_d2) can neither limit the velocity nor block the move
  // (below): most agents are far from every wall and skip both.
  const double wall_reach = r + dt * kMaxAgentSpeed;
  std::span<const std::uint32_t> near_walls;
  if (prep.wall_d2 < wall_reach * wall_reach) near_walls = wall_grid_.near(x, y);

  // Group gaze and coherence (LightSFM computeGroupForce, non-paper variant).
  if (g >= 0 && group_size_[static_cast<std::size_t>(g)] >= 2) {
    const double members = group_size_[static_cast<std::size_t>(g)];
    const double cx = group_cx_[static_cast<std::size_t>(g)];
    const double cy = group_cy_[static_cast<std::size_t>(g)];
    if (heading) {
      // Centre of the other members; when it is more than 90° off the walking direction, slow
      // down along that direction so the agent does not leave the others behind its back.
      const double ox = (members * cx - x) / (members - 1.0) - x;
      const double oy = (members * cy - y) / (members - 1.0) - y;
      const double dot = ex * ox + ey * oy;
      if (ox * ox + oy * oy > kTiny2 && dot < 0.0) {
        f.group.x += fp.group_gaze_factor * dot * ex;
        f.group.y += fp.group_gaze_factor * dot * ey;
      }
    }
    // Coherence: pull towards the centre, softened by (tanh(d − (n−1)/2) + 1)/2.
    const double rx = cx - x;
    const double ry = cy - y;
    const double dist = std::sqrt(rx * rx + ry * ry);
    const double soft = fp.group_coherence_factor / (1.0 + fast_exp(-2.0 * (dist - (members - 1.0) / 2.0)));
    f.group.x += soft * rx;
    f.group.y += soft * ry;
  }

  if (breakdown != nullptr) {
    *breakdown = f;
    return;
  }

  // Semi-implicit Euler with LightSFM's speed clamp, then the wall guard.
  const Vec2 total = f.total();
  double nvx = vx + total.x * dt;
  double nvy = vy + total.y * dt;
  const double s2 = nvx * nvx + nvy * nvy;
  const double vmax = in.vmax;
  if (s2 > vmax * vmax) {
    const double k = s2 > 0.0 ? vmax / std::sqrt(s2) : 0.0;
    nvx *= k;
    nvy *= k;
  }
  // Hard contact: towards each contact j (unit direction n, gap g between the bodies), the
  // velocity along n may exceed the pair's mean frozen velocity along n by at most g/(2·dt). j
  // limits its own velocity the same way, so the pair closes by at most g in this step and the
  // bodies do not interpenetrate (to first order; two passes settle agents with several contacts).
  // Overlapping pairs (g < 0) part at up to 0.2 m/s each; the body force pushes them apart too.
  // Contacts come sorted by agent id: the result does not depend on the order of the scan.
  if (config_.hard_contact) {
    for (int pass = 0; pass < 2; ++pass) {
      for (const BodyContact& c : contacts) {
        // A driven agent (a robot) does not give way: against it the agent takes the whole gap.
        const bool alone = driven_[c.who] != kNotDriven;
        const double mean =
            alone ? c.vx * c.nx + c.vy * c.ny : 0.5 * ((vx + c.vx) * c.nx + (vy + c.vy) * c.ny);
        const double limit = mean + std::max(c.gap, -0.02) / (alone ? dt : 2.0 * dt);
        const double along = nvx * c.nx + nvy * c.ny;
        if (along > limit) {
          nvx -= (along - limit) * c.nx;
          nvy -= (along - limit) * c.ny;
        }
      }
    }
    // Walls are contacts too: towards a wall's nearest point (inside the wall, not at an end)
    // the velocity may close at most the gap between the wall and the body, of radius
    // r + kWallClearance here, in this step, and not at all once it touches. The obstacle force
    // keeps walking bodies off walls; this only acts where the crowd presses one against a wall
    // (without it, with several separation passes, bodies were squeezed onto the wall beside a
    // passage's entrance, centre on the wall line, and stayed wedged there).
    for (std::uint32_t w : near_walls) {
      bool interior = false;
      const Vec2 q = nearest_on_wall({x, y}, walls_[w], &interior);
      if (!interior) continue;  // a wall end (a door jamb): people squeeze past it
      const double wx = q.x - x;
      const double wy = q.y - y;
      const double d2 = wx * wx + wy * wy;
      const double reach = r + dt * kMaxAgentSpeed;
      if (d2 <= kTiny2 || d2 >= reach * reach) continue;
      const double d = std::sqrt(d2);
      const double limit = std::max(0.0, d - (r + kWallClearance)) / dt;
      const double along = (nvx * wx + nvy * wy) / d;
      if (along > limit) {
        nvx -= (along - limit) * wx / d;
        nvy -= (along - limit) * wy / d;
      }
    }
    const double s3 = nvx * nvx + nvy * nvy;
    if (s3 > kMaxAgentSpeed * kMaxAgentSpeed) {
      const double k = kMaxAgentSpeed / std::sqrt(s3);
      nvx *= k;
      nvy *= k;
    }
  }
  const Vec2 target{x + nvx * dt, y + nvy * dt};
  if (near_walls.empty() && (nvx * nvx + nvy * nvy) * dt * dt * 1.01 + 1e-12 >= prep.wall_d2)
    near_walls = wall_grid_.near(x, y);  // a move that could reach a wall (no hard contact)
  Vec2 next = near_walls.empty() ? target : guard_move({x, y}, target, near_walls, walls_);
  if (!(next == target)) {
    nvx = (next.x - x) / dt;
    nvy = (next.y - y) / dt;
  }
  if (!(std::isfinite(next.x) && std::isfinite(next.y) && std::isfinite(nvx) && std::isfinite(nvy))) {
    next = {x, y};  // cannot happen with validated input; kept as the last line of defence
    nvx = 0.0;
    nvy = 0.0;
  }
  next_[i] = {next.x, next.y, nvx, nvy};
  if (config_.hard_contact) {
    // The kStoredContacts nearest (smallest gap, then lowest id), kept in id order: in a pile-up
    // the bodies that can overlap are the near ones, not the lowest ids.
    if (contacts.size() > kStoredContacts) {
      const auto nearer = [](const BodyContact& a, const BodyContact& b) {
        return a.gap < b.gap || (a.gap == b.gap && a.who < b.who);
      };
      const auto cut = contacts.begin() + static_cast<std::ptrdiff_t>(kStoredContacts);
      std::nth_element(contacts.begin(), cut, contacts.end(), nearer);
      contacts = contacts.first(kStoredContacts);
      std::sort(contacts.begin(), contacts.end(),
                [](const BodyContact& a, const BodyContact& b) { return a.who < b.who; });
    }
    for (std::size_t k = 0; k < contacts.size(); ++k) contact_ids_[i * kStoredContacts + k] = contacts[k].who;
    contact_count_[i] = static_cast<std::uint8_t>(contacts.size());
  }
}

void CrowdSimulation::separate_bodies() {
  if (!config_.hard_contact) return;
  constexpr double kTolerance = 0.01;  // m of overlap left alone (the body force handles it)
  constexpr double kMaxShift = 0.05;   // m per pass
  const double length = config_.periodic_length;
  // Jacobi passes, each from the positions the previous one left (next_), until a pass moves
  // no one or kSeparationPasses are done. A body pinned against a wall or squeezed between
  // others is resolved over several passes (each halves what is left where one side cannot
  // move). Whether a pass moved anyone is an OR over per-agent results that do not depend on
  // the order or the thread count, so the number of passes is deterministic too.
  // Only an agent with contacts can move at all (pressed_, in agent order); a pass computes their
  // new positions into shift_ and writes them back after all of them read theirs. A pass after
  // the first skips an agent when neither it nor any of its contacts moved in the pass before:
  // everything it would read is unchanged, so it would not move now either (same result, without
  // the work; in a large crowd most agents are not pressed against anyone). moved_ is 0 for every
  // agent outside the passes.
  // Without a branch (written at every agent, kept where pressed): about two thirds of a dense
  // crowd is pressed, in no pattern, and the branch's mispredictions made this serial loop take
  // 45–52 µs a step for 10,000 agents.
  pressed_.resize(size());
  std::size_t count = 0;
  for (std::size_t i = 0; i < size(); ++i) {
    pressed_[count] = static_cast<std::uint32_t>(i);
    count += static_cast<unsigned>(contact_count_[i] != 0) & static_cast<unsigned>(active_[i] != 0) &
             static_cast<unsigned>(driven_[i] == kNotDriven);
  }
  pressed_.resize(count);
  if (count == 0) return;
  shift_.resize(count);
  for (int pass = 0; pass < kSeparationPasses; ++pass) {
    std::atomic<bool> moved{false};
    pool_->parallel_for(count, 256, [&](std::size_t begin, std::size_t end) {
      bool any = false;
      for (std::size_t at = begin; at < end; ++at) {
        const std::size_t i = pressed_[at];
        Shift& out = shift_[at];
        const double nx = next_[i].x;
        const double ny = next_[i].y;
        out = {nx, ny, 0};
        if (pass > 0 && moved_[i] == 0) {
          bool stirred = false;
          for (std::size_t k = 0; k < contact_count_[i] && !stirred; ++k)
            stirred = moved_[contact_ids_[i * kStoredContacts + k]] != 0;
          if (!stirred) continue;
        }
        double cx = 0.0;
        double cy = 0.0;
        for (std::size_t k = 0; k < contact_count_[i]; ++k) {
          const std::uint32_t j = contact_ids_[i * kStoredContacts + k];
          double dx = next_[j].x - nx;
          if (length > 0.0) dx -= length * std::round(dx / length);  // the nearest image
          const double dy = next_[j].y - ny;
          const double d2 = dx * dx + dy * dy;
          const double reach = radius_[i] + radius_[j] - kTolerance;
          if (d2 >= reach * reach) continue;
          const Separation n = separation(dx, dy, d2, static_cast<std::uint32_t>(i), j);
          const double share = driven_[j] != kNotDriven ? 1.0 : 0.5;  // a robot is not pushed
          cx -= share * (reach - n.d) * n.x;
          cy -= share * (reach - n.d) * n.y;
        }
        const double shift2 = cx * cx + cy * cy;
        if (shift2 == 0.0) continue;
        if (shift2 > kMaxShift * kMaxShift) {
          const double k = kMaxShift / std::sqrt(shift2);
          cx *= k;
          cy *= k;
        }
        // From where the agent was to where it is pushed: still never through a wall, and never
        // pushed closer to a wall than its radius (or than it already was): the shift slides
        // along a wall instead, so a body is not wedged into a corner or a door jamb by the
        // crowd behind it (the partner takes the rest in the next passes).
        const Vec2 from{px_[i], py_[i]};
        const std::span<const std::uint32_t> near = wall_grid_.near(from.x, from.y);
        const Vec2 to = keep_off_walls({nx, ny}, {nx + cx, ny + cy}, radius_[i], near, walls_);
        const Vec2 next = guard_move(from, to, near, walls_);
        const bool shifted = !(next.x == nx && next.y == ny);
        any = any || shifted;
        out = {next.x, next.y, static_cast<std::uint8_t>(shifted ? 1 : 0)};
      }
      if (any) moved.store(true, std::memory_order_relaxed);
    });
    pool_->parallel_for(count, 2048, [&](std::size_t begin, std::size_t end) {
      for (std::size_t at = begin; at < end; ++at) {  // every read of this pass done: write back
        const std::uint32_t i = pressed_[at];
        next_[i].x = shift_[at].x;
        next_[i].y = shift_[at].y;
        moved_[i] = shift_[at].moved;
      }
    });
    if (!moved.load(std::memory_order_relaxed)) break;
  }
  for (const std::uint32_t i : pressed_) moved_[i] = 0;
}

void CrowdSimulation::finish_step() {
  // Per agent and independent (each touches only its own entries), so it runs in parallel.
  const double dt = config_.dt;
  pool_->parallel_for(size(), 1024, [&](std::size_t begin, std::size_t end) {
    // The headings of the new velocities, a block at a time (vectorised; those of agents that do
    // not move are not used).
    constexpr std::size_t kBlock = 256;
    double heading[kBlock];
    double block_vx[kBlock];
    double block_vy[kBlock];
    for (std::size_t i = begin; i < end; ++i) {
      if ((i - begin) % kBlock == 0) {
        const std::size_t count = std::min(kBlock, end - i);
        for (std::size_t b = 0; b < count; ++b) {
          block_vx[b] = next_[i + b].vx;
          block_vy[b] = next_[i + b].vy;
        }
        fast_atan2_batch(block_vy, block_vx, heading, count);
      }
      if (!active_[i] || driven_[i] != kNotDriven) continue;
      px_[i] = wrap_x(next_[i].x);
      py_[i] = next_[i].y;
      vx_[i] = next_[i].vx;
      vy_[i] = next_[i].vy;
      if (vx_[i] * vx_[i] + vy_[i] * vy_[i] > 1e-12) {
        const double yaw = heading[(i - begin) % kBlock];  // fast_atan2(vy_[i], vx_[i])
        omega_[i] = wrap_angle(yaw - yaw_[i]) / dt;
        yaw_[i] = yaw;
      } else {
        omega_[i] = 0.0;
      }
      if (!has_goal_[i]) continue;
      const double dx = gx_[i] - px_[i];
      const double dy = gy_[i] - py_[i];
      if (dx * dx + dy * dy > gr_[i] * gr_[i]) continue;
      AgentMeta& m = meta_[i];
      ++m.goal_index;
      if (m.goal_index >= m.goals.size() && m.cyclic) m.goal_index = 0;
      if (m.goal_index < m.goals.size()) {
        gx_[i] = m.goals[m.goal_index].position.x;
        gy_[i] = m.goals[m.goal_index].position.y;
        gr_[i] = m.goals[m.goal_index].radius;
        m.intent.goal_id = static_cast<std::int64_t>(m.goal_index);
      } else {
        has_goal_[i] = 0;
        m.intent.goal_id = -1;
      }
    }
  });
  ++steps_;
}

void CrowdSimulation::step() {
  prepare_step();
  build_cells();
  const CellIndex& c = *cells_;
  const GridScan scan{
      c.start,
      c.cell_of,
      c.origin_x,
      c.origin_y,
      c.cell,
      c.inv_cell,
      config_.neighbor_cutoff,
      c.nx,
      c.ny,
      {c.x.data(), c.y.data(), c.vx.data(), c.vy.data(), c.r.data(), c.fx.data(), c.fy.data(), c.fvx.data(),
       c.fvy.data(), c.group.data(), c.id.data(), nullptr, static_cast<std::uint32_t>(c.fx.size())}};
  if (pairs_once()) {
    step_pairs();
  } else {
    pool_->parallel_for(c.agents.size(), 128, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
        advance_agent(c.agents[k], inputs_of(c.agents[k]), scan, nullptr);
    });
  }
  separate_bodies();
  finish_step();
}

bool CrowdSimulation::pairs_once() const {
  return config_.pairs_once && config_.periodic_length <= 0.0 && !mixed_pair_terms_;
}

// The step with each pair once (pairs_once()): the same results as advance_agent agent by agent,
// bit for bit (CrowdSimulation.PairsOnceGiveTheSameBits). Three passes over the agents in the
// cells' order: (1) each agent's walking direction and walls (prepare_agent); (2) each agent's
// pairs with the neighbours that come after it in that order — the rows of cells from its own
// upwards — through pair_kernel, the results added to both agents' sums in the running thread's
// own arrays (each thread empties its own when it takes its first range); (3) the sums of the
// threads that took part and finish_agent.
void CrowdSimulation::step_pairs() {
  CellIndex& c = *cells_;                 // read only, except the sorted copies the first pass fills
  const std::size_t n = c.agents.size();  // no periodic images here: entries = agents
  if (n == 0) return;
  if (!pairs_) pairs_ = std::make_unique<PairState>();
  PairState& ps = *pairs_;
  ps.threads.resize(pool_->threads());
  for (PairState::Thread& t : ps.threads) {
    t.social.resize(n);
    t.contacts.records.clear();
    t.touches.records.clear();
  }
  ++ps.round;
  ps.prep.resize(n);
  ps.heading.resize(4 * n);
  const std::int32_t no_cap = std::bit_cast<std::int32_t>(std::numeric_limits<float>::infinity());

  pool_->parallel_for(n, 256, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const AgentInputs& in = c.inputs[k];
      // The sorted copies build_cells leaves to this pass (sequential writes here).
      c.agents[k] = c.id[k];
      c.fx[k] = static_cast<float>(in.x);
      c.fy[k] = static_cast<float>(in.y);
      c.fvx[k] = static_cast<float>(in.vx);
      c.fvy[k] = static_cast<float>(in.vy);
      float* heading = ps.heading.data() + 4 * k;
      if (in.driven != kNotDriven) {  // its own sums are not used
        std::fill(heading, heading + 4, 0.0f);
        continue;
      }
      const AgentPrep prep = prepare_agent(in);
      const ForceParameters& fp = roles_.at(in.role).forces;
      ps.prep[k] = prep;
      // As NeighbourSums takes them.
      heading[0] = static_cast<float>(prep.ex);
      heading[1] = static_cast<float>(prep.ey);
      heading[2] = static_cast<float>(in.vx * prep.ex + in.vy * prep.ey);
      heading[3] = static_cast<float>((prep.wall_sides == 3u ? fp.zipper_band : fp.headway_band) * in.r);
    }
  });

  const ForceParameters& fp = roles_.at(role_[c.agents[0]]).forces;  // every agent's pair terms
  const SocialParams social{static_cast<float>(fp.lambda),      static_cast<float>(fp.gamma),
                            static_cast<float>(1.0 / fp.gamma), static_cast<float>(fp.n),
                            static_cast<float>(fp.n_prime),     static_cast<float>(fp.social_factor)};
  const PairAheadParams ahead{kOncoming,
                              static_cast<float>(fp.headway_distance),
                              static_cast<float>(fp.headway_time > 0.0 ? 1.0 / fp.headway_time : 0.0),
                              static_cast<float>(fp.headway_anticipation),
                              static_cast<float>(fp.side_band),
                              static_cast<float>(fp.side_bias),
                              static_cast<float>(fp.side_factor),
                              static_cast<float>(1.0 / fp.side_range)};
  const auto cutoff2 = static_cast<float>(config_.neighbor_cutoff * config_.neighbor_cutoff);
  const double widest_margin = config_.hard_contact ? config_.dt * 2.0 * max_vmax_ + 0.05 : 0.0;
  const double repulsion = fp.group_repulsion_factor;
  const double stiffness = config_.body_stiffness;
  const auto readable = static_cast<std::uint32_t>(c.fx.size());
  const int granule = pair_kernel_lanes();  // at most kLaneSlack: the pad lanes stay in the arrays
  // fill_pair_sides writes kFillSlack lanes past the batch's pairs into PairLanes' side arrays.
  static_assert(kLaneSlack >= kFillSlack);
  const RowHalves halves = row_halves(config_.neighbor_cutoff + 1e-9, c.cell);

  // Chunks of 64 agents: about 60 µs each, so the threads finish close together.
  pool_->parallel_for(n, 64, [&](std::size_t begin, std::size_t end) {
    PairState::Thread& t = ps.threads[WorkerPool::current_thread()];
    if (t.round != ps.round) {
      std::fill(t.social.begin(), t.social.end(), PairState::Social{0, 0, 0, no_cap});
      t.round = ps.round;
    }
    struct Batch {
      PairLanes lanes;
      std::uint32_t owner[kBatch + kFillSlack];
      std::uint32_t slot[kBatch + kFillSlack];
      std::uint8_t close[kBatch];
      // Runs of consecutive lanes with the same owner: run_owner[r] from lane run_begin[r].
      std::uint32_t run_owner[kBatch];
      int run_begin[kBatch];
      int runs = 0;
      int count = 0;
      int close_count = 0;
      bool tied = false;  // some tie direction is set (else tie_x, tie_y are all 0)
      Batch() {
        std::fill(std::begin(lanes.tie_x), std::end(lanes.tie_x), 0.0f);
        std::fill(std::begin(lanes.tie_y), std::end(lanes.tie_y), 0.0f);
      }
    };
    thread_local Batch batch;
    Batch& b = batch;
    PairLanes& l = b.lanes;
    const SideLanes sides{l.ex_i, l.ey_i, l.along_i, l.band_i, l.ex_j, l.ey_j, l.along_j, l.band_j, b.owner};
    const auto flush = [&] {
      // Pairs that may touch: contacts, group repulsion and the body force, on both sides (as
      // NeighbourSums::flush does for each).
      for (int q = 0; q < b.close_count; ++q) {
        const int m = b.close[q];
        const std::uint32_t ki = b.owner[m];
        const std::uint32_t kj = b.slot[m];
        const double fdx = l.dx[m];
        const double fdy = l.dy[m];
        const double d2 = fdx * fdx + fdy * fdy;
        const AgentInputs& in_i = c.inputs[ki];
        const AgentInputs& in_j = c.inputs[kj];
        const double reach = in_i.r + in_j.r;
        const double mi = contact_margin(in_i);
        const double mj = contact_margin(in_j);
        if (mi > 0.0 && d2 < (reach + mi) * (reach + mi)) t.contacts.records.push_back({ki, kj});
        if (mj > 0.0 && d2 < (reach + mj) * (reach + mj)) t.contacts.records.push_back({kj, ki});
        if (d2 >= reach * reach) continue;
        const std::uint32_t id_i = c.id[ki];
        const std::uint32_t id_j = c.id[kj];
        if (d2 <= kTiny2) {  // coincident: part along the pair's fixed direction
          const Vec2 u = tie_break_direction(id_i, id_j);
          l.dx[m] = 0.0f;
          l.dy[m] = 0.0f;
          l.tie_x[m] = static_cast<float>(u.x);
          l.tie_y[m] = static_cast<float>(u.y);
          b.tied = true;
        }
        const bool same_group = in_i.group >= 0 && in_j.group == in_i.group;
        const auto add = [&](std::uint32_t to, const TouchTerms& terms) {
          t.touches.records.push_back(
              {to, {terms.repulsion_x, terms.repulsion_y, terms.body_x, terms.body_y}});
        };
        add(ki, touch_terms(in_j.x - in_i.x, in_j.y - in_i.y, d2, reach, same_group, repulsion, stiffness,
                            id_i, id_j));
        add(kj, touch_terms(in_i.x - in_j.x, in_i.y - in_j.y, d2, reach, same_group, repulsion, stiffness,
                            id_j, id_i));
      }
      // The lanes past the last pair (up to the kernel's width) inert: a fixed kLaneSlack of
      // them, in whole vectors (a loop to `padded` became twelve calls to memset per batch).
      const int padded = (b.count + granule - 1) / granule * granule;
      for (int m = b.count; m < b.count + kLaneSlack; ++m) {
        l.dx[m] = l.dy[m] = l.dvx[m] = l.dvy[m] = 0.0f;
        l.ex_i[m] = l.ey_i[m] = l.along_i[m] = l.band_i[m] = 0.0f;
        l.ex_j[m] = l.ey_j[m] = l.along_j[m] = l.band_j[m] = 0.0f;
      }
      pair_kernel(social, ahead, padded, l);
      if (b.tied) {
        std::fill(std::begin(l.tie_x), std::end(l.tie_x), 0.0f);
        std::fill(std::begin(l.tie_y), std::end(l.tie_y), 0.0f);
        b.tied = false;
      }
      // The forces, headway caps and side pushes (INT32_MAX and 0 in the lanes without one: no
      // branch to mispredict), summed per owner over its run of lanes, and to each other agent
      // (the force minus).
      for (int r = 0; r < b.runs; ++r) {
        const int stop = r + 1 < b.runs ? b.run_begin[r + 1] : b.count;
        std::int64_t sx = 0;
        std::int64_t sy = 0;
        std::int64_t push = 0;
        std::int32_t cap = INT32_MAX;
        for (int m = b.run_begin[r]; m < stop; ++m) {
          sx += l.fx[m];
          sy += l.fy[m];
          push += l.push_i[m];
          cap = std::min(cap, l.cap_i[m]);
        }
        PairState::Social& si = t.social[b.run_owner[r]];
        si.x += sx;
        si.y += sy;
        si.side_push += push;
        si.cap = std::min(si.cap, cap);
      }
      for (int m = 0; m < b.count; ++m) {
        PairState::Social& sj = t.social[b.slot[m]];
        sj.x -= l.fx[m];
        sj.y -= l.fy[m];
        sj.side_push += l.push_j[m];
        sj.cap = std::min(sj.cap, l.cap_j[m]);
      }
      b.count = 0;
      b.close_count = 0;
      b.runs = 0;
    };
    for (std::size_t k = begin; k < end; ++k) {
      const auto self = static_cast<std::uint32_t>(k);
      const double px = c.inputs[k].x;
      const double py = c.inputs[k].y;
      const double close = c.inputs[k].r + max_radius_ + widest_margin;
      const GatherQuery q{
          c.fx.data(), c.fy.data(), c.fvx.data(), c.fvy.data(), c.fx[k], c.fy[k], c.fvx[k], c.fvy[k], cutoff2,
          // As NeighbourSums' (widened: the other side's margin may be the larger).
          static_cast<float>(close * close * (1.0 + 1e-5) + 2.0 * kTiny2), self, nullptr, readable};
      GatherRange ranges[kMaxGridRows];
      const GridQuery g{
          c.start.data(), c.origin_x, c.origin_y, c.cell, c.inv_cell, config_.neighbor_cutoff + 1e-9,
          c.nx,           c.ny,       px,         py,     true};
      const int rows = grid_ranges_upper(g, halves, ranges);
      int count = 0;
      for (int r = 0; r < rows; ++r) {  // the own row from the agent on: later entries only
        const std::uint32_t from = std::max(ranges[r].begin, self + 1);
        if (from < ranges[r].end) ranges[count++] = {from, ranges[r].end};
      }
      GatherBatch gb{l.dx, l.dy, l.dvx, l.dvy, b.slot, b.close, kBatch, b.count, b.close_count};
      int done = 0;
      while (true) {
        const int first = gb.count;
        done += gather_neighbours(q, ranges + done, count - done, gb);
        if (gb.count > first) {
          fill_pair_sides(ps.heading.data(), b.slot, ps.heading.data() + 4 * k, self, first, gb.count, sides);
          b.run_owner[b.runs] = self;
          b.run_begin[b.runs++] = first;
        }
        b.count = gb.count;
        b.close_count = gb.close_count;
        if (done == count) break;
        flush();  // the batch is full
        gb.count = gb.close_count = 0;
      }
      // Batches of 40–53 pairs: one agent by one thread, 10,000 agents (tests/bench `crowd`), two
      // builds run at once one per core, 8 rounds each way: 5–10 % faster than at 48 or at 32.
      if (b.count >= 40) flush();
    }
    if (b.count > 0) flush();
  });

  // The sums of the threads that took some range of the pairs (at least one did; the others'
  // arrays hold an earlier step's sums).
  std::vector<const PairState::Social*> sums;
  for (const PairState::Thread& t : ps.threads)
    if (t.round == ps.round) sums.push_back(t.social.data());

  // Each thread's contact and touching-pair records by block of agents (few: most agents touch
  // no one), the threads in parallel.
  const std::size_t blocks = (n >> PairState::kContactShift) + 1;
  pool_->parallel_for(ps.threads.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t th = begin; th < end; ++th) {
      ps.threads[th].contacts.sort(blocks);
      ps.threads[th].touches.sort(blocks);
    }
  });

  pool_->parallel_for(n, PairState::kContactBlock, [&](std::size_t begin, std::size_t end) {
    // This range's contacts by agent (threads in order, each thread's records in order): those of
    // the agent at k are range[at[k − begin] .. [k − begin + 1]).
    thread_local std::vector<BodyContact> range;
    thread_local std::vector<std::uint32_t> at;
    // and each agent's touching-pair terms, summed (integers: in any order).
    thread_local std::vector<PairState::Sums> touch;
    at.assign(end - begin + 1, 0);
    const auto each_record = [&](const auto& visit) {
      for (const PairState::Thread& t : ps.threads) t.contacts.each(begin, end, visit);
    };
    touch.assign(end - begin, PairState::Sums{0, 0, 0, 0});
    for (const PairState::Thread& t : ps.threads) {
      t.touches.each(begin, end, [&](const PairState::Touch& r) {
        PairState::Sums& s = touch[r.to - begin];
        s.repulsion_x += r.terms.repulsion_x;
        s.repulsion_y += r.terms.repulsion_y;
        s.body_x += r.terms.body_x;
        s.body_y += r.terms.body_y;
      });
    }
    each_record([&](const PairState::Record& r) { ++at[r.to - begin + 1]; });
    for (std::size_t a = 0; a + 1 < at.size(); ++a) at[a + 1] += at[a];
    range.resize(at.back());
    // Each contact as the close pair saw it: the offset from the single-precision positions the
    // gather compared (x_other − x_self rounds to minus x_self − x_other: either side's record
    // gives its own direction), the distance in double from it, the bodies' reach, and the
    // neighbour's frozen velocity.
    each_record([&](const PairState::Record& r) {
      const double dx = c.fx[r.other] - c.fx[r.to];
      const double dy = c.fy[r.other] - c.fy[r.to];
      const double d2 = dx * dx + dy * dy;
      const AgentInputs& other = c.inputs[r.other];
      const double reach = c.inputs[r.to].r + other.r;
      const std::uint32_t who = c.id[r.other];
      const Separation sep = separation(dx, dy, d2, c.id[r.to], who);
      range[at[r.to - begin]++] = {who, sep.x, sep.y, sep.d - reach, other.vx, other.vy};
    });
    for (std::size_t a = at.size() - 1; a > 0; --a) at[a] = at[a - 1];  // back to each agent's start
    at[0] = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t i = c.agents[k];
      const AgentInputs& in = c.inputs[k];
      if (in.driven != kNotDriven) {
        hold_driven(i, in, nullptr);
        continue;
      }
      PairState::Social force = sums[0][k];
      for (std::size_t th = 1; th < sums.size(); ++th) {
        const PairState::Social& f = sums[th][k];
        force.x += f.x;
        force.y += f.y;
        force.side_push += f.side_push;
        force.cap = std::min(force.cap, f.cap);
      }
      const PairState::Sums& s = touch[k - begin];
      NeighbourTotals totals;
      totals.speed_cap = static_cast<double>(std::bit_cast<float>(force.cap));
      totals.social =
          social_total(force.x, force.y, force.side_push, ps.heading[4 * k], ps.heading[4 * k + 1]);
      totals.repulsion = {FixedSum::to_double(s.repulsion_x), FixedSum::to_double(s.repulsion_y)};
      totals.body = {FixedSum::to_double(s.body_x), FixedSum::to_double(s.body_y)};
      // As NeighbourSums keeps them: by agent id, the lowest kMaxContacts (sorted where they are
      // in `range`, which finish_agent may reorder: each agent's own part only).
      std::span<BodyContact> contacts(range.data() + at[k - begin], at[k - begin + 1] - at[k - begin]);
      // By id (each neighbour once): an insertion sort, as the lists are short (std::sort's order).
      for (std::size_t a = 1; a < contacts.size(); ++a) {
        const BodyContact next = contacts[a];
        std::size_t b = a;
        for (; b > 0 && next.who < contacts[b - 1].who; --b) contacts[b] = contacts[b - 1];
        contacts[b] = next;
      }
      if (contacts.size() > NeighbourSums::kMaxContacts)
        contacts = contacts.first(NeighbourSums::kMaxContacts);
      finish_agent(i, in, ps.prep[k], totals, contacts, nullptr);
    }
  });
}

void CrowdSimulation::step_reference() {
  prepare_step();
  Images m;
  build_images(m);
  const FullScan scan = full_scan(m);
  pool_->parallel_for(size(), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (seen(i))
        advance_agent(static_cast<std::uint32_t>(i), inputs_of(static_cast<std::uint32_t>(i)), scan, nullptr);
  });
  separate_bodies();
  finish_step();
}

ForceBreakdown CrowdSimulation::forces(AgentId id) {
  ForceBreakdown out;
  if (id.value() >= size() || !active_[id.value()]) return out;
  prepare_step();  // group centres and wall grid of the current state; the O(N) scan gives the same forces
  Images m;
  build_images(m);
  const FullScan scan = full_scan(m);
  advance_agent(id.value(), inputs_of(id.value()), scan, &out);
  return out;
}

}  // namespace socsim::crowd
