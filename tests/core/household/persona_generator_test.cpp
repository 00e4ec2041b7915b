// Offline persona generation: valid, deterministic, within the constraints, readable by the
// schedule generator (no inconsistencies), and never a near-duplicate of the built-in 50 or of
// each other.
#include "core/household/persona_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/household/schedule.hpp"
#include "tests/core/household/household_fixture.hpp"

namespace socsim::household {
namespace {

using testing::knowledge;

std::vector<Persona> builtin() {
  std::vector<Persona> out;
  for (const auto& p : knowledge().personas) out.push_back(p);
  return out;
}

TEST(PersonaGenerator, GeneratesValidDistinctPersonasThatScheduleConsistently) {
  const auto existing = builtin();
  ASSERT_EQ(existing.size(), 50u);
  PersonaRequest r;
  r.count = 60;
  r.seed = 11;
  auto personas = generate_personas_offline(r, existing, knowledge().persona_parts);
  ASSERT_TRUE(personas) << personas.error().message();
  ASSERT_EQ(personas->size(), 60u);
  std::set<std::string> ids, occupations_seen;
  double sum_similarity = 0.0;
  int pairs = 0;
  for (std::size_t i = 0; i < personas->size(); ++i) {
    const Persona& p = (*personas)[i];
    ASSERT_TRUE(persona_from_json(to_json(p))) << p.name;
    EXPECT_TRUE(ids.insert(persona_id(p)).second) << p.name;
    for (const auto& b : existing) EXPECT_FALSE(near_duplicate(p, b)) << p.name << " ~ " << b.name;
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_FALSE(near_duplicate(p, (*personas)[j])) << p.name << " ~ " << (*personas)[j].name;
      sum_similarity += persona_similarity(p, (*personas)[j]);
      ++pairs;
    }
    occupations_seen.insert(std::string(work_pattern_name(infer_traits(p).work)));
    // Every generated persona gets a consistent five-day schedule from the offline generators.
    auto vocab = ActivityVocabulary::initial(knowledge());
    auto s = generate_schedule_offline(p, knowledge(), {5, Weekday::kWednesday, 3}, vocab);
    ASSERT_TRUE(s) << p.name << ": " << s.error().message();
    const auto issues = check_schedule(*s, p, knowledge());
    EXPECT_TRUE(issues.empty()) << p.name << " (" << p.occupation
                                << "): " << (issues.empty() ? "" : issues[0].kind + " " + issues[0].detail);
  }
  EXPECT_GE(occupations_seen.size(), 8u) << "work patterns should vary";
  EXPECT_LT(sum_similarity / pairs, 0.15) << "personas share few content words on average";
}

TEST(PersonaGenerator, SameSeedSamePersonasOtherSeedOthers) {
  const auto existing = builtin();
  PersonaRequest r;
  r.count = 5;
  r.seed = 42;
  auto a = generate_personas_offline(r, existing, knowledge().persona_parts);
  auto b = generate_personas_offline(r, existing, knowledge().persona_parts);
  r.seed = 43;
  auto c = generate_personas_offline(r, existing, knowledge().persona_parts);
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(*a, *b);
  EXPECT_NE(*a, *c);
}

TEST(PersonaGenerator, HonoursAgeOccupationRoleAndGender) {
  PersonaRequest r;
  r.count = 6;
  r.seed = 5;
  r.constraints.min_age = 30;
  r.constraints.max_age = 45;
  r.constraints.occupation = "nurse";
  r.constraints.gender = "female";
  auto nurses = generate_personas_offline(r, builtin(), knowledge().persona_parts);
  ASSERT_TRUE(nurses) << nurses.error().message();
  for (const auto& p : *nurses) {
    EXPECT_GE(p.age, 30);
    EXPECT_LE(p.age, 45);
    EXPECT_EQ(p.gender, "female");
    EXPECT_NE(p.occupation.find("nurse"), std::string::npos);
    EXPECT_EQ(infer_traits(p).work, WorkPattern::kNightShift);
  }

  PersonaRequest kids;
  kids.count = 8;
  kids.seed = 9;
  kids.constraints.household_role = HouseholdRole::kChild;
  auto children = generate_personas_offline(kids, builtin(), knowledge().persona_parts);
  ASSERT_TRUE(children) << children.error().message();
  for (const auto& p : *children) {
    EXPECT_LT(p.age, 18);
    const auto w = infer_traits(p).work;
    EXPECT_TRUE(w == WorkPattern::kSchool || w == WorkPattern::kPreschool) << p.occupation;
  }

  PersonaRequest grand;
  grand.count = 4;
  grand.constraints.household_role = HouseholdRole::kGrandparent;
  auto g = generate_personas_offline(grand, builtin(), knowledge().persona_parts);
  ASSERT_TRUE(g) << g.error().message();
  for (const auto& p : *g) {
    EXPECT_GE(p.age, 55);
    EXPECT_NE(p.lifestyle.find("grand"), std::string::npos) << p.lifestyle;
  }
}

TEST(PersonaGenerator, UnknownOccupationBecomesADayJob) {
  PersonaRequest r;
  r.count = 2;
  r.constraints.occupation = "beekeeper";
  auto p = generate_personas_offline(r, builtin(), knowledge().persona_parts);
  ASSERT_TRUE(p) << p.error().message();
  for (const auto& q : *p) {
    EXPECT_NE(q.occupation.find("works as a beekeeper"), std::string::npos);
    EXPECT_EQ(infer_traits(q).work, WorkPattern::kCommute);
  }
}

TEST(PersonaGenerator, ImpossibleConstraintsAreNamed) {
  PersonaRequest r;
  r.constraints.min_age = 4;
  r.constraints.max_age = 5;
  r.constraints.occupation = "accountant";
  auto p = generate_personas_offline(r, builtin(), knowledge().persona_parts);
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error().code, ErrorCode::kValidation);
  ASSERT_FALSE(p.error().errors.empty());
  EXPECT_EQ(p.error().errors[0].pointer, "/constraints/occupation");

