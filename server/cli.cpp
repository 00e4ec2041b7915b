// `socsim` subcommands other than serve: card list|show|export|import, migrate, version.
#include "server/cli.hpp"

#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "core/cards/catalogue.hpp"
#include "core/store/store.hpp"
#include "socsim/buildinfo.hpp"

namespace socsim::server {
namespace {

constexpr const char* kUsage =
    "usage: socsim <command> [options]\n\n"
    "commands:\n"
    "  serve                 run the REST + WebSocket daemon (socsim serve --help)\n"
    "  card list             list cards   [--q TEXT] [--tag T] [--author A] [--domain D] [--page-size N] [--cursor C]\n"
    "  card show ID          print a card as JSON\n"
    "  card export ID        write the card's export file  [-o FILE]\n"
    "  card import FILE      import an export file ('-' reads standard input)\n"
    "  migrate               apply pending migrations and print the schema version\n"
    "  version               print version and build\n\n"
    "Every command but serve and version takes --db FILE (default ./var/socsim.db, or $SOCSIM_DB).\n";

// Splits "--key value" options from positional words.
struct Parsed {
  std::vector<std::string> words;
  std::map<std::string, std::string> options;
};

Parsed parse(const std::vector<std::string>& args) {
  Parsed p;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if ((a.rfind("--", 0) == 0 || a == "-o") && a.size() > 1) {
      if (auto eq = a.find('='); eq != std::string::npos) {
        p.options[a.substr(0, eq)] = a.substr(eq + 1);
      } else if (i + 1 < args.size()) {
        p.options[a] = args[++i];
      } else {
        p.options[a] = "";
      }
    } else {
      p.words.push_back(a);
    }
  }
  return p;
}

std::string db_path(const Parsed& p) {
  if (auto it = p.options.find("--db"); it != p.options.end()) return it->second;
  if (const char* env = std::getenv("SOCSIM_DB"); env && *env) return env;
  return "./var/socsim.db";
}

int report(const Error& e) {
  std::cerr << "socsim: " << e.message() << "\n";
  return e.status() >= 500 ? 1 : 2;
}

std::optional<std::string> opt(const Parsed& p, const std::string& key) {
  auto it = p.options.find(key);
  if (it == p.options.end()) return std::nullopt;
  return it->second;
}

}  // namespace

int run_card_command(const std::vector<std::string>& args) {
  const Parsed p = parse(args);
  if (p.words.empty()) {
    std::cerr << kUsage;
    return 2;
  }
  auto store = store::Store::open(db_path(p));
  if (!store) return report(store.error());
  cards::CardCatalogue catalogue(**store);
  const std::string& verb = p.words[0];

  if (verb == "list") {
    cards::CardQuery q;
    q.text = opt(p, "--q");
    q.tag = opt(p, "--tag");
    q.author = opt(p, "--author");
    q.domain = opt(p, "--domain");
    q.cursor = opt(p, "--cursor");
    if (auto n = opt(p, "--page-size")) {
      try {
        q.page_size = static_cast<std::size_t>(std::stoul(*n));
      } catch (const std::exception&) {
        std::cerr << "socsim: --page-size must be a positive integer\n";
        return 2;
      }
      if (q.page_size == 0 || q.page_size > 1000) {
        std::cerr << "socsim: --page-size must be between 1 and 1000\n";
        return 2;
      }
    }
    auto page = catalogue.list(q);
    if (!page) return report(page.error());
    Json items = Json::array();
    for (const auto& c : page->items) items.push_back(cards::summary_json(c));
    std::cout << Json{{"items", items}, {"next_cursor", page->next_cursor ? Json(*page->next_cursor) : Json(nullptr)}}.dump(2)
              << "\n";
    return 0;
  }
  if (p.words.size() < 2) {
    std::cerr << "socsim: card " << verb << " needs an argument\n" << kUsage;
    return 2;
  }
  if (verb == "show") {
    auto c = catalogue.get(p.words[1]);
    if (!c) return report(c.error());
    std::cout << cards::to_json(*c).dump(2) << "\n";
    return 0;
  }
  if (verb == "export") {
    auto doc = catalogue.export_card(p.words[1]);
    if (!doc) return report(doc.error());
    if (auto out = opt(p, "-o")) {
      std::ofstream f(*out, std::ios::binary);
      f << *doc;
      if (!f) {
        std::cerr << "socsim: cannot write " << *out << "\n";
        return 1;
      }
    } else {
      std::cout << *doc;
    }
    return 0;
  }
  if (verb == "import") {
    std::stringstream buf;
    if (p.words[1] == "-") {
      buf << std::cin.rdbuf();
    } else {
      std::ifstream f(p.words[1], std::ios::binary);
      if (!f) {
        std::cerr << "socsim: cannot read " << p.words[1] << "\n";
        return 2;
      }
      buf << f.rdbuf();
    }
    auto outcome = catalogue.import_card(buf.str());
    if (!outcome) return report(outcome.error());
    std::cout << Json{{"id", outcome->card.id}, {"content_hash", outcome->card.content_hash}, {"created", outcome->created}}.dump()
              << "\n";
    return 0;
  }
  std::cerr << "socsim: unknown card command '" << verb << "'\n" << kUsage;
  return 2;
}

int run_cli(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
  }
  const std::string& cmd = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (cmd == "serve") return run_serve(rest);
  if (cmd == "card") return run_card_command(rest);
  if (cmd == "version" || cmd == "--version") {
    std::cout << "socsim " << build::kVersion << " (" << build::kGitSha << ", " << build::kFlavor << ", "
              << build::kCompiler << ")\n";
    return 0;
  }
  if (cmd == "migrate") {
    auto store = store::Store::open(db_path(parse(rest)));
    if (!store) return report(store.error());
    const auto& r = (*store)->migration_report();
    std::cout << Json{{"db", (*store)->path()}, {"from_version", r.from_version}, {"to_version", r.to_version}, {"applied", r.applied}}.dump()
              << "\n";
    return 0;
  }
  std::cerr << "socsim: unknown command '" << cmd << "'\n" << kUsage;
  return 2;
}

}  // namespace socsim::server
