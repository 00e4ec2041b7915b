// The prompt constructions of issue 16 carried through to the scenario program (the intent-level
// tests are in scenario_intent_test.cpp): each prompt becomes an offline program in the hospital
// plan, and the people in it are counted per role — numbers, products, ranges, exceptions,
// negation, coordination, relative clauses — and the groups of clauses with different places
// start in the places the prompt named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/scenario/program_offline.hpp"
#include "tests/core/scenario/offline_worlds.hpp"
#include "tests/core/scenario/prompt_facts.hpp"

namespace socsim::scenario {
namespace {

class Constructions : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { worlds_ = new testing::OfflineWorlds(); }
  static void TearDownTestSuite() {
    delete worlds_;
    worlds_ = nullptr;
  }
  static GeneratedProgram generate(const std::string& prompt) {
    auto g = generate_program_offline(worlds_->plan("hospital"), worlds_->kb(),
                                      ProgramRequest{prompt, 5, std::nullopt, 60}, ScenarioLimits{});
    EXPECT_TRUE(g.has_value()) << prompt << ": " << g.error().message();
    return g ? std::move(*g) : GeneratedProgram{};
  }
  static std::map<std::string, double> people(const std::string& prompt) {
    return facts::program_people(generate(prompt).program);
  }
  static inline testing::OfflineWorlds* worlds_ = nullptr;
};

using Roles = std::map<std::string, double>;

TEST_F(Constructions, NumbersInDigitsAndWords) {
  EXPECT_EQ(people("Twenty-five patients wait in the lobby."), (Roles{{"patient", 25}}));
  EXPECT_EQ(people("12 visitors walk to the corridor."), (Roles{{"visitor", 12}}));
}

TEST_F(Constructions, Products) {
  EXPECT_EQ(people("Two classes of 15 pupils each walk down the corridor."), (Roles{{"pupil", 30}}));
}

TEST_F(Constructions, RangesStayInRange) {
  const auto p = people("Between 10 and 14 visitors queue at the reception.");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_GE(p.at("visitor"), 10);
  EXPECT_LE(p.at("visitor"), 14);
}

TEST_F(Constructions, ExceptionsLeaveOnlyWhoIsNamed) {
  EXPECT_EQ(people("The lobby is empty except for one security guard."), (Roles{{"security_guard", 1}}));
}

TEST_F(Constructions, NegationDropsTheNegatedGroup) {
  EXPECT_EQ(people("Nobody is waiting at the reception; a single nurse walks along the corridor."),
            (Roles{{"nurse", 1}}));
  EXPECT_EQ(people("Eight patients wait in the lobby, but no visitors."), (Roles{{"patient", 8}}));
}

TEST_F(Constructions, CoordinationKeepsEachCount) {
  EXPECT_EQ(people("Two nurses and three doctors chat near the nurse station."),
            (Roles{{"doctor", 3}, {"nurse", 2}}));
}

TEST_F(Constructions, RelativeClausesKeepTheirGroups) {
  EXPECT_EQ(people("The nurse who works at the reception greets two visitors who arrived late."),
            (Roles{{"nurse", 1}, {"visitor", 2}}));
  EXPECT_EQ(people("Patients who are waiting for their results sit in the lobby; there are nine of them."),
            (Roles{{"patient", 9}}));
}

TEST_F(Constructions, SeveralClausesWithDifferentPlaces) {
  const auto g = generate("Two nurses chat at the nurse station while six patients wait in the lobby.");
  EXPECT_EQ(facts::program_people(g.program), (Roles{{"nurse", 2}, {"patient", 6}}));
  const world::World& w = worlds_->plan("hospital");
  auto zone_of = [&](const std::string& region) {
    if (auto z = w.find_zone(region)) return w.zone(*z).type;
    for (const auto& r : w.rois())
      if (r.name == region) return std::string("roi:") + r.kind;
    return std::string("?");
  };
  for (const auto& a : g.program["agents"]) {
    const std::string spawn = a.value("spawn", std::string());
    if (a["role"] == "nurse") {
      EXPECT_THAT(spawn, ::testing::HasSubstr("nurse_station")) << zone_of(spawn);
    }
    if (a["role"] == "patient") {
      EXPECT_THAT(spawn, ::testing::HasSubstr("lobby")) << zone_of(spawn);
    }
  }
}

}  // namespace
}  // namespace socsim::scenario
