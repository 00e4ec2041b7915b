// Gazebo actors from a trajectory log: the world's SDF with one <actor> per logged person whose
// trajectory has a waypoint per logged frame (or per stride), times from 0 rising, poses equal to
// the logged ones, read back with the XML reader the world importers use.
#include "core/interop/export_gazebo_actors.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "core/world/xml_reader.hpp"
#include "tests/core/interop/interop_text.hpp"

namespace socsim::interop {
namespace {

const world::XmlElement& world_of(const world::XmlElement& sdf) {
  return sdf.children.at(0);
}

TEST(GazeboActors, OneActorPerPersonWalkingTheLoggedPoses) {
  const testing::HallRun hall = testing::run_hall(2.0);
  const scenario::TrajectoryLog& log = hall.log;
  const auto sdf = world::parse_xml(export_gazebo_actors(log, hall.imported.scenario.world));
  ASSERT_TRUE(sdf) << sdf.error().message();
  EXPECT_EQ(*sdf->attribute("version"), "1.7");
  const auto actors = world_of(*sdf).children_named("actor");
  ASSERT_EQ(actors.size(), log.agent_count());
  ASSERT_EQ(world_of(*sdf).children_named("model").size(), 2u);  // floor and walls come first, as before
  const world::XmlElement& first = *actors.front();
  EXPECT_EQ(*first.attribute("name"), "person_" + std::to_string(log.frame(0)[0].id));
  const auto& script = *first.children_named("script").at(0);
  const auto waypoints = script.children_named("trajectory").at(0)->children_named("waypoint");
  ASSERT_EQ(waypoints.size(), log.frame_count());
  double last = -1;
  for (std::size_t f = 0; f < waypoints.size(); ++f) {
    const double t = std::stod(waypoints[f]->children_named("time").at(0)->text);
    EXPECT_GT(t, last);
    last = t;
    EXPECT_NEAR(t, log.frame_time(f) - log.frame_time(0), 1e-6);
    std::istringstream pose(waypoints[f]->children_named("pose").at(0)->text);
    double x, y, z, roll, pitch, yaw;
    pose >> x >> y >> z >> roll >> pitch >> yaw;
    EXPECT_NEAR(x, log.frame(f)[0].x, 1e-6);  // the hall's origin is the identity
    EXPECT_NEAR(y, log.frame(f)[0].y, 1e-6);
    EXPECT_NEAR(yaw, log.frame(f)[0].yaw, 1e-6);
  }

  GazeboActorOptions options;
  options.frame_stride = 5;
  const auto sparse = world::parse_xml(export_gazebo_actors(log, hall.imported.scenario.world, options));
  ASSERT_TRUE(sparse);
  const auto sparse_points = world_of(*sparse)
                                 .children_named("actor")
                                 .front()
                                 ->children_named("script")
                                 .at(0)
                                 ->children_named("trajectory")
                                 .at(0)
                                 ->children_named("waypoint");
  EXPECT_EQ(sparse_points.size(), (log.frame_count() - 1) / 5 + 1 + ((log.frame_count() - 1) % 5 != 0));
}

}  // namespace
}  // namespace socsim::interop
