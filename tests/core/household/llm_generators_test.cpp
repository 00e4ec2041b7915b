// The LLM household generators against a scripted OpenAI-compatible server on 127.0.0.1: a valid
// answer is accepted, an invalid one is repaired with the problem quoted by JSON pointer, one that
// never validates is rejected naming the field — for personas, day plans, minute schedules,
// activity databases, hints and hint interpretations. A two-day LLM schedule passes check_schedule.
#include "core/household/llm_generators.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/household/llm_answers.hpp"
#include "core/llm/call_log.hpp"
#include "tests/core/household/household_fixture.hpp"
#include "tests/core/llm/scripted_server.hpp"

namespace socsim::household {
namespace {

using socsim::testing::ScriptedServer;
using ::testing::HasSubstr;
using testing::knowledge;

const char* kNewPersona = R"({"name": "Wanjiru Kamau", "age": 39, "gender": "female",
  "routine": "Wanjiru goes to bed at 10:30 pm and gets up at 6 am.", "personality": ["calm", "tidy", "curious"],
  "occupation": "Wanjiru is a midwife at the district hospital and works from 7 am to 3 pm.",
  "thoughts": "She is planning a trip to see her sister.", "lifestyle": "She grows herbs on the balcony and bakes bread at weekends."})";

const char* kPlanDay0 = R"({"day": 0, "weekday": "Wednesday", "blocks": [
  {"start": "00:00", "end": "06:00", "kind": "sleep", "description": "sleeping"},
  {"start": "06:00", "end": "07:30", "kind": "home", "description": "getting ready for work"},
  {"start": "07:30", "end": "17:30", "kind": "away", "description": "working at the audit firm"},
  {"start": "17:30", "end": "22:30", "kind": "home", "description": "a quiet evening at home"},
  {"start": "22:30", "end": "24:00", "kind": "sleep", "description": "sleeping"}]})";

std::string activities_answer(const std::string& day, bool split_leave_home = false) {
  const std::string away =
      split_leave_home
          ? R"({"start": "07:30", "end": "12:00", "activity": "leave home"}, {"start": "12:00", "end": "17:30", "activity": "leave home"},)"
          : R"({"start": "07:30", "end": "17:30", "activity": "leave home"},)";
  return R"({"day": ")" + day + R"(", "activities": [
    {"start": "00:00", "end": "06:00", "activity": "sleeping"},
    {"start": "06:00", "end": "06:15", "activity": "getting out of bed"},
    {"start": "06:15", "end": "06:35", "activity": "taking a shower"},
    {"start": "06:35", "end": "06:50", "activity": "getting dressed"},
    {"start": "06:50", "end": "07:15", "activity": "having breakfast"},
    {"start": "07:15", "end": "07:30", "activity": "brushing teeth"},
    )" + away +
         R"(
    {"start": "17:30", "end": "17:45", "activity": "coming home"},
    {"start": "17:45", "end": "18:45", "activity": "cooking dinner"},
    {"start": "18:45", "end": "19:30", "activity": "having dinner"},
    {"start": "19:30", "end": "19:50", "activity": "washing dishes"},
    {"start": "19:50", "end": "21:30", "activity": "reading a book"},
    {"start": "21:30", "end": "22:00", "activity": "untangling the fairy lights", "new": true},
    {"start": "22:00", "end": "22:30", "activity": "getting ready for bed"},
    {"start": "22:30", "end": "24:00", "activity": "sleeping"}]})";
}

const char* kDatabase = R"({"activities": [
  {"activity": "having breakfast", "locations": [
    {"room": "Kitchen", "p": 0.8, "objects": [{"type": "Mug", "p": 0.7, "receptacles": {"CounterTop": 0.6, "DiningTable": 0.4}}]},
    {"room": "LivingRoom", "p": 0.2, "objects": [{"type": "Mug", "p": 0.5, "receptacles": {"CoffeeTable": 1.0}}]}]},
  {"activity": "reading a book", "locations": [
    {"room": "LivingRoom", "p": 0.6, "objects": [{"type": "Book", "p": 0.9, "receptacles": {"Sofa": 0.5, "ShelvingUnit": 0.5}}]},
    {"room": "Bedroom", "p": 0.4, "objects": [{"type": "Book", "p": 0.9, "receptacles": {"SideTable": 0.7, "Bed": 0.3}}]}]}]})";

class HouseholdLlmTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto s = store::Store::open(dir_.file("socsim.db"));
    ASSERT_TRUE(s.has_value()) << s.error().message();
    store_ = std::move(*s);
    llm::LlmConfig config;
    config.base_url = server_.base_url();
    config.model = "test-model";
    config.connect_timeout_ms = 500;
    config.attempt_timeout_ms = 3000;
    config.deadline_ms = 6000;
    config.max_retries = 0;
    auto c = llm::LlmClient::create(config);
    ASSERT_TRUE(c.has_value()) << c.error().message();
    client_ = std::move(*c);
    generator_ = std::make_unique<llm::StructuredGenerator>(*client_, store_.get());
    settings_.generator = generator_.get();
    settings_.job_id = "job-household";
  }

  // The last user message of request i (a repair request quotes the problems there).
  std::string last_user_message(std::size_t i) const {
    const auto seen = server_.seen();
    if (i >= seen.size()) return "";
    std::string last;
    for (const auto& m : seen[i].body["messages"])
      if (m["role"] == "user") last = m["content"].get<std::string>();
    return last;
  }

  const Persona& amara() const { return *knowledge().persona("amara-diallo"); }

  ScriptedServer server_;
  socsim::testing::TempDir dir_;
  std::unique_ptr<store::Store> store_;
  std::unique_ptr<llm::LlmClient> client_;
  std::unique_ptr<llm::StructuredGenerator> generator_;
  LlmSettings settings_;
};

TEST_F(HouseholdLlmTest, AnswerSchemasCompileForEveryArtifact) {
  for (const char* a :
       {"persona", "day_plan", "activity_schedule", "activity_database", "hint", "hint_interpretation"}) {
    auto s = answer_schema(a);
    ASSERT_TRUE(s) << a;
    EXPECT_FALSE((*s)->document().dump().find("$ref") != std::string::npos) << a << " is self-contained";
  }
  EXPECT_FALSE(answer_schema("floor_plan"));
}

TEST_F(HouseholdLlmTest, PersonaValidIsAcceptedAndLogged) {
  server_.push_chat(ScriptedServer::chat(kNewPersona));
  PersonaRequest r;
  r.count = 1;
  r.seed = 3;
  auto p = generate_personas_llm(r, knowledge().personas, settings_);
  ASSERT_TRUE(p) << p.error().message();
  ASSERT_EQ(p->size(), 1u);
  EXPECT_EQ((*p)[0].name, "Wanjiru Kamau");
  EXPECT_EQ(server_.count(), 1);
  const auto seen = server_.seen();
  EXPECT_EQ(seen[0].body["response_format"]["json_schema"]["name"], "persona");
  EXPECT_THAT(last_user_message(0),
              HasSubstr("Margit Halvorsen"));  // the existing personas are in the prompt
  auto calls = llm::job_llm_calls(*store_, "job-household");
  ASSERT_TRUE(calls);
  EXPECT_EQ((*calls)["totals"]["calls"], 1);
}

TEST_F(HouseholdLlmTest, PersonaOutOfRangeOrDuplicateIsRepaired) {
  Json old = Json::parse(kNewPersona);
  old["age"] = 150;
  server_.push_chat(ScriptedServer::chat(old.dump()));
  Json dup = Json::parse(kNewPersona);
  dup["name"] = "Margit Halvorsen";
  server_.push_chat(ScriptedServer::chat(dup.dump()));
  server_.push_chat(ScriptedServer::chat(kNewPersona));
  PersonaRequest r;
  auto p = generate_personas_llm(r, knowledge().personas, settings_);
  ASSERT_TRUE(p) << p.error().message();
  EXPECT_EQ((*p)[0].name, "Wanjiru Kamau");
  EXPECT_EQ(server_.count(), 3);
  EXPECT_THAT(last_user_message(1), HasSubstr("/age"));
  EXPECT_THAT(last_user_message(2), HasSubstr("/name"));
}

TEST_F(HouseholdLlmTest, PersonaThatNeverFitsIsRejectedNamingTheField) {
  Json young = Json::parse(kNewPersona);
  young["age"] = 19;
  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(young.dump()));
  PersonaRequest r;
  r.constraints.min_age = 60;
  auto p = generate_personas_llm(r, knowledge().personas, settings_);
  ASSERT_FALSE(p);
  EXPECT_EQ(p.error().code, ErrorCode::kValidation);
  ASSERT_FALSE(p.error().errors.empty());
  EXPECT_EQ(p.error().errors[0].pointer, "/age");
  EXPECT_EQ(server_.count(), 3);  // 1 + 2 repair rounds
}

