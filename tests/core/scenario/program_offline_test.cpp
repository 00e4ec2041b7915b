// Offline scenario programs: every Table II category from a natural prompt in hospital, office,
// residential and warehouse floor plans gives a program that passes check_program; the same
// prompt uses each world's own places; counts in the prompt are honoured; the same seed gives the
// same JSON and 20 seeds give valid, not all identical programs; bounds and bad requests.
#include "core/scenario/program_offline.hpp"

#include <cstdlib>
#include <iostream>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/scenario/program_check.hpp"
#include "tests/core/scenario/offline_worlds.hpp"

namespace socsim::scenario {
namespace {

using ::testing::HasSubstr;

class ProgramOffline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { worlds_ = new testing::OfflineWorlds(); }
  static void TearDownTestSuite() {
    delete worlds_;
    worlds_ = nullptr;
  }
  static GeneratedProgram generate(const world::World& w, const std::string& prompt, std::uint64_t seed = 1,
                                   std::optional<std::size_t> agents = std::nullopt) {
    ProgramRequest r;
    r.prompt = prompt;
    r.seed = seed;
    r.agents = agents;
    auto g = generate_program_offline(w, worlds_->kb(), r, ScenarioLimits{});
    EXPECT_TRUE(g.has_value()) << prompt << " in " << w.name() << ": " << (g ? "" : g.error().message());
    if (!g) {
      GeneratedProgram empty;
      empty.program = Json::object({{"agents", Json::array()}, {"ambient_groups", Json::array()}});
      empty.provenance = Json::object();
      return empty;
    }
    if (std::getenv("SOCSIM_DUMP_PROGRAMS") != nullptr)
      std::cerr << "=== " << prompt << " / " << w.name() << "\n"
                << g->program.dump(1) << "\n"
                << g->provenance.dump(1) << "\n";
    return std::move(*g);
  }
  static testing::OfflineWorlds* worlds_;
};
testing::OfflineWorlds* ProgramOffline::worlds_ = nullptr;

std::size_t count_role(const Json& program, const std::string& role) {
  std::size_t n = 0;
  for (const Json& a : program["agents"])
    if (a.value("role", "adult") == role) n += a.value("count", 1u);
  for (const Json& g : program["ambient_groups"])
    if (g.value("role", "adult") == role) n += g["size"].get<std::size_t>();
  return n;
}

std::set<std::string> places_of(const Json& program) {
  std::set<std::string> out;
  for (const Json& a : program["agents"])
    if (a.contains("spawn")) out.insert(a["spawn"].get<std::string>());
  for (const auto& [name, t] : program["behavior_trees"].items()) {
    const std::string xml = t["xml"].get<std::string>();
    for (const char* port :
         {"queue=\"", "counter=\"", "point=\"", "region=\"", "location=\"", "seat=\"", "exit=\""}) {
      for (std::size_t at = xml.find(port); at != std::string::npos; at = xml.find(port, at + 1)) {
        const std::size_t b = at + std::string(port).size();
        out.insert(xml.substr(b, xml.find('"', b) - b));
      }
    }
  }
  return out;
}

TEST_F(ProgramOffline, EveryCategoryInEveryDomainPassesTheCheck) {
  const std::vector<std::pair<std::string, std::string>> prompts = {
      {"emergency", "Fire alarm! Everyone evacuates the building"},
      {"queuing", "People queue at the counter"},
      {"social_party", "A birthday party with friends mingling"},
      {"coffee_break", "Colleagues take a coffee break and chat"},
      {"reception", "Visitors check in at the front desk"},
      {"bottleneck", "A crowd squeezes through a narrow door"},
      {"normal_operation", "Normal operation, everyday traffic"},
  };
  for (const char* domain : {"hospital", "office", "residential", "warehouse"}) {
    const world::World& w = worlds_->plan(domain);
    for (const auto& [category, prompt] : prompts) {
      const GeneratedProgram g = generate(w, prompt);
      ASSERT_FALSE(g.categories.empty()) << prompt;
      EXPECT_EQ(g.categories.front(), category) << prompt << " in " << domain;
      EXPECT_TRUE(check_program(g.program, w, ScenarioLimits{}).has_value()) << prompt << " in " << domain;
      EXPECT_GT(g.program["agents"].size() + g.program["ambient_groups"].size(), 0u)
          << prompt << " in " << domain;
    }
  }
}

// Fig. 6: the same prompt adapts to each world — the hospital queues at its lobby's reception
// counter, the office at its reception counter; no place of one world appears in the other's program.
TEST_F(ProgramOffline, SamePromptUsesEachWorldsOwnPlaces) {
  const std::string prompt = "Patients queue at the reception while two nurses chat near the corridor";
  const world::World& hospital = worlds_->plan("hospital");
  const world::World& office = worlds_->plan("office");
  const GeneratedProgram h = generate(hospital, prompt);
  const GeneratedProgram o = generate(office, prompt);
  ASSERT_TRUE(h.program.is_object() && o.program.is_object());
  EXPECT_THAT(h.categories, ::testing::ElementsAre("queuing", "coffee_break"));
  const auto hp = places_of(h.program);
  const auto op = places_of(o.program);
  EXPECT_TRUE(hp.count("lobby_reception_counter_queue")) << ::testing::PrintToString(hp);
  EXPECT_TRUE(op.count("reception_reception_counter_queue")) << ::testing::PrintToString(op);
  for (const std::string& name : hp)
    if (!name.empty()) {
      const bool in_hospital = hospital.find_roi(name) || hospital.find_entity(name) ||
                               hospital.find_zone(name) || hospital.find_door(name);
      EXPECT_TRUE(in_hospital) << name;
    }
  for (const std::string& name : op)
    if (!name.empty()) {
      const bool in_office = office.find_roi(name) || office.find_entity(name) || office.find_zone(name) ||
                             office.find_door(name);
      EXPECT_TRUE(in_office) << name;
    }
  EXPECT_NE(hp, op);
}

TEST_F(ProgramOffline, CountsFromThePromptAreHonoured) {
  const world::World& w = worlds_->plan("hospital");
  const GeneratedProgram a = generate(w, "Two nurses and about thirty visitors queue at the reception desk");
  EXPECT_EQ(count_role(a.program, "nurse"), 2u);
  EXPECT_EQ(count_role(a.program, "visitor"), 30u);
  const GeneratedProgram b = generate(w, "A dozen staff have a coffee break, 5 doctors chat in the corridor");
  EXPECT_EQ(count_role(b.program, "staff"), 12u);
  EXPECT_EQ(count_role(b.program, "doctor"), 5u);
  const GeneratedProgram c = generate(w, "Evacuation drill with a crowd of 120 after 10 seconds");
  std::size_t total = 0;
  for (const Json& x : c.program["agents"]) total += x.value("count", 1u);
  for (const Json& x : c.program["ambient_groups"]) total += x["size"].get<std::size_t>();
  EXPECT_EQ(total, 120u) << c.provenance["notes"].dump();
  EXPECT_EQ(c.provenance["timing"]["alarm_s"], 10.0);
}

TEST_F(ProgramOffline, SameSeedSameJsonAndTwentySeedsAreValidAndVaried) {
  const world::World& w = worlds_->plan("office");
  const std::string prompt = "Visitors queue at the reception while colleagues have a coffee break";
  const GeneratedProgram a = generate(w, prompt, 42);
  const GeneratedProgram b = generate(w, prompt, 42);
  EXPECT_EQ(canonical_json(a.program), canonical_json(b.program));
  EXPECT_EQ(canonical_json(a.provenance), canonical_json(b.provenance));
  std::set<std::string> distinct;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const GeneratedProgram g = generate(w, prompt, seed);
    EXPECT_TRUE(check_program(g.program, w, ScenarioLimits{}).has_value()) << "seed " << seed;
    distinct.insert(canonical_json(g.program));
  }
  EXPECT_GE(distinct.size(), 10u);
}

