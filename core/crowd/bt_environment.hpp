#pragma once
// What the behaviour-node library acts on: the CrowdSimulation, the World's named places, and
// the state behaviours share (HuNavSim goal lists, queues, seats, speech, gaze, velocity
// fields, exits). Nodes issue steering commands; apply() turns them into simulation goals,
// routing around walls along geodesic distance fields.
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/rng.hpp"
#include "core/crowd/crowd_simulation.hpp"
#include "core/crowd/velocity_field.hpp"
#include "core/world/geodesic.hpp"
#include "core/world/world.hpp"

namespace socsim::crowd {

// A named place of the world that behaviours refer to.
struct Place {
  enum class Kind : std::uint8_t { kRoi, kEntity, kDoor, kZone };
  std::string name;
  Kind kind = Kind::kRoi;
  std::string type;  // ROI kind, entity type, "door" or zone type
  Vec2 point;        // where to walk to: entity/door position, a point inside the region
  const geometry::Polygon* region = nullptr;  // ROI or zone polygon; null for entities and doors
  std::vector<std::string> affordances;
};

struct EnvironmentOptions {
  double navigation_resolution = 0.1;  // m per cell of the routing grid (coarsened above max_cells)
  // m kept from walls by routes: an adult's radius (0.23 m) plus a margin, so that routes do not
  // hug door jambs and corners where the wall force would stall the agent. Still passes a 0.9 m door.
  double navigation_inflation = 0.4;
  std::size_t navigation_max_cells = 400'000;
  std::size_t max_cached_routes = 64;  // distance fields kept for routing
  double lookahead = 2.0;              // m along the route to the intermediate goal
};

enum class Routing : std::uint8_t { kPath, kDirect };

class BtEnvironment {
 public:
  BtEnvironment(CrowdSimulation& sim, const world::World* world, EnvironmentOptions options = {});
  BtEnvironment(const BtEnvironment&) = delete;
  BtEnvironment& operator=(const BtEnvironment&) = delete;

  [[nodiscard]] CrowdSimulation& sim() { return sim_; }
  [[nodiscard]] const CrowdSimulation& sim() const { return sim_; }
  [[nodiscard]] const world::World* world() const { return world_; }
  // Agents known to the environment (call after adding agents to the simulation).
  void sync_agents();
  [[nodiscard]] bool valid(std::int64_t id) const {
    return id >= 0 && static_cast<std::uint64_t>(id) < agents_.size();
  }

  // --- decision steps ----------------------------------------------------------------------
  void begin_tick(double now);
  [[nodiscard]] double now() const { return now_; }
  // Pushes this tick's steering into the simulation (goals, desired speed, activity).
  void apply();

  // --- places --------------------------------------------------------------------------------
  [[nodiscard]] std::optional<Place> place(std::string_view name) const;
  // Message for a name that is not a place of the right sort; nullopt when it is fine.
  [[nodiscard]] std::optional<std::string> check_place(std::string_view name, std::string_view what) const;
  [[nodiscard]] bool inside(const Place& place, Vec2 p) const;

  // --- robot ---------------------------------------------------------------------------------
  void set_robot(std::optional<AgentId> robot) { robot_ = robot; }
  [[nodiscard]] std::optional<AgentId> robot() const { return robot_; }

  // --- HuNavSim goal lists -------------------------------------------------------------------
  struct GoalList {
    std::vector<Goal> goals;
    std::size_t index = 0;
    bool cyclic = true;
    std::optional<Goal> named;  // set by SetGoal with an ROI/POI name; cleared by UpdateGoal
  };
  void set_goal_list(AgentId id, std::vector<Goal> goals, bool cyclic);
  [[nodiscard]] GoalList& goal_list(AgentId id) { return agents_.at(id.value()).goals; }
  [[nodiscard]] std::optional<Goal> current_goal(AgentId id) const;
  void advance_goal(AgentId id);

  // --- steering (issued by nodes during a tick) ----------------------------------------------
  // A leader's commands (group walk, conversation) override the members' own for this tick.
  enum class Priority : std::uint8_t { kOwn, kLeader };
  void move_to(AgentId id, Vec2 target, double radius, double speed, Activity activity,
               Routing routing = Routing::kPath, Priority priority = Priority::kOwn);
  void hold(AgentId id, Activity activity, Priority priority = Priority::kOwn);
  // Stays at a spot (a seat, a place in line): walks back slowly when pushed off it.
  void hold_at(AgentId id, Vec2 spot, Activity activity, Priority priority = Priority::kOwn);
  void face(AgentId id, std::optional<Vec2> point) { agents_.at(id.value()).face = point; }
  void set_stopped(AgentId id, bool stopped) { agents_.at(id.value()).stopped = stopped; }
  [[nodiscard]] double base_speed(AgentId id) const { return agents_.at(id.value()).base_speed; }
  [[nodiscard]] Rng& rng(AgentId id) { return agents_.at(id.value()).rng; }

