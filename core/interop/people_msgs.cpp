#include "core/interop/people_msgs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace socsim::interop {

// Generated from schemas/ros2/socsim_people_msgs/msg/*.msg (core/interop/CMakeLists.txt).
const std::map<std::string, std::string>& embedded_people_msgs();

namespace {

// The ROS 2 definitions our messages use (common_interfaces, builtin_interfaces), as ros2msg
// dependency sections name them.
constexpr std::pair<std::string_view, std::string_view> kRosDefinitions[] = {
    {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
    {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
    {"geometry_msgs/Pose", "Point position\nQuaternion orientation\n"},
    {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
    {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
    {"geometry_msgs/Twist", "Vector3 linear\nVector3 angular\n"},
    {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
};

// Dependencies of People, depth first in field order, each once.
constexpr std::string_view kPeopleDependencies[] = {
    "std_msgs/Header",
    "builtin_interfaces/Time",
    "socsim_people_msgs/Person",
    "geometry_msgs/Pose",
    "geometry_msgs/Point",
    "geometry_msgs/Quaternion",
    "geometry_msgs/Twist",
    "geometry_msgs/Vector3",
    "socsim_people_msgs/Intent",
    "socsim_people_msgs/Proxemics",
    "socsim_people_msgs/PersonMetadata",
    "socsim_people_msgs/Group",
};

std::string_view definition_of(std::string_view type) {
  for (const auto& [name, text] : kRosDefinitions)
    if (name == type) return text;
  const std::string_view ours = "socsim_people_msgs/";
  if (type.substr(0, ours.size()) == ours) return people_msg_file(type.substr(ours.size()));
  return {};
}

void put_vector3(CdrWriter& out, double x, double y, double z) {
  out.f64(x);
  out.f64(y);
  out.f64(z);
}

}  // namespace

const std::string& people_msg_file(std::string_view name) {
  static const std::string none;
  const auto& files = embedded_people_msgs();
  auto it = files.find("socsim_people_msgs/msg/" + std::string(name) + ".msg");
  return it == files.end() ? none : it->second;
}

const std::string& people_msg_definition() {
  static const std::string text = [] {
    std::string t = people_msg_file("People");
    for (std::string_view dep : kPeopleDependencies) {
      if (!t.empty() && t.back() != '\n') t += '\n';
      t += std::string(80, '=') + "\nMSG: " + std::string(dep) + "\n";
      t += definition_of(dep);
    }
    return t;
  }();
  return text;
}

std::uint64_t to_nanoseconds(double seconds) {
  return seconds <= 0.0 ? 0 : static_cast<std::uint64_t>(std::llround(seconds * 1e9));
}

// Orientation components on a binary grid of 2^-12: a heading within 0.03 degrees, and a quarter of
// the bytes of full-precision components once compressed.
constexpr double kQuaternionSteps = 4096.0;

void encode_people_cdr(CdrWriter& out, double time, std::string_view frame_id,
                       std::span<const crowd::PedestrianState> people) {
  out.reset();
  const std::uint64_t ns = to_nanoseconds(time);
  out.i32(static_cast<std::int32_t>(ns / 1'000'000'000u));
  out.u32(static_cast<std::uint32_t>(ns % 1'000'000'000u));
  out.string(frame_id);

  out.sequence_size(people.size());
  for (const crowd::PedestrianState& p : people) {
    out.u32(p.id.value());
    put_vector3(out, p.pose.x, p.pose.y, 0.0);  // pose.position
    // pose.orientation: yaw about +z, in float precision (1e-7 rad): states are float32 in logs and
    // frames, and the full-precision sin/cos would double the compressed size of a recording.
    const double half_yaw = p.pose.yaw / 2;
    out.f64(0.0);
    out.f64(0.0);
    out.f64(std::round(std::sin(half_yaw) * kQuaternionSteps) / kQuaternionSteps);
    out.f64(std::round(std::cos(half_yaw) * kQuaternionSteps) / kQuaternionSteps);
    put_vector3(out, p.twist.vx, p.twist.vy, 0.0);  // twist.linear
    put_vector3(out, 0.0, 0.0, p.twist.omega);      // twist.angular
    out.u8(static_cast<std::uint8_t>(p.activity));  // the STATE_* constants follow crowd::Activity
    out.string(p.role);
    out.string(p.intent.target);
    out.i64(p.intent.goal_id);
    out.i64(p.group_id);
    out.f64(p.proxemics.intimate_radius);
    out.f64(p.proxemics.comfort_radius);
    out.f64(p.proxemics.social_radius);
    out.f64(p.proxemics.compliance);
    out.u64(p.metadata.seed);
    out.string(p.metadata.bt_node);
    out.sequence_size(p.metadata.tags.size());
    for (const std::string& tag : p.metadata.tags) out.string(tag);
  }

  // Groups: (group_id, person index) sorted, so members come in the people's order.
  std::vector<std::pair<std::int64_t, std::size_t>> members;
  for (std::size_t i = 0; i < people.size(); ++i)
    if (people[i].group_id >= 0) members.emplace_back(people[i].group_id, i);
  std::stable_sort(members.begin(), members.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t groups = 0;
  for (std::size_t i = 0; i < members.size(); ++i)
    groups += i == 0 || members[i].first != members[i - 1].first;
  out.sequence_size(groups);
  for (std::size_t begin = 0; begin < members.size();) {
    std::size_t end = begin;
    while (end < members.size() && members[end].first == members[begin].first) ++end;
    out.i64(members[begin].first);
    out.sequence_size(end - begin);
    double cx = 0, cy = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const crowd::PedestrianState& p = people[members[k].second];
      out.u32(p.id.value());
      cx += p.pose.x;
      cy += p.pose.y;
    }
    const double n = static_cast<double>(end - begin);
    put_vector3(out, cx / n, cy / n, 0.0);
    begin = end;
  }
}

}  // namespace socsim::interop
