#pragma once
// Per-role pedestrian parameters: desired-speed distribution, body radius, proxemics and the
// LightSFM force weights; a table of built-in roles that scenario programs can override.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "core/crowd/pedestrian_state.hpp"

namespace socsim::crowd {

// Social-force weights. Defaults are LightSFM's (robotics-upo/lightsfm, include/lightsfm/sfm.hpp,
// struct Parameters); names in comments are LightSFM's.
struct ForceParameters {
  double desired_factor = 2.0;          // forceFactorDesired
  double obstacle_factor = 10.0;        // forceFactorObstacle, m/s^2
  double obstacle_sigma = 0.2;          // forceSigmaObstacle, m
  double social_factor = 2.1;           // forceFactorSocial, m/s^2
  double group_gaze_factor = 3.0;       // forceFactorGroupGaze
  double group_coherence_factor = 2.0;  // forceFactorGroupCoherence
  double group_repulsion_factor = 1.0;  // forceFactorGroupRepulsion
  double lambda = 2.0;                  // weight of relative velocity in the interaction vector
  double gamma = 0.35;                  // interaction range per unit interaction length
  double n = 2.0;                       // angular decay of the sideways term
  double n_prime = 3.0;                 // angular decay of the deceleration term (nPrime)
  double relaxation_time = 0.5;         // s
  // Speed–headway adaptation (an addition to LightSFM, after Seyfried et al. 2005 and Tordeux,
  // Chraibi & Seyfried 2016): the desired speed is capped at (s − headway_distance)/headway_time,
  // s being the centre distance to the nearest person straight ahead who is not coming towards the
  // agent. Defaults calibrated on Weidmann's fundamental diagram (docs/crowd.md); headway_time = 0
  // turns it off (pure LightSFM).
  double headway_distance = 0.4;  // m
  double headway_time = 0.6;      // s
  // Who counts as "ahead": a centre within headway_band × the agent's radius of its walking line.
  double headway_band = 1.5;
  // Anticipation (s): the gap is taken headway_anticipation seconds ahead at the current relative
  // speed, s + τ·(v_j − v_i)·e. Neutral in uniform flow (the fundamental diagram is set by
  // headway_distance and headway_time); lets followers keep up with people accelerating away, as
  // through a door (calibrated on Seyfried's and Kretz's bottleneck flows, docs/crowd.md).
  double headway_anticipation = 2.5;
  // The zipper (Hoogendoorn & Daamen 2005; Seyfried et al. 2009): in a narrow opening people
  // follow in two staggered lanes, shoulders turned, closer than in single file. Where walls
  // come within zipper_reach of the agent on both sides of its walking line (abreast of it, in or
  // just before an opening narrower than ~2·zipper_reach), the band in which someone counts as
  // ahead narrows to zipper_band × the radius. zipper_band = headway_band turns it off.
  double zipper_band = 0.75;
  double zipper_reach = 0.8;  // m
  // Side preference towards oncoming walkers (an addition): each walker coming towards the agent
  // within side_band of its walking line pushes it sideways with side_factor·exp(−ahead/side_range),
  // to the right unless that walker is already more than side_bias right of the line. 0 = off.
  double side_factor = 1.5;  // m/s²
  double side_range = 1.5;   // m
  double side_bias = 0.1;    // m
  double side_band = 0.7;    // m
  friend bool operator==(const ForceParameters&, const ForceParameters&) = default;
};

// Desired speed ~ Normal(mean, sd) truncated to [min, max] by clamping.
struct SpeedDistribution {
  double mean = 1.34;
  double sd = 0.26;
  double min = 0.5;
  double max = 2.2;
  friend bool operator==(const SpeedDistribution&, const SpeedDistribution&) = default;
};

struct RoleParameters {
  std::string name;
  SpeedDistribution speed;
  double radius = 0.23;           // m
  double max_speed_factor = 1.0;  // |v| <= factor · desired speed (LightSFM clamps at 1.0)
  ForceParameters forces;
  Proxemics proxemics;
  friend bool operator==(const RoleParameters&, const RoleParameters&) = default;
};

// Largest speed any role may reach (m/s); keeps one step's move shorter than the wall cut-off.
inline constexpr double kMaxAgentSpeed = 8.0;

// Checks ranges; errors carry JSON pointers below `pointer`.
Status validate(const RoleParameters& role, const std::string& pointer = "");
Json to_json(const RoleParameters& role);
// Reads a role; absent fields keep the values of `base`.
Result<RoleParameters> role_parameters_from_json(const Json& j, const RoleParameters& base,
                                                 const std::string& pointer = "");

class RoleTable {
 public:
  // adult, elderly, staff, jogger, stroller_pusher (sources in docs/crowd.md).
  static RoleTable defaults();
  // Adds a role or replaces the role of the same name.
  Status put(RoleParameters role);
  // Applies {"roles": {...}}-style overrides: each key names a role; absent fields keep the
  // table's values from before this call (new names start from "adult"). All or nothing.
  Status apply_json(const Json& roles, const std::string& pointer = "");

  [[nodiscard]] std::optional<std::size_t> index_of(std::string_view name) const;
  [[nodiscard]] const RoleParameters& at(std::size_t index) const { return roles_.at(index); }
  [[nodiscard]] std::size_t size() const { return roles_.size(); }
  [[nodiscard]] std::vector<std::string> names() const;

 private:
  std::vector<RoleParameters> roles_;
};

}  // namespace socsim::crowd
