// socsim-bench world: build + validate a 10-room plan (GEOS checks, derived walls, reachability
// grid), a 256 x 256 geodesic field, a world.yaml read/write round trip, and offline floor-plan
// generation of a 10-room hospital plan and of 60-room mall and arena plans (layout, furnishing,
// validation, compliance, layout check); p50/p95 in ms.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "core/floorplan/offline.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/store/store.hpp"

#include "core/world/geodesic.hpp"
#include "core/world/occupancy_grid.hpp"
#include "core/world/world_builder.hpp"
#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/bench/bench.hpp"

namespace {

using namespace socsim::world;
using namespace socsim::floorplan;

// Ten 4 x 5 m rooms, five on each side of a 2 m corridor, each with a door into it, an
// entrance at the corridor's west end, a queue lane and a waiting zone — a generator's output.
WorldBuilder ten_room_plan() {
  WorldBuilder b;
  b.set_name("ten_rooms");
  b.add_zone(Zone{"corridor", "corridor", "washable_paint", {{{0, 5}, {20, 5}, {20, 7}, {0, 7}}, {}}});
  for (int side = 0; side < 2; ++side) {
    for (int i = 0; i < 5; ++i) {
      const std::string name = "room_" + std::to_string(side * 5 + i);
      const double x0 = 4.0 * i;
      const double y0 = side == 0 ? 0.0 : 7.0;
      b.add_zone(Zone{
          name, "office", "painted_plaster", {{{x0, y0}, {x0 + 4, y0}, {x0 + 4, y0 + 5}, {x0, y0 + 5}}, {}}});
      b.add_door(DoorSpec{name + "_door", {x0 + 2, side == 0 ? 5.0 : 7.0, 0}, 0.9, {"corridor", name}});
      b.add_entity(EntitySpec{"desk", name + "_desk", {x0 + 2, y0 + 2.5, 0}, {"work"}});
    }
  }
  b.add_door(DoorSpec{"entrance", {0, 6, 0}, 1.2, {"corridor"}});
  b.add_roi(Roi{"queue_lane", "queue_lane", {{{1, 5.3}, {4, 5.3}, {4, 6}, {1, 6}}, {}}});
  b.add_roi(Roi{"waiting_zone", "waiting_zone", {{{14, 5.2}, {19, 5.2}, {19, 6.8}, {14, 6.8}}, {}}});
  return b;
}

int floor_plans(int runs, const std::string& only);

// CPU time of this thread: on a loaded machine wall time mostly measures the other processes.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

int run_world(const socsim::bench::Args& a) {
  const int runs = static_cast<int>(a.integer("runs", 50));
  // --only mall: just the floor plans whose label has this word (for a profiler).
  const std::string only = a.str("only", "");
  if (!only.empty()) return floor_plans(runs, only);
  const WorldBuilder plan = ten_room_plan();
  std::vector<double> build_ms;
  std::vector<double> build_cpu;
  std::size_t walls = 0;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_ms();
    auto w = plan.build();
    build_cpu.push_back(thread_cpu_ms() - c0);
    build_ms.push_back(socsim::bench::ms_since(t0));
    if (!w) {
      std::cerr << w.error().message() << "\n";
      return 1;
    }
    walls = w->walls().size();
  }
  socsim::bench::emit({{"bench", "world_build_10_rooms"},
                       {"runs", runs},
                       {"zones", 11},
                       {"walls", walls},
                       {"p50_ms", socsim::bench::percentile(build_ms, 50)},
                       {"p95_ms", socsim::bench::percentile(build_ms, 95)},
                       {"cpu_p50_ms", socsim::bench::percentile(build_cpu, 50)},
                       {"cpu_p95_ms", socsim::bench::percentile(build_cpu, 95)}});