  auto bad = persona_request_from_json(
      Json{{"count", 0}, {"constraints", {{"household_role", "uncle"}, {"min_age", 50}, {"max_age", 20}}}});
  ASSERT_FALSE(bad);
  std::set<std::string> ptrs;
  for (const auto& f : bad.error().errors) ptrs.insert(f.pointer);
  EXPECT_TRUE(ptrs.count("/count"));
  EXPECT_TRUE(ptrs.count("/constraints/household_role"));
  EXPECT_TRUE(ptrs.count("/constraints/max_age"));
}

TEST(PersonaGenerator, NearDuplicatesAreRecognised) {
  const Persona& a = knowledge().personas[0];
  Persona copy = a;
  copy.name = "Someone Else";
  copy.age = a.age + 2;
  EXPECT_TRUE(near_duplicate(a, copy));
  Persona renamed = knowledge().personas[1];
  renamed.name = a.name;
  EXPECT_TRUE(near_duplicate(a, renamed));  // same id
  EXPECT_FALSE(near_duplicate(knowledge().personas[0], knowledge().personas[1]));
}

TEST(PersonaGenerator, PartsComeFromTheStoreAndBadRowsAreNamed) {
  const PersonaParts& parts = knowledge().persona_parts;
  EXPECT_TRUE(check_persona_parts(parts));
  const auto known = known_occupations(parts);
  EXPECT_NE(std::find(known.begin(), known.end(), "night nurse"), known.end());

  PersonaParts bad;
  const Status pattern = add_persona_part(bad, "occupation", "astronaut",
                                          Json::parse(R"({"keywords":[],"pattern":"orbit","ages":[20,60],
      "variants":[],"text":"{F} flies.","bed":[1320,1380],"wake":[360,420],"day_sleeper":false,
      "thoughts":["{F} looks up."],"habit":""})"));
  ASSERT_FALSE(pattern);
  EXPECT_EQ(pattern.error().code, ErrorCode::kStore);
  EXPECT_NE(pattern.error().detail.find("occupation 'astronaut'"), std::string::npos)
      << pattern.error().detail;
  EXPECT_FALSE(add_persona_part(bad, "hobby", "h", Json::parse(R"({"text":"rows","ages":[60,20]})")));
  EXPECT_FALSE(add_persona_part(bad, "traits", "grumpy", Json::parse(R"(["cross"])")));
  EXPECT_FALSE(add_persona_part(bad, "spaceship", "x", Json::object()));

  // Without the parts (a store that lacks the migration) generation says so instead of crashing.
  PersonaRequest r;
  auto none = generate_personas_offline(r, builtin(), PersonaParts{});
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().code, ErrorCode::kStore);
  EXPECT_NE(none.error().detail.find("migration 0026"), std::string::npos) << none.error().detail;
}

}  // namespace
}  // namespace socsim::household
