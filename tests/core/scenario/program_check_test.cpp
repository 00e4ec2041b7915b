// check_program: what the LLM repair loop quotes back. Unknown ROIs/POIs (with valid names listed),
// unknown behaviour nodes, bad ports and port values, unknown roles and tree references, counts over
// the limits or beyond what a region holds — all reported at once with JSON pointers.
#include "core/scenario/program_check.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/core/scenario/offline_worlds.hpp"

namespace socsim::scenario {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

class ProgramCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { worlds_ = new testing::OfflineWorlds(); }
  static void TearDownTestSuite() {
    delete worlds_;
    worlds_ = nullptr;
  }
  static const world::World& hospital() { return worlds_->plan("hospital"); }

  // The message of the error at `pointer` ("" when there is none).
  static std::string message_at(const Error& e, const std::string& pointer) {
    for (const FieldError& f : e.errors)
      if (f.pointer == pointer) return f.message;
    return "";
  }
  static std::string pointers(const Error& e) {
    std::string out;
    for (const FieldError& f : e.errors) out += f.pointer + " | " + f.message + "\n";
    return out;
  }

  static testing::OfflineWorlds* worlds_;
};
testing::OfflineWorlds* ProgramCheck::worlds_ = nullptr;

Json tree(const std::string& body) {
  return Json{{"xml", "<root BTCPP_format=\"4\"><BehaviorTree ID=\"T\">" + body + "</BehaviorTree></root>"}};
}

Json queue_program() {
  return Json{
      {"version", 1},
      {"behavior_trees",
       {{"visit",
         tree("<Sequence><JoinQueue agent_id=\"{id}\" queue=\"lobby_reception_counter_queue\" "
              "position=\"{place}\"/><ServeAtCounter agent_id=\"{id}\" counter=\"lobby_reception_counter\" "
              "queue=\"lobby_reception_counter_queue\" service_time=\"5\"/></Sequence>")}}},
      {"agents",
       Json::array({Json{{"role", "adult"}, {"spawn", "lobby"}, {"count", 4}, {"behavior", "visit"}}})},
      {"ambient_groups",
       Json::array(
           {Json{{"name", "arrivals"}, {"start", {"corridor"}}, {"goal", {"lobby_waiting"}}, {"size", 6}}})}};
}

TEST_F(ProgramCheck, AValidProgramPasses) {
  const auto ok = check_program(queue_program(), hospital(), ScenarioLimits{});
  EXPECT_TRUE(ok.has_value()) << pointers(ok.error());
}

TEST_F(ProgramCheck, UnknownPlacesAreNamedWithValidNames) {
  Json p = queue_program();
  p["agents"][0]["spawn"] = "cafeteria";
  p["agents"][0]["goals"] = Json::array({"helipad"});
  p["ambient_groups"][0]["goal"] = Json::array({"parking_lot"});
  const auto r = check_program(p, hospital(), ScenarioLimits{});
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::kValidation);
  EXPECT_THAT(message_at(r.error(), "/agents/0/spawn"),
              AllOf(HasSubstr("'cafeteria'"), HasSubstr("lobby_reception_counter_queue"), HasSubstr("ROIs")));
  EXPECT_THAT(message_at(r.error(), "/agents/0/goals/0"), AllOf(HasSubstr("'helipad'"), HasSubstr("POIs")));
  EXPECT_THAT(message_at(r.error(), "/ambient_groups/0/goal/0"), HasSubstr("'parking_lot'"));
}

TEST_F(ProgramCheck, UnknownNodesAndBadPortsAreErrorsInTheTree) {
  Json p = queue_program();
  p["behavior_trees"]["dance"] = tree("<DanceWildly agent_id=\"{id}\"/>");
  p["behavior_trees"]["colour"] = tree(
      "<JoinQueue agent_id=\"{id}\" queue=\"lobby_reception_counter_queue\" colour=\"red\" "
      "position=\"{p}\"/>");
  p["behavior_trees"]["moon"] = tree("<WaitAt agent_id=\"{id}\" location=\"the_moon\" duration=\"5\"/>");
  p["behavior_trees"]["lane"] =
      tree("<JoinQueue agent_id=\"{id}\" queue=\"lobby_waiting\" position=\"{p}\"/>");
  p["behavior_trees"]["negative"] = tree("<StopAndWait agent_id=\"{id}\" wait_duration=\"-3\"/>");
  const auto r = check_program(p, hospital(), ScenarioLimits{});
  ASSERT_FALSE(r.has_value());
  const Error& e = r.error();
  EXPECT_THAT(message_at(e, "/behavior_trees/dance/xml"), HasSubstr("DanceWildly")) << pointers(e);
  EXPECT_THAT(message_at(e, "/behavior_trees/colour/xml"), HasSubstr("colour")) << pointers(e);
  EXPECT_THAT(message_at(e, "/behavior_trees/moon/xml"), HasSubstr("the_moon")) << pointers(e);
  EXPECT_THAT(message_at(e, "/behavior_trees/lane/xml"),
              AllOf(HasSubstr("queue_lane"), HasSubstr("lobby_reception_counter_queue")))
      << pointers(e);
  EXPECT_THAT(message_at(e, "/behavior_trees/negative/xml"), HasSubstr("negative")) << pointers(e);
  for (const FieldError& f : e.errors)
    if (f.pointer.find("/behavior_trees/") == 0) {
      EXPECT_GT(f.line, 0) << f.pointer;
    }
}

