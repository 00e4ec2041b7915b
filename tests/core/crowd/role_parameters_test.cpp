// Role parameters: LightSFM's defaults, the built-in roles, JSON overrides and their errors.
#include "core/crowd/role_parameters.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace socsim::crowd {
namespace {

using ::testing::Contains;
using ::testing::Field;

TEST(RoleParameters, ForceDefaultsAreLightSfms) {
  // robotics-upo/lightsfm include/lightsfm/sfm.hpp, struct Parameters.
  const ForceParameters f;
  EXPECT_EQ(f.desired_factor, 2.0);
  EXPECT_EQ(f.obstacle_factor, 10.0);
  EXPECT_EQ(f.obstacle_sigma, 0.2);
  EXPECT_EQ(f.social_factor, 2.1);
  EXPECT_EQ(f.group_gaze_factor, 3.0);
  EXPECT_EQ(f.group_coherence_factor, 2.0);
  EXPECT_EQ(f.group_repulsion_factor, 1.0);
  EXPECT_EQ(f.lambda, 2.0);
  EXPECT_EQ(f.gamma, 0.35);
  EXPECT_EQ(f.n, 2.0);
  EXPECT_EQ(f.n_prime, 3.0);
  EXPECT_EQ(f.relaxation_time, 0.5);
}

TEST(RoleParameters, BuiltInRolesAreValidAndAdultFollowsWeidmann) {
  const RoleTable t = RoleTable::defaults();
  for (const std::string& name : t.names()) EXPECT_TRUE(validate(t.at(*t.index_of(name)))) << name;
  const RoleParameters& adult = t.at(*t.index_of("adult"));
  EXPECT_DOUBLE_EQ(adult.speed.mean, 1.34);  // Weidmann (1993)
  EXPECT_DOUBLE_EQ(adult.speed.sd, 0.26);
  EXPECT_TRUE(t.index_of("jogger"));
  EXPECT_TRUE(t.index_of("stroller_pusher"));
  EXPECT_LT(t.at(*t.index_of("elderly")).speed.mean, adult.speed.mean);
}

TEST(RoleParameters, JsonRoundTripAndPartialOverride) {
  const RoleTable t = RoleTable::defaults();
  const RoleParameters& adult = t.at(*t.index_of("adult"));
  auto same = role_parameters_from_json(to_json(adult), RoleParameters{});
  ASSERT_TRUE(same) << same.error().message();
  EXPECT_EQ(*same, adult);

  auto faster =
      role_parameters_from_json(Json::parse(R"({"speed": {"mean": 1.6}, "forces": {"lambda": 1.5}})"), adult);
  ASSERT_TRUE(faster) << faster.error().message();
  EXPECT_DOUBLE_EQ(faster->speed.mean, 1.6);
  EXPECT_DOUBLE_EQ(faster->speed.sd, 0.26);
  EXPECT_DOUBLE_EQ(faster->forces.lambda, 1.5);
  EXPECT_DOUBLE_EQ(faster->forces.gamma, 0.35);
}

TEST(RoleParameters, TableAppliesOverridesAndAddsRoles) {
  RoleTable t = RoleTable::defaults();
  auto ok = t.apply_json(
      Json::parse(R"({"nurse": {"speed": {"mean": 1.5, "sd": 0.1}}, "adult": {"radius": 0.25}})"));
  ASSERT_TRUE(ok) << ok.error().message();
  ASSERT_TRUE(t.index_of("nurse"));
  EXPECT_DOUBLE_EQ(t.at(*t.index_of("nurse")).speed.mean, 1.5);
  EXPECT_DOUBLE_EQ(t.at(*t.index_of("nurse")).radius, 0.23);  // from adult
  EXPECT_DOUBLE_EQ(t.at(*t.index_of("adult")).radius, 0.25);
}

TEST(RoleParameters, BadOverridesNameTheFieldAndChangeNothing) {
  RoleTable t = RoleTable::defaults();
  auto bad = t.apply_json(Json::parse(R"({
    "adult": {"radius": -1, "forces": {"gamma": 0, "unknown": 1}},
    "child": {"speed": {"min": 2.0, "max": 1.0}},
    "robot": {"max_speed_factor": 3.0, "speed": {"max": 4.0}}
  })"),
                          "/roles");
  ASSERT_FALSE(bad);
  const auto& e = bad.error().errors;
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/roles/adult/radius")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/roles/adult/forces/gamma")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/roles/adult/forces/unknown")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/roles/child/speed/min")));
  EXPECT_THAT(e, Contains(Field(&FieldError::pointer, "/roles/robot/max_speed_factor")));
  EXPECT_FALSE(t.index_of("child"));
  EXPECT_DOUBLE_EQ(t.at(*t.index_of("adult")).radius, 0.23);
  // The speed–headway parameters are checked like the LightSFM ones.
  auto headway =
      t.apply_json(Json::parse(R"({"adult": {"forces": {"headway_time": -1, "headway_distance": "far"}}})"));
  ASSERT_FALSE(headway);
  EXPECT_THAT(headway.error().errors, Contains(Field(&FieldError::pointer, "/adult/forces/headway_time")));
  EXPECT_THAT(headway.error().errors,
              Contains(Field(&FieldError::pointer, "/adult/forces/headway_distance")));
  EXPECT_DOUBLE_EQ(t.at(*t.index_of("adult")).forces.headway_time, 0.6);
  EXPECT_FALSE(t.apply_json(Json::array()));
}

}  // namespace
}  // namespace socsim::crowd
