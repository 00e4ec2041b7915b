// `socsim scenario generate|replay`: text to scenario from the shell with the offline generator
// (the same pipeline as POST /api/v1/scenarios), and the replay check of a card file.
#include <iostream>

#include "core/cards/catalogue.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/scenario/pipeline.hpp"
#include "core/scenario/trajectory_store.hpp"
#include "core/store/store.hpp"
#include "core/world/world_yaml.hpp"
#include "server/cli/cli.hpp"
#include "server/prompt_gate.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

constexpr const char* kGenerateUsage =
    "  scenario generate --prompt TEXT [--world W.yaml | --scene-graph G.json] [--domain D] [--seed S]\n"
    "                    [--seconds T] [--agents N] [-o card.json] [--log traj.socsim-traj] [--store]\n"
    "                                                                     offline text to scenario; --store "
    "adds the card\n"
    "                                                                     and its log to the catalogue "
    "(--db)\n";
constexpr const char* kReplayUsage =
    "  scenario replay CARD.json                                          re-run a card; exit 0 when "
    "bit-identical\n";

// Whole numbers and decimals from the command line become JSON numbers; the request parser
// then checks their ranges with the same messages as the API.
Json number_or_text(const std::string& text) {
  auto j = parse_json_untrusted(text);
  if (j && j->is_number()) return *j;
  return text;
}

int generate_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  const auto prompt = a.opt("--prompt");
  if (!prompt || !a.words.empty()) {
    std::cerr << "usage:\n" << kGenerateUsage;
    return 2;
  }
  Json body = {{"prompt", *prompt}};
  if (auto v = a.opt("--seed")) body["seed"] = number_or_text(*v);
  if (auto v = a.opt("--seconds")) body["duration_s"] = number_or_text(*v);
  if (auto v = a.opt("--agents")) body["agents"] = number_or_text(*v);
  if (auto v = a.opt("--domain")) body["domain"] = *v;
  if (auto v = a.opt("--scene-graph")) {
    auto text = cli_read_file(*v);
    if (!text) return cli_report(text.error());
    auto graph = parse_json_untrusted(*text);
    if (!graph) return cli_report(graph.error());
    body["scene_graph"] = *graph;
  }
  std::optional<scenario::ScenarioWorld> world;
  if (auto v = a.opt("--world")) {
    auto text = cli_read_file(*v);
    if (!text) return cli_report(text.error());
    auto w = world::world_from_yaml(*text);
    if (!w) return cli_report(w.error());
    world = scenario::ScenarioWorld{std::move(*w), a.opt("--domain").value_or(""), Json{{"source", *v}}};
  }
  scenario::ScenarioConfig config;
  auto request = scenario::scenario_request_from_json(body, config);
  if (!request) return cli_report(request.error());
  if (auto intent = checked_prompt(request->prompt, config.max_prompt_bytes); !intent)
    return cli_report(intent.error());

  auto store = store::Store::open(cli_db_path(a));
  if (!store) return cli_report(store.error());
  knowledge::KnowledgeBase kb(**store);
  int shown = -1;  // progress on stderr, one line per tenth
  scenario::ScenarioServices services{
      kb, nullptr, config, std::nullopt, {}, [&shown](double f, const std::string& m) {
        const int tenth = static_cast<int>(f * 10);
        if (tenth == shown) return;
        shown = tenth;
        std::cerr << "[" << static_cast<int>(f * 100) << "%] " << m << "\n";
      }};
  auto outcome = scenario::run_scenario(*request, world, services);
  if (!outcome) return cli_report(outcome.error());

  const std::string card_text = cards::content_to_json(outcome->card).dump(2) + "\n";
  if (auto out = a.opt("-o")) {
    if (auto s = cli_write_file(*out, card_text); !s) return cli_report(s.error());
  } else if (!a.flag("--store")) {
    std::cout << card_text;
  }
  if (auto path = a.opt("--log")) {
    if (auto s = cli_write_file(*path, outcome->log.compressed()); !s) return cli_report(s.error());
  }
  if (a.flag("--store")) {
    if (auto s = scenario::save_trajectory_log(**store, outcome->log); !s) return cli_report(s.error());
    cards::CardCatalogue catalogue(**store);
    auto card = catalogue.create(outcome->card, "cli");
    if (!card) return cli_report(card.error());
    std::cout << card->id << "\n";
  }
  std::cerr << outcome->card.title << ": " << outcome->card.description << "\ntrajectory sha256 "
            << outcome->log.sha256() << " (" << outcome->log.frame_count() << " frames)\n";
  return 0;
}

int replay_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  if (a.words.size() != 1) {
    std::cerr << "usage:\n" << kReplayUsage;
    return 2;
  }
  auto text = cli_read_file(a.words[0]);
  if (!text) return cli_report(text.error());
  // A catalogue export document (`socsim card export`, GET /cards/{id}/export), or the content
  // alone (`scenario generate -o`).
  cards::CardContent content;
  if (auto exported = cards::parse_export_document(*text, cards::CardLimits{})) {
    content = exported->content;
  } else {
    auto json = parse_json_untrusted(*text);
    if (!json) return cli_report(json.error());
    if (json->contains("socsim_card_export")) return cli_report(exported.error());
    auto parsed = cards::parse_card_content(*json, cards::CardLimits{});
    if (!parsed) return cli_report(parsed.error());
    content = std::move(*parsed);
  }
  const cards::CardContent* card = &content;
  auto out = scenario::replay_card(*card);
  if (!out) return cli_report(out.error());
  const std::string expected = card->trajectory_log.value("sha256", "");
  const bool same = out->log.sha256() == expected;
  std::cout << (same ? "identical" : "DIFFERENT") << " " << out->log.sha256() << " (card: " << expected
            << ", " << out->log.frame_count() << " frames)\n";
  return same ? 0 : 1;
}

}  // namespace

SOCSIM_COMMAND("scenario generate", kGenerateUsage, generate_command);
SOCSIM_COMMAND("scenario replay", kReplayUsage, replay_command);

}  // namespace socsim::server
