// Prompt understanding: Table II categories from their phrases (and several from mixed prompts),
// counts in words and digits bound to the role they precede, roles, place mentions resolved to a
// world's places by type and name (never invented), timing, and the provenance of each match.
#include "core/scenario/intent.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/core/scenario/offline_worlds.hpp"

namespace socsim::scenario {
namespace {

using ::testing::ElementsAre;

std::string top(const Intent& i) {
  return i.categories.empty() ? "" : std::string(to_string(i.categories.front().category));
}

std::vector<std::string> categories(const Intent& i) {
  std::vector<std::string> out;
  for (const CategoryScore& c : i.categories) out.emplace_back(to_string(c.category));
  return out;
}

const RoleMention* role(const Intent& i, const std::string& r) {
  for (const Clause& c : i.clauses)
    for (const RoleMention& m : c.roles)
      if (m.role == r) return &m;
  return nullptr;
}

TEST(Intent, EveryCategoryFromItsPhrases) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"The fire alarm goes off and everyone evacuates", "emergency"},
      {"A fire drill in the office", "emergency"},
      {"Customers line up and wait in line at the checkout", "queuing"},
      {"A birthday party at home with friends", "social_party"},
      {"Staff take a coffee break in the break room", "coffee_break"},
      {"Patients check in at the front desk", "reception"},
      {"Visitors register at registration", "reception"},
      {"People squeeze through the narrow doorway", "bottleneck"},
      {"A crowd rushes through one door", "bottleneck"},
      {"Normal operation, routine everyday traffic", "normal_operation"},
  };
  for (const auto& [prompt, category] : cases) EXPECT_EQ(top(parse_intent(prompt)), category) << prompt;
  EXPECT_TRUE(parse_intent("").categories.empty());
  EXPECT_TRUE(parse_intent("purple elephants").categories.empty());
}

TEST(Intent, MixedPromptsGiveSeveralCategoriesByClause) {
  const Intent i =
      parse_intent("Patients queue at the reception desk while staff chat near the corridor intersection");
  ASSERT_EQ(i.clauses.size(), 2u);
  EXPECT_EQ(i.clauses[0].categories.front().category, Category::kQueuing);
  EXPECT_EQ(i.clauses[1].categories.front().category, Category::kCoffeeBreak);
  EXPECT_THAT(categories(i), ::testing::IsSupersetOf({"queuing", "coffee_break"}));
  // "reception" names the place here: it counts half.
  for (const CategoryScore& c : i.categories)
    if (c.category == Category::kReception) {
      EXPECT_LT(c.score, 1.0);
    }
  // Provenance: the phrases that matched.
  EXPECT_THAT(i.clauses[0].categories.front().phrases, ElementsAre("queue"));
  EXPECT_THAT(i.clauses[1].categories.front().phrases, ElementsAre("chat"));
}

TEST(Intent, CountsInWordsAndDigitsBindToTheirRole) {
  const Intent i = parse_intent(
      "Two nurses, about thirty visitors, a dozen patients, 5 staff members, a few doctors, several children "
      "and "
      "twenty-five elderly people wait; a receptionist watches");
  ASSERT_NE(role(i, "nurse"), nullptr);
  EXPECT_EQ(role(i, "nurse")->count, 2u);
  EXPECT_FALSE(role(i, "nurse")->approximate);
  ASSERT_NE(role(i, "visitor"), nullptr);
  EXPECT_EQ(role(i, "visitor")->count, 30u);
  EXPECT_TRUE(role(i, "visitor")->approximate);
  EXPECT_EQ(role(i, "visitor")->count_phrase, "about thirty");
  EXPECT_EQ(role(i, "patient")->count, 12u);
  EXPECT_EQ(role(i, "staff")->count, 5u);
  EXPECT_EQ(role(i, "staff")->phrase, "staff members");
  EXPECT_EQ(role(i, "doctor")->count, 3u);
  EXPECT_TRUE(role(i, "doctor")->approximate);
  EXPECT_EQ(role(i, "child")->count, 5u);
  EXPECT_EQ(role(i, "elderly")->count, 25u);
  EXPECT_EQ(role(i, "receptionist")->count, 1u);
}

