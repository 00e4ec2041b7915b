#include "core/world/world_document.hpp"

#include <cmath>
#include <numbers>

#include "core/common/json_check.hpp"

namespace socsim::world {

namespace {

struct Units {
  double length = 1.0;  // metres per unit
  double angle = 1.0;   // radians per unit
};

class DocumentReader {
 public:
  explicit DocumentReader(JsonChecker& check) : check_(check) {}

  Units units(const Json& doc) {
    Units u;
    const Json* units = check_.object(doc, "", "units", false);
    if (!units) return u;
    check_.only_keys(*units, "/units", {"length", "angle"});
    if (auto len = check_.string(*units, "/units", "length", false)) {
      if (*len == "m")
        u.length = 1.0;
      else if (*len == "cm")
        u.length = 0.01;
      else if (*len == "mm")
        u.length = 0.001;
      else if (*len == "ft")
        u.length = 0.3048;
      else if (*len == "in")
        u.length = 0.0254;
      else
        check_.add("/units/length", "unknown length unit '" + *len + "' (known: m, cm, mm, ft, in)");
    }
    if (auto ang = check_.string(*units, "/units", "angle", false)) {
      if (*ang == "rad")
        u.angle = 1.0;
      else if (*ang == "deg")
        u.angle = std::numbers::pi / 180.0;
      else
        check_.add("/units/angle", "unknown angle unit '" + *ang + "' (known: rad, deg)");
    }
    units_ = u;
    return u;
  }

  std::optional<double> number_at(const Json& v, const std::string& ptr) {
    if (!v.is_number()) {
      check_.add(ptr, std::string("must be a number, not ") + v.type_name());
      return std::nullopt;
    }
    const double d = v.get<double>();
    if (!std::isfinite(d)) {
      check_.add(ptr, "must be a finite number");
      return std::nullopt;
    }
    return d;
  }

  std::optional<Point> point_at(const Json& v, const std::string& ptr) {
    if (!v.is_array() || v.size() != 2) {
      check_.add(ptr, "must be a point [x, y]");
      return std::nullopt;
    }
    auto x = number_at(v[0], ptr + "/0");
    auto y = number_at(v[1], ptr + "/1");
    if (!x || !y) return std::nullopt;
    return Point{*x * units_.length, *y * units_.length};
  }

  std::optional<Point> point(const Json& obj, const std::string& ptr, const char* key) {
    const Json* v = find(obj, ptr, key, true);
    if (!v) return std::nullopt;
    return point_at(*v, JsonChecker::child(ptr, key));
  }

  std::optional<Pose2> pose(const Json& obj, const std::string& ptr, const char* key, bool required) {
    const Json* v = find(obj, ptr, key, required);
    if (!v) return std::nullopt;
    const std::string p = JsonChecker::child(ptr, key);
    if (!v->is_array() || v->size() < 2 || v->size() > 3) {
      check_.add(p, "must be a pose [x, y] or [x, y, yaw]");
      return std::nullopt;
    }
    auto x = number_at((*v)[0], p + "/0");
    auto y = number_at((*v)[1], p + "/1");
    std::optional<double> yaw = 0.0;
    if (v->size() == 3) yaw = number_at((*v)[2], p + "/2");
    if (!x || !y || !yaw) return std::nullopt;
    return Pose2{*x * units_.length, *y * units_.length, *yaw * units_.angle};
  }

  std::optional<Polygon> polygon(const Json& obj, const std::string& ptr, const char* key) {
    const Json* v = check_.array(obj, ptr, key, true, kMaxPolygonPoints);
    if (!v) return std::nullopt;
    const std::string p = JsonChecker::child(ptr, key);
    Polygon poly;
    bool ok = true;
    for (std::size_t i = 0; i < v->size(); ++i) {
      auto q = point_at((*v)[i], JsonChecker::child(p, i));
      if (q)
        poly.outer.push_back(*q);
      else
        ok = false;
    }
    if (!ok) return std::nullopt;
    // A closed ring ([..., first]) is accepted; it is stored open.
    if (poly.outer.size() > 1 && poly.outer.front() == poly.outer.back()) poly.outer.pop_back();
    if (poly.outer.size() < 3) {
      check_.add(p, "a polygon needs at least 3 points");
      return std::nullopt;
    }
    return poly;
  }

