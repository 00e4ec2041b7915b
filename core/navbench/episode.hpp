#pragma once
// One search episode on the map: the planner picks a receptacle, the agent walks a shortest step
// path to the nearest pose that sees it, every receptacle seen on the way is ruled out, and the
// episode ends when the target is seen (success) or the step budget is spent. No stop action, as
// in paper 000 §VI-B.
#include <span>
#include <vector>

#include "core/navbench/nav_map.hpp"
#include "core/navbench/planners.hpp"

namespace socsim::navbench {

struct EpisodeSpec {
  int start = -1;              // pose
  int target_receptacle = -1;  // index into NavMap::receptacles(); the target rests on it
  int max_steps = 200;         // paper 000 §VI-B for map-based methods
  // The paper's planners route over receptacles' viewpoints and cross off the ones they reach;
  // true also crosses off every receptacle seen on the way (a more thorough searcher).
  bool rule_out_on_the_way = false;
  // Poses that see the target object where it lies on its receptacle (NavMap::views_of_point),
  // sorted; empty: the receptacle's own views (the object at its centre).
  std::vector<int> target_views = {};
};

struct EpisodeResult {
  bool success = false;
  int steps = 0;          // actions taken (EL)
  int shortest = -1;      // fewest actions from the start to a pose that sees the target; −1: unreachable
  double spl = 0.0;       // success · shortest / max(shortest, steps)
  std::vector<int> path;  // pose after every action
  std::vector<int> visited;     // receptacles the planner chose and reached, in order
  std::vector<int> visited_at;  // the step at which each was reached
};

// Fewest actions from `start` to any pose that sees the receptacle, −1 when none is reachable.
int shortest_steps(const NavMap& map, int start, int receptacle);

// `probabilities`: one per map receptacle (any scale; zeros are searched last, nearest first).
EpisodeResult run_episode(const NavMap& map, const EpisodeSpec& spec, std::span<const double> probabilities,
                          const Planner& planner);

}  // namespace socsim::navbench