  // --- social state --------------------------------------------------------------------------
  void speak(AgentId id, std::string message);
  [[nodiscard]] std::optional<double> last_spoke(AgentId id) const { return agents_.at(id.value()).spoke_at; }
  // The reported group and the simulation's group forces.
  void set_group(AgentId id, std::int64_t group) {
    agents_.at(id.value()).group = group;
    (void)sim_.set_group(id, group);
  }
  [[nodiscard]] std::int64_t group(AgentId id) const { return agents_.at(id.value()).group; }
  // Heading as reported: towards the face point while the agent stays somewhere (standing,
  // queuing, sitting, talking, waiting) or moves slower than 0.25 m/s, else its walking yaw.
  [[nodiscard]] double heading(AgentId id) const;
  // The simulation's state with the environment's additions (heading, group, speech tag).
  [[nodiscard]] PedestrianState state(AgentId id) const;
  // Whether the straight line a→b crosses no wall; with a clearance, also the two lines offset
  // sideways by it (the path of a body that wide).
  [[nodiscard]] bool line_of_sight(Vec2 a, Vec2 b, double clearance = 0.0) const;

  // --- queues --------------------------------------------------------------------------------
  struct Queue {
    std::string name;
    Vec2 head;     // first place in line
    Vec2 to_tail;  // unit vector from the head towards the tail
    Vec2 service;  // where the head is served (in front of the counter)
    std::optional<Vec2> counter;
    double spacing = 0.7;
    std::vector<AgentId> members;  // in order, head first
    double head_since = 0.0;       // when the current head became head
    std::uint64_t served = 0;
  };
  // The queue of a queue_lane ROI (built on first use); nullptr when there is no such ROI.
  Queue* queue(std::string_view name);
  [[nodiscard]] Vec2 queue_place(const Queue& q, std::size_t index) const;
  [[nodiscard]] std::optional<std::size_t> queue_index(const Queue& q, AgentId id) const;
  void join_queue(Queue& q, AgentId id);
  void leave_queue(Queue& q, AgentId id);
  // Service order of every queue so far (agent ids in the order they left the head).
  [[nodiscard]] const std::vector<std::pair<std::string, AgentId>>& service_log() const {
    return service_log_;
  }
  void log_service(const Queue& q, AgentId id) { service_log_.emplace_back(q.name, id); }

  // --- seats ---------------------------------------------------------------------------------
  // Reserves the free seat of `place` nearest to `from`; nullopt when all are taken.
  std::optional<Vec2> reserve_seat(const Place& place, AgentId id, Vec2 from);
  void release_seat(AgentId id);

  // --- velocity fields and exits -------------------------------------------------------------
  void add_velocity_field(std::string name, VelocityField field, std::vector<geometry::Polygon> goal_regions);
  struct FieldEntry {
    VelocityField field;
    std::vector<geometry::Polygon> goals;
  };
  [[nodiscard]] const FieldEntry* velocity_field(std::string_view name) const;

  struct Exit {
    std::string name;
    Vec2 point;                  // door centre or a point of the exit ROI
    std::optional<Vec2> beyond;  // a point outside the plan (doors to the outside), 1 m out
    const geometry::Polygon* region = nullptr;
    Vec2 half_opening{};  // doors: from the centre to one jamb along the opening
  };
  [[nodiscard]] const std::vector<Exit>& exits() const { return exits_; }
  // The exit with the shortest walk from p (geodesic); nullopt when none is reachable.
  std::optional<std::size_t> nearest_exit(Vec2 p);
  std::optional<std::size_t> exit_index(std::string_view name) const;
  // Whether p lies outside every zone (the agent has left the building).
  [[nodiscard]] bool outside(Vec2 p) const;
  // Geodesic walking distance from p to the target (+inf when unreachable; Euclidean without a world).
  double walking_distance(Vec2 p, Vec2 target);

 private:
  struct Command {
    bool set = false;
    bool hold = true;
    Vec2 target;
    double radius = 0.3;
    double speed = 0.0;
    Activity activity = Activity::kStanding;
    Routing routing = Routing::kPath;
  };
  struct AgentState {
    GoalList goals;
    double base_speed = 1.34;
    Rng rng{0};
    Command own;
    Command leader;
    std::optional<Vec2> face;
    bool stopped = false;
    std::int64_t group = -1;
    std::optional<double> spoke_at;
    std::string message;
    std::optional<Vec2> seat;
    Activity activity = Activity::kWalking;  // of the last applied command
    bool applied = false;
  };
  const world::GeodesicField* route_field(Vec2 target);
  // The intermediate goal towards `target`: the farthest point, up to `lookahead` along the route,
  // reached by a straight walk that keeps `clearance` (the body's radius plus a margin) from walls.
  Vec2 route_waypoint(Vec2 from, Vec2 target, double clearance);
  void build_exits();

  CrowdSimulation& sim_;
  const world::World* world_;
  EnvironmentOptions options_;
  std::optional<world::OccupancyGrid> grid_;
  std::vector<AgentState> agents_;
  std::optional<AgentId> robot_;
  double now_ = 0.0;
  std::map<std::string, Queue, std::less<>> queues_;
  std::vector<std::pair<std::string, AgentId>> service_log_;
  std::map<std::string, std::vector<Vec2>, std::less<>> seats_;          // per place name
  std::map<std::pair<std::int64_t, std::int64_t>, AgentId> seat_taken_;  // quantised seat → agent
  std::map<std::string, FieldEntry, std::less<>> fields_;
  std::vector<Exit> exits_;
  std::vector<std::shared_ptr<world::GeodesicField>> exit_fields_;
  // Routing fields by target cell, least recently used first.
  std::deque<std::pair<std::int64_t, std::shared_ptr<world::GeodesicField>>> routes_;
};

}  // namespace socsim::crowd