  // 25.4 m square at 0.1 m plus a one-cell margin: a 256 x 256 grid.
  WorldBuilder square;
  square.add_zone(Zone{"hall", "hall", "", {{{0, 0}, {25.4, 0}, {25.4, 25.4}, {0, 25.4}}, {}}});
  square.add_wall(Wall{{{5, 0}, {5, 20}}, 3.0, ""});
  square.add_wall(Wall{{{12, 25.4}, {12, 5}}, 3.0, ""});
  square.add_wall(Wall{{{19, 0}, {19, 20}}, 3.0, ""});
  const World hall = square.build().value();
  const auto grid = OccupancyGrid::rasterise(hall, GridOptions{0.1, 0.25});
  std::vector<double> field_ms;
  std::vector<double> field_cpu;
  double far = 0;
  const Point source{1, 1};
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_ms();
    const auto f = GeodesicField::from_points(grid, std::span<const Point>(&source, 1));
    field_cpu.push_back(thread_cpu_ms() - c0);
    field_ms.push_back(socsim::bench::ms_since(t0));
    far = f.distance({24, 1}).value_or(-1);
  }
  socsim::bench::emit({{"bench", "geodesic_field"},
                       {"runs", runs},
                       {"width", grid.width()},
                       {"height", grid.height()},
                       {"serpentine_distance_m", far},
                       {"p50_ms", socsim::bench::percentile(field_ms, 50)},
                       {"p95_ms", socsim::bench::percentile(field_ms, 95)},
                       {"cpu_p50_ms", socsim::bench::percentile(field_cpu, 50)},
                       {"cpu_p95_ms", socsim::bench::percentile(field_cpu, 95)}});

  const std::string yaml = world_to_yaml(plan.build().value());
  std::vector<double> yaml_ms;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    auto w = world_from_yaml(yaml);
    const std::string again = world_to_yaml(*w);
    yaml_ms.push_back(socsim::bench::ms_since(t0));
    if (again != yaml) return 1;
  }
  socsim::bench::emit({{"bench", "world_yaml_read_build_write"},
                       {"runs", runs},
                       {"bytes", yaml.size()},
                       {"p50_ms", socsim::bench::percentile(yaml_ms, 50)},
                       {"p95_ms", socsim::bench::percentile(yaml_ms, 95)}});
  return floor_plans(runs, "");
}

// Offline generation of one plan per run (one seed each) against the seeded knowledge store:
// layout, furnishing, validation, compliance, extra exits, the layout check. `label` names it.
int floor_plan(socsim::knowledge::KnowledgeBase& kb, const std::string& label, const std::string& domain,
               const SceneGraph& graph, int runs) {
  const auto constraints = kb.constraints_for(domain).value();
  std::vector<double> gen_ms;
  std::vector<double> gen_cpu;
  double attempts = 0;
  std::size_t entities = 0, zones = 0;
  for (int i = 0; i < runs; ++i) {
    OfflineOptions o;
    o.seed = static_cast<std::uint64_t>(i + 1);
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_ms();
    auto plan = generate_floor_plan(graph, constraints, o);
    gen_cpu.push_back(thread_cpu_ms() - c0);
    gen_ms.push_back(socsim::bench::ms_since(t0));
    if (!plan || !plan->compliance.passed) {
      std::cerr << label << " seed " << o.seed << ": "
                << (plan ? "plan not compliant" : plan.error().message()) << "\n";
      return 1;
    }
    attempts += plan->provenance["attempts"].get<double>();
    entities += plan->world.entities().size();
    zones = plan->world.zones().size();
  }
  socsim::bench::emit({{"bench", label},
                       {"runs", runs},
                       {"zones", zones},
                       {"constraints", constraints.size()},
                       {"mean_attempts", attempts / runs},
                       {"mean_entities", static_cast<double>(entities) / runs},
                       {"p50_ms", socsim::bench::percentile(gen_ms, 50)},
                       {"p95_ms", socsim::bench::percentile(gen_ms, 95)},
                       {"cpu_p50_ms", socsim::bench::percentile(gen_cpu, 50)},
                       {"cpu_p95_ms", socsim::bench::percentile(gen_cpu, 95)}});
  return 0;
}

SceneGraph big_mall() {
  return room_program("mall", {{"shop_unit", 50}, {"private_office", 2}, {"toilet", 6}});
}
// A 60-room hospital (corridor, lobby, 50 patient rooms, nurse station, 4 treatment rooms, 3
// toilets): always laid out in wings (the multi_wing family).
SceneGraph big_hospital() {
  return room_program("hospital", {{"patient_room", 50}, {"treatment_room", 4}, {"toilet", 3}});
}
SceneGraph big_arena() {
  return room_program(
      "arena", {{"concession", 20}, {"locker_room", 10}, {"first_aid", 2}, {"storage", 6}, {"toilet", 20}});
}

// A 10-room hospital plan (lobby, corridor, 3 patient rooms, nurse station, 2 treatment rooms,
// 2 toilets), a 60-room mall (concourse, 50 shops, food court, 2 offices, 6 toilets) and a
// 60-room arena (concourse, arena floor, 20 concession stands, 10 locker rooms, 2 first-aid
// rooms, 6 stores, 20 toilets; the auditorium family) and a 60-room hospital in wings.
// Runs fn(kb) on a knowledge base in a scratch SQLite file (the embedded knowledge, migrated), removed
// afterwards; fn's status, or 1 when the store cannot be opened.
template <class F>
int with_scratch_knowledge(const std::string& name, F&& fn) {
  const auto db = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".db");
  int status = 0;
  {
    auto store = socsim::store::Store::open(db.string());
    if (!store) {
      std::cerr << store.error().message() << "\n";
      return 1;
    }
    socsim::knowledge::KnowledgeBase kb(**store);
    status = fn(kb);
  }
  std::error_code ec;
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db.string() + suffix, ec);
  return status;
}

