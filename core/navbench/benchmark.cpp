#include "core/navbench/benchmark.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"
#include "core/household/household_document.hpp"
#include "core/household/procthor.hpp"

namespace socsim::navbench {
namespace {

using household::House;
using household::Seconds;

enum class EstimatorKind : std::uint8_t { kUniform, kPrior, kHint, kPosterior };
enum class PlannerKind : std::uint8_t { kGreedy, kOsg, kCeg };
struct MethodParts {
  EstimatorKind estimator;
  PlannerKind planner;
};
constexpr MethodParts kParts[] = {
    {EstimatorKind::kUniform, PlannerKind::kGreedy}, {EstimatorKind::kPrior, PlannerKind::kOsg},
    {EstimatorKind::kPrior, PlannerKind::kCeg},      {EstimatorKind::kHint, PlannerKind::kOsg},
    {EstimatorKind::kHint, PlannerKind::kCeg},       {EstimatorKind::kPosterior, PlannerKind::kOsg},
    {EstimatorKind::kPosterior, PlannerKind::kCeg}};

// Cells of the largest 4-connected part of the grid (ties: the one holding the lowest cell).
std::vector<int> largest_component(const NavMap& map) {
  std::vector<int> label(static_cast<std::size_t>(map.cells()), -1), best, current;
  for (int c = 0; c < map.cells(); ++c) {
    if (!map.free(c) || label[static_cast<std::size_t>(c)] >= 0) continue;
    current.clear();
    current.push_back(c);
    label[static_cast<std::size_t>(c)] = c;
    for (std::size_t head = 0; head < current.size(); ++head)
      for (int h = 0; h < kHeadings; ++h) {
        const int n = map.ahead(current[head], h);
        if (n >= 0 && label[static_cast<std::size_t>(n)] < 0) {
          label[static_cast<std::size_t>(n)] = c;
          current.push_back(n);
        }
      }
    if (current.size() > best.size()) best = current;
  }
  std::sort(best.begin(), best.end());
  return best;
}

Json pose_json(const NavMap& map, int pose) {
  const auto c = map.center(cell_of(pose));
  return Json::array({c.x, c.z, heading_of(pose)});
}

// What the viewer draws: rooms, solid walls, receptacles, the grid of reachable points.
// The house as every view gets it (household::house_plan_json, floors included: targets may lie
// on one), plus the map's grid of reachable cells.
Json map_json(const House& house, const NavMap& map) {
  std::string free(static_cast<std::size_t>(map.cells()), '0');
  for (int c = 0; c < map.cells(); ++c)
    if (map.free(c)) free[static_cast<std::size_t>(c)] = '1';
  Json j = household::house_plan_json(house, true);
  j["grid"] = {{"origin", Json::array({map.origin_x(), map.origin_z()})},
               {"cell", map.cell_size()},
               {"width", map.width()},
               {"depth", map.depth()},
               {"free", free}};
  return j;
}

}  // namespace

std::string_view split_name(Split split) {
  return split == Split::kNormal ? "normal" : "hard";
}

std::optional<Split> parse_split(std::string_view name) {
  if (name == "normal") return Split::kNormal;
  if (name == "hard") return Split::kHard;
  return std::nullopt;
}

const std::vector<std::string>& target_types() {
  // The paper names no list. Its released tasks (DynamicTHOR sampled_scenes_normal/hard data_0)
  // target eight types: Book, CellPhone, Laptop, Mug, Newspaper, Pen, Pencil, RemoteControl. The
  // other three are our choice: of our earlier eleven we keep the carried personal items closest
  // in kind to those (Cloth, KeyChain, Watch) and drop AlarmClock, Apple and Bowl.
  static const std::vector<std::string> types = {"Book",   "CellPhone",     "Cloth",     "KeyChain",
                                                 "Laptop", "Mug",           "Newspaper", "Pen",
                                                 "Pencil", "RemoteControl", "Watch"};
  return types;
}

const std::vector<Method>& methods() {
  static const std::vector<Method> list = {{"Uniform+Greedy", "Greedy", false},
                                           {"SP+OSG", "SP + OSG", false},
                                           {"SP+CEG", "SP + CEG", false},
                                           {"Hint+OSG", "Hint + OSG", true},
                                           {"Hint+CEG", "Hint + CEG", true},
                                           {"Posterior+OSG", "Posterior + OSG", false},
                                           {"Posterior+CEG", "Posterior + CEG", false}};
  return list;
}

Result<BenchmarkRequest> benchmark_request_from_json(const Json& json) {
  JsonChecker check;
  if (!json.is_object())
    return fail(ErrorCode::kValidation, "the request must be a JSON object",
                {FieldError{"", "must be an object"}});
  check.only_keys(json, "",
                  {"split", "scenes", "seed", "tasks_per_scene", "max_steps", "training_houses", "alpha"});
  BenchmarkRequest r;
  if (auto s = check.string(json, "", "split", true)) {
    if (auto split = parse_split(*s))
      r.split = *split;
    else
      check.add("/split", "must be \"normal\" or \"hard\"");
  }
  if (auto v = check.integer(json, "", "scenes", true, 1, 500)) r.scenes = static_cast<int>(*v);
  if (auto v = check.integer(json, "", "seed", true, 0, INT64_MAX)) r.seed = static_cast<std::uint64_t>(*v);
  if (auto v = check.integer(json, "", "tasks_per_scene", false, 1, 50))
    r.tasks_per_scene = static_cast<int>(*v);
  if (auto v = check.integer(json, "", "max_steps", false, 1, 5000)) r.max_steps = static_cast<int>(*v);
  if (auto v = check.integer(json, "", "training_houses", false, 1, 20000))
    r.training_houses = static_cast<int>(*v);
  if (auto v = check.number(json, "", "alpha", false, 0.0, 1.0)) r.alpha = *v;
  if (!check.ok()) return tl::unexpected(check.error("invalid navigation benchmark request"));
  return r;
}

Json to_json(const BenchmarkRequest& r) {
  return {{"split", split_name(r.split)},
          {"scenes", r.scenes},
          {"seed", r.seed},
          {"tasks_per_scene", r.tasks_per_scene},
          {"max_steps", r.max_steps},
          {"training_houses", r.training_houses},
          {"alpha", r.alpha}};
}

Result<std::vector<std::shared_ptr<const household::House>>> read_procthor_houses(
    std::string_view jsonl, const household::HouseholdKnowledge& knowledge) {
  std::vector<std::shared_ptr<const household::House>> out;
  std::size_t at = 0;
  for (int line = 0; at <= jsonl.size(); ++line) {
    const std::size_t end = std::min(jsonl.find('\n', at), jsonl.size());
    const std::string_view text = jsonl.substr(at, end - at);
    at = end + 1;
    if (text.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    const std::string pointer = "/houses/" + std::to_string(out.size());
    auto json = parse_json_untrusted(std::string(text));
    if (!json)
      return fail(ErrorCode::kValidation, "line " + std::to_string(line + 1) + " is not JSON",
                  {FieldError{pointer, json.error().message()}});
    auto house = household::import_procthor(*json, knowledge, "procthor-" + std::to_string(out.size()));
    if (!house) return tl::unexpected(house.error().under(pointer));
    out.push_back(std::make_shared<const House>(std::move(*house)));
  }
  if (out.empty())
    return fail(ErrorCode::kValidation, "no houses", {FieldError{"/houses", "holds no ProcTHOR house"}});
  return out;
}

Result<ResidentPool> make_resident_pool(const household::HouseholdKnowledge& knowledge, std::uint64_t seed,
                                        int days) {
  ResidentPool pool;
  auto vocabulary = household::ActivityVocabulary::initial(knowledge);
  for (const auto& persona : knowledge.personas) {
    auto r = household::make_resident_offline(persona, knowledge,
                                              {days, household::Weekday::kWednesday, seed}, vocabulary);
    if (!r) return tl::unexpected(r.error());
    pool.push_back(std::make_shared<const household::ResidentProfile>(std::move(*r)));
  }
  if (pool.empty()) return fail(ErrorCode::kValidation, "no personas to draw residents from");
  return pool;
}

Result<household::HouseholdKnowledge> load_benchmark_knowledge(store::Store& store) {
  auto knowledge = household::load_household_knowledge(store);
  if (!knowledge) return tl::unexpected(knowledge.error());
  auto posted = household::list_stored_personas(store, false);
  if (!posted) return tl::unexpected(posted.error());
  std::erase_if(knowledge->personas, [&](const household::Persona& p) {
    return std::any_of(posted->begin(), posted->end(), [&](const household::Persona& q) {
      return household::persona_id(q) == household::persona_id(p);
    });
  });
  knowledge->index();
  return knowledge;
}

Result<BenchmarkInputs> prepare_inputs(const household::HouseholdKnowledge& knowledge,
                                       const BenchmarkRequest& request, int threads) {
  BenchmarkInputs in;
  auto pool = make_resident_pool(knowledge, request.seed);
  if (!pool) return tl::unexpected(pool.error());
  in.pool = std::move(*pool);
  auto counts = count_training_placements(knowledge, request.training_houses, request.training_seed, threads);
  if (!counts) return tl::unexpected(counts.error());
  in.counts = std::make_shared<const PlacementCounts>(std::move(*counts));
  return in;
}

std::vector<Seconds> paper_instants() {
  constexpr Seconds kHour = 3600;
  return {2 * household::kSecondsPerDay + 17 * kHour + kHour / 2,
          4 * household::kSecondsPerDay + 23 * kHour + kHour / 2};
}

std::uint64_t test_scene_seed(std::uint64_t seed, Split split, int index) {
  std::uint64_t state = seed ^
                        fnv1a64(split == Split::kNormal ? "navbench/test/normal" : "navbench/test/hard") ^
                        (static_cast<std::uint64_t>(index) * 0x9E3779B97F4A7C15ULL);
  return splitmix64(state) & ~(std::uint64_t{1} << 63);
}

Result<TestScene> make_test_scene(const BenchmarkRequest& request, int index,
                                  const household::HouseholdKnowledge& knowledge, const ResidentPool& pool) {
  const bool hard = request.split == Split::kHard;
  // A layout that cannot be packed is drawn again from the next seed of the same scene.
  for (int attempt = 0; attempt < 8; ++attempt) {
    TestScene t;
    t.seed = test_scene_seed(request.seed, request.split, index * 8 + attempt);
    Rng rng(t.seed, fnv1a64("navbench/scene"));
    const int rooms = static_cast<int>(hard ? rng.between(8, 10) : rng.between(4, 7));
    const int wanted = static_cast<int>(hard ? rng.between(3, 4) : rng.between(1, 2));
    if (!request.houses.empty()) {
      t.house = request.houses[static_cast<std::size_t>(index) % request.houses.size()];
    } else {
      auto house = household::generate_house({rooms, std::nullopt, t.seed}, knowledge);
      if (!house) continue;
      t.house = std::make_shared<const House>(std::move(*house));
    }
    const int bedrooms = static_cast<int>(t.house->rooms_of(household::RoomType::kBedroom).size());
    const int residents = std::max(1, std::min({wanted, bedrooms, static_cast<int>(pool.size())}));
    auto scene = household::configure_scene(t.house, pool, {residents, t.seed}, knowledge);
    if (!scene) return tl::unexpected(scene.error());
    t.scene = std::make_shared<const household::DynamicScene>(std::move(*scene));
    auto map = build_nav_map(*t.house, request.nav);
    if (!map) return tl::unexpected(map.error());
    t.map = std::make_shared<const NavMap>(std::move(*map));
    return t;
  }
  return fail(ErrorCode::kInternal, "could not generate test scene " + std::to_string(index));
}

// Where on its receptacle the target lies: a point drawn uniformly on the receptacle's top, kept
// 0.1 m inside its edges (an object rests wholly on the surface), as AI2-THOR spawns objects
// anywhere on a receptacle (the paper's released houses put objects a median 0.3–0.4 m from their
// receptacle's centre, up to 1 m). A point seen from no pose of the start's part of the grid
// (e.g. the far side of a bed against a wall) is drawn again, up to 16 times; then the centre.
namespace {
void place_on_top(const NavMap& map, NavTask& task, const std::vector<char>& in_part, Rng rng) {
  const MapReceptacle& r = map.receptacles()[static_cast<std::size_t>(task.target_receptacle)];
  task.target_x = r.x, task.target_z = r.z;
  task.target_views = r.views;
  std::vector<std::size_t> spots;  // those seen from the start's part
  for (std::size_t j = 0; j < r.spots.size(); ++j) {
    bool seen_from_part = false;
    for (int v : r.spots[j]) seen_from_part = seen_from_part || in_part[static_cast<std::size_t>(cell_of(v))];
    if (seen_from_part) spots.push_back(j);
  }
  if (spots.empty()) return;
  const std::size_t j = spots[rng.below(static_cast<std::uint32_t>(spots.size()))];
  task.target_x = r.spot_points[j].x, task.target_z = r.spot_points[j].z;
  task.target_views = r.spots[j];
}
}  // namespace

std::vector<NavTask> sample_tasks(const BenchmarkRequest& request, const TestScene& t, int index) {
  const House& house = *t.house;
  const auto& scene = *t.scene;
  const NavMap& map = *t.map;
  Rng rng(t.seed, fnv1a64("navbench/tasks"));
  const std::vector<int> part = largest_component(map);
  std::vector<char> in_part(static_cast<std::size_t>(map.cells()), 0);
  for (int c : part) in_part[static_cast<std::size_t>(c)] = 1;
  if (part.empty()) return {};

  // Target types with exactly one instance in this house.
  std::vector<std::pair<std::string, int>> singles;  // type, index into House::objects
  for (const auto& type : target_types()) {
    int found = -1, count = 0;
    for (std::size_t o = 0; o < house.objects.size(); ++o)
      if (house.entities[static_cast<std::size_t>(house.objects[o])].type == type)
        found = static_cast<int>(o), ++count;
    if (count == 1) singles.emplace_back(type, found);
  }
  struct Option {
    Seconds time;
    std::size_t single;
    int receptacle;
  };
  std::vector<Option> candidates;
  for (const Seconds t0 : request.instants) {
    if (t0 < 0 || t0 >= scene.end()) continue;
    for (std::size_t s = 0; s < singles.size(); ++s) {
      const int object = singles[s].second;
      bool moved = false;
      for (const auto& r : scene.relocations_between(t0 - request.recent + 1, t0 + 1))
        moved = moved || r.object == object;
      if (!moved) continue;
      const int receptacle = map.receptacle_of_entity(scene.receptacle_at(object, t0));
      if (receptacle < 0) continue;
      bool seen_from_part = false;
      for (int v : map.receptacles()[static_cast<std::size_t>(receptacle)].views)
        seen_from_part = seen_from_part || in_part[static_cast<std::size_t>(cell_of(v))];
      if (seen_from_part) candidates.push_back({t0, s, receptacle});
    }
  }
  rng.shuffle(candidates);
  if (candidates.size() > static_cast<std::size_t>(request.tasks_per_scene))
    candidates.resize(static_cast<std::size_t>(request.tasks_per_scene));
  std::stable_sort(candidates.begin(), candidates.end(), [](const Option& a, const Option& b) {
    return a.time != b.time ? a.time < b.time : a.single < b.single;
  });
  std::vector<NavTask> tasks;
  for (const auto& c : candidates) {
    NavTask task;
    task.scene = index;
    task.time = c.time;
    task.target_type = singles[c.single].first;
    task.target_id = house
                         .entities[static_cast<std::size_t>(
                             house.objects[static_cast<std::size_t>(singles[c.single].second)])]
                         .id;
    task.target_receptacle = c.receptacle;
    task.receptacle_id = map.receptacles()[static_cast<std::size_t>(c.receptacle)].id;
    place_on_top(map, task, in_part,
                 Rng(t.seed, fnv1a64("navbench/spot")).fork(task.target_id + "|" + std::to_string(c.time)));
    for (int attempt = 0; attempt < 64 && task.start < 0; ++attempt) {
      const int cell = part[rng.below(static_cast<std::uint32_t>(part.size()))];
      const int pose = pose_of(cell, static_cast<int>(rng.below(kHeadings)));
      const StepField f = map.steps_from(pose);
      const int goal = f.nearest(task.target_views);
      const int steps = goal < 0 ? -1 : f.distance[static_cast<std::size_t>(goal)];
      if (steps > 0) task.start = pose, task.shortest = steps;
    }
    if (task.start < 0) continue;
    // Every resident is asked (paper 000 §VI-A: "asking the simulated humans whether they have
    // recently used the target object"), starting from one drawn at random; one answer a line.
    const int n = static_cast<int>(scene.residents().size());
    task.hint_resident = static_cast<int>(rng.below(static_cast<std::uint32_t>(n)));
    for (int k = 0; k < n; ++k) {
      const int who = (task.hint_resident + k) % n;
      task.hint += (k ? "\n" : "") + scene.residents()[static_cast<std::size_t>(who)].profile->persona.name +
                   ": " + scene.hint(who, task.target_type, task.time, request.recent).text;
    }
    tasks.push_back(std::move(task));
  }
  return tasks;
}

MethodSuite::MethodSuite(const BenchmarkRequest& request, std::shared_ptr<const PlacementCounts> counts,
                         const household::HouseholdKnowledge& knowledge)
    : recent_(static_cast<double>(request.recent)),
      prior_(std::make_shared<const ScenePriorEstimator>(std::move(counts))),
      hint_(prior_, knowledge, request.hint_trust),
      osg_(request.alpha) {}

std::vector<EpisodeResult> MethodSuite::run(const TestScene& t, const NavTask& task, int max_steps) const {
  const GenerativeModel model = generative_model_of(*t.scene);
  EstimateQuery q;
  q.map = t.map.get();
  q.target_type = task.target_type;
  q.time = task.time;
  q.recent = static_cast<Seconds>(recent_);
  q.model = &model;
  const std::vector<double> uniform = uniform_.estimate(q);
  const std::vector<double> prior = prior_->estimate(q);
  const std::vector<double> posterior = posterior_.estimate(q);
  q.hint = task.hint;
  const std::vector<double> hinted = hint_.estimate(q);
  std::vector<EpisodeResult> out;
  const EpisodeSpec spec{task.start, task.target_receptacle, max_steps, false, task.target_views};
  for (const auto& parts : kParts) {
    const std::vector<double>& p = parts.estimator == EstimatorKind::kUniform ? uniform
                                   : parts.estimator == EstimatorKind::kPrior ? prior
                                   : parts.estimator == EstimatorKind::kHint  ? hinted
                                                                              : posterior;
    const Planner& planner = parts.planner == PlannerKind::kGreedy ? static_cast<const Planner&>(greedy_)
                             : parts.planner == PlannerKind::kOsg  ? static_cast<const Planner&>(osg_)
                                                                   : static_cast<const Planner&>(ceg_);
    out.push_back(run_episode(*t.map, spec, p, planner));
  }
  return out;
}

Result<BenchmarkResult> run_benchmark(const BenchmarkRequest& request,
                                      const household::HouseholdKnowledge& knowledge,
                                      const ResidentPool& pool, std::shared_ptr<const PlacementCounts> counts,
                                      const RunHooks& hooks) {
  if (request.scenes < 1)
    return fail(ErrorCode::kValidation, "no scenes", {FieldError{"/scenes", "must be at least 1"}});
  if (!counts) return fail(ErrorCode::kValidation, "the scene prior needs training counts");
  for (std::uint64_t s : counts->seeds)
    if (!is_training_seed(s))
      return fail(ErrorCode::kValidation,
                  "the scene prior was counted on a house that is not a training house");
  const auto t0 = std::chrono::steady_clock::now();
  const MethodSuite suite(request, counts, knowledge);
  struct SceneOutcome {
    std::vector<NavTask> tasks;
    std::vector<std::vector<Outcome>> outcomes;
    std::optional<Error> error;
  };
  std::vector<SceneOutcome> per_scene(static_cast<std::size_t>(request.scenes));
  std::atomic<int> next{0}, done{0};
  std::atomic<bool> stop{false};
  std::mutex report;
  auto work = [&] {
    for (int i; !stop && (i = next.fetch_add(1)) < request.scenes;) {
      if (hooks.cancelled && hooks.cancelled()) {
        stop = true;
        break;
      }
      auto& out = per_scene[static_cast<std::size_t>(i)];
      auto scene = make_test_scene(request, i, knowledge, pool);
      if (!scene) {
        out.error = scene.error();
        stop = true;
        break;
      }
      out.tasks = sample_tasks(request, *scene, i);
      for (const auto& task : out.tasks) {
        std::vector<Outcome> row;
        for (const auto& e : suite.run(*scene, task, request.max_steps))
          row.push_back({e.success, e.steps, e.spl});
        out.outcomes.push_back(std::move(row));
      }
      const int finished = ++done;
      if (hooks.progress) {
        std::lock_guard<std::mutex> lock(report);
        hooks.progress(static_cast<double>(finished) / request.scenes,
                       "scene " + std::to_string(finished) + " of " + std::to_string(request.scenes));
      }
    }
  };
  std::vector<std::thread> threads;
  for (int k = 1; k < std::max(1, hooks.threads); ++k) threads.emplace_back(work);
  work();
  for (auto& th : threads) th.join();
  for (const auto& s : per_scene)
    if (s.error) return tl::unexpected(*s.error);
  if (hooks.cancelled && hooks.cancelled()) return fail(ErrorCode::kCancelled, "the benchmark was cancelled");

  BenchmarkResult result;
  result.request = request;
  result.training_houses = counts->houses;
  // Per-scene means of each method's EL, SR and SPL, for the intervals over scenes.
  std::vector<std::vector<std::array<double, 3>>> scene_means(methods().size());
  for (const auto& s : per_scene) {
    if (s.outcomes.empty()) continue;
    const double k = static_cast<double>(s.outcomes.size());
    for (std::size_t m = 0; m < methods().size(); ++m) {
      std::array<double, 3> x{0.0, 0.0, 0.0};
      for (const auto& row : s.outcomes) {
        x[0] += row[m].steps;
        x[1] += row[m].success ? 100.0 : 0.0;
        x[2] += 100.0 * row[m].spl;
      }
      for (double& v : x) v /= k;
      scene_means[m].push_back(x);
    }
  }
  for (auto& s : per_scene) {
    for (auto& t : s.tasks) result.tasks.push_back(std::move(t));
    for (auto& o : s.outcomes) result.outcomes.push_back(std::move(o));
  }
  const double n = static_cast<double>(std::max<std::size_t>(1, result.tasks.size()));
  for (std::size_t m = 0; m < methods().size(); ++m) {
    MethodScore score{methods()[m].key};
    for (const auto& row : result.outcomes) {
      score.el += row[m].steps;
      score.sr += row[m].success ? 1.0 : 0.0;
      score.spl += row[m].spl;
    }
    score.el /= n;
    score.sr = 100.0 * score.sr / n;  // k·(100/n) can exceed 100 by an ulp when k = n
    score.spl = 100.0 * score.spl / n;
    const auto& xs = scene_means[m];
    score.scenes = static_cast<int>(xs.size());
    if (xs.size() >= 2) {
      const double c = static_cast<double>(xs.size());
      std::array<double, 3> half{};
      for (std::size_t j = 0; j < 3; ++j) {
        double mean = 0.0, ss = 0.0;
        for (const auto& x : xs) mean += x[j];
        mean /= c;
        for (const auto& x : xs) ss += (x[j] - mean) * (x[j] - mean);
        half[j] = student_t_975(static_cast<int>(xs.size()) - 1) * std::sqrt(ss / (c - 1.0) / c);
      }
      score.el_ci = half[0];
      score.sr_ci = half[1];
      score.spl_ci = half[2];
    }
    result.scores.push_back(score);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

Json to_json(const BenchmarkResult& r, bool with_tasks) {
  Json methods_json = Json::object();
  for (const auto& s : r.scores) {
    methods_json[s.key] = {{"EL", s.el},         {"SR", s.sr},         {"SPL", s.spl},
                           {"EL_ci95", s.el_ci}, {"SR_ci95", s.sr_ci}, {"SPL_ci95", s.spl_ci},
                           {"scenes", s.scenes}};
    for (const auto& p : paper_table_i())
      if (p.key == s.key) {
        const bool hard = r.request.split == Split::kHard;
        methods_json[s.key]["paper"] = {{"EL", hard ? p.el_hard : p.el_normal},
                                        {"SR", hard ? p.sr_hard : p.sr_normal},
                                        {"SPL", hard ? p.spl_hard : p.spl_normal}};
      }
  }
  Json out = {{"split", split_name(r.request.split)},
              {"tasks", r.tasks.size()},
              {"scenes", r.request.scenes},
              {"seed", r.request.seed},
              {"max_steps", r.request.max_steps},
              {"training_houses", r.training_houses},
              {"methods", methods_json}};
  if (!r.request.houses.empty()) out["given_houses"] = r.request.houses.size();
  if (with_tasks) {
    Json rows = Json::array();
    for (std::size_t i = 0; i < r.tasks.size(); ++i) {
      const auto& t = r.tasks[i];
      Json outcome = Json::object();
      for (std::size_t m = 0; m < methods().size(); ++m)
        outcome[methods()[m].key] = {{"success", r.outcomes[i][m].success},
                                     {"steps", r.outcomes[i][m].steps}};
      rows.push_back({{"task", i},
                      {"scene", t.scene},
                      {"time", t.time},
                      {"target", t.target_type},
                      {"receptacle", t.receptacle_id},
                      {"hint", t.hint},
                      {"shortest", t.shortest},
                      {"outcomes", outcome}});
    }
    out["episodes"] = rows;
  }
  return out;
}

const std::vector<PaperRow>& paper_table_i() {
  static const std::vector<PaperRow> rows = {
      {"Uniform+Greedy", 161.5, 41.30, 16.02, 176.49, 22.69, 10.14},
      {"SP+OSG", 139.5, 58.94, 27.73, 165.09, 32.53, 16.22},
      {"SP+CEG", 129.2, 68.12, 34.56, 159.51, 36.35, 20.57},
      {"Hint+OSG", 140.7, 59.42, 27.33, 165.25, 31.53, 16.14},
      {"Hint+CEG", 107.4, 76.81, 46.13, 146.65, 46.59, 28.56},
  };
  return rows;
}

double student_t_975(int df) {
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                      2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                      2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (df < 1) return 0.0;
  if (df <= 30) return kTable[df - 1];
  // Cornish–Fisher expansion around the normal quantile (error < 1e-4 above 30 degrees of freedom).
  const double z = 1.959963984540054, n = df;
  return z + (z * z * z + z) / (4 * n) + (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * n * n);
}

std::string format_markdown(const BenchmarkResult& r) {
  const bool hard = r.request.split == Split::kHard;
  std::string out = "Object-goal navigation, " + std::string(split_name(r.request.split)) +
                    " split: " + std::to_string(r.request.scenes) + " scenes, " +
                    std::to_string(r.tasks.size()) + " tasks, seed " + std::to_string(r.request.seed) +
                    " (map-based, " + std::to_string(r.request.max_steps) +
                    " steps; ± half-widths of 95 % t intervals over scenes)\n\n";
  out += "| Method | Map | Hint | EL ↓ | SR (%) ↑ | SPL ↑ | paper EL | paper SR | paper SPL |\n";
  out += "|---|---|---|---|---|---|---|---|---|\n";
  char line[400];
  for (std::size_t m = 0; m < methods().size(); ++m) {
    const auto& s = r.scores[m];
    std::string paper = "— | — | —";
    for (const auto& p : paper_table_i())
      if (p.key == s.key) {
        char b[80];
        std::snprintf(b, sizeof b, "%.1f | %.2f | %.2f", hard ? p.el_hard : p.el_normal,
                      hard ? p.sr_hard : p.sr_normal, hard ? p.spl_hard : p.spl_normal);
        paper = b;
      }
    std::snprintf(line, sizeof line, "| %s | ✓ | %s | %.1f ± %.1f | %.2f ± %.2f | %.2f ± %.2f | %s |\n",
                  methods()[m].label.c_str(), methods()[m].uses_hint ? "✓" : "✗", s.el, s.el_ci, s.sr,
                  s.sr_ci, s.spl, s.spl_ci, paper.c_str());
    out += line;
  }
  return out;
}

std::string format_table(const BenchmarkResult& r) {
  char line[160];
  std::string out;
  std::snprintf(line, sizeof line,
                "Object-goal navigation, %s split: %d scenes, %zu tasks, seed %llu (map-based, %d steps)\n",
                std::string(split_name(r.request.split)).c_str(), r.request.scenes, r.tasks.size(),
                static_cast<unsigned long long>(r.request.seed), r.request.max_steps);
  out += line;
  std::snprintf(line, sizeof line, "%-18s %-4s %-5s %8s %8s %8s\n", "Method", "Map", "Hint", "EL", "SR(%)",
                "SPL");
  out += line;
  for (std::size_t m = 0; m < r.scores.size(); ++m) {
    const auto& s = r.scores[m];
    std::snprintf(line, sizeof line, "%-18s %-4s %-5s %8.1f %8.2f %8.2f\n", methods()[m].label.c_str(), "yes",
                  methods()[m].uses_hint ? "yes" : "no", s.el, s.sr, s.spl);
    out += line;
  }
  return out;
}

Result<Json> replay_task(const BenchmarkRequest& request, int index,
                         const household::HouseholdKnowledge& knowledge, const ResidentPool& pool,
                         std::shared_ptr<const PlacementCounts> counts) {
  if (index < 0) return fail(ErrorCode::kNotFound, "no such episode");
  int seen = 0;
  const MethodSuite suite(request, std::move(counts), knowledge);
  for (int s = 0; s < request.scenes; ++s) {
    auto scene = make_test_scene(request, s, knowledge, pool);
    if (!scene) return tl::unexpected(scene.error());
    const auto tasks = sample_tasks(request, *scene, s);
    if (index >= seen + static_cast<int>(tasks.size())) {
      seen += static_cast<int>(tasks.size());
      continue;
    }
    const NavTask& task = tasks[static_cast<std::size_t>(index - seen)];
    const NavMap& map = *scene->map;
    const auto episodes = suite.run(*scene, task, request.max_steps);
    Json per_method = Json::object();
    for (std::size_t m = 0; m < episodes.size(); ++m) {
      const auto& e = episodes[m];
      Json path = Json::array({pose_json(map, task.start)});
      for (int p : e.path) path.push_back(pose_json(map, p));
      Json visited = Json::array();
      for (std::size_t v = 0; v < e.visited.size(); ++v)
        visited.push_back({{"receptacle", map.receptacles()[static_cast<std::size_t>(e.visited[v])].id},
                           {"step", e.visited_at[v]}});
      per_method[methods()[m].key] = {
          {"success", e.success}, {"steps", e.steps}, {"spl", e.spl}, {"path", path}, {"visited", visited}};
    }
    const auto& rec = map.receptacles()[static_cast<std::size_t>(task.target_receptacle)];
    return Json{{"task", index},
                {"scene", s},
                {"split", split_name(request.split)},
                {"seed", request.seed},
                {"time", task.time},
                {"clock", household::format_clock(task.time, scene->scene->first_day())},
                {"target",
                 {{"type", task.target_type},
                  {"id", task.target_id},
                  {"receptacle", task.receptacle_id},
                  {"x", task.target_x},
                  {"z", task.target_z},
                  {"receptacle_x", rec.x},
                  {"receptacle_z", rec.z}}},
                {"start", pose_json(map, task.start)},
                {"shortest", task.shortest},
                {"hint", task.hint},
                {"house", map_json(*scene->house, map)},
                {"methods", per_method}};
  }
  return fail(
      ErrorCode::kNotFound,
      "the benchmark has " + std::to_string(seen) + " episodes; there is no episode " + std::to_string(index),
      {FieldError{"/n", "must be below " + std::to_string(seen), "n", 0, 0}});
}

}  // namespace socsim::navbench
