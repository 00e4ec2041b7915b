#pragma once
// The crowd simulation facade (RVO2-style): add agents and walls, give goals, step(), read back.
// LightSFM's social force model on structure-of-arrays state; each step computes
// next = f(frozen current) in parallel, so results do not depend on the number of threads.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/crowd/large_pages.hpp"
#include "core/crowd/pedestrian_state.hpp"
#include "core/crowd/role_parameters.hpp"
#include "core/crowd/wall_grid.hpp"
#include "core/crowd/worker_pool.hpp"

namespace socsim::crowd {

struct BodyContact;  // a neighbour the agent could touch in this step (crowd_simulation.cpp)

struct SimulationConfig {
  double dt = 0.05;              // s, fixed step
  double neighbor_cutoff = 3.0;  // m, agents farther apart do not interact
  double wall_cutoff = 2.0;      // m, walls farther away exert no force
  unsigned threads = 1;          // compute threads, including the caller
  std::uint64_t seed = 0;        // drives the sampled desired speeds
  // Body contact force k·overlap between touching agents (1/s²; Helbing, Farkas & Vicsek 2000,
  // k/m = 1.2e5/80 there, softened for dt = 0.05 s). LightSFM has none, and without it bodies
  // interpenetrate in crowds: a 1 m door then passes 6.4 persons/s instead of the observed 1–2.
  // 0 gives pure LightSFM.
  double body_stiffness = 500.0;
  // Periodic boundary along x for corridor studies (RiMEA 4, fundamental diagrams): when > 0,
  // positions wrap into [periodic_origin, periodic_origin + periodic_length) after every step
  // and agents interact with the images of the others one period to either side (so the period
  // must exceed twice the neighbour cut-off). Walls are not wrapped: extend corridor walls by
  // wall_cutoff beyond both ends. Goals are not wrapped either (give far goals along ±x), and
  // group centres use the wrapped positions. 0 = no periodic boundary.
  double periodic_length = 0.0;  // m
  double periodic_origin = 0.0;  // m
  // Hard body contact (an addition to LightSFM): after the forces, each agent limits its velocity
  // towards every neighbour it could reach within one step so that, the other doing the same,
  // the two bodies do not come closer than the sum of their radii (see docs/crowd.md, "Body
  // contact"). false: bodies are kept apart by the body force alone.
  bool hard_contact = true;
  // Compute each pair's social force once where the model allows it (CrowdSimulation::step):
  // the same bits as agent by agent, in less time. false: agent by agent (for comparisons).
  bool pairs_once = true;
};
Status validate(const SimulationConfig& config);

// How a driven agent shows itself to the others.
enum class Presence : std::uint8_t { kVisible, kInvisible };

struct Goal {
  Vec2 position;
  double radius = 0.3;  // m, reached when the agent's centre is this close
};

struct AgentSpec {
  Vec2 position;
  Vec2 velocity;
  std::optional<double> yaw;  // default: direction of velocity, else 0
  std::string role = "adult";
  std::optional<double> desired_speed;  // default: sampled from the role's distribution
  std::optional<double> radius;         // default: the role's radius
  std::int64_t group_id = -1;           // agents with the same id >= 0 walk as a group
  Activity activity = Activity::kWalking;
  Intent intent;
  std::vector<std::string> tags;
};

// The force terms acting on one agent in the current state (m/s²), for inspection and tests.
struct ForceBreakdown {
  Vec2 desired;
  Vec2 obstacle;
  Vec2 social;
  Vec2 group;  // gaze + coherence + repulsion
  Vec2 body;
  [[nodiscard]] Vec2 total() const {
    return {desired.x + obstacle.x + social.x + group.x + body.x,
            desired.y + obstacle.y + social.y + group.y + body.y};
  }
};

class CrowdSimulation {
 public:
  static Result<CrowdSimulation> create(const SimulationConfig& config,
                                        RoleTable roles = RoleTable::defaults());

  CrowdSimulation(CrowdSimulation&&) noexcept;
  CrowdSimulation& operator=(CrowdSimulation&&) noexcept;
  CrowdSimulation(const CrowdSimulation&) = delete;
  CrowdSimulation& operator=(const CrowdSimulation&) = delete;
  ~CrowdSimulation();

  // --- building -------------------------------------------------------------------------
  Result<AgentId> add_agent(const AgentSpec& spec);
  // A wall segment; a == b is a point obstacle (pushes, cannot be crossed).
  Status add_wall(Vec2 a, Vec2 b);
  // Consecutive points joined by walls; `closed` joins the last to the first.
  Status add_polyline(std::span<const Vec2> points, bool closed);

