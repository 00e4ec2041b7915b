#include "core/navbench/episode.hpp"

#include <algorithm>

namespace socsim::navbench {

int shortest_steps(const NavMap& map, int start, int receptacle) {
  const StepField f = map.steps_from(start);
  const int v = f.nearest(map.receptacles()[static_cast<std::size_t>(receptacle)].views);
  return v < 0 ? -1 : f.distance[static_cast<std::size_t>(v)];
}

EpisodeResult run_episode(const NavMap& map, const EpisodeSpec& spec, std::span<const double> probabilities,
                          const Planner& planner) {
  EpisodeResult out;
  const auto& recs = map.receptacles();
  if (spec.start < 0 || spec.start >= map.poses() || spec.target_receptacle < 0 ||
      spec.target_receptacle >= static_cast<int>(recs.size()) || probabilities.size() != recs.size())
    return out;
  std::vector<char> observed(recs.size(), 0);
  const std::vector<int>& target_views = spec.target_views.empty()
                                             ? recs[static_cast<std::size_t>(spec.target_receptacle)].views
                                             : spec.target_views;
  // True when the target is seen from `pose`; rules out what is seen when the spec says so.
  auto observe = [&](int pose) {
    if (spec.rule_out_on_the_way)
      for (int r : map.visible_from(pose)) observed[static_cast<std::size_t>(r)] = 1;
    return std::binary_search(target_views.begin(), target_views.end(), pose);
  };
  StepField field = map.steps_from(spec.start);
  const int goal = field.nearest(target_views);
  out.shortest = goal < 0 ? -1 : field.distance[static_cast<std::size_t>(goal)];
  out.success = observe(spec.start);
  int pose = spec.start;
  std::vector<Candidate> candidates;
  std::vector<int> view_of;
  // Spots of each receptacle's top already seen; a receptacle is crossed off once all are.
  std::vector<std::vector<char>> spot_seen(recs.size());
  for (std::size_t r = 0; r < recs.size(); ++r) spot_seen[r].assign(recs[r].spots.size(), 0);
  auto look_at = [&](std::size_t r, int at) {
    for (std::size_t j = 0; j < recs[r].spots.size(); ++j)
      if (!spot_seen[r][j] && std::binary_search(recs[r].spots[j].begin(), recs[r].spots[j].end(), at))
        spot_seen[r][j] = 1;
  };
  while (!out.success && out.steps < spec.max_steps) {
    if (pose != spec.start || out.steps > 0) field = map.steps_from(pose);
    candidates.clear();
    view_of.clear();
    double total = 0.0;
    for (std::size_t r = 0; r < recs.size(); ++r) {
      if (observed[r]) continue;
      // The nearest pose that sees a spot of its top not seen yet (ties: the smaller pose).
      int v = -1;
      for (std::size_t j = 0; j < recs[r].spots.size(); ++j) {
        if (spot_seen[r][j]) continue;
        const int w = field.nearest(recs[r].spots[j]);
        if (w < 0) continue;
        const int dw = field.distance[static_cast<std::size_t>(w)];
        const int dv = v < 0 ? -1 : field.distance[static_cast<std::size_t>(v)];
        if (v < 0 || dw < dv || (dw == dv && w < v)) v = w;
      }
      if (v < 0) continue;
      const double p = std::max(0.0, probabilities[r]);
      candidates.push_back({static_cast<int>(r), p, field.distance[static_cast<std::size_t>(v)]});
      view_of.push_back(v);
      total += p;
    }
    if (candidates.empty()) break;  // everything reachable has been seen
    if (total > 0)
      for (auto& c : candidates) c.p /= total;
    const std::size_t k = planner.choose(candidates);
    const auto chosen = static_cast<std::size_t>(candidates[k].receptacle);
    const std::vector<int> path = field.path_to(view_of[k]);
    for (int next : path) {
      pose = next;
      ++out.steps;
      out.path.push_back(pose);
      look_at(chosen, pose);
      out.success = observe(pose);
      if (out.success || out.steps >= spec.max_steps) break;
    }
    if (pose == view_of[k]) {
      look_at(chosen, pose);
      bool done = true;
      for (std::size_t j = 0; j < spot_seen[chosen].size(); ++j)
        done = done && (spot_seen[chosen][j] || field.nearest(recs[chosen].spots[j]) < 0);
      if (done) {
        observed[chosen] = 1;
        out.visited.push_back(candidates[k].receptacle);
        out.visited_at.push_back(out.steps);
      }
    }
  }
  if (out.success && out.shortest >= 0) {
    const int longer = std::max(out.shortest, out.steps);
    out.spl = longer == 0 ? 1.0 : static_cast<double>(out.shortest) / longer;
  }
  return out;
}

}  // namespace socsim::navbench
