// `socsim world generate|validate|export`: floor plans, world.yaml validation with the compliance
// report, and simulator exports from the shell (offline generator; the knowledge store gives the codes).
#include <filesystem>
#include <iostream>

#include "core/floorplan/offline.hpp"
#include "core/floorplan/request.hpp"
#include "core/knowledge/building_type.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/store/store.hpp"
#include "core/world/world_export.hpp"
#include "core/world/world_yaml.hpp"
#include "server/cli/cli.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

constexpr const char* kWorldUsage =
    "  world generate (--prompt TEXT | --scene-graph FILE) [--domain D] [--seed S] [--jurisdiction J] [-o "
    "world.yaml] [--report FILE]\n"
    "                                                                     offline floor plan; compliance "
    "summary on stderr\n"
    "  world validate FILE [--domain D] [--jurisdiction J]                 validation (line, field) and "
    "compliance report\n"
    "  world export FILE --format sdf|usda|pedsim|map|svg -o OUT          simulator/map export (map: OUT.pgm "
    "+ OUT.yaml)\n";

int usage(const std::string& why) {
  std::cerr << "socsim: " << why << "\nusage:\n" << kWorldUsage;
  return 2;
}

std::string summary_line(const floorplan::ComplianceReport& r) {
  int pass = 0, failed = 0, other = 0;
  for (const auto& c : r.checks) {
    if (c.status == floorplan::CheckStatus::kPass)
      ++pass;
    else if (c.status == floorplan::CheckStatus::kFail)
      ++failed;
    else
      ++other;
  }
  return std::string(r.passed ? "compliant" : "NOT compliant") + " (" + r.building_type +
         "): " + std::to_string(pass) + " pass, " + std::to_string(failed) + " fail, " +
         std::to_string(other) + " not applicable/checked/used";
}

int generate(const CliArgs& a) {
  Json body = Json::object();
  if (auto p = a.opt("--prompt")) body["prompt"] = *p;
  if (auto f = a.opt("--scene-graph")) {
    auto text = cli_read_file(*f);
    if (!text) return cli_report(text.error());
    auto j = parse_json_untrusted(*text);
    if (!j) return cli_report(j.error());
    body["scene_graph"] = *j;
  }
  if (auto d = a.opt("--domain")) body["domain"] = *d;
  if (auto j = a.opt("--jurisdiction")) body["jurisdiction"] = *j;
  if (auto s = a.opt("--seed")) {
    try {
      body["seed"] = std::stoll(*s);
    } catch (const std::exception&) {
      return usage("--seed must be a non-negative integer");
    }
  }
  auto request = floorplan::floor_plan_request_from_json(body);
  if (!request) return cli_report(request.error());
  auto resolved = floorplan::resolve_scene_graph(*request);
  if (!resolved) return cli_report(resolved.error());
  auto store = store::Store::open(cli_db_path(a));
  if (!store) return cli_report(store.error());
  knowledge::KnowledgeBase kb(**store);
  auto cs = kb.constraints_for(resolved->graph.domain, request->jurisdiction);
  if (!cs) return cli_report(cs.error());
  floorplan::OfflineOptions o;
  o.seed = request->seed;
  o.requirements = request->requirements;
  auto plan = floorplan::generate_floor_plan(resolved->graph, *cs, o);
  if (!plan) return cli_report(plan.error());
  const std::string yaml = world::world_to_yaml(plan->world);
  if (auto out = a.opt("-o")) {
    if (auto s = cli_write_file(*out, yaml); !s) return cli_report(s.error());
  } else {
    std::cout << yaml;
  }
  if (auto report = a.opt("--report")) {
    Json j = {{"compliance", floorplan::to_json(plan->compliance)},
              {"provenance", plan->provenance},
              {"scene_graph", floorplan::to_json(plan->scene_graph)}};
    if (auto s = cli_write_file(*report, j.dump(2) + "\n"); !s) return cli_report(s.error());
  }
  std::cerr << plan->world.name() << ": " << plan->world.zones().size() << " zones, "
            << plan->world.doors().size() << " doors, " << plan->world.area() << " m²; "
            << summary_line(plan->compliance) << "\n";
  return 0;
}

int validate(const CliArgs& a) {
  if (a.words.size() < 2) return usage("name the world.yaml to validate");
  auto text = cli_read_file(a.words[1]);
  if (!text) return cli_report(text.error());
  auto w = world::world_from_yaml(*text);
  if (!w) return cli_report(w.error());
  std::string domain;
  if (auto d = a.opt("--domain")) {
    if (!knowledge::is_building_type(*d)) return usage("unknown --domain '" + *d + "'");
    domain = *d;
  } else {
    domain = floorplan::building_type_of(*w);
  }
  auto store = store::Store::open(cli_db_path(a));
  if (!store) return cli_report(store.error());
  knowledge::KnowledgeBase kb(**store);
  auto cs = kb.constraints_for(domain, a.opt("--jurisdiction").value_or(""));
  if (!cs) return cli_report(cs.error());
  const auto report = floorplan::check_compliance(*w, domain, *cs);
  std::cout << Json{{"valid", true}, {"compliance", floorplan::to_json(report)}}.dump(2) << "\n";
  std::cerr << a.words[1] << ": valid; " << summary_line(report) << "\n";
  return report.passed ? 0 : 1;
}

int export_world(const CliArgs& a) {
  if (a.words.size() < 2) return usage("name the world.yaml to export");
  const auto format = a.opt("--format");
  const auto out = a.opt("-o");
  if (!format || !out) return usage("export needs --format and -o");
  auto text = cli_read_file(a.words[1]);
  if (!text) return cli_report(text.error());
  auto w = world::world_from_yaml(*text);
  if (!w) return cli_report(w.error());
  Status s;
  if (*format == "sdf") {
    s = cli_write_file(*out, world::export_sdf(*w));
  } else if (*format == "usda") {
    s = cli_write_file(*out, world::export_usda(*w));
  } else if (*format == "pedsim") {
    s = cli_write_file(*out, world::export_pedsim(*w));
  } else if (*format == "svg") {
    s = cli_write_file(*out, world::export_svg(*w));
  } else if (*format == "map") {
    // OUT names the image; the metadata goes next to it with .yaml.
    std::string stem = *out;
    if (stem.size() > 4 && stem.ends_with(".pgm")) stem.resize(stem.size() - 4);
    world::RosMapOptions mo;
    mo.image_file = std::filesystem::path(stem + ".pgm").filename().string();
    const auto map = world::export_ros_map(*w, mo);
    s = cli_write_file(stem + ".pgm", map.pgm);
    if (s) s = cli_write_file(stem + ".yaml", map.yaml);
  } else {
    return usage("--format is sdf, usda, pedsim, map or svg");
  }
  if (!s) return cli_report(s.error());
  return 0;
}

int world_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  if (a.words.empty()) return usage("say generate, validate or export");
  const std::string& verb = a.words[0];
  if (verb == "generate") return generate(a);
  if (verb == "validate") return validate(a);
  if (verb == "export") return export_world(a);
  return usage("unknown world command '" + verb + "'");
}

}  // namespace

SOCSIM_COMMAND("world", kWorldUsage, world_command);

}  // namespace socsim::server
