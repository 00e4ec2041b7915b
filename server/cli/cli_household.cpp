// `socsim persona list|show|generate` and `socsim household generate|objects|export`: residents
// and dynamic household scenes from the shell. A SCENE is a household document written with -o,
// or the id of a stored household.
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/household/household_document.hpp"
#include "core/household/llm_generators.hpp"
#include "core/household/persona_generator.hpp"
#include "core/household/procthor.hpp"
#include "core/llm/llm_config.hpp"
#include "server/cli/cli.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

namespace hh = socsim::household;

constexpr const char* kPersonaUsage =
    "  persona list                                   built-in and stored personas (id, age, occupation)\n"
    "  persona show ID                                one persona as JSON\n"
    "  persona generate [--count N] [--seed S] [--min-age A] [--max-age B] [--occupation X] [--role R] "
    "[--gender G] [--store]\n"
    "                                                 new personas (offline), printed as JSON; --store keeps "
    "them\n";

constexpr const char* kHouseholdUsage =
    "  household generate --rooms N | --house procthor.json  [--residents K | --personas a,b] [--days D] "
    "[--seed S]\n"
    "                     [--start-weekday W] [--generator offline|llm] [-o scene.json] [--store]\n"
    "                                                 a dynamic household scene; -o writes its document\n"
    "  household objects SCENE --t T                  where every object is T seconds after 00:00 of the "
    "first day\n"
    "  household export SCENE --format procthor [--t T] [-o house.json]\n"
    "                                                 the house as ProcTHOR JSON (objects placed as at T)\n";

// Prints the error with every field it names; 2 for the caller's mistakes, 1 for ours.
int report(const Error& e) {
  return cli_report(e);
}

std::optional<std::int64_t> integer_option(const CliArgs& a, const std::string& key, bool& bad) {
  auto v = a.opt(key);
  if (!v) return std::nullopt;
  try {
    std::size_t used = 0;
    const auto n = std::stoll(*v, &used);
    if (used == v->size()) return n;
  } catch (const std::exception&) {
  }
  std::cerr << "socsim: " << key << " must be an integer\n";
  bad = true;
  return std::nullopt;
}

Result<Json> read_json_file(const std::string& path) {
  auto text = cli_read_file(path);
  if (!text) return tl::unexpected(text.error());
  auto j = parse_json_untrusted(*text);
  if (!j) {
    auto e = j.error();
    e.detail = path + ": " + e.detail;
    return tl::unexpected(e);
  }
  return j;
}

int write_or_print(const CliArgs& a, const Json& j) {
  if (auto out = a.opt("-o")) {
    if (auto s = cli_write_file(*out, j.dump(2) + "\n"); !s) return cli_report(s.error());
    return 0;
  }
  std::cout << j.dump(2) << "\n";
  return 0;
}

int persona_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  if (a.words.empty()) {
    std::cerr << "usage:\n" << kPersonaUsage;
    return 2;
  }
  auto store = store::Store::open(cli_db_path(a));
  if (!store) return report(store.error());
  auto all = hh::list_stored_personas(**store, true);
  if (!all) return report(all.error());
  const std::string& verb = a.words[0];
  if (verb == "list") {
    for (const auto& p : *all) {
      std::string occ = p.occupation.substr(0, 70);
      std::cout << hh::persona_id(p) << "\t" << p.age << "\t" << p.gender << "\t" << occ
                << (p.occupation.size() > 70 ? "…" : "") << "\n";
    }
    return 0;
  }
  if (verb == "show") {
    if (a.words.size() != 2) {
      std::cerr << "usage:\n" << kPersonaUsage;
      return 2;
    }
    for (const auto& p : *all)
      if (hh::persona_id(p) == a.words[1]) {
        Json j = hh::to_json(p);
        j["id"] = hh::persona_id(p);
        std::cout << j.dump(2) << "\n";
        return 0;
      }
    return report(Error(ErrorCode::kNotFound, "no persona '" + a.words[1] + "'"));
  }
  if (verb == "generate") {
    bool bad = false;
    Json body = Json::object(), constraints = Json::object();
    if (auto v = integer_option(a, "--count", bad)) body["count"] = *v;
    if (auto v = integer_option(a, "--seed", bad)) body["seed"] = *v;
    if (auto v = integer_option(a, "--min-age", bad)) constraints["min_age"] = *v;
    if (auto v = integer_option(a, "--max-age", bad)) constraints["max_age"] = *v;
    if (bad) return 2;
    if (auto v = a.opt("--occupation")) constraints["occupation"] = *v;
    if (auto v = a.opt("--role")) constraints["household_role"] = *v;
    if (auto v = a.opt("--gender")) constraints["gender"] = *v;
    if (!constraints.empty()) body["constraints"] = constraints;
    auto request = hh::persona_request_from_json(body);
    if (!request) return report(request.error());
    auto knowledge = hh::load_household_knowledge(**store);
    if (!knowledge) return report(knowledge.error());
    auto personas = hh::generate_personas_offline(*request, *all, knowledge->persona_parts);
    if (!personas) return report(personas.error());
    Json out = Json::array();
    for (const auto& p : *personas) {
      if (a.flag("--store"))
        if (auto s = hh::store_persona(**store, p); !s) return report(s.error());
      Json j = hh::to_json(p);
      j["id"] = hh::persona_id(p);
      out.push_back(j);
    }
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cerr << "socsim: unknown persona command '" << verb << "'\nusage:\n" << kPersonaUsage;
  return 2;
}

