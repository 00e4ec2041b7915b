// Building-type classification of prompts and scene graphs, explained by the deciding words.
#include "core/knowledge/building_type.hpp"

#include <cctype>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::knowledge {
namespace {

using ::testing::HasSubstr;

struct Case {
  const char* prompt;
  const char* type;
  const char* deciding_word;  // must appear in the explanation
};

class KnowledgeClassifyPrompt : public ::testing::TestWithParam<Case> {};

TEST_P(KnowledgeClassifyPrompt, FindsTheTypeAndNamesTheWordsThatDecidedIt) {
  const Case& c = GetParam();
  const BuildingTypeGuess g = classify_building_type(c.prompt);
  EXPECT_EQ(g.type, c.type) << c.prompt << " → " << g.explanation;
  EXPECT_THAT(g.explanation, HasSubstr(c.deciding_word)) << c.prompt;
  EXPECT_GT(g.confidence, 0.0);
  EXPECT_LT(g.confidence, 1.0);
}

INSTANTIATE_TEST_SUITE_P(
    Prompts, KnowledgeClassifyPrompt,
    ::testing::Values(
        Case{"a quiet flat", "residential", "flat"}, Case{"the ER waiting room", "hospital", "'er'"},
        Case{"warehouse picking aisles", "warehouse", "picking"},
        Case{"lunch at the canteen", "canteen", "canteen"},
        Case{"Patients queuing at the reception desk of a hospital", "hospital", "patient"},
        Case{"nurses walking between patient rooms near the ICU", "hospital", "icu"},
        Case{"an open-plan office with two meeting rooms", "office", "office"},
        Case{"colleagues chatting by the printer before the board meeting in the conference room", "office",
             "conference room"},
        Case{"a supermarket checkout queue on Saturday", "supermarket", "supermarket"},
        Case{"shoppers browsing the shelves of a boutique", "retail", "boutique"},
        Case{"people ordering at a coffee shop counter", "restaurant", "coffee shop"},
        Case{"commuters rushing through the ticket barriers of a metro station", "train_station",
             "metro station"},
        Case{"guests checking in at the hotel reception", "hotel", "hotel"},
        Case{"students reading in the library", "library", "library"},
        Case{"visitors looking at paintings in the art gallery", "museum", "art gallery"},
        Case{"the audience leaves the cinema after the film", "theatre", "cinema"},
        Case{"fans leaving the stadium after the concert", "arena", "stadium"},
        Case{"workers on the production line of a factory", "factory", "factory"},
        Case{"a busy shopping mall on Saturday", "mall", "shopping mall"},
        Case{"a waiter brings the menu in a restaurant", "restaurant", "restaurant"},
        Case{"students leaving the lecture hall at the university", "university", "university"},
        Case{"people working out in the gym", "gym", "gym"},
        Case{"residents of a care home having lunch", "care_home", "care home"},
        Case{"voters queue at the polling station", "community_hall", "polling station"},
        Case{"forklifts and pickers on the loading dock", "warehouse", "forklift"},
        Case{"pupils leaving the classroom for recess", "school", "classroom"},
        Case{"passengers waiting at the departure gate", "airport", "departure gate"},
        Case{"a family home with two bedrooms and a living room", "residential", "bedroom"},
        Case{"an office building, not a hospital", "office", "office"},
        Case{"visitors waiting by the elevator in the clinic", "hospital", "clinic"}),
    [](const ::testing::TestParamInfo<Case>& param_info) {
      std::string name;
      for (const char* p = param_info.param.prompt; *p != '\0'; ++p)
        name += std::isalnum(static_cast<unsigned char>(*p)) ? *p : '_';
      return name;
    });

TEST(KnowledgeClassifyBuildingType, DefaultsToResidentialWhenNothingIndicatesATypeAndSaysSo) {
  const BuildingTypeGuess g = classify_building_type("people walking around");
  EXPECT_EQ(g.type, "residential");
  EXPECT_TRUE(g.evidence.empty());
  EXPECT_DOUBLE_EQ(g.confidence, 0.3);
  EXPECT_THAT(g.explanation, HasSubstr("default"));
  EXPECT_EQ(classify_building_type("").type, "residential");
}

TEST(KnowledgeClassifyBuildingType, NegatedIndicatorsDoNotCount) {
  const BuildingTypeGuess g = classify_building_type("an office building, not a hospital");
  EXPECT_EQ(g.scores.count("hospital"), 0u);
  for (const auto& e : g.evidence) EXPECT_NE(e.term, "hospital");
}

TEST(KnowledgeClassifyBuildingType, PhrasesWinOverTheirWordsAndEvidenceKeepsTextOrder) {
  const BuildingTypeGuess g = classify_building_type("a coffee shop next to a hospital");
  ASSERT_EQ(g.evidence.size(), 2u);
  EXPECT_EQ(g.evidence[0].term, "coffee shop");
  EXPECT_EQ(g.evidence[0].type, "restaurant");
  EXPECT_EQ(g.evidence[1].term, "hospital");
  EXPECT_EQ(g.scores.count("retail"), 0u);  // "shop" was not counted on its own
}

TEST(KnowledgeClassifyBuildingType, StrongerEvidenceGivesHigherConfidence) {
  EXPECT_GT(classify_building_type("hospital ward with nurses and patients").confidence,
            classify_building_type("a ward").confidence);
}

TEST(KnowledgeClassifyBuildingType, SceneGraphRoomNamesAreSplitAndClassified) {
  const auto hospital =
      classify_building_type(std::vector<std::string>{"patient_room_01", "NurseStation", "corridor_2"});
  EXPECT_EQ(hospital.type, "hospital");
  EXPECT_THAT(hospital.explanation, HasSubstr("patient room"));
  const auto home = classify_building_type(
      std::vector<std::string>{"bedroom_1", "bedroom_2", "kitchen", "LivingRoom", "bathroom"});
  EXPECT_EQ(home.type, "residential");
  const auto shop =
      classify_building_type(std::vector<std::string>{"sales_floor", "stockroom", "checkout_1"});
  EXPECT_EQ(shop.type, "retail");
}

TEST(KnowledgeClassifyBuildingType, JsonNamesTypeConfidenceAndEvidence) {
  const Json j = to_json(classify_building_type("lunch at the canteen"));
  EXPECT_EQ(j["type"], "canteen");
  EXPECT_EQ(j["evidence"].size(), 2u);
  EXPECT_TRUE(j["scores"].contains("canteen"));
}

}  // namespace
}  // namespace socsim::knowledge
