#pragma once
// The object-goal navigation benchmark of paper 000 §VI on dynamic household scenes: test scenes
// per split, tasks at two fixed instants (recently moved, single-instance targets of 11 types), the
// methods of Table I plus the schedule-aware posterior, and EL / SR / SPL. The seed fixes every
// scene, task, episode and number; the thread count does not change them.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"
#include "core/household/scene.hpp"
#include "core/navbench/episode.hpp"
#include "core/navbench/estimators.hpp"

namespace socsim::navbench {

enum class Split : std::uint8_t { kNormal, kHard };  // 4–7 rooms, 1–2 residents | 8–10 rooms, 3–4 residents
std::string_view split_name(Split split);
std::optional<Split> parse_split(std::string_view name);

// The 11 target object types (things people carry around and then look for).
const std::vector<std::string>& target_types();

// Friday 17:30 and Sunday 23:30 of a scene starting Wednesday 00:00 (see BenchmarkRequest).
std::vector<household::Seconds> paper_instants();

struct BenchmarkRequest {
  Split split = Split::kNormal;
  int scenes = 50;
  std::uint64_t seed = 0;
  int tasks_per_scene = 10;  // "up to 10 tasks per scene at two instants"
  // When the tasks are set, from 00:00 of the first day (Wednesday): the paper's released scenes
  // (DynamicTHOR sampled_scenes_normal and _hard) put both at Friday 17:30 and Sunday 23:30.
  // An instant at or after the scene's end is skipped.
  std::vector<household::Seconds> instants = paper_instants();
  int max_steps = 200;
  household::Seconds recent = household::kSecondsPerDay;  // "recently moved": within this before the instant
  int training_houses = 10000;      // static houses the scene prior is counted on (as ProcTHOR-10k)
  std::uint64_t training_seed = 1;  // their seeds lie in the other half of the range (is_training_seed)
  double alpha = 0.5;               // OSG
  double hint_trust = 0.85;
  NavConfig nav;
  // Test houses given instead of generated ones (e.g. ProcTHOR houses, read_procthor_houses):
  // scene i uses houses[i % size]; residents, tasks and seeds are drawn as for generated houses.
  std::vector<std::shared_ptr<const household::House>> houses;
};
// ProcTHOR house JSON, one house per line (as ProcTHOR-10k ships; blank lines skipped). A line
// that is not JSON or not a house is kValidation with its pointer, e.g. "/houses/2/rooms/0".
Result<std::vector<std::shared_ptr<const household::House>>> read_procthor_houses(
    std::string_view jsonl, const household::HouseholdKnowledge& knowledge);
// Reads {split, scenes, seed, tasks_per_scene?, max_steps?, training_houses?, alpha?}; every bad
// field is named by JSON pointer.
Result<BenchmarkRequest> benchmark_request_from_json(const Json& json);
Json to_json(const BenchmarkRequest& request);

// A method of the table: estimator + planner. Keys are "<estimator>+<planner>".
struct Method {
  std::string key, label;
  bool uses_hint = false;
};
const std::vector<Method>& methods();

using ResidentPool = std::vector<std::shared_ptr<const household::ResidentProfile>>;
// The residents test scenes draw from: every built-in persona's offline schedule (`days` from
// Wednesday, as the paper's five days) and activity database.
Result<ResidentPool> make_resident_pool(const household::HouseholdKnowledge& knowledge, std::uint64_t seed,
                                        int days = 5);

// The household knowledge with only the built-in personas: personas posted later must not change
// the residents, or the same seed would give another table.
Result<household::HouseholdKnowledge> load_benchmark_knowledge(store::Store& store);

// What a run needs besides the request: the resident pool (from the seed) and the scene-prior
// counts (from the training seed).
struct BenchmarkInputs {
  ResidentPool pool;
  std::shared_ptr<const PlacementCounts> counts;
};
Result<BenchmarkInputs> prepare_inputs(const household::HouseholdKnowledge& knowledge,
                                       const BenchmarkRequest& request, int threads = 2);

// A test scene: the house, its dynamic scene and its navigation map.
struct TestScene {
  std::uint64_t seed = 0;  // never a training seed
  std::shared_ptr<const household::House> house;
  std::shared_ptr<const household::DynamicScene> scene;
  std::shared_ptr<const NavMap> map;
};
std::uint64_t test_scene_seed(std::uint64_t seed, Split split, int index);
Result<TestScene> make_test_scene(const BenchmarkRequest& request, int index,
                                  const household::HouseholdKnowledge& knowledge, const ResidentPool& pool);

struct NavTask {
  int scene = 0;
  household::Seconds time = 0;
  std::string target_type, target_id;
  int target_receptacle = -1;  // map index
  std::string receptacle_id;
  // Where on the receptacle's top the target lies (drawn uniformly, as AI2-THOR spawns objects
  // anywhere on a surface) and the poses that see it there (NavMap::views_of_point), sorted.
  double target_x = 0.0, target_z = 0.0;
  std::vector<int> target_views;
  int start = -1;          // pose
  int shortest = 0;        // steps
  int hint_resident = -1;  // the resident asked first; every resident answers
  std::string hint;        // one answer a line, "<name>: <answer>"
};
// Up to tasks_per_scene tasks: at the request's instants, targets of the 11 types with
// one instance in the house that moved within `recent` before the instant and can be seen from
// the start's part of the grid; the start pose drawn uniformly from that part, not already seeing
// the target; one resident asked for a hint.
std::vector<NavTask> sample_tasks(const BenchmarkRequest& request, const TestScene& scene, int index);

struct Outcome {
  bool success = false;
  int steps = 0;
  double spl = 0.0;
};
struct MethodScore {
  std::string key;
  double el = 0.0, sr = 0.0, spl = 0.0;  // SR and SPL in percent, over tasks
  // Half-widths of 95 % Student-t intervals over scenes (each scene's mean over its tasks; scenes
  // without tasks left out; 0 with fewer than two scenes).
  double el_ci = 0.0, sr_ci = 0.0, spl_ci = 0.0;
  int scenes = 0;  // scenes with tasks
};
// Paper 000 Table I, map-based rows (its hint rows are LLM + OSG / LLM + CEG), by method key.
struct PaperRow {
  std::string key;
  double el_normal, sr_normal, spl_normal, el_hard, sr_hard, spl_hard;
};
const std::vector<PaperRow>& paper_table_i();
// t_{0.975, df}: the two-sided 95 % quantile of Student's t distribution.
double student_t_975(int df);
struct BenchmarkResult {
  BenchmarkRequest request;
  std::vector<NavTask> tasks;
  std::vector<std::vector<Outcome>> outcomes;  // [task][method]
  std::vector<MethodScore> scores;             // in methods() order
  int training_houses = 0;
  double seconds = 0.0;
};

struct RunHooks {
  std::function<void(double, const std::string&)> progress;  // called from one thread at a time
  std::function<bool()> cancelled;
  int threads = 2;
};

// The estimators and planners of every method, built once (the scene prior from `counts`).
class MethodSuite {
 public:
  MethodSuite(const BenchmarkRequest& request, std::shared_ptr<const PlacementCounts> counts,
              const household::HouseholdKnowledge& knowledge);
  // The episodes of one task under every method, in methods() order.
  [[nodiscard]] std::vector<EpisodeResult> run(const TestScene& scene, const NavTask& task,
                                               int max_steps) const;