  std::optional<double> length(const Json& obj, const std::string& ptr, const char* key, bool required) {
    auto d = check_.number(obj, ptr, key, required);
    if (!d) return std::nullopt;
    return *d * units_.length;
  }

  std::vector<std::string> strings(const Json& obj, const std::string& ptr, const char* key,
                                   std::size_t max_items) {
    std::vector<std::string> out;
    const Json* v = check_.array(obj, ptr, key, false, max_items);
    if (!v) return out;
    const std::string p = JsonChecker::child(ptr, key);
    for (std::size_t i = 0; i < v->size(); ++i) {
      if (!(*v)[i].is_string()) {
        check_.add(JsonChecker::child(p, i), std::string("must be a string, not ") + (*v)[i].type_name());
        continue;
      }
      out.push_back((*v)[i].get<std::string>());
    }
    return out;
  }

  // Each element of an optional list of objects.
  template <class Fn>
  void each(const Json& doc, const char* key, bool required, Fn&& fn) {
    const Json* list = check_.array(doc, "", key, required, kMaxWorldElements);
    if (!list) return;
    const std::string base = JsonChecker::child("", key);
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string ptr = JsonChecker::child(base, i);
      const Json& item = (*list)[i];
      if (!item.is_object()) {
        check_.add(ptr, std::string("must be an object, not ") + item.type_name());
        continue;
      }
      fn(item, ptr);
    }
  }

  const Json* find(const Json& obj, const std::string& ptr, const char* key, bool required) {
    auto it = obj.find(key);
    if (it == obj.end() || it->is_null()) {
      if (required) check_.add(JsonChecker::child(ptr, key), "is required");
      return nullptr;
    }
    return &*it;
  }

 private:
  JsonChecker& check_;
  Units units_;
};

Json point_json(Point p) {
  return Json::array({p.x, p.y});
}

Json pose_json(const Pose2& p) {
  if (p.yaw == 0.0) return Json::array({p.x, p.y});
  return Json::array({p.x, p.y, p.yaw});
}

Json polygon_json(const Polygon& poly) {
  Json out = Json::array();
  for (const Point& p : poly.outer) out.push_back(point_json(p));
  return out;
}

}  // namespace

std::string infer_roi_kind(std::string_view name) {
  std::string_view base = name;
  const auto us = base.find_last_of('_');
  if (us != std::string_view::npos && us + 1 < base.size() &&
      base.find_first_not_of("0123456789", us + 1) == std::string_view::npos) {
    base = base.substr(0, us);
  }
  return is_roi_kind(base) ? std::string(base) : std::string("area");
}

