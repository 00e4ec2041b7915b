// `socsim scenario import-pedsim` and `socsim scenario export`: pedsim_ros scenarios in as a
// world.yaml + scenario program, and a world + program out as HuNavSim or pedsim_ros input.
#include <charconv>
#include <filesystem>
#include <iostream>

#include "core/crowd/program.hpp"
#include "core/interop/export_arena.hpp"
#include "core/interop/export_hunav.hpp"
#include "core/interop/export_isaac.hpp"
#include "core/interop/export_pedsim_scenario.hpp"
#include "core/interop/pedsim_program.hpp"
#include "core/world/world_yaml.hpp"
#include "server/cli/cli.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

constexpr const char* kImportUsage =
    "  scenario import-pedsim FILE.xml --world-out W.yaml --program-out P.json\n"
    "                        a pedsim_ros scenario as a world and a scenario program (for socsim simulate)\n";
constexpr const char* kExportUsage =
    "  scenario export --world W.yaml --program P.json --format hunav|pedsim|arena|isaac --out DIR [--seed "
    "S]\n"
    "                        HuNavSim agents YAML + one BT per agent, a pedsim_ros scenario XML,\n"
    "                        an Arena-Rosnav scenario JSON, or Isaac Sim files (world.usda, IRA\n"
    "                        config, omni.anim.people commands)\n";

bool write_file(const std::filesystem::path& path, const std::string& text) {
  auto s = cli_write_file(path.string(), text);
  if (!s) cli_report(s.error());
  return s.has_value();
}

// One line per problem, "FILE:LINE: pointer: message", as compilers print them.
int report(const std::string& file, const Error& e) {
  std::cerr << "socsim: " << file << ": " << error_info(e.code).title << ": " << e.detail << "\n";
  for (const FieldError& f : e.errors) {
    std::cerr << file;
    if (f.line > 0) std::cerr << ":" << f.line;
    std::cerr << ": " << (f.pointer.empty() ? std::string() : f.pointer + ": ") << f.message << "\n";
  }
  return e.status() >= 500 ? 1 : 2;
}

int import_pedsim_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  const auto world_out = a.opt("--world-out");
  const auto program_out = a.opt("--program-out");
  if (a.words.size() != 1 || !world_out || !program_out) {
    std::cerr << "usage:\n" << kImportUsage;
    return 2;
  }
  const std::string& file = a.words[0];
  const auto text = cli_read_file(file);
  if (!text) return cli_report(text.error());
  world::PedsimImportOptions options;
  options.name = std::filesystem::path(file).stem().string();
  auto imported = interop::import_pedsim_scenario(*text, options);
  if (!imported) return report(file, imported.error());
  if (!write_file(*world_out, world::world_to_yaml(imported->scenario.world))) return 1;
  if (!write_file(*program_out, imported->program.program.dump(2) + "\n")) return 1;
  std::size_t agents = imported->parsed.robot ? 1 : 0;
  for (const auto& e : imported->parsed.agents) agents += e.count;
  std::cerr << "socsim: " << file << ": " << imported->scenario.world.walls().size() << " walls, "
            << imported->scenario.waypoints.size() << " waypoints, " << imported->scenario.queues.size()
            << " queues, " << imported->scenario.attractions.size() << " attractions, " << agents
            << " agents; world in " << *world_out << ", program in " << *program_out << "\n";
  return 0;
}

int export_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  const auto world_path = a.opt("--world");
  const auto program_path = a.opt("--program");
  const auto format = a.opt("--format");
  const auto out = a.opt("--out");
  if (!a.words.empty() || !world_path || !program_path || !format || !out) {
    std::cerr << "usage:\n" << kExportUsage;
    return 2;
  }
  if (*format != "hunav" && *format != "pedsim" && *format != "arena" && *format != "isaac") {
    std::cerr << "socsim: --format must be hunav, pedsim, arena or isaac, not '" << *format << "'\n";
    return 2;
  }
  std::uint64_t seed = 0;
  if (auto s = a.opt("--seed")) {
    const auto [ptr, ec] = std::from_chars(s->data(), s->data() + s->size(), seed);
    if (ec != std::errc() || ptr != s->data() + s->size()) {
      std::cerr << "socsim: --seed must be a whole number\n";
      return 2;
    }
  }
  const auto world_text = cli_read_file(*world_path);
  if (!world_text) return cli_report(world_text.error());
  auto w = world::world_from_yaml(*world_text);
  if (!w) return report(*world_path, w.error());
  const auto program_text = cli_read_file(*program_path);
  if (!program_text) return cli_report(program_text.error());
  auto program = crowd::program_from_text(*program_text);
  if (!program) return report(*program_path, program.error());

  std::vector<interop::ExportFile> files;
  if (*format == "hunav") {
    interop::HunavOptions options;
    options.seed = seed;
    auto bundle = interop::export_hunav(*w, *program, options);
    if (!bundle) return report(*program_path, bundle.error());
    files = std::move(*bundle);
  } else if (*format == "isaac") {
    interop::IsaacExportOptions options;
    options.seed = seed;
    auto bundle = interop::export_isaac(*w, *program, options);
    if (!bundle) return report(*program_path, bundle.error());
    files = std::move(*bundle);
  } else if (*format == "arena") {
    interop::ArenaExportOptions options;
    options.seed = seed;
    auto json = interop::export_arena_scenario(*w, *program, options);
    if (!json) return report(*program_path, json.error());
    files.push_back(
        {interop::file_stem(program->name.empty() ? w->name() : program->name, "scenario") + ".json",
         std::move(*json)});
  } else {
    interop::PedsimExportOptions options;
    options.seed = seed;
    auto xml = interop::export_pedsim_scenario(*w, *program, options);
    if (!xml) return report(*program_path, xml.error());
    files.push_back(
        {interop::file_stem(program->name.empty() ? w->name() : program->name, "scenario") + ".xml",
         std::move(*xml)});
  }
  for (const auto& f : files)
    if (!write_file(std::filesystem::path(*out) / f.path, f.content)) return 1;
  std::cerr << "socsim: wrote " << files.size() << " file" << (files.size() == 1 ? "" : "s") << " to " << *out
            << " (" << files.front().path << (files.size() > 1 ? ", …" : "") << ")\n";
  return 0;
}

}  // namespace

SOCSIM_COMMAND("scenario import-pedsim", kImportUsage, import_pedsim_command);
SOCSIM_COMMAND("scenario export", kExportUsage, export_command);

}  // namespace socsim::server
