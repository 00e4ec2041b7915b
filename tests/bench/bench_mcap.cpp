// socsim-bench mcap: a large card's log as MCAP (issue 20 acceptance: a 10,000-agent, 60 s card
// exports in <= 2 s to no more than 1.5x its own compressed log). Simulates --agents people in a
// walled hall for --seconds, logged at 10 Hz as a card's log is, then times export_mcap (--repeat
// times, with and without the per-frame people scene) and compares sizes with log.compressed().
#include <time.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/crowd/scenario_runner.hpp"
#include "core/interop/mcap_export.hpp"
#include "core/scenario/trajectory_log.hpp"
#include "core/world/world_yaml.hpp"
#include "tests/bench/bench.hpp"

namespace {

using socsim::Json;

// CPU seconds of the calling thread (encoding) and of the process (with the compression threads):
// on a machine shared with builds, wall time says more about the neighbours than about the export.
double cpu_seconds(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

// A square hall of `side` metres with four ROI bands `b` metres wide along its walls.
std::string hall_yaml(double side, double b) {
  std::ostringstream y;
  const double s = side;
  y << "zones:\n  - {name: hall, type: hall, polygon: [[0,0],[" << s << ",0],[" << s << "," << s << "],[0,"
    << s << "]]}\n"
    << "walls:\n"
    << "  - {start: [0,0], end: [" << s << ",0]}\n  - {start: [" << s << ",0], end: [" << s << "," << s
    << "]}\n"
    << "  - {start: [" << s << "," << s << "], end: [0," << s << "]}\n  - {start: [0," << s
    << "], end: [0,0]}\n"
    << "segmentation:\n"
    << "  - {name: west, polygon: [[1,1],[" << b << ",1],[" << b << "," << s - 1 << "],[1," << s - 1
    << "]]}\n"
    << "  - {name: east, polygon: [[" << s - b << ",1],[" << s - 1 << ",1],[" << s - 1 << "," << s - 1
    << "],[" << s - b << "," << s - 1 << "]]}\n"
    << "  - {name: south, polygon: [[1,1],[" << s - 1 << ",1],[" << s - 1 << "," << b << "],[1," << b
    << "]]}\n"
    << "  - {name: north, polygon: [[1," << s - b << "],[" << s - 1 << "," << s - b << "],[" << s - 1 << ","
    << s - 1 << "],[1," << s - 1 << "]]}\n";
  return y.str();
}

// Four counter-flows (west↔east, south↔north), a quarter of the people each, every fourth pair
// walking as a group of two; roles adult, elderly, staff.
Json crossing_program(std::size_t agents) {
  Json program = {{"version", 1}, {"name", "bench crossing"}, {"dt", 0.05}, {"agents", Json::array()}};
  const char* flows[][2] = {{"west", "east"}, {"east", "west"}, {"south", "north"}, {"north", "south"}};
  const char* roles[] = {"adult", "elderly", "staff"};
  for (std::size_t f = 0; f < 4; ++f) {
    const std::size_t n = agents / 4 + (f < agents % 4 ? 1 : 0);
    for (std::size_t r = 0; r < 3; ++r) {
      const std::size_t count = n / 3 + (r < n % 3 ? 1 : 0);
      if (count == 0) continue;
      program["agents"].push_back({{"name", std::string(flows[f][0]) + "_" + roles[r]},
                                   {"role", roles[r]},
                                   {"count", count},
                                   {"spawn", flows[f][0]},
                                   {"goals", {flows[f][1], flows[f][0]}},
                                   {"cyclic_goals", true}});
    }
  }
  return program;
}

int mcap_bench(const socsim::bench::Args& a) {
  using socsim::bench::seconds_since;
  const auto agents = static_cast<std::size_t>(a.integer("agents", 10000));
  const double seconds = a.number("seconds", 60.0);
  const auto repeat = std::max<std::int64_t>(1, a.integer("repeat", 3));
  // The hall grows with the crowd; each band holds a quarter of it at about 0.7 people/m².
  const double side = std::max(30.0, std::ceil(std::sqrt(static_cast<double>(agents)) * 1.6));
  const double band = std::clamp(static_cast<double>(agents) / 4 / 0.7 / (side - 2), 4.0, side / 3);
  auto world = socsim::world::world_from_yaml(hall_yaml(side, band));
  if (!world) return std::cerr << world.error().message() << "\n", 1;
  auto program = socsim::crowd::program_from_json(crossing_program(agents));
  if (!program) return std::cerr << program.error().message() << "\n", 1;
  socsim::crowd::RunnerOptions options;
  options.seed = static_cast<std::uint64_t>(a.integer("seed", 1));
  options.threads = static_cast<unsigned>(a.integer("threads", 2));
  options.record_metrics = false;
  auto runner = socsim::crowd::ScenarioRunner::create(&*world, *program, options);
  if (!runner) return std::cerr << runner.error().message() << "\n", 1;

  auto t0 = std::chrono::steady_clock::now();
  socsim::scenario::TrajectoryRecorder recorder(0.1);
  (*runner)->run(
      seconds, [&](double t, std::span<const socsim::crowd::PedestrianState> s) { recorder.add(t, s); }, 2);
  const socsim::scenario::TrajectoryLog log = std::move(recorder).finish();
  const double simulate_s = seconds_since(t0);
  const std::size_t log_bytes = log.compressed().size();

  // Best of --repeat runs: wall seconds, the calling thread's and the process's CPU seconds.
  struct Cpu {
    double thread = 1e300, process = 1e300;
  };
  auto time_export = [&](bool scene_people, std::size_t& bytes, Cpu& cpu) {
    socsim::interop::McapExportOptions mcap;
    mcap.card_id = "bench";
    mcap.roles = program->roles;
    mcap.scene_people = scene_people;
    mcap.zstd_level = static_cast<int>(a.integer("level", mcap.zstd_level));
    if (a.str("compression", "zstd") == "none") mcap.compression = socsim::interop::McapCompression::kNone;
    mcap.chunk_size =
        static_cast<std::size_t>(a.integer("chunk-kib", static_cast<std::int64_t>(mcap.chunk_size / 1024))) *
        1024;
    std::vector<double> times;
    for (std::int64_t i = 0; i < repeat; ++i) {
      const auto start = std::chrono::steady_clock::now();
      const double thread_start = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
      const double process_start = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
      auto file = socsim::interop::export_mcap(log, *world, mcap);
      times.push_back(seconds_since(start));
      cpu.thread = std::min(cpu.thread, cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - thread_start);
      cpu.process = std::min(cpu.process, cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - process_start);
      if (!file) throw std::runtime_error(file.error().message());
      bytes = file->size();
    }
    return *std::min_element(times.begin(), times.end());
  };
  std::size_t full_bytes = 0, people_bytes = 0;
  Cpu full_cpu, people_cpu;
  const double full_s = time_export(true, full_bytes, full_cpu);
  const double people_s = time_export(false, people_bytes, people_cpu);
  const double ratio = static_cast<double>(full_bytes) / static_cast<double>(log_bytes);
  const double people_ratio = static_cast<double>(people_bytes) / static_cast<double>(log_bytes);
  socsim::bench::emit({{"bench", "mcap"},
                       {"agents", log.agent_count()},
                       {"frames", log.frame_count()},
                       {"seconds", seconds},
                       {"simulate_s", simulate_s},
                       {"log_compressed_bytes", log_bytes},
                       {"mcap_bytes", full_bytes},
                       {"mcap_s", full_s},
                       {"mcap_encode_cpu_s", full_cpu.thread},
                       {"mcap_cpu_s", full_cpu.process},
                       {"mcap_over_log", ratio},
                       {"people_only_bytes", people_bytes},
                       {"people_only_s", people_s},
                       {"people_only_encode_cpu_s", people_cpu.thread},
                       {"people_only_cpu_s", people_cpu.process},
                       {"people_only_over_log", people_ratio},
                       {"acceptance_full", full_s <= 2.0 && ratio <= 1.5},
                       {"acceptance_people_only", people_s <= 2.0 && people_ratio <= 1.5}});
  return 0;
}

}  // namespace

SOCSIM_BENCH(
    "mcap", "card log as MCAP: --agents 10000 --seconds 60 --threads 2 --repeat 3 (time and size vs the log)",
    mcap_bench);
