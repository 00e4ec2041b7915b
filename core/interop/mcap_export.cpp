#include "core/interop/mcap_export.hpp"

#include <charconv>
#include <cmath>
#include <vector>

#include "core/crowd/role_parameters.hpp"
#include "core/interop/foxglove_scene.hpp"
#include "core/interop/people_msgs.hpp"

namespace socsim::interop {

Result<std::string> export_mcap(const scenario::TrajectoryLog& log, const world::World& world,
                                const McapExportOptions& options) {
  crowd::RoleTable table = crowd::RoleTable::defaults();
  if (!options.roles.is_null())
    if (auto s = table.apply_json(options.roles, "/roles"); !s) return tl::unexpected(s.error());
  // Per logged role: its parameters (proxemics, body size) from the program's table.
  std::vector<crowd::Proxemics> proxemics;
  std::vector<double> diameters;
  std::vector<std::string> colors;
  for (std::size_t i = 0; i < log.roles().size(); ++i) {
    const auto index = table.index_of(log.roles()[i]);
    const crowd::RoleParameters role = index ? table.at(*index) : crowd::RoleParameters{};
    proxemics.push_back(role.proxemics);
    diameters.push_back(2 * role.radius);
    colors.push_back(role_color(i));
  }

  McapOptions mcap;
  mcap.profile = "ros2";
  mcap.compression = options.compression;
  mcap.zstd_level = options.zstd_level;
  mcap.chunk_size = options.chunk_size;
  McapWriter writer(mcap);
  const bool scene_people = options.scene_people.value_or(log.agent_count() <= kScenePeopleLimit);
  const std::uint16_t people_schema = writer.add_schema(kPeopleMsgType, "ros2msg", people_msg_definition());
  const std::uint16_t scene_schema =
      writer.add_schema("foxglove.SceneUpdate", "jsonschema", scene_update_json_schema().dump());
  const std::uint16_t people_channel = writer.add_channel(people_schema, "/people", "cdr");
  const std::uint16_t world_channel = writer.add_channel(scene_schema, "/scene/world", "json");
  const std::uint16_t scene_channel =
      scene_people ? writer.add_channel(scene_schema, "/scene/people", "json") : 0;

  const geometry::Box box = world.bounds();
  auto text_of = [](double v) {
    std::string s;
    put_shortest(s, v);
    return s;
  };
  writer.add_metadata("socsim_map", {{"frame_id", options.frame_id},
                                     {"world", world.name()},
                                     {"origin_x", text_of(world.origin().x)},
                                     {"origin_y", text_of(world.origin().y)},
                                     {"origin_yaw", text_of(world.origin().yaw)},
                                     {"min_x", text_of(box.min.x)},
                                     {"min_y", text_of(box.min.y)},
                                     {"max_x", text_of(box.max.x)},
                                     {"max_y", text_of(box.max.y)},
                                     {"card_id", options.card_id},
                                     {"seed", std::to_string(options.seed)},
                                     {"frame_interval", text_of(log.frame_interval())},
                                     {"frames", std::to_string(log.frame_count())},
                                     {"agents", std::to_string(log.agent_count())}});

  const std::uint64_t first = log.frame_count() ? to_nanoseconds(log.frame_time(0)) : 0;
  const std::string world_json = world_scene_update(world, first, options.frame_id);
  writer.add_message(world_channel, first, first, world_json);

  CdrWriter cdr;
  PeopleSceneEncoder scene(options.frame_id, diameters, colors);
  std::vector<crowd::PedestrianState> people;
  std::vector<std::uint16_t> roles;
  for (std::size_t f = 0; f < log.frame_count(); ++f) {
    const auto agents = log.frame(f);
    people.resize(agents.size());
    roles.resize(agents.size());
    for (std::size_t i = 0; i < agents.size(); ++i) {
      const scenario::LoggedAgent& a = agents[i];
      crowd::PedestrianState& p = people[i];
      p.id = crowd::AgentId(a.id);
      p.pose = {a.x, a.y, a.yaw};
      p.twist = {a.vx, a.vy, 0.0};
      p.activity = a.activity;
      p.role = log.roles().at(a.role);
      p.group_id = a.group_id;
      p.proxemics = proxemics.at(a.role);
      roles[i] = a.role;
    }
    const double t = log.frame_time(f);
    const std::uint64_t ns = to_nanoseconds(t);
    encode_people_cdr(cdr, t, options.frame_id, people);
    writer.add_message(people_channel, ns, ns, cdr.bytes());
    if (scene_people) writer.add_message(scene_channel, ns, ns, scene.encode(ns, people, roles));
  }
  return writer.finish();
}

}  // namespace socsim::interop