int floor_plans(int runs, const std::string& only) {
  return with_scratch_knowledge("socsim-bench-world", [&](socsim::knowledge::KnowledgeBase& kb) {
    auto wanted = [&only](const std::string& label) {
      return only.empty() || label.find(only) != std::string::npos;
    };
    const int big_runs = std::max(1, runs / 5);
    int status = 0;
    for (const auto& [label, domain, graph, n] :
         {std::tuple{"floor_plan_offline_10_rooms", "hospital",
                     room_program("hospital", {{"patient_room", 3}}), runs},
          std::tuple{"floor_plan_offline_60_room_mall", "mall", big_mall(), big_runs},
          std::tuple{"floor_plan_offline_60_room_arena", "arena", big_arena(), big_runs},
          std::tuple{"floor_plan_offline_60_room_hospital", "hospital", big_hospital(), big_runs}})
      if (status == 0 && wanted(label)) status = floor_plan(kb, label, domain, graph, n);
    return status;
  });
}

// FNV-1a of a text: a short digest to compare plans across commits.
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

void emit_digest(const std::string& prompt, int seed, const FloorPlan& plan) {
  socsim::bench::emit({{"prompt", prompt},
                       {"seed", seed},
                       {"family", plan.provenance.value("layout_family", "")},
                       {"rooms", plan.world.zones().size()},
                       {"world", fnv1a(world_to_document(plan.world).dump())},
                       {"provenance", fnv1a(plan.provenance.dump())}});
}

// One line per prompt x seed: the digest of the world's JSON document and of the provenance,
// so a speed change can show that it left every plan byte-identical (docs/PERFORMANCE.md).
int run_world_digest(const socsim::bench::Args& a) {
  const int seeds = static_cast<int>(a.integer("seeds", 3));
  const std::vector<std::string> prompts = {
      "a hospital ward with six patient rooms, a waiting room and two treatment rooms",
      "guests checking in at a small hotel",
      "visitors in a museum",
      "passengers in the station concourse",
      "a family at home in their small flat",
      "shoppers at the supermarket check-outs",
      "an evening at the cinema",
      "a concert at the arena",
      "shoppers in a shopping mall",
      "workers on the factory floor",
      "students at the university lecture halls",
      "lunch in the office canteen",
  };
  return with_scratch_knowledge("socsim-bench-digest", [&](socsim::knowledge::KnowledgeBase& kb) {
    int status = 0;
    for (const auto& prompt : prompts) {
      auto g = scene_graph_from_prompt(prompt);
      if (!g) {
        std::cerr << prompt << ": " << g.error().message() << "\n";
        status = 1;
        continue;
      }
      const auto constraints = kb.constraints_for(g->graph.domain).value();
      for (int seed = 0; seed < seeds; ++seed) {
        OfflineOptions o;
        o.seed = static_cast<std::uint64_t>(seed);
        auto plan = generate_floor_plan(g->graph, constraints, o);
        if (!plan) {
          socsim::bench::emit({{"prompt", prompt}, {"seed", seed}, {"error", plan.error().message()}});
          continue;
        }
        emit_digest(prompt, seed, *plan);
      }
    }
    // The benchmark's 60-room mall and arena.
    for (const auto& [label, graph] :
         {std::pair{"60-room mall", big_mall()}, std::pair{"60-room arena", big_arena()}}) {
      const auto constraints = kb.constraints_for(graph.domain).value();
      for (int seed = 1; seed <= seeds; ++seed) {
        OfflineOptions o;
        o.seed = static_cast<std::uint64_t>(seed);
        auto plan = generate_floor_plan(graph, constraints, o);
        if (plan) emit_digest(label, seed, *plan);
      }
    }
    return status;
  });
}

}  // namespace

SOCSIM_BENCH("world-digest",
             "digests of the offline worlds of 12 venue prompts x --seeds seeds (default 3), to compare "
             "plans across commits",
             run_world_digest);

SOCSIM_BENCH("world",
             "world build+validate (10 rooms), 256x256 geodesic field, world.yaml round trip, offline "
             "floor plans (10-room hospital, 60-room mall, arena and hospital)",
             run_world);