TEST_F(HouseholdLlmTest, TwoDayLlmScheduleIsConsistentAndGrowsTheVocabulary) {
  const std::string plan1 = [] {
    Json j = Json::parse(kPlanDay0);
    j["day"] = 1;
    j["weekday"] = "Thursday";
    return j.dump();
  }();
  server_.push_chat(ScriptedServer::chat(kPlanDay0));
  server_.push_chat(ScriptedServer::chat(activities_answer("Wednesday")));
  server_.push_chat(ScriptedServer::chat(plan1));
  server_.push_chat(ScriptedServer::chat(activities_answer("Thursday")));
  LlmDayPlanner planner(knowledge(), settings_);
  LlmDecomposer decomposer(knowledge(), settings_);
  auto vocab = ActivityVocabulary::initial(knowledge());
  const auto names_before = vocab.name_count();
  auto s = generate_schedule(amara(), {2, Weekday::kWednesday, 5}, planner, decomposer, vocab);
  ASSERT_TRUE(s) << s.error().message();
  EXPECT_TRUE(check_schedule(*s, amara(), knowledge()).empty());
  EXPECT_GT(vocab.name_count(), names_before);  // "untangling the fairy lights" joined
  // Sleep across midnight is one entry; time away is "leave home".
  const auto away = std::count_if(s->entries.begin(), s->entries.end(),
                                  [](const ScheduleEntry& e) { return e.role == ActivityRole::kLeaveHome; });
  EXPECT_EQ(away, 2);
  const auto overnight = std::find_if(s->entries.begin(), s->entries.end(),
                                      [](const ScheduleEntry& e) { return e.start == 22 * 60 + 30; });
  ASSERT_NE(overnight, s->entries.end());
  EXPECT_EQ(overnight->end, 1440 + 6 * 60);
  // The decomposer's prompt carried the plan with "leave home" and the activity list.
  EXPECT_THAT(last_user_message(1), HasSubstr("07:30-17:30 away: leave home"));
  EXPECT_THAT(last_user_message(1), HasSubstr("having breakfast"));
}

TEST_F(HouseholdLlmTest, DayPlanWithAGapIsRepairedAndSplitLeaveHomeRejected) {
  Json gap = Json::parse(kPlanDay0);
  gap["blocks"][1]["start"] = "06:30";
  server_.push_chat(ScriptedServer::chat(gap.dump()));
  server_.push_chat(ScriptedServer::chat(kPlanDay0));
  LlmDayPlanner planner(knowledge(), settings_);
  auto plan = planner.plan_day(amara(), {0, Weekday::kWednesday, 1, nullptr});
  ASSERT_TRUE(plan) << plan.error().message();
  EXPECT_THAT(last_user_message(1), HasSubstr("/blocks/1/start"));

  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(activities_answer("Wednesday", true)));
  LlmDecomposer decomposer(knowledge(), settings_);
  auto vocab = ActivityVocabulary::initial(knowledge());
  auto entries = decomposer.decompose(amara(), leave_home_filter(*plan), vocab, 1);
  ASSERT_FALSE(entries);
  EXPECT_EQ(entries.error().code, ErrorCode::kValidation);
  std::vector<std::string> ptrs;
  for (const auto& f : entries.error().errors) ptrs.push_back(f.pointer);
  EXPECT_THAT(ptrs, ::testing::Contains("/activities/6/activity"));
}

TEST_F(HouseholdLlmTest, ActivityDatabaseSumsAreRepairedAndUnknownTypesRejected) {
  Json bad = Json::parse(kDatabase);
  bad["activities"][0]["locations"][0]["p"] = 0.5;  // p(l|a) sums to 0.7
  server_.push_chat(ScriptedServer::chat(bad.dump()));
  server_.push_chat(ScriptedServer::chat(kDatabase));
  LlmActivityDatabaseGenerator gen(knowledge(), settings_);
  const std::vector<std::string> primaries = {"having breakfast", "leave home", "reading a book"};
  auto db = gen.generate(amara(), primaries, 9);
  ASSERT_TRUE(db) << db.error().message();
  ASSERT_EQ(db->activities.size(), 3u);
  EXPECT_TRUE(db->find("leave home")->locations.empty());
  EXPECT_TRUE(validate_activity_db(*db, knowledge()));
  EXPECT_THAT(last_user_message(1), HasSubstr("/activities/0/locations"));
  EXPECT_THAT(last_user_message(0), HasSubstr("- Mug:"));  // the scene prior lists what goes where

  Json wrong = Json::parse(kDatabase);
  wrong["activities"][1]["locations"][0]["objects"][0]["receptacles"] = {
      {"Bathtub", 1.0}};  // not in a living room
  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(wrong.dump()));
  auto never = gen.generate(amara(), primaries, 10);
  ASSERT_FALSE(never);
  EXPECT_EQ(never.error().code, ErrorCode::kValidation);
  bool named = false;
  for (const auto& f : never.error().errors)
    named = named || f.pointer.find("/activities/1/locations/0/objects/0/receptacles") == 0;
  EXPECT_TRUE(named) << never.error().message();
}