  // --- steering ---------------------------------------------------------------------------
  // Goals are visited in order; the next becomes current when the agent is within its radius.
  Status set_goals(AgentId id, std::vector<Goal> goals, bool cyclic = false);
  Status set_goal(AgentId id, Goal goal) { return set_goals(id, {goal}); }
  Status clear_goals(AgentId id) { return set_goals(id, {}); }
  Status set_desired_speed(AgentId id, double speed);
  Status set_activity(AgentId id, Activity activity);
  Status set_intent(AgentId id, Intent intent);
  Status set_bt_node(AgentId id, std::string node);
  // An inactive agent is frozen and invisible to the others (e.g. after leaving by an exit).
  Status set_active(AgentId id, bool active);
  // Moves the agent into group `group_id` (-1: no group); group forces apply from the next step.
  Status set_group(AgentId id, std::int64_t group_id);

  // --- driven agents (robots under outside control) ----------------------------------------------
  // A driven agent is not moved by the forces: its state is what set_driven_state() last gave
  // (goals are ignored). Visible, the others avoid it exactly as they avoid a person (social,
  // body and contact terms); invisible, no one sees it.
  Status set_driven(AgentId id, Presence presence);
  // Pose and velocity of a driven agent (finite, within ±1e6 m, speed ≤ 8 m/s, |ω| ≤ 20 rad/s).
  Status set_driven_state(AgentId id, Pose2 pose, Twist2 twist);
  [[nodiscard]] bool driven(AgentId id) const { return driven_.at(id.value()) != kNotDriven; }

  // --- running ------------------------------------------------------------------------------
  void step();
  // The same step with an O(N²) neighbour scan (same forces, same cut-off): the reference the
  // cell-list step is checked against.
  void step_reference();

  // --- reading ------------------------------------------------------------------------------
  [[nodiscard]] std::size_t size() const { return px_.size(); }
  [[nodiscard]] double time() const { return static_cast<double>(steps_) * config_.dt; }
  [[nodiscard]] std::uint64_t steps() const { return steps_; }
  [[nodiscard]] const SimulationConfig& config() const { return config_; }
  [[nodiscard]] const RoleTable& roles() const { return roles_; }
  [[nodiscard]] const std::vector<WallSegment>& walls() const { return walls_; }

  [[nodiscard]] Vec2 position(AgentId id) const { return {px_.at(id.value()), py_.at(id.value())}; }
  [[nodiscard]] Vec2 velocity(AgentId id) const { return {vx_.at(id.value()), vy_.at(id.value())}; }
  [[nodiscard]] double yaw(AgentId id) const { return yaw_.at(id.value()); }
  [[nodiscard]] double desired_speed(AgentId id) const { return v0_.at(id.value()); }
  [[nodiscard]] double radius(AgentId id) const { return radius_.at(id.value()); }
  [[nodiscard]] bool active(AgentId id) const { return active_.at(id.value()) != 0; }
  // The current goal, or nothing when all goals were reached (or none was given).
  [[nodiscard]] std::optional<Goal> current_goal(AgentId id) const;
  [[nodiscard]] PedestrianState state(AgentId id) const;
  // The forces on an agent in the current state (refreshes the cached group centres and walls).
  [[nodiscard]] ForceBreakdown forces(AgentId id);

 private:
  CrowdSimulation(const SimulationConfig& config, RoleTable roles);
  struct CellIndex;
  struct AgentMeta;
  struct Images;
  // Every agent's frozen state followed by its periodic images (for the O(N²) reference scan).
  void build_images(Images& images) const;
  Status check_id(AgentId id, const char* what) const;
  // The dense index of a group id (created on first use); -1 for no group.
  std::int32_t group_slot(std::int64_t group_id);
  void prepare_step();
  // Hard contact, second half: pairs whose bodies the moves of this step would still leave
  // overlapping by more than 1 cm are pushed apart, each by half the excess, in up to
  // kSeparationPasses Jacobi passes, never through a wall nor into one (see docs/crowd.md).
  void separate_bodies();
  void finish_step();
  void build_cells();
  // x of the images one period to the left/right of agent i's position (periodic boundary only).
  [[nodiscard]] bool near_low_end(double x) const;
  [[nodiscard]] bool near_high_end(double x) const;
  [[nodiscard]] double wrap_x(double x) const;
  // What advance_agent reads of agent i itself, in one place (inputs_of). step_pairs reads them
  // from the cell index's copy in the cells' order (CellIndex::inputs, gathered where the index
  // is built: passes in that order then read them in order, not one random record an agent).
  struct AgentInputs {
    double x, y, vx, vy, r, v0, vmax, gx, gy, gr;
    std::int32_t group;
    std::uint16_t role;
    std::uint8_t driven, has_goal;
  };
  [[nodiscard]] AgentInputs inputs_of(std::uint32_t i) const;
  // One agent's step: prepare_agent (walking direction, walls), the neighbour sums, finish_agent
  // (the other forces, the integration, the hard contact, the wall guard).
  template <class Neighbours>
  void advance_agent(std::uint32_t i, const AgentInputs& in, const Neighbours& neighbours,
                     ForceBreakdown* breakdown);
  struct AgentPrep;
  struct NeighbourTotals;
  [[nodiscard]] AgentPrep prepare_agent(const AgentInputs& in) const;
  void finish_agent(std::uint32_t i, const AgentInputs& in, const AgentPrep& prep, const NeighbourTotals& t,
                    std::span<BodyContact> contacts, ForceBreakdown* breakdown);
  void hold_driven(std::uint32_t i, const AgentInputs& in, ForceBreakdown* breakdown);
  [[nodiscard]] double contact_margin(const AgentInputs& in) const;
  // Each pair once (social_kernel.hpp, pair_kernel): step() does so when pairs_once() holds — no
  // periodic boundary, every agent's role (active or not) with the same pair parameters — else
  // agent by agent.
  // The results are the same bits either way.
  [[nodiscard]] bool pairs_once() const;
  void step_pairs();
  bool mixed_pair_terms_ = false;  // some agent's role has other pair terms than the first's
  struct PairState;
  std::unique_ptr<PairState> pairs_;