// A household document from a file written with -o, or a stored household by id.
Result<hh::HouseholdDocument> load_scene(store::Store& store, const std::string& scene,
                                         const hh::HouseholdKnowledge& k) {
  Result<Json> json =
      std::filesystem::exists(scene) ? read_json_file(scene) : hh::load_household_document(store, scene);
  if (!json) return tl::unexpected(json.error());
  return hh::household_document_from_json(*json, k);
}

int household_command(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  if (a.words.empty()) {
    std::cerr << "usage:\n" << kHouseholdUsage;
    return 2;
  }
  auto store = store::Store::open(cli_db_path(a));
  if (!store) return report(store.error());
  auto knowledge = hh::load_household_knowledge(**store);
  if (!knowledge) return report(knowledge.error());
  const std::string& verb = a.words[0];

  if (verb == "generate") {
    bool bad = false;
    Json body = Json::object();
    if (auto v = integer_option(a, "--rooms", bad)) body["rooms"] = *v;
    if (auto v = integer_option(a, "--residents", bad)) body["residents"] = *v;
    if (auto v = integer_option(a, "--days", bad)) body["days"] = *v;
    if (auto v = integer_option(a, "--seed", bad)) body["seed"] = *v;
    if (bad) return 2;
    if (auto v = a.opt("--personas")) {
      Json ids = Json::array();
      std::stringstream ss(*v);
      for (std::string id; std::getline(ss, id, ',');)
        if (!id.empty()) ids.push_back(id);
      body["residents"] = ids;
    }
    if (auto v = a.opt("--start-weekday")) body["start_weekday"] = *v;
    if (auto v = a.opt("--generator")) body["generator"] = *v;
    if (auto v = a.opt("--house")) {
      auto house = read_json_file(*v);
      if (!house) return report(house.error());
      body["house"] = *house;
    }
    auto request = hh::household_request_from_json(body);
    if (!request) return report(request.error());
    auto personas = hh::list_stored_personas(**store, true);
    if (!personas) return report(personas.error());
    std::unique_ptr<llm::LlmClient> client;
    std::unique_ptr<llm::StructuredGenerator> gen;
    std::unique_ptr<hh::LlmDayPlanner> planner;
    std::unique_ptr<hh::LlmDecomposer> decomposer;
    std::unique_ptr<hh::LlmActivityDatabaseGenerator> dbgen;
    hh::ProfileGenerators gens;
    if (request->generator == "llm") {
      auto config = llm::LlmConfig::from_environment();
      if (!config) return report(config.error());
      auto c = llm::LlmClient::create(*config);
      if (!c) return report(c.error());
      client = std::move(*c);
      gen = std::make_unique<llm::StructuredGenerator>(*client, store->get());
      hh::LlmSettings settings;
      settings.generator = gen.get();
      settings.model = request->model;
      planner = std::make_unique<hh::LlmDayPlanner>(*knowledge, settings);
      decomposer = std::make_unique<hh::LlmDecomposer>(*knowledge, settings);
      dbgen = std::make_unique<hh::LlmActivityDatabaseGenerator>(*knowledge, settings);
      gens = {planner.get(), decomposer.get(), dbgen.get()};
    }
    const std::string id = hh::household_id(*request, "cli");
    auto doc = hh::generate_household(*request, *knowledge, *personas, gens, {}, id);
    if (!doc) return report(doc.error());
    auto scene = hh::instantiate_household(*doc, *knowledge);
    if (!scene) return report(scene.error());
    Json summary = hh::household_summary_json(*doc, *scene);
    summary.erase("schedules");
    if (a.flag("--store"))
      if (auto s = hh::store_household(**store, *doc, summary, "cli", std::nullopt); !s)
        return report(s.error());
    if (auto out = a.opt("-o")) {
      if (auto s = cli_write_file(*out, hh::to_json(*doc).dump() + "\n"); !s) return cli_report(s.error());
    }
    std::cout << summary.dump(2) << "\n";
    return 0;
  }

  if (verb == "objects" || verb == "export") {
    if (a.words.size() != 2) {
      std::cerr << "usage:\n" << kHouseholdUsage;
      return 2;
    }
    auto doc = load_scene(**store, a.words[1], *knowledge);
    if (!doc) return report(doc.error());
    auto scene = hh::instantiate_household(*doc, *knowledge);
    if (!scene) return report(scene.error());
    bool bad = false;
    const auto t = integer_option(a, "--t", bad);
    if (bad) return 2;
    if (t && (*t < 0 || *t > scene->end()))
      return report(Error(ErrorCode::kValidation,
                          "--t must be between 0 and " + std::to_string(scene->end()) + " seconds"));
    if (verb == "objects") {
      if (!t) {
        std::cerr << "socsim: household objects needs --t SECONDS\n";
        return 2;
      }
      return write_or_print(a, hh::objects_at_json(*scene, *t));
    }
    if (a.opt("--format").value_or("procthor") != "procthor") {
      std::cerr << "socsim: --format must be procthor\n";
      return 2;
    }
    if (t) {
      const auto placement = scene->placement_at(*t);
      return write_or_print(a, hh::export_procthor(scene->house(), &placement));
    }
    return write_or_print(a, hh::export_procthor(scene->house()));
  }
  std::cerr << "socsim: unknown household command '" << verb << "'\nusage:\n" << kHouseholdUsage;
  return 2;
}

}  // namespace

SOCSIM_COMMAND("persona", kPersonaUsage, persona_command);
SOCSIM_COMMAND("household", kHouseholdUsage, household_command);

}  // namespace socsim::server
