#include "core/interop/foxglove_scene.hpp"

#include <charconv>
#include <cmath>

namespace socsim::interop {
namespace {

constexpr double kPersonHeight = 1.7;  // m, the cylinders drawn for people
constexpr double kWallThickness = 0.1;

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

}  // namespace

void put_shortest(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0.0;
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

// Walls as boxes, zones as outlines with their names, doors as green openings.
std::string world_scene_update(const world::World& world, std::uint64_t ns, const std::string& frame_id) {
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

PeopleSceneEncoder::PeopleSceneEncoder(const std::string& frame_id, std::vector<double> diameters,
                                       std::vector<std::string> colors)
    : frame_id_(Json(frame_id).dump()), diameters_(std::move(diameters)), colors_(std::move(colors)) {}

const std::string& PeopleSceneEncoder::encode(std::uint64_t ns,
                                              std::span<const crowd::PedestrianState> people,
                                              std::span<const std::uint16_t> roles) {
  out_.clear();
  out_ += R"({"deletions":[],"entities":[{"timestamp":{"sec":)";
  put_shortest(out_, static_cast<double>(ns / 1'000'000'000u));
  out_ += R"(,"nsec":)";
  put_shortest(out_, static_cast<double>(ns % 1'000'000'000u));
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
    put_shortest(out_, kPersonHeight / 2);
    out_ += R"(},"orientation":{"x":0,"y":0,"z":0,"w":1}},"size":{"x":)";
    const double d = diameters_.at(roles[i]);
    put_shortest(out_, d);
    out_ += R"(,"y":)";
    put_shortest(out_, d);
    out_ += R"(,"z":)";
    put_shortest(out_, kPersonHeight);
    out_ += R"(},"bottom_scale":1,"top_scale":1,"color":)";
    out_ += colors_.at(roles[i]);
    out_ += '}';
  }
  out_ += R"(],"lines":[],"triangles":[],"texts":[],"models":[]}]})";
  return out_;
}

std::string role_color(std::size_t i) {
  // A fixed palette in the log's role order.
  static const double palette[][3] = {{0.95, 0.55, 0.2},  {0.3, 0.75, 0.95}, {0.9, 0.35, 0.6},
                                      {0.55, 0.85, 0.35}, {0.95, 0.85, 0.3}, {0.7, 0.5, 0.95}};
  const auto& c = palette[i % std::size(palette)];
  return color(c[0], c[1], c[2]).dump();
}

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

}  // namespace socsim::interop
