// A program read against the prompt: groups nobody asked for are contradictions when the prompt
// names who is there and are listed with their reason when it asks for more; counts as said.
#include "core/scenario/intent_check.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::scenario {
namespace {

using ::testing::HasSubstr;

ScenarioIntent intent_of(const std::string& prompt) {
  auto i = interpret_prompt(prompt);
  EXPECT_TRUE(i.has_value());
  return *i;
}

Json program(const Json& agents, const Json& ambient = Json::array()) {
  return Json{{"agents", agents}, {"ambient_groups", ambient}};
}

std::string all(const std::vector<FieldError>& es) {
  std::string out;
  for (const auto& e : es) out += e.pointer + " " + e.message + "\n";
  return out;
}

TEST(IntentCheck, CountsAsSaidAndNobodyElseWhenThePromptNamesWhoIsThere) {
  const auto in = intent_of("Twelve patients wait while one nurse calls them in.");
  const auto ok = program(Json::array({Json{{"role", "patient"}, {"count", 12}}, Json{{"role", "nurse"}}}));
  EXPECT_TRUE(intent_contradictions(ok, in, 2000).empty()) << all(intent_contradictions(ok, in, 2000));
  const auto bad =
      program(Json::array({Json{{"role", "patients"}, {"count", 10}}, Json{{"role", "doctor"}}}),
              Json::array({Json{{"name", "visitors"}, {"description", "visitors"}, {"size", 4}}}));
  const std::string got = all(intent_contradictions(bad, in, 2000));
  EXPECT_THAT(got, HasSubstr("/agents/0 the prompt says 'Twelve patients' (exactly 12), the program has 10"));
  EXPECT_THAT(got, HasSubstr("'one nurse' but the program has nobody of that role"));
  EXPECT_THAT(got, HasSubstr("/agents/1 1 doctor: nobody asked for them"));
  EXPECT_THAT(got, HasSubstr("/ambient_groups/0/size 4 adult: nobody asked for them"));
  // Over the agents cap the generator scales counts: they are not contradictions then.
  EXPECT_THAT(all(intent_contradictions(bad, in, 5)), ::testing::Not(HasSubstr("exactly 12")));
}

TEST(IntentCheck, ApproximateAndRangeCounts) {
  const auto in = intent_of("About forty shoppers and between two and four cashiers.");
  auto p = [](int shoppers, int cashiers) {
    return program(
        Json::array({Json{{"role", "cashier"}, {"count", cashiers}}}),
        Json::array(
            {Json{{"name", "s"}, {"description", "shoppers"}, {"role", "shopper"}, {"size", shoppers}}}));
  };
  EXPECT_TRUE(intent_contradictions(p(43, 3), in, 2000).empty())
      << all(intent_contradictions(p(43, 3), in, 2000));
  EXPECT_THAT(all(intent_contradictions(p(50, 3), in, 2000)), HasSubstr("about 40 (within 10 %)"));
  EXPECT_THAT(all(intent_contradictions(p(40, 6), in, 2000)), HasSubstr("between 2 and 4"));
}

TEST(IntentCheck, BackgroundPeopleAreListedWithTheWordsThatAskedForThem) {
  const auto in = intent_of("A busy station concourse with two security guards and lots of other people.");
  const auto p = program(
      Json::array({Json{{"role", "security_guard"}, {"count", 2}}}),
      Json::array(
          {Json{{"name", "commuters"}, {"description", "walking"}, {"role", "commuter"}, {"size", 30}}}));
  EXPECT_TRUE(intent_contradictions(p, in, 2000).empty()) << all(intent_contradictions(p, in, 2000));
  const Json added = added_groups(p, in, {"normal_operation"}, "airport");
  ASSERT_EQ(added.size(), 1u) << added.dump();
  EXPECT_EQ(added[0]["role"], "commuter");
  EXPECT_EQ(added[0]["count"], 30);
  EXPECT_THAT(added[0]["why"].get<std::string>(), HasSubstr("beyond those it names"));
}

TEST(IntentCheck, APromptWithoutPeopleGetsTheUsualOnesAndSaysSo) {
  const auto in = intent_of("Fire drill in the office.");
  const auto p = program(Json::array({Json{{"role", "worker"}, {"count", 8}}}));
  const Json added = added_groups(p, in, {"emergency"}, "office");
  ASSERT_EQ(added.size(), 1u);
  EXPECT_THAT(added[0]["why"].get<std::string>(), HasSubstr("the prompt names nobody"));
  EXPECT_TRUE(intent_contradictions(p, in, 2000).empty());
}

}  // namespace
}  // namespace socsim::scenario