class HouseholdLlmSceneTest : public HouseholdLlmTest {
 protected:
  void SetUp() override {
    HouseholdLlmTest::SetUp();
    auto house = generate_house({6, std::nullopt, 21}, knowledge());
    ASSERT_TRUE(house) << house.error().message();
    auto vocab = ActivityVocabulary::initial(knowledge());
    auto profile = make_resident_offline(amara(), knowledge(), {2, Weekday::kWednesday, 4}, vocab);
    ASSERT_TRUE(profile);
    pool_.push_back(std::make_shared<const ResidentProfile>(std::move(*profile)));
    auto scene =
        configure_scene(std::make_shared<const House>(std::move(*house)), pool_, {1, 8}, knowledge());
    ASSERT_TRUE(scene) << scene.error().message();
    scene_ = std::make_unique<DynamicScene>(std::move(*scene));
  }
  std::vector<std::shared_ptr<const ResidentProfile>> pool_;
  std::unique_ptr<DynamicScene> scene_;
};

TEST_F(HouseholdLlmSceneTest, HintFromCoarseMemoryNamesAnActivityOfThatMemory) {
  const Seconds t = kSecondsPerDay + 21 * 3600;  // Thursday 21:00
  const std::string memory = coarse_memory(*scene_, 0, t, kSecondsPerDay);
  EXPECT_THAT(memory, HasSubstr("Thu 07:00-08:00"));
  EXPECT_THAT(memory, HasSubstr("(kitchen)"));
  // Pick a remembered activity with a room to answer with.
  std::string remembered;
  for (int idx : scene_->events_of(0)) {
    const auto& e = scene_->events()[static_cast<std::size_t>(idx)];
    if (e.start > t - kSecondsPerDay && e.end < t && e.room >= 0) remembered = scene_->entry(e).name;
  }
  ASSERT_FALSE(remembered.empty());
  server_.push_chat(ScriptedServer::chat(
      R"({"used_recently": true, "hint": "I had it while juggling.", "activity": "juggling"})"));
  server_.push_chat(ScriptedServer::chat(
      Json{{"used_recently", true}, {"hint", "I think I had it earlier."}, {"activity", remembered}}.dump()));
  LlmHintGenerator gen(settings_);
  auto h = gen.hint({scene_.get(), 0, "Mug", t, kSecondsPerDay});
  ASSERT_TRUE(h) << h.error().message();
  EXPECT_TRUE(h->used);
  EXPECT_EQ(h->activity, remembered);
  EXPECT_GE(h->event, 0);
  EXPECT_FALSE(h->room_id.empty());
  EXPECT_THAT(last_user_message(0), HasSubstr("Did you use the mug recently?"));
  EXPECT_THAT(last_user_message(1), HasSubstr("/activity"));
}

TEST_F(HouseholdLlmSceneTest, HintInterpretationGivesAReceptacleDistributionOrNamesTheBadField) {
  const House& h = scene_->house();
  ASSERT_GE(h.receptacles.size(), 2u);
  const std::string a = h.entities[static_cast<std::size_t>(h.receptacles[0])].id,
                    b = h.entities[static_cast<std::size_t>(h.receptacles[1])].id;
  server_.push_chat(ScriptedServer::chat(
      Json{{"event", {{"activity", "having breakfast"}, {"room", "kitchen"}}},
           {"receptacles", {{{"receptacle_id", a}, {"p", 0.7}}, {{"receptacle_id", b}, {"p", 0.3}}}}}
          .dump()));
  LlmHintInterpreter interp(settings_);
  HintInterpretationQuery q{&h, "Mug", "I left it on the counter after breakfast.", 9 * 3600,
                            Weekday::kWednesday};
  auto r = interp.interpret(q);
  ASSERT_TRUE(r) << r.error().message();
  ASSERT_EQ(r->receptacles.size(), 2u);
  EXPECT_EQ(r->receptacles[0].first, h.receptacles[0]);
  EXPECT_NEAR(r->receptacles[0].second + r->receptacles[1].second, 1.0, 1e-9);
  EXPECT_THAT(last_user_message(0), HasSubstr(a + " | "));

  const Json bogus = {{"event", {{"activity", ""}, {"room", ""}}},
                      {"receptacles", {{{"receptacle_id", "Nowhere|1"}, {"p", 1.0}}}}};
  for (int i = 0; i < 3; ++i) server_.push_chat(ScriptedServer::chat(bogus.dump()));
  q.hint = "No, I have not seen it today.";  // another request: the cached answer above does not apply
  auto never = interp.interpret(q);
  ASSERT_FALSE(never);
  ASSERT_FALSE(never.error().errors.empty());
  EXPECT_EQ(never.error().errors[0].pointer, "/receptacles/0/receptacle_id");
}

}  // namespace
}  // namespace socsim::household
