// `socsim simulate`: runs a scenario program in a world headless and writes the trajectories
// (CSV: t, id, x, y, vx, vy, state, role, group_id) and, on request, HuNavSim's metrics (JSON).
#include <charconv>
#include <chrono>
#include <fstream>
#include <iostream>

#include "core/crowd/scenario_runner.hpp"
#include "core/world/world_yaml.hpp"
#include "server/cli/cli.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

constexpr const char* kSimulateUsage =
    "  simulate --world W.yaml --program P.json --seconds T --seed S --out traj.csv [--metrics m.json]\n"
    "           [--threads 1] [--every 1]   run a scenario program headless (frames every N steps)\n";

// Shortest text that reads back as the same double (the CSV is as deterministic as the run).
void put(std::string& out, double v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? ptr : buf);
}

std::optional<double> number_option(const CliArgs& a, const std::string& key, double fallback, double lo,
                                    double hi) {
  auto v = a.opt(key);
  if (!v) return fallback;
  double n = 0.0;
  const auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), n);
  if (ec == std::errc() && ptr == v->data() + v->size() && n >= lo && n <= hi) return n;
  std::cerr << "socsim: " << key << " must be a number between " << lo << " and " << hi << "\n";
  return std::nullopt;
}

int simulate_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  const auto world_path = a.opt("--world");
  const auto program_path = a.opt("--program");
  const auto out_path = a.opt("--out");
  if (!a.words.empty() || !world_path || !program_path || !out_path || !a.opt("--seconds")) {
    std::cerr << "usage:\n" << kSimulateUsage;
    return 2;
  }
  const auto seconds = number_option(a, "--seconds", 0.0, 0.0, 1.0e6);
  const auto seed = number_option(a, "--seed", 0.0, 0.0, 9.0e15);
  const auto threads = number_option(a, "--threads", 1.0, 1.0, 64.0);
  const auto every = number_option(a, "--every", 1.0, 1.0, 1.0e6);
  if (!seconds || !seed || !threads || !every) return 2;
  if (*seed != std::floor(*seed) || *threads != std::floor(*threads) || *every != std::floor(*every)) {
    std::cerr << "socsim: --seed, --threads and --every are whole numbers\n";
    return 2;
  }

  const auto world_text = cli_read_file(*world_path);
  if (!world_text) return cli_report(world_text.error());
  auto world = world::world_from_yaml(*world_text);
  if (!world) return cli_report(world.error());
  const auto program_text = cli_read_file(*program_path);
  if (!program_text) return cli_report(program_text.error());
  auto program = crowd::program_from_text(*program_text);
  if (!program) return cli_report(program.error());

  crowd::RunnerOptions options;
  options.seed = static_cast<std::uint64_t>(*seed);
  options.threads = static_cast<unsigned>(*threads);
  options.base_dir = std::filesystem::path(*program_path).parent_path();
  options.record_metrics = a.opt("--metrics").has_value();
  auto runner = crowd::ScenarioRunner::create(&*world, *program, options);
  if (!runner) {
    for (const FieldError& f : runner.error().errors)
      std::cerr << "  " << f.pointer << (f.line > 0 ? " line " + std::to_string(f.line) : std::string())
                << ": " << f.message << "\n";
    return cli_report(runner.error());
  }

  std::ofstream csv(*out_path, std::ios::binary);
  if (!csv) return cli_report(Error(ErrorCode::kBadRequest, "cannot write " + *out_path));
  csv << "t,id,x,y,vx,vy,state,role,group_id\n";
  std::vector<std::uint8_t> was_active;
  std::string block;
  const auto t0 = std::chrono::steady_clock::now();
  (*runner)->run(
      *seconds,
      [&](double t, std::span<const crowd::PedestrianState> states) {
        was_active.resize(states.size(), 1);
        block.clear();
        for (const crowd::PedestrianState& s : states) {
          const bool exited = s.activity == crowd::Activity::kExited;
          // An agent that left appears once more, in the frame it left.
          if (exited && !was_active[s.id.value()]) continue;
          was_active[s.id.value()] = exited ? 0 : 1;
          put(block, t);
          block += ',' + std::to_string(s.id.value()) + ',';
          put(block, s.pose.x);
          block += ',';
          put(block, s.pose.y);
          block += ',';
          put(block, s.twist.vx);
          block += ',';
          put(block, s.twist.vy);
          block += ',';
          block += crowd::activity_name(s.activity);
          block += ',' + s.role + ',' + std::to_string(s.group_id) + '\n';
        }
        csv << block;
      },
      static_cast<unsigned>(*every));
  csv.close();
  if (!csv) return cli_report(Error(ErrorCode::kInternal, "writing " + *out_path + " failed"));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  if (auto metrics_path = a.opt("--metrics")) {
    Json m = crowd::to_json((*runner)->metrics());
    m["program"] = program->name;
    m["seed"] = options.seed;
    std::ofstream out(*metrics_path, std::ios::binary);
    out << m.dump(2) << "\n";
    if (!out) return cli_report(Error(ErrorCode::kBadRequest, "cannot write " + *metrics_path));
  }
  const auto warnings = (*runner)->errors();
  for (const std::string& w : warnings) std::cerr << "socsim: warning: " << w << "\n";
  std::cerr << "socsim: simulated " << (*runner)->agents().size() << " agents for " << (*runner)->time()
            << " s in " << wall << " s; trajectories in " << *out_path << "\n";
  return 0;
}

}  // namespace

SOCSIM_COMMAND("simulate", kSimulateUsage, simulate_command);

}  // namespace socsim::server
