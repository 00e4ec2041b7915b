// The benchmark: splits have the paper's room and resident counts; tasks target recently moved,
// single-instance objects of the 11 types from starts that do not see them; SR and SPL are
// percentages with SPL ≤ SR; the seed fixes the table whatever the thread count; requests are
// validated field by field; an episode replays with its path and visited receptacles.
#include "core/navbench/benchmark.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <unistd.h>

#include "tests/core/navbench/navbench_fixture.hpp"

namespace socsim::navbench {
namespace {

using testing::knowledge;
using testing::small_counts;
using testing::small_pool;

BenchmarkRequest small(Split split, std::uint64_t seed, int scenes = 4) {
  BenchmarkRequest r;
  r.split = split;
  r.seed = seed;
  r.scenes = scenes;
  return r;
}

TEST(Benchmark, ElevenTargetTypesAndSevenMethods) {
  EXPECT_EQ(target_types().size(), 11u);
  for (const auto& t : target_types()) EXPECT_TRUE(knowledge().is_movable(t)) << t;
  std::vector<std::string> keys;
  for (const auto& m : methods()) keys.push_back(m.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"Uniform+Greedy", "SP+OSG", "SP+CEG", "Hint+OSG", "Hint+CEG",
                                            "Posterior+OSG", "Posterior+CEG"}));
}

TEST(Benchmark, SplitsHaveThePapersRoomsAndResidents) {
  for (Split split : {Split::kNormal, Split::kHard}) {
    for (int i = 0; i < 6; ++i) {
      auto t = make_test_scene(small(split, 2), i, knowledge(), small_pool());
      ASSERT_TRUE(t) << t.error().message();
      const auto rooms = t->house->rooms.size();
      const auto residents = t->scene->residents().size();
      const auto bedrooms = t->house->rooms_of(household::RoomType::kBedroom).size();
      if (split == Split::kNormal) {
        EXPECT_TRUE(rooms >= 4 && rooms <= 7) << rooms;
        EXPECT_TRUE(residents >= 1 && residents <= 2) << residents;
      } else {
        EXPECT_TRUE(rooms >= 8 && rooms <= 10) << rooms;
        EXPECT_TRUE(residents >= std::min<std::size_t>(3, bedrooms) && residents <= 4) << residents;
      }
      EXPECT_FALSE(is_training_seed(t->seed));
    }
  }
}

TEST(Benchmark, TasksTargetRecentlyMovedSingleObjectsOutOfSight) {
  const auto request = small(Split::kHard, 4, 6);
  int total = 0;
  for (int s = 0; s < request.scenes; ++s) {
    auto t = make_test_scene(request, s, knowledge(), small_pool());
    ASSERT_TRUE(t);
    const auto tasks = sample_tasks(request, *t, s);
    EXPECT_LE(tasks.size(), 10u);
    std::set<household::Seconds> instants;
    for (const auto& task : tasks) {
      instants.insert(task.time);
      EXPECT_NE(std::find(target_types().begin(), target_types().end(), task.target_type),
                target_types().end());
      int instances = 0, object = -1;
      for (std::size_t o = 0; o < t->house->objects.size(); ++o)
        if (t->house->entities[static_cast<std::size_t>(t->house->objects[o])].type == task.target_type)
          ++instances, object = static_cast<int>(o);
      EXPECT_EQ(instances, 1);
      bool moved = false;
      for (const auto& r : t->scene->relocations_between(task.time - request.recent + 1, task.time + 1))
        moved = moved || r.object == object;
      EXPECT_TRUE(moved);
      EXPECT_EQ(t->map->receptacles()[static_cast<std::size_t>(task.target_receptacle)].entity,
                t->scene->receptacle_at(object, task.time));
      EXPECT_NE(std::find(request.instants.begin(), request.instants.end(), task.time),
                request.instants.end());
      EXPECT_GT(task.shortest, 0);
      // The target lies at one spot of its receptacle's top; the shortest path ends where it is seen.
      const auto& rec = t->map->receptacles()[static_cast<std::size_t>(task.target_receptacle)];
      ASSERT_FALSE(task.target_views.empty());
      EXPECT_TRUE(std::is_sorted(task.target_views.begin(), task.target_views.end()));
      bool at_spot = false;
      for (std::size_t j = 0; j < rec.spots.size(); ++j)
        at_spot = at_spot || (rec.spots[j] == task.target_views && rec.spot_points[j].x == task.target_x &&
                              rec.spot_points[j].z == task.target_z);
      EXPECT_TRUE(at_spot);
      const StepField f = t->map->steps_from(task.start);
      EXPECT_EQ(task.shortest, f.distance[static_cast<std::size_t>(f.nearest(task.target_views))]);
      // Every resident answers, one a line.
      EXPECT_EQ(static_cast<std::size_t>(std::count(task.hint.begin(), task.hint.end(), '\n') + 1),
                t->scene->residents().size())
          << task.hint;
      ++total;
    }
    EXPECT_LE(instants.size(), 2u);
  }
  EXPECT_GT(total, 20);
}