 private:
  double recent_ = 0;
  UniformEstimator uniform_;
  std::shared_ptr<const ScenePriorEstimator> prior_;
  HintEstimator hint_;
  PosteriorEstimator posterior_;
  GreedyPlanner greedy_;
  OsgPlanner osg_;
  CegPlanner ceg_;
};

Result<BenchmarkResult> run_benchmark(const BenchmarkRequest& request,
                                      const household::HouseholdKnowledge& knowledge,
                                      const ResidentPool& pool, std::shared_ptr<const PlacementCounts> counts,
                                      const RunHooks& hooks = {});

// {"split", "tasks", "methods": {"<estimator>+<planner>": {"EL", "SR", "SPL"}}, …}; with
// `with_tasks`, also one row per task (scene, time, target, outcomes per method) for replay.
Json to_json(const BenchmarkResult& result, bool with_tasks = false);
// The table in the shape of paper 000 Table I (method × EL, SR, SPL).
std::string format_table(const BenchmarkResult& result);
// The Table I layout in Markdown: per method EL, SR and SPL with their 95 % intervals over scenes
// and the paper's figures for the same split beside them.
std::string format_markdown(const BenchmarkResult& result);

// Task `index` of the benchmark replayed: the house, the target, the start, and every method's
// path and visited receptacles. kNotFound when the benchmark has fewer tasks.
Result<Json> replay_task(const BenchmarkRequest& request, int index,
                         const household::HouseholdKnowledge& knowledge, const ResidentPool& pool,
                         std::shared_ptr<const PlacementCounts> counts);

}  // namespace socsim::navbench
