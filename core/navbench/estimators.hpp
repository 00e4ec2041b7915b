#pragma once
// Where the target object may be (paper 000 §VI-A c): one probability per receptacle of the map.
// Uniform; Scene Prior (object–receptacle co-occurrence counted on separately generated static
// training houses); Hint (the resident's answer read as text, backed by the scene prior); and a
// schedule-aware Posterior that runs the scene's generative model forward exactly up to time t.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/household/hints.hpp"
#include "core/household/scene.hpp"
#include "core/navbench/nav_map.hpp"

namespace socsim::navbench {

// What the posterior may know about a scene: the static house (receptacles, and where objects
// stood before anyone moved them) and its residents (schedules, activity databases, own bedroom
// and bathroom). Not the events' sampled rooms or the relocations.
struct GenerativeModel {
  std::shared_ptr<const household::House> house;
  std::vector<household::Resident> residents;
};
// Borrows the scene's house: the scene must outlive the model.
GenerativeModel generative_model_of(const household::DynamicScene& scene);

struct EstimateQuery {
  const NavMap* map = nullptr;
  std::string target_type;
  household::Seconds time = 0;
  // The task's promise: the target was moved within (time − recent, time]; ≤ 0: no promise.
  household::Seconds recent = household::kSecondsPerDay;
  std::string hint;                        // the residents' answers, one a line; "" when none
  const GenerativeModel* model = nullptr;  // only the posterior reads it
};

class LocationEstimator {
 public:
  virtual ~LocationEstimator() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  // One probability per map receptacle, summing to 1, or all zero when it knows nothing.
  [[nodiscard]] virtual std::vector<double> estimate(const EstimateQuery& query) const = 0;
};

class UniformEstimator final : public LocationEstimator {
 public:
  [[nodiscard]] std::string_view name() const override { return "Uniform"; }
  [[nodiscard]] std::vector<double> estimate(const EstimateQuery& query) const override;
};

// How often objects of each type rest on receptacles of each type in each room type.
struct PlacementCounts {
  std::map<std::string, double, std::less<>> objects;  // "Mug|DiningTable|Kitchen", "Mug|DiningTable", "Mug"
  std::map<std::string, double, std::less<>> receptacles;  // "DiningTable|Kitchen", "DiningTable"
  double total_receptacles = 0.0;
  int houses = 0;
  std::vector<std::uint64_t> seeds;  // of the houses counted
};
void add_house(PlacementCounts& counts, const household::House& house, std::uint64_t seed);

// Training houses and test scenes draw seeds from disjoint halves of the 64-bit range (top bit
// set for training), so no test house is ever a training house.
std::uint64_t training_house_seed(std::uint64_t training_seed, int index);
inline bool is_training_seed(std::uint64_t seed) {
  return (seed >> 63) != 0;
}
// Counts `houses` generated static houses of 1–10 rooms (as ProcTHOR-10k's training split).
Result<PlacementCounts> count_training_placements(const household::HouseholdKnowledge& knowledge, int houses,
                                                  std::uint64_t training_seed, int threads = 1);

class ScenePriorEstimator final : public LocationEstimator {
 public:
  explicit ScenePriorEstimator(std::shared_ptr<const PlacementCounts> counts) : counts_(std::move(counts)) {}
  [[nodiscard]] std::string_view name() const override { return "SP"; }
  [[nodiscard]] std::vector<double> estimate(const EstimateQuery& query) const override;
  // Expected objects of `object_type` on one receptacle of this type in this room type, with
  // back-off to the receptacle type alone and to the object type's overall rate.
  [[nodiscard]] double rate(std::string_view object_type, std::string_view receptacle_type,
                            household::RoomType room) const;
  [[nodiscard]] const PlacementCounts& counts() const { return *counts_; }

 private:
  std::shared_ptr<const PlacementCounts> counts_;
};

// The residents' answers (one a line) read by household::read_hints (room, receptacle and activity
// words of the curated knowledge), each turned into a distribution by household::hint_distribution
// with the scene prior as the base: `trust` of the mass on a named receptacle, or spread evenly over
// the named room's receptacles (half when the answer is hedged), the rest on the scene prior, which
// thus still ranks the room's receptacles by ratios that CEG follows but with absolute differences
// too small to beat OSG's distance share; the mean over the answers that say
// "used"; the scene prior alone when every answer says no or names nothing known. The named
// activity's curated p(l|a) and p(r|o,a,l) are not read: they are the scene generator's own tables
// (as the paper's LLM estimator goes from the event to a room and then to receptacles by its own
// judgement; docs/navbench.md, "Hints and the two planners").
class HintEstimator final : public LocationEstimator {
 public:
  HintEstimator(std::shared_ptr<const ScenePriorEstimator> prior,
                const household::HouseholdKnowledge& knowledge, double trust = 0.85)
      : prior_(std::move(prior)), knowledge_(&knowledge), trust_(trust) {}
  [[nodiscard]] std::string_view name() const override { return "Hint"; }
  [[nodiscard]] std::vector<double> estimate(const EstimateQuery& query) const override;

 private:
  std::shared_ptr<const ScenePriorEstimator> prior_;
  const household::HouseholdKnowledge* knowledge_;
  double trust_;
};

// P(receptacle | the residents' schedules and activity databases up to t, and the task's promise
// that the target moved recently), computed exactly by running the scene configuration's
// sampling model (paper 000 §IV-C) forward as a distribution. Exact for a type with one instance
// in the house (every benchmark target); all zero for other types.
class PosteriorEstimator final : public LocationEstimator {
 public:
  [[nodiscard]] std::string_view name() const override { return "Posterior"; }
  [[nodiscard]] std::vector<double> estimate(const EstimateQuery& query) const override;
};

}  // namespace socsim::navbench
