#pragma once
// socsim_people_msgs (schemas/ros2/socsim_people_msgs): the ros2msg schema text MCAP carries for
// socsim_people_msgs/msg/People, and People messages in ROS 2 CDR from pedestrian states.
#include <span>
#include <string>
#include <string_view>

#include "core/crowd/pedestrian_state.hpp"
#include "core/interop/cdr_writer.hpp"

namespace socsim::interop {

inline constexpr std::string_view kPeopleMsgType = "socsim_people_msgs/msg/People";

// One package .msg file as shipped ("Person" → schemas/ros2/socsim_people_msgs/msg/Person.msg);
// empty when there is no such message.
const std::string& people_msg_file(std::string_view name);

// People.msg, then each message it depends on (ours and std_msgs, geometry_msgs,
// builtin_interfaces), each after a line of 80 '=' and "MSG: package/Type": the ros2msg encoding.
const std::string& people_msg_definition();

// Nanoseconds of a time in seconds (rounded), as MCAP log times and ROS stamps count them.
std::uint64_t to_nanoseconds(double seconds);

// One socsim_people_msgs/msg/People message: header {stamp = time, frame_id}, people in the given
// order, and groups (people sharing a group_id >= 0), ascending by id. The writer is reset first.
void encode_people_cdr(CdrWriter& out, double time, std::string_view frame_id,
                       std::span<const crowd::PedestrianState> people);

}  // namespace socsim::interop
