// `socsim knowledge search|classify|constraints`: the knowledge store from the shell.
#include <iostream>

#include "core/knowledge/building_type.hpp"
#include "core/knowledge/knowledge_base.hpp"
#include "core/store/store.hpp"
#include "server/cli/cli.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

constexpr const char* kKnowledgeUsage =
    "  knowledge search TEXT [--kind building_code|behavior_node] [--k 5]   retrieve entries (BM25 + offline "
    "embedding)\n"
    "  knowledge classify TEXT                                            building type of a prompt, with "
    "the deciding words\n"
    "  knowledge constraints TYPE [--jurisdiction J]                      constraints a floor plan of TYPE "
    "must meet\n";

int knowledge_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  if (a.words.size() < 2) {
    std::cerr << "usage:\n" << kKnowledgeUsage;
    return 2;
  }
  const std::string& verb = a.words[0];
  std::string text;
  for (std::size_t i = 1; i < a.words.size(); ++i) text += (i > 1 ? " " : "") + a.words[i];
  if (verb == "classify") {
    std::cout << knowledge::to_json(knowledge::classify_building_type(text)).dump(2) << "\n";
    return 0;
  }
  auto store = store::Store::open(cli_db_path(a));
  if (!store) return cli_report(store.error());
  knowledge::KnowledgeBase kb(**store, knowledge::hashed_ngram_embedding());
  if (verb == "search") {
    std::vector<knowledge::Kind> kinds = {knowledge::Kind::kBuildingCode, knowledge::Kind::kBehaviorNode};
    if (auto k = a.opt("--kind")) {
      auto kind = knowledge::kind_from_string(*k);
      if (!kind) {
        std::cerr << "socsim: --kind is building_code or behavior_node\n";
        return 2;
      }
      kinds = {*kind};
    }
    std::size_t k = 5;
    if (auto n = a.opt("--k")) {
      try {
        k = std::stoul(*n);
      } catch (const std::exception&) {
        std::cerr << "socsim: --k must be a positive integer\n";
        return 2;
      }
    }
    Json out = Json::object();
    for (auto kind : kinds) {
      auto r = kb.search(text, kind, k);
      if (!r) return cli_report(r.error());
      Json hits = Json::array();
      for (const auto& h : r->hits) hits.push_back(knowledge::to_json(h.provenance));
      out[std::string(knowledge::to_string(kind))] = hits;
    }
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  if (verb == "constraints") {
    auto list = kb.constraints_for(text, a.opt("--jurisdiction").value_or(""));
    if (!list) return cli_report(list.error());
    Json items = Json::array();
    for (const auto& c : *list) items.push_back(knowledge::to_json(c));
    std::cout << items.dump(2) << "\n";
    return 0;
  }
  std::cerr << "socsim: unknown knowledge command '" << verb << "'\nusage:\n" << kKnowledgeUsage;
  return 2;
}

}  // namespace

SOCSIM_COMMAND("knowledge", kKnowledgeUsage, knowledge_command);

}  // namespace socsim::server
