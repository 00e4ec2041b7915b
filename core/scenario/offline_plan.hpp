#pragma once
// The program the offline generator is writing (agents, trees, ambient groups, roles, notes) and
// the per-category planners that fill it: each turns one activity of the prompt into spotlight
// agents and ambient groups placed in the world. Internal to program_offline.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/common/rng.hpp"
#include "core/scenario/intent.hpp"
#include "core/scenario/offline_tree.hpp"
#include "core/scenario/offline_world.hpp"
#include "core/scenario/program_offline.hpp"

namespace socsim::scenario {

// One thing the prompt asks for: a category with the clauses that ask for it.
struct Activity {
  Category category = Category::kNormalOperation;
  double score = 0.0;
  std::vector<std::size_t> clauses;
  std::vector<RoleMention> roles;
  std::vector<std::pair<PlaceMention, std::optional<ResolvedPlace>>> places;
  std::optional<std::size_t> crowd;  // "a crowd of 200" said in one of its clauses
  // The first place mention that resolved, if any.
  [[nodiscard]] const ResolvedPlace* place() const;
  [[nodiscard]] const PlaceMention* unresolved() const;  // first mention that did not resolve
};

struct People {
  std::string role;
  std::size_t count = 0;
  bool explicit_count = false;
  std::string phrase;  // the prompt's words, or "default"
};

class Draft {
 public:
  Draft(WorldProbe& probe, NodeCatalogue& nodes, const Intent& intent, const ProgramRequest& request,
        const ScenarioLimits& limits);

  WorldProbe& probe;
  NodeCatalogue& nodes;
  const Intent& intent;
  const ProgramRequest& request;
  const ScenarioLimits& limits;
  std::optional<double> alarm_s;     // emergency in the prompt: every tree evacuates from then on
  std::optional<double> start_s;     // "after 20 seconds" without an emergency: activities start then
  std::optional<double> activity_s;  // "for two minutes": how long chats, gatherings, visits last
  // The prompt names who is there (scenario_intent.hpp) and asks for nobody else: planners add no
  // default people (no receptionist nobody asked for, no passing traffic).
  bool named_only = false;
  // Program role → the known role whose crowd parameters it takes ("librarian" → "worker").
  std::map<std::string, std::string> role_basis;

  // Who takes part: the activity's roles with their counts (defaults where the prompt gives none),
  // else the world's usual people for the category, `default_total` in all.
  std::vector<People> people(const Activity& a, std::size_t default_total, Rng& rng) const;
  // Spotlight places left in the limit; grants at most `wanted`.
  std::size_t take_spotlight(std::size_t wanted);
  // Splits n people over regions (in order) within what each still holds; the rest is unplaced.
  std::vector<std::pair<std::string, std::size_t>> spread(const std::vector<std::string>& regions,
                                                          std::size_t n);
  [[nodiscard]] std::size_t room_left(const std::string& region) const;

  // A tree named after `base` (made unique); the body must write one root element. The emergency
  // and delayed-start wrappers are added here.
  Result<std::string> add_tree(Category category, const std::string& base,
                               const std::function<void(TreeXml&)>& body);
  void add_agents(const std::string& name, const People& who, const std::string& spawn, std::size_t count,
                  const std::string& tree, std::int64_t group, Category category);
  void add_agent_at(const std::string& name, const std::string& role, crowd::Vec2 position,
                    const std::string& tree, Category category);
  struct Ambient {
    std::string name;
    std::string role;
    std::vector<std::string> start;
    std::vector<std::string> goal;
    std::size_t size = 0;
    double speed = 1.34;
    double variation = 0.1;
    bool exit_at_goal = true;
    std::string description;
    bool explicit_count = false;
  };
  Status add_ambient(Category category, Ambient group);
  std::int64_t new_group() { return next_group_++; }
  void note(std::string text) { notes_.push_back(std::move(text)); }
  void place_used(Category category, const std::string& purpose, const std::string& name,
                  const std::string& why);

  // Scales counts down to the agent bound (ambient first, defaults before explicit counts).
  void fit(std::size_t bound);
  [[nodiscard]] std::size_t total() const;
  [[nodiscard]] Json program(const std::string& name) const;
  [[nodiscard]] Json provenance() const;

 private:
  struct Entry {
    Json json;
    std::size_t count = 0;
    bool explicit_count = false;
    bool positioned = false;
  };
  struct AmbientEntry {
    Ambient group;
    std::string tree;  // behaviour-tree name when wrapped (alarm or delayed start)
    std::string xml;
  };
  std::vector<Entry> agents_;
  std::vector<AmbientEntry> ambient_;
  std::vector<std::pair<std::string, std::string>> trees_;
  std::map<std::string, std::size_t> used_room_;
  std::vector<std::string> roles_;
  std::vector<std::string> notes_;
  Json places_ = Json::array();
  std::size_t spotlight_ = 0;
  std::int64_t next_group_ = 1;
};

// The planners, one per category (category_plans.cpp).
Status plan_emergency(Draft& d, const Activity& a, Rng& rng);
Status plan_queuing(Draft& d, const Activity& a, Rng& rng);
Status plan_social_party(Draft& d, const Activity& a, Rng& rng);
Status plan_coffee_break(Draft& d, const Activity& a, Rng& rng);
Status plan_reception(Draft& d, const Activity& a, Rng& rng);
Status plan_bottleneck(Draft& d, const Activity& a, Rng& rng);
Status plan_normal_operation(Draft& d, const Activity& a, Rng& rng);

}  // namespace socsim::scenario
