#include "core/crowd/pedestrian_state.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "core/common/json_check.hpp"

namespace socsim::crowd {
namespace {

constexpr std::array<std::string_view, 9> kActivityNames = {
    "walking", "standing", "queuing", "sitting", "interacting", "evacuating", "waiting", "running", "exited"};

std::string join_names() {
  std::string out;
  for (std::string_view n : kActivityNames) {
    if (!out.empty()) out += ", ";
    out += n;
  }
  return out;
}

double read_number(JsonChecker& check, const Json& obj, const std::string& ptr, std::string_view key,
                   double fallback, bool required, double lo = -1e300, double hi = 1e300) {
  auto v = check.number(obj, ptr, key, required, lo, hi);
  return v ? *v : fallback;
}

}  // namespace

std::string_view activity_name(Activity a) {
  return kActivityNames.at(static_cast<std::size_t>(a));
}

std::optional<Activity> activity_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kActivityNames.size(); ++i)
    if (kActivityNames[i] == name) return static_cast<Activity>(i);
  return std::nullopt;
}

const std::vector<std::string_view>& activity_names() {
  static const std::vector<std::string_view> names(kActivityNames.begin(), kActivityNames.end());
  return names;
}

Json to_json(const PedestrianState& s) {
  return Json{
      {"id", s.id.value()},
      {"pose", {{"x", s.pose.x}, {"y", s.pose.y}, {"yaw", s.pose.yaw}}},
      {"twist", {{"vx", s.twist.vx}, {"vy", s.twist.vy}, {"omega", s.twist.omega}}},
      {"state", activity_name(s.activity)},
      {"role", s.role},
      {"intent", {{"target", s.intent.target}, {"goal_id", s.intent.goal_id}}},
      {"group_id", s.group_id},
      {"proxemics",
       {{"intimate_radius", s.proxemics.intimate_radius},
        {"comfort_radius", s.proxemics.comfort_radius},
        {"social_radius", s.proxemics.social_radius},
        {"compliance", s.proxemics.compliance}}},
      {"metadata", {{"seed", s.metadata.seed}, {"bt_node", s.metadata.bt_node}, {"tags", s.metadata.tags}}},
  };
}

Result<PedestrianState> pedestrian_state_from_json(const Json& j, const std::string& pointer) {
  JsonChecker check;
  PedestrianState s;
  if (!j.is_object()) {
    check.add(pointer, std::string("must be an object, not ") + j.type_name());
    return tl::unexpected(check.error("invalid pedestrian state"));
  }
  check.only_keys(j, pointer,
                  {"id", "pose", "twist", "state", "role", "intent", "group_id", "proxemics", "metadata"});
  if (auto id = check.integer(j, pointer, "id", true, 0, UINT32_MAX))
    s.id = AgentId(static_cast<std::uint32_t>(*id));

  if (const Json* pose = check.object(j, pointer, "pose", true)) {
    const std::string p = JsonChecker::child(pointer, "pose");
    check.only_keys(*pose, p, {"x", "y", "yaw"});
    s.pose.x = read_number(check, *pose, p, "x", 0.0, true);
    s.pose.y = read_number(check, *pose, p, "y", 0.0, true);
    s.pose.yaw = read_number(check, *pose, p, "yaw", 0.0, false, -std::numbers::pi, std::numbers::pi);
  }
  if (const Json* twist = check.object(j, pointer, "twist", false)) {
    const std::string p = JsonChecker::child(pointer, "twist");
    check.only_keys(*twist, p, {"vx", "vy", "omega"});
    s.twist.vx = read_number(check, *twist, p, "vx", 0.0, false);
    s.twist.vy = read_number(check, *twist, p, "vy", 0.0, false);
    s.twist.omega = read_number(check, *twist, p, "omega", 0.0, false);
  }
  if (auto state = check.string(j, pointer, "state", false)) {
    if (auto a = activity_from_name(*state)) {
      s.activity = *a;
    } else {
      check.add(JsonChecker::child(pointer, "state"),
                "unknown state '" + *state + "' (one of: " + join_names() + ")");
    }
  }
  if (auto role = check.string(j, pointer, "role", false, 1, 64)) s.role = *role;
  if (const Json* intent = check.object(j, pointer, "intent", false)) {
    const std::string p = JsonChecker::child(pointer, "intent");
    check.only_keys(*intent, p, {"target", "goal_id"});
    if (auto t = check.string(*intent, p, "target", false, 0, 256)) s.intent.target = *t;
    if (auto g = check.integer(*intent, p, "goal_id", false, -1)) s.intent.goal_id = *g;
  }
  if (auto g = check.integer(j, pointer, "group_id", false, -1)) s.group_id = *g;
  if (const Json* prox = check.object(j, pointer, "proxemics", false)) {
    const std::string p = JsonChecker::child(pointer, "proxemics");
    check.only_keys(*prox, p, {"intimate_radius", "comfort_radius", "social_radius", "compliance"});
    s.proxemics.intimate_radius =
        read_number(check, *prox, p, "intimate_radius", s.proxemics.intimate_radius, false, 0, 100);
    s.proxemics.comfort_radius =
        read_number(check, *prox, p, "comfort_radius", s.proxemics.comfort_radius, false, 0, 100);
    s.proxemics.social_radius =
        read_number(check, *prox, p, "social_radius", s.proxemics.social_radius, false, 0, 100);
    s.proxemics.compliance = read_number(check, *prox, p, "compliance", s.proxemics.compliance, false, 0, 1);
    if (s.proxemics.intimate_radius > s.proxemics.comfort_radius ||
        s.proxemics.comfort_radius > s.proxemics.social_radius)
      check.add(p, "radii must satisfy intimate_radius <= comfort_radius <= social_radius");
  }
  if (const Json* meta = check.object(j, pointer, "metadata", false)) {
    const std::string p = JsonChecker::child(pointer, "metadata");
    check.only_keys(*meta, p, {"seed", "bt_node", "tags"});
    if (auto it = meta->find("seed"); it != meta->end()) {  // full 64-bit range
      if (it->is_number_unsigned()) {
        s.metadata.seed = it->get<std::uint64_t>();
      } else if (it->is_number_integer() && it->get<std::int64_t>() >= 0) {
        s.metadata.seed = static_cast<std::uint64_t>(it->get<std::int64_t>());
      } else {
        check.add(JsonChecker::child(p, "seed"), "must be an integer in [0, 2^64)");
      }
    }
    if (auto node = check.string(*meta, p, "bt_node", false, 0, 256)) s.metadata.bt_node = *node;
    if (const Json* tags = check.array(*meta, p, "tags", false, 256)) {
      const std::string tp = JsonChecker::child(p, "tags");
      for (std::size_t i = 0; i < tags->size(); ++i) {
        const Json& t = (*tags)[i];
        if (!t.is_string()) {
          check.add(JsonChecker::child(tp, i), std::string("must be a string, not ") + t.type_name());
        } else {
          s.metadata.tags.push_back(t.get<std::string>());
        }
      }
    }
  }
  if (!check.ok()) return tl::unexpected(check.error("invalid pedestrian state"));
  return s;
}

}  // namespace socsim::crowd
