// ScenarioIntent, construction by construction: numbers, products, ranges, exceptions, negation,
// coordination, relative clauses and several clauses with different places; open vocabulary
// (WordNet roles and venues the lexicon lacks), robots, background, warnings, spans, determinism,
// and every fixture's interpretation against schemas/intent.schema.json.
#include "core/scenario/scenario_intent.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "core/common/json_schema.hpp"
#include "tests/core/scenario/prompt_facts.hpp"

namespace socsim::scenario {
namespace {

ScenarioIntent read(const std::string& prompt) {
  auto i = interpret_prompt(prompt);
  EXPECT_TRUE(i.has_value()) << (i ? "" : i.error().message());
  return i ? *i : ScenarioIntent{};
}

const PeopleGroup* group(const ScenarioIntent& i, const std::string& role) {
  for (const PeopleGroup& g : i.groups)
    if (facts::role_matches(role, g.role)) return &g;
  return nullptr;
}

std::string roles(const ScenarioIntent& i) {
  std::string out;
  for (const PeopleGroup& g : i.groups) out += g.role + "=" + facts::describe(g.count) + " ";
  return out;
}

void expect_exact(const ScenarioIntent& i, const std::string& role, double n) {
  const PeopleGroup* g = group(i, role);
  ASSERT_NE(g, nullptr) << role << " in " << i.prompt << ": " << roles(i);
  EXPECT_EQ(g->count.kind, CountKind::kExact) << role << " in " << i.prompt;
  EXPECT_EQ(g->count.value, n) << role << " in " << i.prompt;
}

TEST(ScenarioIntent, Numbers) {
  expect_exact(read("Exactly forty people attend a seminar at the university."), "person", 40);
  expect_exact(read("Two hundred and fifty pupils gather in the hall."), "pupil", 250);
  const auto i = read("About 1,500 fans leave the arena.");
  EXPECT_EQ(group(i, "fan")->count.kind, CountKind::kApprox);
  expect_exact(read("A dozen nurses walk down the corridor."), "nurse", 12);
  expect_exact(read("Seventy-five children play in the school playground."), "child", 75);
}

TEST(ScenarioIntent, Products) {
  expect_exact(read("Two classes of 25 pupils each line up in the schoolyard."), "pupil", 50);
  expect_exact(read("Three checkouts are open and each has a queue of six customers."), "customer", 18);
  expect_exact(read("Three ticket machines in the hall, each with a queue of five people."), "person", 15);
  expect_exact(read("A queue of 20 children and their parents, one parent per child."), "parent", 20);
  expect_exact(read("A gallery with a guard at each of its 4 doors."), "guard", 4);
  expect_exact(read("A plant with 3 production lines and four operators per line."), "operator", 12);
  expect_exact(read("Sports hall: two teams of five players each warm up."), "player", 10);
}

TEST(ScenarioIntent, Ranges) {
  const auto i = read("Between 20 and 30 visitors crowd the doorway.");
  const PeopleGroup* g = group(i, "visitor");
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->count.kind, CountKind::kRange);
  EXPECT_EQ(g->count.min, 20);
  EXPECT_EQ(g->count.max, 30);
  const auto j = read("A coffee shop with 10-15 people waiting and a few baristas.");
  EXPECT_EQ(group(j, "person")->count.max, 15);
  EXPECT_EQ(group(j, "barista")->count.min, 3);
  EXPECT_EQ(group(j, "barista")->count.max, 5);
}

TEST(ScenarioIntent, Exceptions) {
  const auto i = read("The hospital ward is empty except for one security guard doing his rounds.");
  ASSERT_EQ(i.groups.size(), 1u) << roles(i);
  expect_exact(i, "security guard", 1);
  EXPECT_EQ(i.groups[0].normalized_role, "security");
  EXPECT_TRUE(i.exclusivity.exclusive);
  EXPECT_FALSE(i.background);
  const auto j = read("Everyone has left the office except two cleaners.");
  ASSERT_EQ(j.groups.size(), 1u) << roles(j);
  expect_exact(j, "cleaner", 2);
}

TEST(ScenarioIntent, Negation) {
  const auto i =
      read("At the emergency department nobody is waiting; a single triage nurse sits at the desk.");
  ASSERT_EQ(i.groups.size(), 1u) << roles(i);
  expect_exact(i, "nurse", 1);
  EXPECT_TRUE(i.exclusivity.exclusive);
  const auto j = read("Two library assistants reshelve books; no visitors.");
  ASSERT_EQ(j.groups.size(), 1u) << roles(j);
  EXPECT_EQ(j.exclusivity.excluded_roles, std::vector<std::string>{"visitor"});
  const auto k = read("A waiting room with eight patients but without any staff.");
  ASSERT_EQ(k.groups.size(), 1u) << roles(k);
  EXPECT_EQ(k.exclusivity.excluded_roles, std::vector<std::string>{"staff"});
}

TEST(ScenarioIntent, Coordination) {
  const auto i = read("Two nurses and three doctors chat by the coffee machine.");
  ASSERT_EQ(i.groups.size(), 2u) << roles(i);
  expect_exact(i, "nurse", 2);
  expect_exact(i, "doctor", 3);
  EXPECT_EQ(i.total().value, 5);
  const auto j = read("A consultant, two junior doctors and a medical student walk together.");
  ASSERT_EQ(j.groups.size(), 3u) << roles(j);
  expect_exact(j, "consultant", 1);
  expect_exact(j, "doctor", 2);
  expect_exact(j, "student", 1);
  for (const PeopleGroup& g : j.groups) EXPECT_TRUE(g.together) << g.role;
  // A rarer sense of a word (a cleaner is first a substance in WordNet) is a person next to people.
  const auto k = read("Only the cleaner and one security guard are left.");
  ASSERT_EQ(k.groups.size(), 2u) << roles(k);
}

TEST(ScenarioIntent, RelativeClauses) {
  const auto i = read("The nurse who works at the reception greets two visitors who arrived late.");
  ASSERT_EQ(i.groups.size(), 2u) << roles(i);
  expect_exact(i, "nurse", 1);
  expect_exact(i, "visitor", 2);
  const auto j = read(
      "Patients who are waiting for their results sit in the waiting room; there are nine of them, "
      "plus one receptionist.");
  ASSERT_EQ(j.groups.size(), 2u) << roles(j);
  expect_exact(j, "patient", 9);
  expect_exact(j, "receptionist", 1);
}

TEST(ScenarioIntent, WhatPartOfAGroupHasWithItIsAThing) {
  const auto i =
      read("30 elderly residents, some with walkers, and 8 care workers move to the assembly point.");
  ASSERT_EQ(i.groups.size(), 2u) << roles(i);
  expect_exact(i, "resident", 30);
  expect_exact(i, "care worker", 8);
  // A person with a group stays a person ("a tour guide" after "some with" has no thing sense first).
  const auto j = read("Twelve tourists, some with a tour guide, and three children walk through the museum.");
  EXPECT_GE(j.groups.size(), 2u) << roles(j);
  expect_exact(j, "tourist", 12);
}

TEST(ScenarioIntent, SeveralClausesWithDifferentPlaces) {
  const auto i = read("At the office, 3 people queue at the microwave while 4 others chat near the windows.");
  ASSERT_EQ(i.groups.size(), 2u) << roles(i);
  EXPECT_EQ(i.groups[0].count.value, 3);
  EXPECT_EQ(i.groups[0].place, "at the microwave");
  EXPECT_EQ(i.groups[1].count.value, 4);
  EXPECT_EQ(i.groups[1].place, "near the windows");
  EXPECT_EQ(i.total().value, 7);
  const auto j =
      read("At platform 2, 70 passengers board a train, and at platform 5 another 30 passengers wait.");
  ASSERT_EQ(j.groups.size(), 2u) << roles(j);
  EXPECT_EQ(j.total().value, 100);
}

TEST(ScenarioIntent, OpenVocabularyRolesAndVenues) {
  const auto i = read("A quiet library afternoon: one librarian at the issue desk and six students reading.");
  ASSERT_TRUE(i.venue);
  EXPECT_EQ(i.venue->type, "library");
  expect_exact(i, "librarian", 1);
  EXPECT_EQ(group(i, "librarian")->program_role, "librarian");
  // WordNet hypernyms: an inn is a hotel, a brasserie a restaurant; a docent is a person.
  EXPECT_EQ(read("A quiet evening at the inn with two guests.").venue->type, "hotel");
  EXPECT_EQ(read("Twelve diners at the brasserie.").venue->type, "restaurant");
  expect_exact(read("In the museum, three docents take a coffee break."), "docent", 3);
  // The nearest known role keeps the user's word.
  const auto g = read("Two police officers stand at the entrance.");
  EXPECT_EQ(group(g, "police officer")->normalized_role, "security");
  // Venues outside the old list keep their kind and map to the nearest building type for worlds.
  const auto s = read("Rush hour at the central train station.");
  EXPECT_EQ(s.venue->type, "train_station");
  EXPECT_FALSE(s.venue->building_type.empty());
}

TEST(ScenarioIntent, WorldRequirements) {
  const auto i =
      read("Supermarket with 2 exits and 4 checkouts, 35 customers shopping around a music system.");
  std::map<std::string, double> features;
  for (const Feature& f : i.world.features) features[f.head] = f.count.value;
  EXPECT_EQ(features["exit"], 2);
  EXPECT_EQ(features["checkout"], 4);
  const auto j = read("Guests evacuate through the front door and the back door.");
  ASSERT_EQ(j.world.features.size(), 1u);
  EXPECT_EQ(j.world.features[0].count.value, 2);
  const auto k = read("Fifteen friends dance around the music system in the living room.");
  ASSERT_FALSE(k.world.objects.empty());
  EXPECT_EQ(k.world.objects[0].name, "music system");
  ASSERT_FALSE(k.world.rooms.empty());
}

TEST(ScenarioIntent, RobotsBackgroundAndWarnings) {
  const auto i = read("A delivery robot drives through the hospital lobby among about 40 visitors.");
  ASSERT_EQ(i.robots.size(), 1u);
  EXPECT_EQ(i.robots[0].count.value, 1);
  ASSERT_EQ(i.groups.size(), 1u) << roles(i);
  const auto j = read("A busy hospital corridor with a dozen nurses and lots of other people.");
  EXPECT_TRUE(j.background);
  ASSERT_EQ(j.groups.size(), 1u) << roles(j);
  const auto k = read("A busy crowd of about 250 shoppers strolls through the mall.");
  EXPECT_FALSE(k.background);  // the crowd is counted: "busy" describes it
  const auto z = read("Three zeppelins float over the stadium.");
  EXPECT_TRUE(z.groups.empty());
  bool warned = false;
  for (const IntentWarning& w : z.warnings)
    warned = warned || w.message.find("zeppelins") != std::string::npos;
  EXPECT_TRUE(warned);
}

bool warns(const ScenarioIntent& i, const std::string& words) {
  return std::any_of(i.warnings.begin(), i.warnings.end(),
                     [&](const IntentWarning& w) { return w.message.find(words) != std::string::npos; });
}

TEST(ScenarioIntent, WordsNoDictionaryKnowsAreWarnedAboutButNamesAreNot) {
  const auto i = read("Twenty passengers wait on the platform of the station while the zorgs dance.");
  EXPECT_EQ(i.total().value, 20) << roles(i);
  EXPECT_TRUE(warns(i, "'zorgs' is not a person, place or object I know")) << to_json(i).dump();
  // A capitalised word inside a sentence is a name, not an unknown word.
  EXPECT_FALSE(warns(read("Twenty passengers wait at Okafor Street station."), "okafor"));
  // "a family of four waits": the number belongs to the family, not to "waits".
  const auto f = read("A family of four waits for a taxi outside the hotel.");
  EXPECT_EQ(f.total().value, 4) << roles(f);
  EXPECT_TRUE(f.warnings.size() == 0 || !warns(f, "waits")) << to_json(f).dump();
}

TEST(ScenarioIntent, PeopleWaitedForAreNotThere) {
  const auto i = read("A clinic where three patients are waiting for a doctor.");
  ASSERT_EQ(i.groups.size(), 1u) << roles(i);
  EXPECT_EQ(i.groups[0].role, "patient");
  EXPECT_EQ(i.total().value, 3);
  EXPECT_TRUE(warns(i, "'doctor' is waited for"));
  EXPECT_EQ(read("Two nurses are looking for their patients in the ward.").total().value, 2);
  // Caring for or talking to people keeps them.
  EXPECT_EQ(read("Two nurses care for 6 patients in the ward.").total().value, 8);
}

TEST(ScenarioIntent, AppositionsSayWhoTheCountedPeopleAre) {
  const auto i = read("Five friends, all teenagers, hang out at the mall.");
  EXPECT_EQ(i.groups.size(), 1u) << roles(i);
  EXPECT_EQ(i.total().value, 5);
  const auto j = read("A museum with 30 visitors: parents, some with children.");
  EXPECT_EQ(j.total().value, 30) << roles(j);
  const auto k = read("Forty people, mostly tourists, queue at the museum entrance. Two guards watch them.");
  EXPECT_EQ(k.total().value, 42) << roles(k);
  // A list is not an apposition: each role is its own group.
  const auto l = read("Twelve patients, two nurses and a doctor in a hospital ward.");
  EXPECT_EQ(l.total().value, 15) << roles(l);
  const auto m = read("Five friends and some teenagers hang out at the mall.");
  EXPECT_EQ(m.groups.size(), 2u) << roles(m);
}

TEST(ScenarioIntent, ATitleAndANameAreOnePerson) {
  const auto i = read("Dr Okafor and three nurses do a ward round in the hospital.");
  ASSERT_NE(group(i, "doctor"), nullptr) << roles(i);
  EXPECT_EQ(group(i, "doctor")->count.value, 1);
  EXPECT_EQ(i.total().value, 4);
  const auto j = read("Mrs Patel waits at the bus stop with her two children.");
  EXPECT_EQ(j.total().value, 3) << roles(j);
  const auto k = read("Professor Lee lectures 80 students in the auditorium of a university.");
  EXPECT_EQ(group(k, "professor")->count.value, 1) << roles(k);
  EXPECT_EQ(k.total().value, 81);
}

TEST(ScenarioIntent, MoreOfThePeopleJustNamedAndWordsWordNetLacks) {
  const auto i = read(
      "Two baristas work behind the counter of a small cafe while eight customers wait in line and three "
      "more sit by the window.");
  ASSERT_NE(group(i, "barista"), nullptr) << roles(i);
  EXPECT_EQ(group(i, "barista")->count.value, 2);
  EXPECT_EQ(group(i, "customer")->count.value, 11);
  // A compound ending in a person word; people naming the venue are not there.
  const auto m =
      read("At the farmers market a handful of stallholders set up while early shoppers drift in.");
  ASSERT_TRUE(m.venue.has_value());
  EXPECT_EQ(m.venue->type, "mall");
  EXPECT_EQ(group(m, "farmer"), nullptr) << roles(m);
  EXPECT_NE(group(m, "stallholder"), nullptr) << roles(m);
  const auto h = read("A hotel lobby with a receptionist, a concierge and a family of five checking in.");
  EXPECT_EQ(h.total().value, 7) << roles(h);
}

TEST(ScenarioIntent, RarerPersonSensesThatActOrAreExceptedArePeople) {
  // "cleaner" and "fan" are things first in WordNet; acting or excepted, they are people.
  for (const char* prompt : {"Nobody is in the office except a cleaner vacuuming the carpet.",
                             "The office is empty except for a cleaner who vacuums the carpet.",
                             "Nobody is in the office except a cleaner."}) {
    const auto i = read(prompt);
    ASSERT_EQ(i.groups.size(), 1u) << prompt << ": " << roles(i);
    EXPECT_EQ(i.groups[0].role, "cleaner");
    EXPECT_EQ(i.total().value, 1);
    EXPECT_TRUE(i.exclusivity.exclusive);
  }
  const auto f =
      read("Fans stream out of a football stadium after the match, roughly 5000 of them, through 8 gates.");
  ASSERT_NE(group(f, "fan"), nullptr) << roles(f);
  EXPECT_EQ(group(f, "fan")->count.value, 5000);
  // Things stay things.
  EXPECT_EQ(read("An office with desks, fans and a coffee machine where 10 employees work.").total().value,
            10);
}

TEST(ScenarioIntent, APromptWithoutAVenueWordGetsTheVenueItsPlacesBelongTo) {
  const auto i = read("Passengers board a train at platform 2; a conductor checks tickets.");
  ASSERT_TRUE(i.venue.has_value());
  EXPECT_EQ(i.venue->type, "train_station");
  EXPECT_EQ(i.venue->why.rfind("no venue word", 0), 0u) << i.venue->why;
  EXPECT_EQ(read("Kids run around the playground while two teachers watch.").venue->type, "school");
  EXPECT_FALSE(read("Two people talk.").venue.has_value());
  EXPECT_EQ(read("A robot vacuum cleans the living room while a family of three watches TV.").venue->type,
            "residential");
  // Buildings without a type of their own go to the nearest by use (WordNet hypernyms).
  EXPECT_EQ(
      read("Pilgrims gather in front of the cathedral; about 70 of them listen to a priest.").venue->type,
      "community_hall");
  const auto b = read("Generate a scene: bank branch, 3 tellers, 15 customers queuing, 1 security guard.");
  EXPECT_EQ(b.venue->type, "office");
  EXPECT_EQ(b.total().value, 19) << roles(b);
}

TEST(ScenarioIntent, IrregularPluralsPairsAndVenueWordsThatDescribePeople) {
  const auto c = read("Children play in the yard.");
  ASSERT_NE(group(c, "child"), nullptr) << roles(c);
  EXPECT_FALSE(group(c, "child")->count.specified());
  EXPECT_EQ(read("Two firemen and a child wait.").total().value, 3);
  const auto p = read("A pair of police officers walk through the mall.");
  EXPECT_EQ(group(p, "police officer")->count.kind, CountKind::kExact);
  EXPECT_EQ(p.total().value, 2);
  const auto a = read("Three groups of eight school children visit the aquarium with their teachers.");
  EXPECT_EQ(a.venue->type, "museum") << a.venue->why;
  EXPECT_EQ(group(a, "child")->count.value, 24);
  EXPECT_EQ(read("Hospital staff wait at the train station.").venue->type, "train_station");
  EXPECT_EQ(read("Women and men queue at the post office.").venue->type, "office");
}

TEST(ScenarioIntent, PeopleMovedThroughArePeopleAndTimesAreNoUnknownWords) {
  const auto i =
      read("Simulate a crowded subway platform at 8am with a delivery robot navigating through commuters.");
  EXPECT_NE(group(i, "commuter"), nullptr) << roles(i);
  EXPECT_EQ(i.robots.size(), 1u);
  EXPECT_FALSE(warns(i, "8am"));
}

TEST(ScenarioIntent, ZeroMoreAndOddCounts) {
  const auto i = read("0 people in the office.");
  EXPECT_TRUE(i.groups.empty());
  EXPECT_TRUE(i.exclusivity.exclusive);
  EXPECT_EQ(read("Ten people and ten more people.").total().value, 20);
  const auto j = read("Twenty-odd students and 40-odd parents.");
  EXPECT_EQ(group(j, "student")->count.kind, CountKind::kApprox);
  EXPECT_EQ(group(j, "parent")->count.value, 40);
  for (const IntentWarning& w : j.warnings)
    EXPECT_EQ(w.message.find("English"), std::string::npos) << w.message;
}

TEST(ScenarioIntent, OtherLanguagesAreSaidToBe) {
  const auto i = read("Bonjour, deux infirmières attendent dans le couloir.");
  EXPECT_TRUE(i.groups.empty());
  bool said = false;
  for (const IntentWarning& w : i.warnings) said = said || w.message.find("English") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(ScenarioIntent, SpansPointAtTheWords) {
  const std::string prompt = "In the lobby, two nurses wait near the elevator.";
  const auto i = read(prompt);
  ASSERT_EQ(i.groups.size(), 1u);
  const PeopleGroup& g = i.groups[0];
  EXPECT_EQ(prompt.substr(g.span.begin, g.span.end - g.span.begin), "two nurses");
  EXPECT_EQ(prompt.substr(g.place_span.begin, g.place_span.end - g.place_span.begin), "near the elevator");
  EXPECT_EQ(prompt.substr(g.count.span.begin, g.count.span.end - g.count.span.begin), "two");
}

TEST(ScenarioIntent, OddTextNeverBreaksItAndSpansStayInside) {
  // Random sequences of tricky pieces: numbers, dashes, apostrophes, UTF-8, bare punctuation.
  const std::vector<std::string> pieces = {"two",
                                           "20-30",
                                           "1,500",
                                           "'s",
                                           "nurses'",
                                           "\xE2\x80\x93",
                                           "\xE2\x80\x94",
                                           "café",
                                           "-",
                                           "each",
                                           "per",
                                           "of",
                                           "them",
                                           "a",
                                           "the",
                                           "queue",
                                           "of",
                                           "per",
                                           "except",
                                           "no",
                                           "nobody",
                                           "around",
                                           "one",
                                           "between",
                                           "and",
                                           ",",
                                           ";",
                                           ".",
                                           "?",
                                           "hundred",
                                           "dozen",
                                           "robot",
                                           "guard",
                                           "exits",
                                           "-odd",
                                           "\xF0\x9F\x98\x80",
                                           "",
                                           "  ",
                                           "9am",
                                           "or",
                                           "so",
                                           "at",
                                           "'",
                                           "each of"};
  std::uint64_t x = 12345;
  for (int n = 0; n < 300; ++n) {
    std::string prompt;
    const int len = static_cast<int>(x % 14);
    for (int k = 0; k < len; ++k) {
      x = x * 6364136223846793005ULL + 1442695040888963407ULL;
      prompt += pieces[(x >> 33) % pieces.size()];
      if ((x >> 20) % 3 != 0) prompt += " ";
    }
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    auto i = interpret_prompt(prompt);
    ASSERT_TRUE(i.has_value()) << prompt;
    for (const PeopleGroup& g : i->groups) {
      EXPECT_LE(g.span.begin, g.span.end) << prompt;
      EXPECT_LE(g.span.end, prompt.size()) << prompt;
      EXPECT_GE(g.count.value, 0) << prompt;
    }
    (void)to_json(*i).dump();
  }
}

TEST(ScenarioIntent, SamePromptSameIntent) {
  const std::string prompt =
      "Hotel lobby: four guests check in at the front desk where two receptionists work.";
  EXPECT_EQ(to_json(read(prompt)).dump(), to_json(read(prompt)).dump());
}

TEST(ScenarioIntent, EveryFixtureMatchesTheSchema) {
  std::ifstream in(std::string(SOCSIM_SOURCE_DIR) + "/schemas/intent.schema.json");
  ASSERT_TRUE(in.good());
  auto schema = JsonSchema::compile(Json::parse(in));
  ASSERT_TRUE(schema.has_value()) << schema.error().message();
  for (const std::string file : {"everyday", "unseen", "probes"}) {
    for (const auto& p :
         facts::load(std::string(SOCSIM_SOURCE_DIR) + "/tests/fixtures/prompts/" + file + ".jsonl")) {
      const Json j = to_json(read(p.prompt));
      const auto errors = schema->validate(j);
      EXPECT_TRUE(errors.empty()) << p.id << ": "
                                  << (errors.empty() ? "" : errors[0].pointer + " " + errors[0].message);
    }
  }
  EXPECT_TRUE(schema->validate(to_json(read(""))).empty());
}

}  // namespace
}  // namespace socsim::scenario
