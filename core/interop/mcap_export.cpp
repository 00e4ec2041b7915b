#include "core/interop/mcap_export.hpp"

#include <charconv>
#include <cmath>
#include <vector>

#include "core/crowd/role_parameters.hpp"
#include "core/interop/people_msgs.hpp"

namespace socsim::interop {
namespace {

constexpr double kPersonHeight = 1.7;  // m, the cylinders drawn for people
constexpr double kWallThickness = 0.1;

void put_number(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0.0;
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

void put_millimetres(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0.0;
  char buf[40];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 3);
  out.append(buf, ec == std::errc() ? end : buf);
}

Json color(double r, double g, double b, double a = 1.0) {
  return {{"r", r}, {"g", g}, {"b", b}, {"a", a}};
}

Json time_json(std::uint64_t ns) {
  return {{"sec", ns / 1'000'000'000u}, {"nsec", ns % 1'000'000'000u}};
}

Json pose_json(double x, double y, double z, double yaw) {
  return {{"position", {{"x", x}, {"y", y}, {"z", z}}},
          {"orientation", {{"x", 0.0}, {"y", 0.0}, {"z", std::sin(yaw / 2)}, {"w", std::cos(yaw / 2)}}}};
}

// A SceneEntity with every primitive list present (empty unless filled).
Json scene_entity(std::uint64_t ns, const std::string& frame_id, const std::string& id) {
  Json e = {{"timestamp", time_json(ns)}, {"frame_id", frame_id},  {"id", id},
            {"lifetime", time_json(0)},   {"frame_locked", false}, {"metadata", Json::array()}};
  for (const char* list :
       {"arrows", "cubes", "spheres", "cylinders", "lines", "triangles", "texts", "models"})
    e[list] = Json::array();
  return e;
}

Json line(int type, const std::vector<geometry::Point>& points, double thickness, const Json& rgba) {
  Json pts = Json::array();
  for (const auto& p : points) pts.push_back({{"x", p.x}, {"y", p.y}, {"z", 0.02}});
  return {{"type", type},
          {"pose", pose_json(0, 0, 0, 0)},
          {"thickness", thickness},
          {"scale_invariant", false},
          {"points", pts},
          {"color", rgba},
          {"colors", Json::array()},
          {"indices", Json::array()}};
}

Json text(const std::string& s, double x, double y, double z) {
  return {
      {"pose", pose_json(x, y, z, 0)}, {"billboard", true}, {"font_size", 0.4}, {"scale_invariant", false},
      {"color", color(1, 1, 1, 0.9)},  {"text", s}};
}

// Walls as boxes, zones as outlines with their names, doors as green openings.
std::string world_scene(const world::World& world, std::uint64_t ns, const std::string& frame_id) {
  Json walls = scene_entity(ns, frame_id, "walls");
  for (const world::Wall& w : world.walls()) {
    const double dx = w.segment.b.x - w.segment.a.x, dy = w.segment.b.y - w.segment.a.y;
    walls["cubes"].push_back(
        {{"pose", pose_json((w.segment.a.x + w.segment.b.x) / 2, (w.segment.a.y + w.segment.b.y) / 2,
                            w.height / 2, std::atan2(dy, dx))},
         {"size", {{"x", std::hypot(dx, dy)}, {"y", kWallThickness}, {"z", w.height}}},
         {"color", color(0.6, 0.6, 0.65)}});
  }
  Json zones = scene_entity(ns, frame_id, "zones");
  for (const world::Zone& z : world.zones()) {
    zones["lines"].push_back(line(1, z.polygon.outer, 0.05, color(0.3, 0.6, 1.0, 0.8)));
    double cx = 0, cy = 0;
    for (const auto& p : z.polygon.outer) cx += p.x, cy += p.y;
    const double n = std::max<double>(1, static_cast<double>(z.polygon.outer.size()));
    zones["texts"].push_back(text(z.name + " (" + z.type + ")", cx / n, cy / n, 0.1));
  }
  Json doors = scene_entity(ns, frame_id, "doors");
  for (const world::Door& d : world.doors()) {
    doors["lines"].push_back(line(0, {d.opening.a, d.opening.b}, 0.15, color(0.2, 0.9, 0.3)));
    doors["texts"].push_back(text(d.name, d.pose.x, d.pose.y, 2.2));
  }
  return Json{{"deletions", Json::array()}, {"entities", {walls, zones, doors}}}.dump();
}

// The per-frame people entity, written by hand (it is most of a large card's JSON).
class PeopleScene {
 public:
  PeopleScene(const std::string& frame_id, const std::vector<double>& diameters,
              const std::vector<std::string>& colors)
      : frame_id_(Json(frame_id).dump()), diameters_(diameters), colors_(colors) {}