TEST(Benchmark, InstantsAreThePapersFridayAfternoonAndSundayNight) {
  // Days from Wednesday 00:00: Friday 17:30 and Sunday 23:30, as in the paper's released scenes.
  EXPECT_EQ(paper_instants(),
            (std::vector<household::Seconds>{2 * 86400 + 17 * 3600 + 1800, 4 * 86400 + 23 * 3600 + 1800}));
  EXPECT_EQ(BenchmarkRequest{}.instants, paper_instants());
}

TEST(Benchmark, ScoresArePercentagesWithSplNoAboveSr) {
  for (Split split : {Split::kNormal, Split::kHard}) {
    BenchmarkRequest request = small(split, 8, 3);
    request.tasks_per_scene = 5;  // ProcTHOR-sized houses make each episode longer: keep the test cheap
    auto r = run_benchmark(request, knowledge(), small_pool(), small_counts(), {});
    ASSERT_TRUE(r) << r.error().message();
    ASSERT_FALSE(r->tasks.empty());
    ASSERT_EQ(r->scores.size(), methods().size());
    for (const auto& s : r->scores) {
      EXPECT_GE(s.sr, 0.0);
      EXPECT_LE(s.sr, 100.0);
      EXPECT_GE(s.spl, 0.0);
      EXPECT_LE(s.spl, s.sr + 1e-9) << s.key;
      EXPECT_GT(s.el, 0.0);
      EXPECT_LE(s.el, 200.0);
    }
    for (std::size_t i = 0; i < r->tasks.size(); ++i)
      for (const auto& o : r->outcomes[i]) {
        if (o.success) {
          EXPECT_GE(o.steps, r->tasks[i].shortest);  // no method beats the grid's shortest path
        }
        EXPECT_LE(o.spl, 1.0);
      }
    const Json j = to_json(*r);
    EXPECT_EQ(j["split"], std::string(split_name(split)));
    EXPECT_EQ(j["tasks"], r->tasks.size());
    EXPECT_TRUE(j["methods"]["SP+CEG"].contains("SPL"));
    EXPECT_NE(format_table(*r).find("Posterior + CEG"), std::string::npos);
  }
}

TEST(Benchmark, TheSeedFixesTheTableWhateverTheThreads) {
  RunHooks one;
  one.threads = 1;
  BenchmarkRequest r21 = small(Split::kNormal, 21, 3), r22 = small(Split::kNormal, 22, 3);
  r21.tasks_per_scene = r22.tasks_per_scene = 4;
  auto a = run_benchmark(r21, knowledge(), small_pool(), small_counts(), one);
  auto b = run_benchmark(r21, knowledge(), small_pool(), small_counts(), {});
  auto c = run_benchmark(r22, knowledge(), small_pool(), small_counts(), {});
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(to_json(*a, true).dump(), to_json(*b, true).dump());
  EXPECT_NE(to_json(*a, true).dump(), to_json(*c, true).dump());
}

TEST(Benchmark, ProgressIsReportedAndCancellingStops) {
  std::vector<double> seen;
  RunHooks hooks;
  hooks.progress = [&](double f, const std::string&) { seen.push_back(f); };
  auto r = run_benchmark(small(Split::kNormal, 3, 3), knowledge(), small_pool(), small_counts(), hooks);
  ASSERT_TRUE(r);
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_DOUBLE_EQ(*std::max_element(seen.begin(), seen.end()), 1.0);
  hooks.cancelled = [] { return true; };
  auto cancelled =
      run_benchmark(small(Split::kNormal, 3, 3), knowledge(), small_pool(), small_counts(), hooks);
  ASSERT_FALSE(cancelled);
  EXPECT_EQ(cancelled.error().code, ErrorCode::kCancelled);
}