Result<WorldBuilder> builder_from_document(const Json& doc) {
  JsonChecker check;
  if (!doc.is_object()) {
    check.add("", std::string("a world document must be an object, not ") + doc.type_name());
    return tl::unexpected(check.error("the world document is not valid"));
  }
  check.only_keys(
      doc, "", {"name", "units", "origin", "floor", "zones", "walls", "doors", "segmentation", "entities"});
  DocumentReader read(check);
  read.units(doc);
  WorldBuilder b;
  if (auto name = check.string(doc, "", "name", false, 0, 128)) b.set_name(*name);
  if (auto origin = read.pose(doc, "", "origin", false)) b.set_origin(*origin);
  if (const Json* floor = check.object(doc, "", "floor", false)) {
    check.only_keys(*floor, "/floor", {"material"});
    if (auto m = check.string(*floor, "/floor", "material", false)) b.set_floor(Floor{*m});
  }
  read.each(doc, "zones", true, [&](const Json& z, const std::string& ptr) {
    check.only_keys(z, ptr, {"name", "type", "material", "polygon"});
    auto name = check.string(z, ptr, "name", true);
    auto type = check.string(z, ptr, "type", false);
    auto material = check.string(z, ptr, "material", false);
    // Without a polygon the builder infers the zone's region (Fig. 3 names the zone only).
    const bool has_polygon = z.contains("polygon") && !z["polygon"].is_null();
    auto poly = has_polygon ? read.polygon(z, ptr, "polygon") : std::optional<Polygon>(Polygon{});
    if (name && poly) b.add_zone(Zone{*name, type.value_or("room"), material.value_or(""), *poly});
  });
  read.each(doc, "walls", false, [&](const Json& w, const std::string& ptr) {
    check.only_keys(w, ptr, {"start", "end", "height", "style"});
    auto a = read.point(w, ptr, "start");
    auto e = read.point(w, ptr, "end");
    auto h = read.length(w, ptr, "height", false);
    auto style = check.string(w, ptr, "style", false);
    b.add_wall(Wall{{a.value_or(Point{}), e.value_or(Point{})}, h.value_or(3.0), style.value_or("")});
  });
  read.each(doc, "doors", false, [&](const Json& d, const std::string& ptr) {
    check.only_keys(d, ptr, {"name", "pose", "width", "connects"});
    DoorSpec spec;
    spec.name = check.string(d, ptr, "name", true).value_or("");
    spec.pose = read.pose(d, ptr, "pose", true).value_or(Pose2{});
    spec.width = read.length(d, ptr, "width", true).value_or(0.0);
    spec.connects = read.strings(d, ptr, "connects", 2);
    b.add_door(std::move(spec));
  });
  read.each(doc, "segmentation", false, [&](const Json& r, const std::string& ptr) {
    check.only_keys(r, ptr, {"name", "kind", "polygon"});
    auto name = check.string(r, ptr, "name", true);
    auto kind = check.string(r, ptr, "kind", false);
    auto poly = read.polygon(r, ptr, "polygon");
    const std::string n = name.value_or("");
    b.add_roi(Roi{n, kind ? *kind : infer_roi_kind(n), poly.value_or(Polygon{})});
  });
  read.each(doc, "entities", false, [&](const Json& e, const std::string& ptr) {
    check.only_keys(e, ptr, {"type", "name", "pose", "affordances"});
    EntitySpec spec;
    spec.type = check.string(e, ptr, "type", true).value_or("");
    spec.name = check.string(e, ptr, "name", true).value_or("");
    spec.pose = read.pose(e, ptr, "pose", true).value_or(Pose2{});
    spec.affordances = read.strings(e, ptr, "affordances", 64);
    b.add_entity(std::move(spec));
  });
  if (!check.ok()) return tl::unexpected(check.error("the world document is not valid"));
  return b;
}

Result<World> world_from_document(const Json& document, const BuildOptions& options) {
  auto builder = builder_from_document(document);
  if (!builder) return tl::unexpected(builder.error());
  return builder->build(options);
}

Json world_to_document(const World& world) {
  Json doc = Json::object();
  if (!world.name().empty()) doc["name"] = world.name();
  doc["units"] = {{"length", "m"}, {"angle", "rad"}};
  const Pose2& o = world.origin();
  doc["origin"] = pose_json(o);
  if (!world.floor().material.empty()) doc["floor"] = {{"material", world.floor().material}};
  Json zones = Json::array();
  for (const auto& z : world.zones()) {
    Json j = {{"name", z.name}, {"type", z.type}};
    if (!z.material.empty()) j["material"] = z.material;
    j["polygon"] = polygon_json(z.polygon);
    zones.push_back(std::move(j));
  }
  doc["zones"] = std::move(zones);
  Json walls = Json::array();
  for (const auto& w : world.walls()) {
    Json j = {{"start", point_json(w.segment.a)}, {"end", point_json(w.segment.b)}, {"height", w.height}};
    if (!w.style.empty()) j["style"] = w.style;
    walls.push_back(std::move(j));
  }
  doc["walls"] = std::move(walls);
  Json doors = Json::array();
  for (const auto& d : world.doors()) {
    Json connects = Json::array({world.zone(d.zone).name});
    if (d.other) connects.push_back(world.zone(*d.other).name);
    doors.push_back(
        {{"name", d.name}, {"pose", pose_json(d.pose)}, {"width", d.width}, {"connects", connects}});
  }
  doc["doors"] = std::move(doors);
  Json rois = Json::array();
  for (const auto& r : world.rois())
    rois.push_back({{"name", r.name}, {"kind", r.kind}, {"polygon", polygon_json(r.polygon)}});
  doc["segmentation"] = std::move(rois);
  Json entities = Json::array();
  for (const auto& e : world.entities()) {
    Json j = {{"type", e.type}, {"name", e.name}, {"pose", pose_json(e.pose)}};
    if (!e.affordances.empty()) j["affordances"] = e.affordances;
    entities.push_back(std::move(j));
  }
  doc["entities"] = std::move(entities);
  return doc;
}

}  // namespace socsim::world