  const std::string& encode(std::uint64_t ns, std::span<const crowd::PedestrianState> people,
                            std::span<const std::uint16_t> roles) {
    out_.clear();
    out_ += R"({"deletions":[],"entities":[{"timestamp":{"sec":)";
    put_number(out_, static_cast<double>(ns / 1'000'000'000u));
    out_ += R"(,"nsec":)";
    put_number(out_, static_cast<double>(ns % 1'000'000'000u));
    out_ += R"(},"frame_id":)" + frame_id_;
    out_ += R"(,"id":"people","lifetime":{"sec":0,"nsec":0},"frame_locked":false,"metadata":[],)"
            R"("arrows":[],"cubes":[],"spheres":[],"cylinders":[)";
    for (std::size_t i = 0; i < people.size(); ++i) {
      const crowd::PedestrianState& p = people[i];
      if (i) out_ += ',';
      // A cylinder is the same at every yaw; positions to the millimetre are plenty to draw.
      out_ += R"({"pose":{"position":{"x":)";
      put_millimetres(out_, p.pose.x);
      out_ += R"(,"y":)";
      put_millimetres(out_, p.pose.y);
      out_ += R"(,"z":)";
      put_number(out_, kPersonHeight / 2);
      out_ += R"(},"orientation":{"x":0,"y":0,"z":0,"w":1}},"size":{"x":)";
      const double d = diameters_.at(roles[i]);
      put_number(out_, d);
      out_ += R"(,"y":)";
      put_number(out_, d);
      out_ += R"(,"z":)";
      put_number(out_, kPersonHeight);
      out_ += R"(},"bottom_scale":1,"top_scale":1,"color":)";
      out_ += colors_.at(roles[i]);
      out_ += '}';
    }
    out_ += R"(],"lines":[],"triangles":[],"texts":[],"models":[]}]})";
    return out_;
  }

 private:
  std::string frame_id_;
  const std::vector<double>& diameters_;
  const std::vector<std::string>& colors_;
  std::string out_;
};

Json color_of_role(std::size_t i) {
  // A fixed palette in the log's role order.
  static const double palette[][3] = {{0.95, 0.55, 0.2},  {0.3, 0.75, 0.95}, {0.9, 0.35, 0.6},
                                      {0.55, 0.85, 0.35}, {0.95, 0.85, 0.3}, {0.7, 0.5, 0.95}};
  const auto& c = palette[i % std::size(palette)];
  return color(c[0], c[1], c[2]);
}

}  // namespace

const Json& scene_update_json_schema() {
  static const Json schema = [] {
    const Json number = {{"type", "number"}};
    const Json vec3 = {{"type", "object"},
                       {"properties", {{"x", number}, {"y", number}, {"z", number}}},
                       {"required", {"x", "y", "z"}}};
    const Json quat = {{"type", "object"},
                       {"properties", {{"x", number}, {"y", number}, {"z", number}, {"w", number}}},
                       {"required", {"x", "y", "z", "w"}}};
    const Json rgba = {{"type", "object"},
                       {"properties", {{"r", number}, {"g", number}, {"b", number}, {"a", number}}},
                       {"required", {"r", "g", "b", "a"}}};
    const Json pose = {{"type", "object"},
                       {"properties", {{"position", vec3}, {"orientation", quat}}},
                       {"required", {"position", "orientation"}}};
    const Json time = {{"type", "object"},
                       {"properties",
                        {{"sec", {{"type", "integer"}, {"minimum", 0}}},
                         {"nsec", {{"type", "integer"}, {"minimum", 0}, {"maximum", 999999999}}}}},
                       {"required", {"sec", "nsec"}}};
    auto list = [](const Json& item) { return Json{{"type", "array"}, {"items", item}}; };
    auto object = [](Json properties) {
      Json required = Json::array();
      for (const auto& [k, v] : properties.items()) required.push_back(k);
      return Json{{"type", "object"}, {"properties", std::move(properties)}, {"required", required}};
    };
    const Json cube = object({{"pose", pose}, {"size", vec3}, {"color", rgba}});
    const Json cylinder = object(
        {{"pose", pose}, {"size", vec3}, {"bottom_scale", number}, {"top_scale", number}, {"color", rgba}});
    const Json line_primitive = object({{"type", {{"type", "integer"}, {"enum", {0, 1, 2}}}},
                                        {"pose", pose},
                                        {"thickness", number},
                                        {"scale_invariant", {{"type", "boolean"}}},
                                        {"points", list(vec3)},
                                        {"color", rgba},
                                        {"colors", list(rgba)},
                                        {"indices", list({{"type", "integer"}, {"minimum", 0}})}});
    const Json text_primitive = object({{"pose", pose},
                                        {"billboard", {{"type", "boolean"}}},
                                        {"font_size", number},
                                        {"scale_invariant", {{"type", "boolean"}}},
                                        {"color", rgba},
                                        {"text", {{"type", "string"}}}});
    const Json entity =
        object({{"timestamp", time},
                {"frame_id", {{"type", "string"}}},
                {"id", {{"type", "string"}}},
                {"lifetime", time},
                {"frame_locked", {{"type", "boolean"}}},
                {"metadata", list(object({{"key", {{"type", "string"}}}, {"value", {{"type", "string"}}}}))},
                {"arrows", list({{"type", "object"}})},
                {"cubes", list(cube)},
                {"spheres", list({{"type", "object"}})},
                {"cylinders", list(cylinder)},
                {"lines", list(line_primitive)},
                {"triangles", list({{"type", "object"}})},
                {"texts", list(text_primitive)},
                {"models", list({{"type", "object"}})}});
    const Json deletion = object({{"timestamp", time},
                                  {"type", {{"type", "integer"}, {"enum", {0, 1}}}},
                                  {"id", {{"type", "string"}}}});
    Json s = object({{"deletions", list(deletion)}, {"entities", list(entity)}});
    s["title"] = "foxglove.SceneUpdate";
    s["$schema"] = "https://json-schema.org/draft/2020-12/schema";
    return s;
  }();
  return schema;
}

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
    colors.push_back(color_of_role(i).dump());
  }

  McapOptions mcap;
  mcap.profile = "ros2";
  mcap.compression = options.compression;
  mcap.zstd_level = options.zstd_level;
  mcap.chunk_size = options.chunk_size;
  McapWriter writer(mcap);
  const std::uint16_t people_schema = writer.add_schema(kPeopleMsgType, "ros2msg", people_msg_definition());
  const std::uint16_t scene_schema =
      writer.add_schema("foxglove.SceneUpdate", "jsonschema", scene_update_json_schema().dump());
  const std::uint16_t people_channel = writer.add_channel(people_schema, "/people", "cdr");
  const std::uint16_t world_channel = writer.add_channel(scene_schema, "/scene/world", "json");
  const std::uint16_t scene_channel =
      options.scene_people ? writer.add_channel(scene_schema, "/scene/people", "json") : 0;

  const geometry::Box box = world.bounds();
  auto text_of = [](double v) {
    std::string s;
    put_number(s, v);
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
  const std::string world_json = world_scene(world, first, options.frame_id);
  writer.add_message(world_channel, first, first, world_json);

  CdrWriter cdr;
  PeopleScene scene(options.frame_id, diameters, colors);
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
    if (options.scene_people) writer.add_message(scene_channel, ns, ns, scene.encode(ns, people, roles));
  }
  return writer.finish();
}

}  // namespace socsim::interop