TEST(Benchmark, RequestsAreValidatedFieldByField) {
  auto ok = benchmark_request_from_json(Json{{"split", "hard"}, {"scenes", 50}, {"seed", 7}});
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->split, Split::kHard);
  EXPECT_EQ(ok->scenes, 50);
  EXPECT_EQ(ok->seed, 7u);
  auto bad =
      benchmark_request_from_json(Json{{"split", "easy"}, {"scenes", 0}, {"seed", -1}, {"colour", "red"}});
  ASSERT_FALSE(bad);
  std::set<std::string> pointers;
  for (const auto& e : bad.error().errors) pointers.insert(e.pointer);
  EXPECT_EQ(pointers, (std::set<std::string>{"/split", "/scenes", "/seed", "/colour"}));
  auto missing = benchmark_request_from_json(Json::object());
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().errors.size(), 3u);
  EXPECT_FALSE(benchmark_request_from_json(Json::array()));
}

TEST(Benchmark, AnEpisodeReplaysWithItsPathAndVisits) {
  const auto request = small(Split::kNormal, 8);
  auto r = run_benchmark(request, knowledge(), small_pool(), small_counts(), {});
  ASSERT_TRUE(r && !r->tasks.empty());
  const int n = static_cast<int>(r->tasks.size()) - 1;
  auto replay = replay_task(request, n, knowledge(), small_pool(), small_counts());
  ASSERT_TRUE(replay) << replay.error().message();
  const Json& j = *replay;
  EXPECT_EQ(j["target"]["type"], r->tasks.back().target_type);
  EXPECT_EQ(j["shortest"], r->tasks.back().shortest);
  EXPECT_FALSE(j["house"]["rooms"].empty());
  EXPECT_EQ(j["house"]["grid"]["free"].get<std::string>().size(),
            static_cast<std::size_t>(j["house"]["grid"]["width"].get<int>() *
                                     j["house"]["grid"]["depth"].get<int>()));
  for (std::size_t m = 0; m < methods().size(); ++m) {
    const Json& e = j["methods"][methods()[m].key];
    EXPECT_EQ(e["steps"], r->outcomes.back()[m].steps);
    EXPECT_EQ(e["success"], r->outcomes.back()[m].success);
    EXPECT_EQ(e["path"].size(), e["steps"].get<std::size_t>() + 1);
    EXPECT_EQ(e["path"][0], j["start"]);
    // Each visit ends where the agent stands within 1.5 m of that receptacle.
    for (const auto& v : e["visited"]) {
      const int step = v["step"];
      ASSERT_LE(step, e["steps"].get<int>());
      const auto& recs = j["house"]["receptacles"];
      const auto rec =
          std::find_if(recs.begin(), recs.end(), [&](const Json& x) { return x["id"] == v["receptacle"]; });
      ASSERT_NE(rec, recs.end());
      const auto& at = e["path"][static_cast<std::size_t>(step)];
      EXPECT_LE(std::hypot(at[0].get<double>() - (*rec)["position"]["x"].get<double>(),
                           at[1].get<double>() - (*rec)["position"]["z"].get<double>()),
                1.5 + 1e-9);
    }
  }
  auto beyond =
      replay_task(request, static_cast<int>(r->tasks.size()), knowledge(), small_pool(), small_counts());
  ASSERT_FALSE(beyond);
  EXPECT_EQ(beyond.error().code, ErrorCode::kNotFound);
}

