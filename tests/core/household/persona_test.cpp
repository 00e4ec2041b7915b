// Personas: posted JSON is validated field by field (errors carry JSON pointers), and the traits
// the offline generators rely on are read correctly from the free text.
#include "core/household/persona.hpp"

#include <gtest/gtest.h>

namespace socsim::household {
namespace {

Json good() {
  return Json{{"name", "Ada Quinn"},
              {"age", 42},
              {"gender", "female"},
              {"routine", "Ada goes to bed at 11 pm and gets up at 6:45 am."},
              {"personality", {"curious", "tidy"}},
              {"occupation", "Ada is a pharmacist at the city hospital."},
              {"thoughts", "She is planning a garden."},
              {"lifestyle", "She swims on Saturdays."}};
}

std::vector<std::string> pointers(const Error& e) {
  std::vector<std::string> out;
  for (const auto& f : e.errors) out.push_back(f.pointer);
  return out;
}

TEST(Persona, ReadsAValidPersonaAndWritesItBack) {
  auto p = persona_from_json(good());
  ASSERT_TRUE(p) << p.error().message();
  EXPECT_EQ(p->name, "Ada Quinn");
  EXPECT_EQ(p->personality.size(), 2u);
  auto again = persona_from_json(to_json(*p));
  ASSERT_TRUE(again);
  EXPECT_EQ(*again, *p);
  EXPECT_EQ(persona_id(*p), "ada-quinn");
}

TEST(Persona, BadFieldsAreNamedByJsonPointer) {
  Json j = good();
  j["age"] = -3;
  j["personality"] = {"kind", 7};
  j.erase("thoughts");
  j["hobby"] = "chess";
  auto p = persona_from_json(j, "/personas/2");
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error().code, ErrorCode::kValidation);
  const auto ptrs = pointers(p.error());
  for (const char* want :
       {"/personas/2/age", "/personas/2/personality/1", "/personas/2/thoughts", "/personas/2/hobby"})
    EXPECT_NE(std::find(ptrs.begin(), ptrs.end(), want), ptrs.end()) << want;
}

TEST(Persona, RejectsNonObjectsEmptyTraitListsAndNamesWithoutLetters) {
  EXPECT_FALSE(persona_from_json(Json::array()));
  Json j = good();
  j["personality"] = Json::array();
  j["name"] = "1234";
  auto p = persona_from_json(j);
  ASSERT_FALSE(p);
  const auto ptrs = pointers(p.error());
  EXPECT_NE(std::find(ptrs.begin(), ptrs.end(), "/personality"), ptrs.end());
  EXPECT_NE(std::find(ptrs.begin(), ptrs.end(), "/name"), ptrs.end());
}

TEST(PersonaTraits, ReadsSleepTimesAndWorkPatternFromText) {
  auto p = *persona_from_json(good());
  auto t = infer_traits(p);
  EXPECT_EQ(t.work, WorkPattern::kCommute);
  EXPECT_EQ(t.work_night.bed, 23 * 60);
  EXPECT_EQ(t.work_night.wake, 6 * 60 + 45);
  EXPECT_GT(t.tidiness, 0.5);

  p.routine = "She sleeps from 8 am to 3 pm after her night shift; on free days she goes to bed at midnight.";
  p.occupation = "She is a nurse on the night shift from 7 pm to 7 am, Monday to Thursday.";
  t = infer_traits(p);
  EXPECT_EQ(t.work, WorkPattern::kNightShift);
  EXPECT_EQ(t.work_night.bed, 8 * 60);
  EXPECT_EQ(t.work_night.wake, 15 * 60);
  EXPECT_EQ(t.free_night.bed, 1440);
  EXPECT_EQ(t.work_start, 19 * 60);
  EXPECT_EQ(t.work_end, 31 * 60);
  EXPECT_TRUE(t.work_days[0] && t.work_days[3]);
  EXPECT_FALSE(t.work_days[4]);

  p.routine = "Goes to bed around 1:30 am, sleeping until 10 am; on weekends he may stay up until 2 am.";
  p.occupation = "He works remotely as a translator.";
  t = infer_traits(p);
  EXPECT_EQ(t.work, WorkPattern::kRemote);
  EXPECT_EQ(t.work_night.bed, 1440 + 90);
  EXPECT_EQ(t.work_night.wake, 600);
  EXPECT_EQ(t.free_night.bed, 1440 + 120);
}

TEST(PersonaTraits, ChildrenGoToSchoolAndMentionsMatchWholeWords) {
  Persona kid{"Lou",           8,
              "male",          "Lou goes to bed at 8 pm and wakes at 7 am.",
              {"messy"},       "Lou is a third grader.",
              "Wants a bike.", "Plays football after school."};
  const auto t = infer_traits(kid);
  EXPECT_EQ(t.work, WorkPattern::kSchool);
  EXPECT_TRUE(t.child);
  EXPECT_TRUE(mentions(t, "male"));
  EXPECT_FALSE(mentions(t, "female"));
  EXPECT_TRUE(mentions(t, "football"));
  EXPECT_FALSE(mentions(t, "foot"));
  EXPECT_LT(t.tidiness, 0.5);
}

}  // namespace
}  // namespace socsim::household
