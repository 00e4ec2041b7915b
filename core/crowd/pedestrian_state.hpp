#pragma once
// One pedestrian's state per frame: the fields of socsim_people_msgs (paper 001, Table I),
// with a strict JSON form so states can be logged, exported and read back.
#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"

namespace socsim::crowd {

// Type-safe agent identifier: the dense index the simulation gave the agent.
class AgentId {
 public:
  constexpr AgentId() = default;
  constexpr explicit AgentId(std::uint32_t value) : value_(value) {}
  [[nodiscard]] constexpr std::uint32_t value() const { return value_; }
  friend constexpr auto operator<=>(AgentId, AgentId) = default;

 private:
  std::uint32_t value_ = 0;
};

// What the pedestrian is doing (Table I `state`).
enum class Activity : std::uint8_t {
  kWalking,
  kStanding,
  kQueuing,
  kSitting,
  kInteracting,
  kEvacuating,
  kWaiting,
  kRunning,
  kExited,  // left the world through an exit; no longer simulated
};

std::string_view activity_name(Activity a);
std::optional<Activity> activity_from_name(std::string_view name);
// All names, in enum order (for error messages and schemas).
const std::vector<std::string_view>& activity_names();

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;  // rad, (-pi, pi]
  friend bool operator==(const Pose2&, const Pose2&) = default;
};

struct Twist2 {
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;  // rad/s
  friend bool operator==(const Twist2&, const Twist2&) = default;
};

// Where the pedestrian is heading in the semantic world (Table I `intent`).
struct Intent {
  std::string target;         // ROI/POI id from world.yaml; empty when none
  std::int64_t goal_id = -1;  // index of the current goal; -1 when none
  friend bool operator==(const Intent&, const Intent&) = default;
};

// Social spacing (Table I `proxemics`): Hall's zones and how strictly they are kept.
struct Proxemics {
  double intimate_radius = 0.45;  // m, Hall (1966)
  double comfort_radius = 1.2;    // m, personal zone, Hall (1966)
  double social_radius = 3.6;     // m, social zone, Hall (1966)
  double compliance = 1.0;        // 0 ignores others' space .. 1 keeps it fully
  friend bool operator==(const Proxemics&, const Proxemics&) = default;
};

struct StateMetadata {
  std::uint64_t seed = 0;  // seed of this agent's random stream
  std::string bt_node;     // behaviour-tree node running now; empty when none
  std::vector<std::string> tags;
  friend bool operator==(const StateMetadata&, const StateMetadata&) = default;
};

struct PedestrianState {
  AgentId id;
  Pose2 pose;
  Twist2 twist;
  Activity activity = Activity::kWalking;
  std::string role = "adult";
  Intent intent;
  std::int64_t group_id = -1;  // -1: walks alone
  Proxemics proxemics;
  StateMetadata metadata;
  friend bool operator==(const PedestrianState&, const PedestrianState&) = default;
};

Json to_json(const PedestrianState& s);
// Strict reading: unknown keys, wrong types, non-finite numbers and unknown state names are
// reported with JSON pointers below `pointer`.
Result<PedestrianState> pedestrian_state_from_json(const Json& j, const std::string& pointer = "");

}  // namespace socsim::crowd
