// PedestrianState: the socsim_people_msgs fields (paper 001, Table I) survive a JSON round trip,
// and every kind of bad field is reported with its JSON pointer.
#include "core/crowd/pedestrian_state.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::crowd {
namespace {

using ::testing::Contains;
using ::testing::Field;
using ::testing::HasSubstr;

PedestrianState sample_state() {
  PedestrianState s;
  s.id = AgentId(17);
  s.pose = {3.5, -2.25, 1.5};
  s.twist = {0.8, -0.1, 0.05};
  s.activity = Activity::kQueuing;
  s.role = "staff";
  s.intent = {"reception_desk", 2};
  s.group_id = 4;
  s.proxemics = {0.4, 1.0, 3.0, 0.5};
  s.metadata = {12345, "JoinQueue", {"spotlight", "nurse"}};
  return s;
}

TEST(PedestrianState, RoundTripsThroughJson) {
  const PedestrianState s = sample_state();
  const Json j = to_json(s);
  EXPECT_EQ(j["state"], "queuing");
  EXPECT_EQ(j["pose"]["x"], 3.5);
  EXPECT_EQ(j["metadata"]["bt_node"], "JoinQueue");
  auto back = pedestrian_state_from_json(j);
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(*back, s);
}

TEST(PedestrianState, EveryActivityHasAUniqueName) {
  for (std::size_t i = 0; i < activity_names().size(); ++i) {
    const auto a = static_cast<Activity>(i);
    EXPECT_EQ(activity_from_name(activity_name(a)), a);
  }
  EXPECT_EQ(activity_from_name("walking"), Activity::kWalking);
  EXPECT_EQ(activity_from_name("evacuating"), Activity::kEvacuating);
  EXPECT_FALSE(activity_from_name("flying"));
}

TEST(PedestrianState, MinimalDocumentTakesDefaults) {
  auto s = pedestrian_state_from_json(Json::parse(R"({"id": 3, "pose": {"x": 1, "y": 2}})"));
  ASSERT_TRUE(s) << s.error().message();
  EXPECT_EQ(s->id, AgentId(3));
  EXPECT_EQ(s->activity, Activity::kWalking);
  EXPECT_EQ(s->role, "adult");
  EXPECT_EQ(s->group_id, -1);
  EXPECT_EQ(s->intent.goal_id, -1);
  EXPECT_DOUBLE_EQ(s->proxemics.comfort_radius, 1.2);
}

TEST(PedestrianState, ReportsEachBadFieldWithItsPointer) {
  const Json j = Json::parse(R"({
    "id": -1,
    "pose": {"x": "left", "y": 2, "yaw": 9},
    "state": "flying",
    "intent": {"target": 5},
    "proxemics": {"intimate_radius": 2.0, "comfort_radius": 1.0},
    "metadata": {"tags": ["ok", 3]},
    "colour": "red"
  })");
  auto s = pedestrian_state_from_json(j, "/agents/2");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().code, ErrorCode::kValidation);
  const auto& e = s.error().errors;
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/id")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/pose/x")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/pose/yaw")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/state")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/intent/target")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/proxemics")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/metadata/tags/1")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/agents/2/colour")));
  for (const FieldError& f : e)
    if (f.pointer == "/agents/2/state") {
      EXPECT_THAT(f.message, HasSubstr("queuing"));
    }
}

TEST(PedestrianState, RejectsNonObjectsAndMissingPose) {
  EXPECT_FALSE(pedestrian_state_from_json(Json::array()));
  auto s = pedestrian_state_from_json(Json::parse(R"({"id": 1})"));
  ASSERT_FALSE(s);
  EXPECT_THAT(s.error().errors, Contains(Field(&FieldError::pointer, "/pose")));
}

}  // namespace
}  // namespace socsim::crowd
