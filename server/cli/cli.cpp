// `socsim` subcommands other than serve: card list|show|export|import, migrate, version.
#include "server/cli/cli.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "core/cards/catalogue.hpp"
#include "core/interop/tar_archive.hpp"
#include "core/store/store.hpp"
#include "server/card_exports.hpp"
#include "server/registry.hpp"
#include "socsim/buildinfo.hpp"

namespace socsim::server {
namespace {

constexpr const char* kCardUsage =
    "  card list             list cards   [--q TEXT] [--tag T] [--author A] [--domain D] [--page-size N] "
    "[--cursor C]\n"
    "  card show ID          print a card as JSON\n"
    "  card export ID        write the card's export file  [-o FILE] [--format "
    "card|mcap|gazebo|arena|isaac]\n"
    "                        mcap: the trajectory as a ROS 2 / Foxglove recording [--scene-people "
    "true|false|auto]\n"
    "                        (auto: the per-frame people scene for cards of at most 2,000 people);\n"
    "                        gazebo: an SDF world whose actors walk the trajectory;\n"
    "                        arena: an Arena-Rosnav scenario (people, obstacles, robot start and goal);\n"
    "                        isaac: a tar of world.usda, ira_config.yaml and people_commands.txt\n"
    "  card import FILE      import an export file ('-' reads standard input)\n";

int card_command(const std::vector<std::string>& args) {
  const CliArgs p = parse_cli(args);
  if (p.words.empty()) {
    std::cerr << "usage:\n" << kCardUsage;
    return 2;
  }
  auto store = store::Store::open(cli_db_path(p));
  if (!store) return cli_report(store.error());
  cards::CardCatalogue catalogue(**store);
  const std::string& verb = p.words[0];

  if (verb == "list") {
    cards::CardQuery q;
    q.text = p.opt("--q");
    q.tag = p.opt("--tag");
    q.author = p.opt("--author");
    q.domain = p.opt("--domain");
    q.cursor = p.opt("--cursor");
    if (auto n = p.opt("--page-size")) {
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
    if (!page) return cli_report(page.error());
    Json items = Json::array();
    for (const auto& c : page->items) items.push_back(cards::summary_json(c));
    std::cout << Json{{"items", items},
                      {"next_cursor", page->next_cursor ? Json(*page->next_cursor) : Json(nullptr)}}
                     .dump(2)
              << "\n";
    return 0;
  }
  if (p.words.size() < 2) {
    std::cerr << "socsim: card " << verb << " needs an argument\n" << kCardUsage;
    return 2;
  }
  if (verb == "show") {
    auto c = catalogue.get(p.words[1]);
    if (!c) return cli_report(c.error());
    std::cout << cards::to_json(*c).dump(2) << "\n";
    return 0;
  }
  if (verb == "export") {
    const std::string format = p.opt("--format").value_or("card");
    const std::string scene_people = p.opt("--scene-people").value_or("auto");
    if ((format != "card" && format != "mcap" && format != "gazebo" && format != "arena" &&
         format != "isaac") ||
        (scene_people != "true" && scene_people != "false" && scene_people != "auto")) {
      std::cerr << "socsim: --format must be card, mcap, gazebo, arena or isaac, --scene-people true, false "
                   "or auto\n"
                << kCardUsage;
      return 2;
    }
    Result<std::string> doc;
    if (format != "card") {
      auto card = catalogue.get(p.words[1]);
      if (!card) return cli_report(card.error());
      if (format == "isaac") {
        auto files = card_isaac(*card);
        doc = files ? interop::tar_archive(*files) : Result<std::string>(tl::unexpected(files.error()));
      } else {
        doc = format == "mcap"
                  ? card_mcap(
                        **store, *card,
                        scene_people == "auto" ? std::nullopt : std::optional<bool>(scene_people == "true"))
              : format == "arena" ? card_arena(*card)
                                  : card_gazebo_actors(**store, *card);
      }
    } else {
      doc = catalogue.export_card(p.words[1]);
    }
    if (!doc) return cli_report(doc.error());
    if (auto out = p.opt("-o")) {
      if (auto s = cli_write_file(*out, *doc); !s) return cli_report(s.error());
    } else {
      std::cout << *doc;
    }
    return 0;
  }
  if (verb == "import") {
    auto text = cli_read_file(p.words[1]);
    if (!text) return cli_report(text.error());
    // The operator's own import keeps the author written in the file (the API does not).
    auto card = cards::parse_export_document(*text, catalogue.limits());
    if (!card) return cli_report(card.error());
    auto outcome = catalogue.import_card(*card);
    if (!outcome) return cli_report(outcome.error());
    std::cout << Json{{"id", outcome->card.id},
                      {"content_hash", outcome->card.content_hash},
                      {"created", outcome->created}}
                     .dump()
              << "\n";
    return 0;
  }
  std::cerr << "socsim: unknown card command '" << verb << "'\n" << kCardUsage;
  return 2;
}

int migrate_command(const std::vector<std::string>& args) {
  auto store = store::Store::open(cli_db_path(parse_cli(args)));
  if (!store) return cli_report(store.error());
  const auto& r = (*store)->migration_report();
  std::cout << Json{{"db", (*store)->path()},
                    {"from_version", r.from_version},
                    {"to_version", r.to_version},
                    {"applied", r.applied}}
                   .dump()
            << "\n";
  return 0;
}

int version_command(const std::vector<std::string>&) {
  std::cout << "socsim " << build::kVersion << " (" << build::kGitSha << ", " << build::kFlavor << ", "
            << build::kCompiler << ")\n";
  return 0;
}

}  // namespace

SOCSIM_COMMAND("card", kCardUsage, card_command);
SOCSIM_COMMAND("migrate", "  migrate               apply pending migrations and print the schema version\n",
               migrate_command);
SOCSIM_COMMAND("version", "  version               print version and build\n", version_command);

std::optional<std::string> CliArgs::opt(const std::string& key) const {
  auto it = options.find(key);
  if (it == options.end()) return std::nullopt;
  return it->second;
}

CliArgs parse_cli(const std::vector<std::string>& args) {
  CliArgs p;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if ((a.rfind("--", 0) == 0 || a == "-o") && a.size() > 1) {
      if (auto eq = a.find('='); eq != std::string::npos) {
        p.options[a.substr(0, eq)] = a.substr(eq + 1);
      } else if (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) {
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

std::string cli_db_path(const CliArgs& a) {
  if (auto db = a.opt("--db")) return *db;
  if (const char* env = std::getenv("SOCSIM_DB"); env && *env) return env;
  return "./var/socsim.db";
}

int cli_report(const Error& e) {
  std::cerr << "socsim: " << e.message() << "\n";
  return e.status() >= 500 ? 1 : 2;
}

Result<std::string> cli_read_file(const std::string& path) {
  std::ostringstream bytes;
  if (path == "-") {
    bytes << std::cin.rdbuf();
    return bytes.str();
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kNotFound, "cannot read '" + path + "'");
  bytes << in.rdbuf();
  return bytes.str();
}

Status cli_write_file(const std::string& path, const std::string& bytes) {
  const std::filesystem::path file(path);
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  std::ofstream out(file, std::ios::binary);
  out << bytes;
  out.close();
  if (!out) return fail(ErrorCode::kInternal, "cannot write '" + path + "'");
  return {};
}

int run_cli(const std::vector<std::string>& args) {
  auto usage = [] {
    std::string u = "usage: socsim <command> [options]\n\ncommands:\n";
    for (const auto& [name, info] : commands()) u += info.usage;
    u += "\nCommands that read the catalogue take --db FILE (default ./var/socsim.db, or $SOCSIM_DB).\n";
    return u;
  };
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << usage();
    return args.empty() ? 2 : 0;
  }
  std::string cmd = args[0];
  if (cmd == "--version") cmd = "version";
  // Two-word commands ("scenario generate") are registered whole, so that several files can add
  // subcommands of one noun; they win over a one-word command of the same noun.
  if (args.size() >= 2) {
    if (auto two = commands().find(cmd + " " + args[1]); two != commands().end())
      return two->second.run(std::vector<std::string>(args.begin() + 2, args.end()));
  }
  auto it = commands().find(cmd);
  if (it == commands().end()) {
    bool noun = false;
    for (const auto& [name, info] : commands()) noun = noun || name.rfind(cmd + " ", 0) == 0;
    std::cerr << "socsim: unknown " << (noun ? "subcommand of '" + cmd + "'" : "command '" + cmd + "'")
              << "\n"
              << usage();
    return 2;
  }
  return it->second.run(std::vector<std::string>(args.begin() + 1, args.end()));
}

}  // namespace socsim::server