  SimulationConfig config_;
  RoleTable roles_;
  std::unique_ptr<WorkerPool> pool_;
  std::uint64_t steps_ = 0;

  std::vector<WallSegment> walls_;
  WallGrid wall_grid_;
  // The walls touching each wall end (end a of wall w is 2w, end b is 2w + 1): the links of end
  // e are wall_links_[wall_link_start_[e] .. wall_link_start_[e + 1]). A free end (a door jamb)
  // has none.
  std::vector<std::uint32_t> wall_link_start_;
  std::vector<std::uint32_t> wall_links_;
  bool walls_dirty_ = false;

  // Frozen state (read during a step) and the next state (written by it).
  std::vector<double> px_, py_, vx_, vy_, yaw_, omega_;
  // The next state of each agent in one record (written in the cells' order: one cache line).
  struct alignas(32) NextState {
    double x, y, vx, vy;
  };
  LargeVector<NextState> next_;
  // Per agent, the ids (ascending) of the neighbours it could touch in this step, for
  // separate_bodies(): up to kStoredContacts at index i·kStoredContacts, count in contact_count_.
  static constexpr std::size_t kStoredContacts = 16;
  static constexpr int kSeparationPasses = 8;  // at most, per step (see separate_bodies())
  LargeVector<std::uint32_t> contact_ids_;
  std::vector<std::uint8_t> contact_count_;
  // Per agent, whether the last separation pass moved it (the next pass re-examines only agents
  // that moved or have a contact that did: for the others nothing it reads has changed).
  std::vector<std::uint8_t> moved_;
  std::vector<std::uint32_t> pressed_;  // agents with contacts (separate_bodies)
  struct Shift {
    double x, y;  // the position a separation pass gives pressed_[k]
    std::uint8_t moved;
  };
  std::vector<Shift> shift_;
  // Per-agent parameters.
  std::vector<double> radius_, v0_, vmax_;
  double max_radius_ = 0.0;   // largest radius of an active agent (set by prepare_step)
  double max_vmax_ = 0.0;     // largest speed limit of an active agent (set by prepare_step)
  bool maxima_dirty_ = true;  // an agent's radius, speed limit or activity changed since
  std::vector<std::uint16_t> role_;
  std::vector<std::int32_t> group_;  // dense group index, -1 = alone
  std::vector<std::uint8_t> active_;
  // kNotDriven, or 1 + Presence: a driven agent is skipped by the force step; an invisible one
  // also by every neighbour scan.
  static constexpr std::uint8_t kNotDriven = 0;
  static constexpr std::uint8_t kDrivenInvisible = 1 + static_cast<std::uint8_t>(Presence::kInvisible);
  std::vector<std::uint8_t> driven_;
  [[nodiscard]] bool seen(std::size_t i) const { return active_[i] != 0 && driven_[i] != kDrivenInvisible; }
  std::vector<std::uint8_t> has_goal_;
  std::vector<double> gx_, gy_, gr_;
  std::vector<AgentMeta> meta_;

  std::map<std::int64_t, std::int32_t> group_index_;
  std::vector<std::int64_t> group_ids_;
  std::vector<double> group_cx_, group_cy_;
  std::vector<std::uint32_t> group_size_;
  // Each group's members in agent order: group_members_[group_member_start_[g] .. [g + 1]),
  // rebuilt by prepare_step when groups_dirty_.
  std::vector<std::uint32_t> group_member_start_;
  std::vector<std::uint32_t> group_members_;
  bool groups_dirty_ = true;

  std::unique_ptr<CellIndex> cells_;
};

}  // namespace socsim::crowd