// `socsim navbench --houses FILE.jsonl`: the four ProcTHOR peer houses, one JSON per line in a
// temporary file (read in place, never copied into the repository), are the test scenes.
TEST(Benchmark, RunsOnProcthorHousesGivenAsJsonLines) {
  const std::vector<std::string> names = {"zhiyuan_houses20_house_6.json", "zhiyuan_houses20_house_15.json",
                                          "quinlan_hallway_houses_3.json", "quinlan_hallway_houses_4.json"};
  const auto dir = std::filesystem::path(household::testing::shared_file("peers/procthor"));
  if (!std::filesystem::exists(dir / names[0])) GTEST_SKIP() << "peer houses not present: " << dir;
  const auto file =
      std::filesystem::temp_directory_path() / ("socsim-procthor-" + std::to_string(::getpid()) + ".jsonl");
  {
    std::ofstream out(file);
    for (const auto& n : names) {
      std::ifstream in(dir / n);
      std::stringstream ss;
      ss << in.rdbuf();
      auto j = parse_json_untrusted(ss.str());
      ASSERT_TRUE(j) << n;
      out << j->dump() << "\n\n";  // blank lines are skipped
    }
  }
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(file);
  auto houses = read_procthor_houses(text.str(), knowledge());
  ASSERT_TRUE(houses) << houses.error().message();
  ASSERT_EQ(houses->size(), 4u);
  EXPECT_EQ((*houses)[2]->rooms.size(), 8u);

  BenchmarkRequest request = small(Split::kNormal, 3, 4);
  request.houses = *houses;
  request.tasks_per_scene = 3;
  auto t = make_test_scene(request, 2, knowledge(), small_pool());
  ASSERT_TRUE(t);
  EXPECT_EQ(t->house, (*houses)[2]) << "scene i is house i";
  auto result = run_benchmark(request, knowledge(), small_pool(), small_counts(), {});
  ASSERT_TRUE(result) << result.error().message();
  const Json table = to_json(*result, false);
  EXPECT_GT(table["tasks"].get<int>(), 0);
  EXPECT_EQ(table["given_houses"].get<int>(), 4);
  for (const auto& [key, row] : table["methods"].items()) {
    EXPECT_GE(row["SR"].get<double>(), 0.0) << key;
    EXPECT_LE(row["SPL"].get<double>(), row["SR"].get<double>() + 1e-9) << key;
  }

  auto bad = read_procthor_houses(text.str().substr(0, 40) + "\n", knowledge());
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().code, ErrorCode::kValidation);
  EXPECT_FALSE(read_procthor_houses("\n\n", knowledge()));
  auto not_a_house = read_procthor_houses("{\"rooms\": 3}\n", knowledge());
  ASSERT_FALSE(not_a_house);
}

// Table I output: 95 % t intervals over scenes in the JSON and the Markdown, the paper's figures
// beside ours for the five map-based rows.
TEST(Benchmark, TableOneHasIntervalsOverScenesAndThePapersFigures) {
  EXPECT_NEAR(student_t_975(1), 12.706, 1e-3);
  EXPECT_NEAR(student_t_975(30), 2.042, 1e-3);
  EXPECT_NEAR(student_t_975(31), 2.040, 2e-3);
  EXPECT_NEAR(student_t_975(1000), 1.962, 1e-3);
  auto result = run_benchmark(small(Split::kNormal, 5, 3), knowledge(), small_pool(), small_counts(), {});
  ASSERT_TRUE(result) << result.error().message();
  const Json j = to_json(*result, false);
  for (const auto& s : result->scores) {
    EXPECT_GE(s.sr_ci, 0.0) << s.key;
    EXPECT_LE(s.scenes, 3);
    if (s.scenes >= 2) {
      EXPECT_GT(s.el_ci + s.sr_ci, 0.0) << s.key << ": scenes differ";
    }
    EXPECT_DOUBLE_EQ(j["methods"][s.key]["SR_ci95"].get<double>(), s.sr_ci);
  }
  EXPECT_DOUBLE_EQ(j["methods"]["SP+CEG"]["paper"]["SR"].get<double>(), 68.12);
  EXPECT_FALSE(j["methods"]["Posterior+CEG"].contains("paper"));
  const std::string md = format_markdown(*result);
  EXPECT_NE(md.find("| Method | Map | Hint | EL ↓ | SR (%) ↑ | SPL ↑ | paper EL | paper SR | paper SPL |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 129.2 | 68.12 | 34.56 |"), std::string::npos) << md;
  EXPECT_NE(md.find(" ± "), std::string::npos);
}

}  // namespace
}  // namespace socsim::navbench