TEST_F(ProgramCheck, ImpossibleCountsAreErrors) {
  Json p = queue_program();
  p["agents"][0]["count"] = 5000;        // over the agent limit
  p["ambient_groups"][0]["size"] = 900;  // far more than the corridor holds
  ScenarioLimits limits;
  const auto r = check_program(p, hospital(), limits);
  ASSERT_FALSE(r.has_value());
  EXPECT_THAT(message_at(r.error(), "/agents/0/count"), AllOf(HasSubstr("5000"), HasSubstr("2000")));
  EXPECT_THAT(message_at(r.error(), "/ambient_groups/0/size"), HasSubstr("do not fit"));
  EXPECT_THAT(message_at(r.error(), "/agents"), HasSubstr("spotlight")) << pointers(r.error());
  EXPECT_THAT(message_at(r.error(), ""), HasSubstr("in all")) << pointers(r.error());

  // Within the limits but more than the spawn room holds.
  Json q = queue_program();
  q["agents"][0]["spawn"] = "lobby_entrance";
  q["agents"][0]["count"] = 40;
  const auto s = check_program(q, hospital(), ScenarioLimits{});
  ASSERT_FALSE(s.has_value());
  EXPECT_THAT(message_at(s.error(), "/agents/0/count"),
              AllOf(HasSubstr("do not fit"), HasSubstr("'lobby_entrance'")));
}

TEST_F(ProgramCheck, RolesReferencesAndStructureAreCheckedAllAtOnce) {
  Json p = queue_program();
  p["agents"][0]["role"] = "astronaut";
  p["agents"][0]["behavior"] = "visit_twice";
  p["ambient_groups"][0]["speed"] = -1;
  const auto r = check_program(p, hospital(), ScenarioLimits{});
  ASSERT_FALSE(r.has_value());
  // Structure first: a malformed program is reported by the parser with its pointer.
  EXPECT_THAT(message_at(r.error(), "/ambient_groups/0/speed"), ::testing::Not(::testing::IsEmpty()))
      << pointers(r.error());

  p["ambient_groups"][0].erase("speed");
  const auto s = check_program(p, hospital(), ScenarioLimits{});
  ASSERT_FALSE(s.has_value());
  EXPECT_THAT(message_at(s.error(), "/agents/0/role"), AllOf(HasSubstr("astronaut"), HasSubstr("/roles")));
  EXPECT_THAT(message_at(s.error(), "/agents/0/behavior"),
              AllOf(HasSubstr("visit_twice"), HasSubstr("visit")));
  EXPECT_GE(s.error().errors.size(), 2u);
}

TEST_F(ProgramCheck, PositionsOutsideThePlanAndUnreachableRegionsAreErrors) {
  Json p = queue_program();
  p["robot"] = Json{{"position", {-50.0, -50.0}}};
  const auto r = check_program(p, hospital(), ScenarioLimits{});
  ASSERT_FALSE(r.has_value());
  EXPECT_THAT(message_at(r.error(), "/robot/position"), HasSubstr("outside"));

  // Every name exists, but the start polygon lies outside the plan: the dry run finds it.
  Json q = queue_program();
  q["ambient_groups"][0]["start"] =
      Json::array({Json::array({{-10.0, -10.0}, {-5.0, -10.0}, {-5.0, -5.0}, {-10.0, -5.0}})});
  const auto s = check_program(q, hospital(), ScenarioLimits{});
  ASSERT_FALSE(s.has_value());
  bool start_named = false;
  for (const FieldError& f : s.error().errors)
    start_named = start_named || f.pointer.find("/ambient_groups/0/start") == 0;
  EXPECT_TRUE(start_named) << pointers(s.error());
}

}  // namespace
}  // namespace socsim::scenario