TEST_F(ProgramOffline, BadRequestsNameTheField) {
  const world::World& w = worlds_->plan("office");
  ProgramRequest r;
  r.prompt = "   ";
  auto e = generate_program_offline(w, worlds_->kb(), r, ScenarioLimits{});
  ASSERT_FALSE(e.has_value());
  EXPECT_EQ(e.error().code, ErrorCode::kBadRequest);
  EXPECT_EQ(e.error().errors.at(0).pointer, "/prompt");
  r.prompt = "a party";
  r.duration_s = 4000;
  r.agents = 0;
  e = generate_program_offline(w, worlds_->kb(), r, ScenarioLimits{});
  ASSERT_FALSE(e.has_value());
  EXPECT_EQ(e.error().code, ErrorCode::kValidation);
  ASSERT_EQ(e.error().errors.size(), 2u);
  EXPECT_EQ(e.error().errors[0].pointer, "/duration_s");
  EXPECT_EQ(e.error().errors[1].pointer, "/agents");
}

TEST_F(ProgramOffline, TotalsStayWithinTheLimitsAndTheRequestedBound) {
  const world::World& w = worlds_->plan("warehouse");
  ScenarioLimits limits;
  limits.max_spotlight = 10;
  limits.max_agents = 150;
  ProgramRequest r;
  r.prompt = "Fire alarm: a crowd of 400 workers evacuates";
  auto g = generate_program_offline(w, worlds_->kb(), r, limits);
  ASSERT_TRUE(g.has_value()) << g.error().message();
  std::size_t spotlight = 0, total = 0;
  for (const Json& a : g->program["agents"]) spotlight += a.value("count", 1u);
  total = spotlight;
  for (const Json& a : g->program["ambient_groups"]) total += a["size"].get<std::size_t>();
  EXPECT_LE(spotlight, 10u);
  EXPECT_LE(total, 150u);
  EXPECT_THAT(g->provenance["notes"].dump(), HasSubstr("scaled down"));
  r.agents = 20;
  g = generate_program_offline(w, worlds_->kb(), r, limits);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->provenance["agents_total"], 20u);
}

