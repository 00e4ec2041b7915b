#pragma once
// Which receptacle to inspect next, given each candidate's probability of holding the target and
// its distance in steps (paper 000 §VI-A b): Greedy (nearest), OSG (one-step greedy with α) and
// CEG (cost-effective greedy: probability ÷ distance).
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace socsim::navbench {

struct Candidate {
  int receptacle = -1;  // index into NavMap::receptacles()
  double p = 0.0;       // renormalised over the receptacles not yet observed
  int steps = 0;        // from the agent's pose to the nearest pose that sees it
};

class Planner {
 public:
  virtual ~Planner() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  // Index into `candidates` (non-empty) of the receptacle to inspect next.
  [[nodiscard]] virtual std::size_t choose(std::span<const Candidate> candidates) const = 0;
};

// The nearest candidate (ties: the smaller receptacle index).
class GreedyPlanner final : public Planner {
 public:
  [[nodiscard]] std::string_view name() const override { return "Greedy"; }
  [[nodiscard]] std::size_t choose(std::span<const Candidate> candidates) const override;
};

// One-step greedy: the candidate maximising α·p − (1 − α)·d/d_max, trading how likely the target
// is there (p renormalised over the candidates) against how far it is (scaled by the farthest).
// p is not rescaled by its maximum: the paper's OSG stays well below CEG (docs/navbench.md).
class OsgPlanner final : public Planner {
 public:
  explicit OsgPlanner(double alpha = 0.5) : alpha_(alpha) {}
  [[nodiscard]] std::string_view name() const override { return "OSG"; }
  [[nodiscard]] std::size_t choose(std::span<const Candidate> candidates) const override;

 private:
  double alpha_;
};

// Cost-effective greedy: the candidate maximising p / d (d ≥ 1 step).
class CegPlanner final : public Planner {
 public:
  [[nodiscard]] std::string_view name() const override { return "CEG"; }
  [[nodiscard]] std::size_t choose(std::span<const Candidate> candidates) const override;
};

}  // namespace socsim::navbench