TEST(Intent, ACrowdWithoutARoleAndLargeNumbers) {
  const Intent a = parse_intent("A crowd of 200 rushes through the narrow door");
  ASSERT_TRUE(a.crowd_size.has_value());
  EXPECT_EQ(*a.crowd_size, 200u);
  const Intent b = parse_intent("two hundred and fifty people evacuate");
  ASSERT_NE(role(b, "adult"), nullptr);
  EXPECT_EQ(role(b, "adult")->count, 250u);
  const Intent c = parse_intent("a crowd of visitors arrives");
  ASSERT_NE(role(c, "visitor"), nullptr);
  EXPECT_EQ(role(c, "visitor")->count, 40u);
  EXPECT_TRUE(role(c, "visitor")->approximate);
  // A number of minutes is no count of people.
  const Intent d = parse_intent("nurses chat for two minutes");
  ASSERT_NE(role(d, "nurse"), nullptr);
  EXPECT_FALSE(role(d, "nurse")->count.has_value());
}

TEST(Intent, TimingStartAndDuration) {
  const Intent a = parse_intent("Fire alarm after 20 seconds; people chat for two minutes");
  ASSERT_TRUE(a.timing.start_after_s.has_value());
  EXPECT_DOUBLE_EQ(*a.timing.start_after_s, 20.0);
  ASSERT_TRUE(a.timing.duration_s.has_value());
  EXPECT_DOUBLE_EQ(*a.timing.duration_s, 120.0);
  EXPECT_THAT(a.timing.phrases, ElementsAre("after 20 seconds", "for two minutes"));
  const Intent b = parse_intent("evacuation 90 s later");
  EXPECT_DOUBLE_EQ(b.timing.start_after_s.value_or(0), 90.0);
  const Intent c = parse_intent("a party lasting half an hour, alarm after 1.5 min");
  EXPECT_DOUBLE_EQ(c.timing.duration_s.value_or(0), 1800.0);
  EXPECT_DOUBLE_EQ(c.timing.start_after_s.value_or(0), 90.0);
}

TEST(Intent, PlaceMentions) {
  const Intent i =
      parse_intent("Visitors wait near the elevator, nurses gather at the nurse station in the living room");
  std::vector<std::string> phrases;
  for (const Clause& c : i.clauses)
    for (const PlaceMention& m : c.places) phrases.push_back(m.preposition + ":" + m.phrase);
  EXPECT_THAT(phrases, ElementsAre("near:elevator", "at:nurse station", "in:living room"));
}

TEST(Intent, PlacesResolveToTheWorldByTypeAndName) {
  testing::OfflineWorlds worlds;
  const world::World& hospital = worlds.plan("hospital");
  const world::World& office = worlds.plan("office");
  auto resolve = [](const std::string& prompt, const world::World& w) -> std::optional<ResolvedPlace> {
    const Intent i = parse_intent(prompt);
    for (const Clause& c : i.clauses)
      for (const PlaceMention& m : c.places) return resolve_place(m, w);
    return std::nullopt;
  };
  EXPECT_EQ(resolve("queue at the reception desk", hospital)->name, "lobby_reception_counter");
  EXPECT_EQ(resolve("queue at the reception desk", office)->name, "reception_reception_counter");
  EXPECT_EQ(resolve("chat at the coffee machine", office)->name, "kitchenette_coffee_machine");
  EXPECT_EQ(resolve("chat near the corridor", hospital)->kind, ResolvedPlace::Kind::kRoi);
  EXPECT_EQ(resolve("meet at the nurse station", hospital)->name, "nurse_station_counter");
  EXPECT_EQ(resolve("leave by the main entrance", hospital)->name, "main_entrance");
  EXPECT_EQ(resolve("drink at the water dispenser", office)->kind, ResolvedPlace::Kind::kEntity);
  // Places the world does not have resolve to nothing (the generator falls back and says so).
  EXPECT_FALSE(resolve("wait near the elevator", hospital).has_value());
  EXPECT_FALSE(resolve("gather in the living room", office).has_value());
}

TEST(Intent, ProvenanceJson) {
  const Json j = to_json(parse_intent("Two nurses chat near the coffee machine after 10 seconds"));
  EXPECT_EQ(j["categories"][0]["category"], "coffee_break");
  EXPECT_EQ(j["clauses"][0]["roles"][0]["role"], "nurse");
  EXPECT_EQ(j["clauses"][0]["roles"][0]["count"], 2);
  EXPECT_EQ(j["clauses"][0]["places"][0]["lexicon"], "coffee machine");
  EXPECT_EQ(j["timing"]["start_after_s"], 10.0);
}

}  // namespace
}  // namespace socsim::scenario