TEST_F(ProgramOffline, MissingPlacesFallBackAndSaySo) {
  // An office has no living room: the party moves to its largest room, with a note, and every
  // name in the program is one of the office's.
  const world::World& office = worlds_->plan("office");
  const GeneratedProgram party = generate(office, "A house party in the living room");
  EXPECT_THAT(party.provenance["notes"].dump(), HasSubstr("no living room"));
  for (const std::string& name : places_of(party.program))
    EXPECT_TRUE(office.find_roi(name) || office.find_entity(name) || office.find_zone(name) ||
                office.find_door(name))
        << name;
  // No elevator anywhere: the mention stays unresolved in the provenance.
  const GeneratedProgram lift = generate(office, "Visitors queue near the elevator");
  bool unresolved = false;
  for (const Json& m : lift.provenance["place_mentions"])
    unresolved = unresolved || (m["phrase"] == "elevator" && m["resolved"].is_null());
  EXPECT_TRUE(unresolved) << lift.provenance["place_mentions"].dump();
  // A residential plan has no queue lane: people wait by a POI, with a note.
  const GeneratedProgram queue = generate(worlds_->plan("residential"), "People queue");
  EXPECT_THAT(queue.provenance["notes"].dump(), HasSubstr("no queue lane"));
}

TEST_F(ProgramOffline, AnAlarmReachesEveryTreeAndProvenanceNamesTheKnowledge) {
  const world::World& w = worlds_->plan("hospital");
  const GeneratedProgram g =
      generate(w, "Patients queue at the reception when the fire alarm sounds after 15 seconds");
  EXPECT_THAT(g.categories, ::testing::Contains("emergency"));
  for (const auto& [name, t] : g.program["behavior_trees"].items()) {
    const std::string xml = t["xml"].get<std::string>();
    EXPECT_THAT(xml, HasSubstr("Evacuate")) << name;
    EXPECT_THAT(xml, HasSubstr("seconds=\"15\"")) << name;
  }
  const Json& k = g.provenance["knowledge"];
  ASSERT_FALSE(k["queries"].empty());
  EXPECT_FALSE(k["queries"][0]["hits"].empty());
  bool join_queue = false;
  for (const Json& n : k["nodes_used"]) join_queue = join_queue || n["name"] == "JoinQueue";
  EXPECT_TRUE(join_queue);
}

}  // namespace
}  // namespace socsim::scenario
