#include "core/navbench/planners.hpp"

#include <algorithm>

namespace socsim::navbench {
namespace {

// Strictly better score, or an equal score (to 1e-12) at a nearer or lower-numbered receptacle.
bool better(double score, const Candidate& c, double best_score, const Candidate& best) {
  if (score > best_score + 1e-12) return true;
  if (score < best_score - 1e-12) return false;
  return c.steps != best.steps ? c.steps < best.steps : c.receptacle < best.receptacle;
}

template <class Score>
std::size_t argmax(std::span<const Candidate> cs, Score score) {
  std::size_t best = 0;
  double best_score = score(cs[0]);
  for (std::size_t i = 1; i < cs.size(); ++i) {
    const double s = score(cs[i]);
    if (better(s, cs[i], best_score, cs[best])) best = i, best_score = s;
  }
  return best;
}

}  // namespace

std::size_t GreedyPlanner::choose(std::span<const Candidate> cs) const {
  return argmax(cs, [](const Candidate& c) { return -static_cast<double>(c.steps); });
}

std::size_t OsgPlanner::choose(std::span<const Candidate> cs) const {
  int d_max = 0;
  for (const auto& c : cs) d_max = std::max(d_max, c.steps);
  const double dm = d_max > 0 ? d_max : 1.0;
  return argmax(cs, [&](const Candidate& c) { return alpha_ * c.p - (1.0 - alpha_) * c.steps / dm; });
}

std::size_t CegPlanner::choose(std::span<const Candidate> cs) const {
  return argmax(cs, [](const Candidate& c) { return c.p / std::max(1, c.steps); });
}

}  // namespace socsim::navbench
