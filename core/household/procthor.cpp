#include "core/household/procthor.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/common/json_check.hpp"

namespace socsim::household {
namespace {

std::vector<std::string> asset_tokens(std::string_view asset) {
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    const bool has_digit = std::any_of(cur.begin(), cur.end(),
                                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (!cur.empty() && !has_digit && cur != "v" && !(out.empty() && cur == "robothor")) out.push_back(cur);
    cur.clear();
  };
  for (char c : asset) {
    if (c == '_' || c == '-' || c == ' ')
      flush();
    else
      cur += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  flush();
  return out;
}

// Asset-name phrases → AI2-THOR types, longest and most specific first.
constexpr std::pair<std::string_view, std::string_view> kAssetPhrases[] = {
    {"alarm clock", "AlarmClock"},
    {"dining table", "DiningTable"},
    {"coffee table", "CoffeeTable"},
    {"side table", "SideTable"},
    {"tv stand", "TVStand"},
    {"shelving unit", "ShelvingUnit"},
    {"desk lamp", "DeskLamp"},
    {"floor lamp", "FloorLamp"},
    {"office chair", "Chair"},
    {"wall decor", "Painting"},
    {"dog bed", "DogBed"},
    {"garbagebag", "GarbageBag"},
    {"garbage bag", "GarbageBag"},
    {"washing machine", "WashingMachine"},
    {"clothes dryer", "ClothesDryer"},
    {"coffee machine", "CoffeeMachine"},
    {"soap bar", "SoapBar"},
    {"soap bottle", "SoapBottle"},
    {"spray bottle", "SprayBottle"},
    {"wine bottle", "WineBottle"},
    {"pepper", "PepperShaker"},
    {"salt shaker", "SaltShaker"},
    {"tissue box", "TissueBox"},
    {"teddy bear", "TeddyBear"},
    {"tennis racquet", "TennisRacket"},
    {"tennis racket", "TennisRacket"},
    {"toilet paper", "ToiletPaper"},
    {"paper towel", "PaperTowelRoll"},
    {"dish sponge", "DishSponge"},
    {"butter knife", "ButterKnife"},
    {"butterknife", "ButterKnife"},
    {"baseball bat", "BaseballBat"},
    {"baseballbat", "BaseballBat"},
    {"credit card", "CreditCard"},
    {"creditcard", "CreditCard"},
    {"faucet", "Faucet"},
    {"statue", "Statue"},
    {"decorativebox", "Box"},
    {"countertop", "CounterTop"},
    {"armchair", "ArmChair"},
    {"bin", "GarbageCan"},
    {"remote", "RemoteControl"},
    {"cellphone", "CellPhone"},
    {"keychain", "KeyChain"},
    {"houseplant", "HousePlant"},
    {"basketball", "BasketBall"},
    {"television", "Television"},
    {"cd", "CD"},
    {"laundry hamper", "LaundryHamper"},
    {"towel holder", "TowelHolder"},
    {"watering can", "WateringCan"},
};

bool has_phrase(const std::string& joined, std::string_view phrase) {
  for (std::size_t pos = joined.find(phrase); pos != std::string::npos; pos = joined.find(phrase, pos + 1)) {
    const bool left = pos == 0 || joined[pos - 1] == ' ';
    const bool right = pos + phrase.size() == joined.size() || joined[pos + phrase.size()] == ' ';
    if (left && right) return true;
  }
  return false;
}

bool known_type(const HouseholdKnowledge& k, std::string_view t) {
  return k.is_movable(t) || k.is_fixture(t) || k.receptacle(t) != nullptr;
}

Json point_json(double x, double y, double z) {
  return Json{{"x", x}, {"y", y}, {"z", z}};
}

struct Importer {
  const HouseholdKnowledge& k;
  JsonChecker check;
  House h;

  std::optional<Vec3> vec(const Json& obj, const std::string& ptr, std::string_view key, bool required) {
    const Json* v = check.object(obj, ptr, key, required);
    if (!v) return std::nullopt;
    const std::string p = JsonChecker::child(ptr, key);
    auto x = check.number(*v, p, "x", true), y = check.number(*v, p, "y", false),
         z = check.number(*v, p, "z", true);
    if (!x || !z) return std::nullopt;
    return Vec3{*x, y.value_or(0.0), *z};
  }

  // False (with an error) unless v is an object: JsonChecker reads fields of objects only and
  // would silently skip a number or a list where a room, wall, door or point belongs.
  bool is_object(const Json& v, const std::string& ptr) {
    if (v.is_object()) return true;
    check.add(ptr, "must be an object");
    return false;
  }

  static Json without(const Json& obj, std::initializer_list<std::string_view> keys) {
    Json e = obj;
    for (auto key : keys) e.erase(std::string(key));
    return e;
  }

  void objects(const Json& arr, const std::string& ptr, int parent, int depth) {
    if (depth > 6) {
      check.add(ptr, "objects are nested too deeply");
      return;
    }
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const Json& o = arr[i];
      const std::string p = JsonChecker::child(ptr, i);
      if (!o.is_object()) {
        check.add(p, "must be an object");
        continue;
      }
      Entity e;
      if (auto id = check.string(o, p, "id", true, 1, 200)) e.id = *id;
      if (auto a = check.string(o, p, "assetId", true, 1, 200)) e.asset_id = *a;
      if (auto pos = vec(o, p, "position", true)) e.position = *pos;
      if (auto rot = vec(o, p, "rotation", false)) e.rotation = *rot;
      const std::string prefix = e.id.substr(0, e.id.find('|'));
      e.type = known_type(k, prefix) ? prefix : object_type_from_asset(e.asset_id, k);
      e.kind = k.receptacle(e.type)   ? EntityKind::kReceptacle
               : k.is_movable(e.type) ? EntityKind::kObject
                                      : EntityKind::kFixture;
      if (const auto* spec = k.receptacle(e.type)) {  // the type's footprint, turned by the yaw
        e.size_x = spec->size_x;
        e.size_z = spec->size_z;
      }
      e.room = h.room_at(e.position.x, e.position.z);
      if (e.room < 0 && parent >= 0) e.room = h.entities[static_cast<std::size_t>(parent)].room;
      if (e.room < 0) e.room = nearest_room(e.position);
      e.parent = parent;
      if (parent < 0 && e.kind == EntityKind::kObject) e.parent = floor_of(e.room);
      e.extra = without(o, {"id", "assetId", "position", "rotation", "children"});
      h.entities.push_back(std::move(e));
      const int self = static_cast<int>(h.entities.size() - 1);
      if (const Json* children = check.array(o, p, "children", false, 1000))
        objects(*children, JsonChecker::child(p, "children"), self, depth + 1);
    }
  }

  int nearest_room(const Vec3& p) const {
    int best = 0;
    double best_d = 1e18;
    for (std::size_t i = 0; i < h.rooms.size(); ++i) {
      double cx = 0, cz = 0;
      for (const auto& f : h.rooms[i].floor) cx += f.x, cz += f.z;
      const double n = static_cast<double>(std::max<std::size_t>(1, h.rooms[i].floor.size()));
      const double d = std::hypot(cx / n - p.x, cz / n - p.z);
      if (d < best_d) best_d = d, best = static_cast<int>(i);
    }
    return best;
  }

  // Movable objects on the floor rest on a per-room pseudo receptacle, made on demand.
  int floor_of(int room) {
    const std::string id = "Floor|" + h.rooms[static_cast<std::size_t>(room)].id;
    for (std::size_t i = 0; i < h.entities.size(); ++i)
      if (h.entities[i].synthetic && h.entities[i].id == id) return static_cast<int>(i);
    Entity f;
    f.id = id;
    f.type = "Floor";
    f.kind = EntityKind::kReceptacle;
    f.synthetic = true;
    f.room = room;
    double cx = 0, cz = 0;
    for (const auto& p : h.rooms[static_cast<std::size_t>(room)].floor) cx += p.x, cz += p.z;
    const double n = static_cast<double>(h.rooms[static_cast<std::size_t>(room)].floor.size());
    f.position = {cx / n, 0.0, cz / n};
    h.entities.push_back(std::move(f));
    return static_cast<int>(h.entities.size() - 1);
  }
};

}  // namespace

std::string object_type_from_asset(std::string_view asset_id, const HouseholdKnowledge& k) {
  const auto tokens = asset_tokens(asset_id);
  std::string joined;
  for (const auto& t : tokens) joined += (joined.empty() ? "" : " ") + t;
  for (const auto& [phrase, type] : kAssetPhrases)
    if (has_phrase(joined, phrase)) return std::string(type);
  if (tokens.empty()) return "Unknown";
  std::string first = tokens.front();
  first[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(first[0])));
  if (known_type(k, first)) return first;
  std::string camel;
  for (auto t : tokens) {
    t[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(t[0])));
    camel += t;
  }
  return camel;
}

Result<House> import_procthor(const Json& json, const HouseholdKnowledge& knowledge, const std::string& id) {
  Importer im{knowledge, {}, {}};
  auto& check = im.check;
  House& h = im.h;
  h.id = id;
  if (!json.is_object()) {
    check.add("", "must be a ProcTHOR house object");
    return tl::unexpected(check.error("invalid ProcTHOR house"));
  }
  if (const Json* rooms = check.array(json, "", "rooms", true, 100)) {
    if (rooms->empty()) check.add("/rooms", "must list at least one room");
    for (std::size_t i = 0; i < rooms->size(); ++i) {
      const Json& r = (*rooms)[i];
      const std::string p = "/rooms/" + std::to_string(i);
      if (!im.is_object(r, p)) continue;
      Room room;
      if (auto rid = check.string(r, p, "id", true, 1, 100)) room.id = *rid;
      if (auto t = check.string(r, p, "roomType", true, 1, 40)) {
        if (auto rt = parse_room_type(*t))
          room.type = *rt;
        else
          check.add(p + "/roomType", "must be Bedroom, Bathroom, LivingRoom or Kitchen (got '" + *t + "')");
      }
      if (const Json* poly = check.array(r, p, "floorPolygon", true, 1000)) {
        if (poly->size() < 3) check.add(p + "/floorPolygon", "needs at least 3 points");
        for (std::size_t j = 0; j < poly->size(); ++j) {
          const std::string pp = p + "/floorPolygon/" + std::to_string(j);
          if (!im.is_object((*poly)[j], pp)) continue;
          auto x = check.number((*poly)[j], pp, "x", true), z = check.number((*poly)[j], pp, "z", true);
          if (x && z) room.floor.push_back({*x, *z});
        }
        if (room.floor.size() >= 3 && polygon_area(room.floor) <= 0.0)
          check.add(p + "/floorPolygon", "has no area");
      }
      room.extra = Importer::without(r, {"id", "roomType", "floorPolygon"});
      h.rooms.push_back(std::move(room));
    }
  }
  if (const Json* walls = check.array(json, "", "walls", true, 10000))
    for (std::size_t i = 0; i < walls->size(); ++i) {
      const Json& w = (*walls)[i];
      const std::string p = "/walls/" + std::to_string(i);
      if (!im.is_object(w, p)) continue;
      Wall wall;
      if (auto wid = check.string(w, p, "id", true, 1, 200)) wall.id = *wid;
      if (auto rid = check.string(w, p, "roomId", true, 1, 100)) wall.room_id = *rid;
      if (auto e = check.boolean(w, p, "empty", false)) wall.empty = *e;
      if (const Json* poly = check.array(w, p, "polygon", true, 64)) {
        if (poly->size() < 2) check.add(p + "/polygon", "needs at least 2 points");
        double top = 0.0;
        for (std::size_t j = 0; j < poly->size(); ++j) {
          const std::string pp = p + "/polygon/" + std::to_string(j);
          if (!im.is_object((*poly)[j], pp)) continue;
          auto x = check.number((*poly)[j], pp, "x", true), y = check.number((*poly)[j], pp, "y", true),
               z = check.number((*poly)[j], pp, "z", true);
          if (!x || !y || !z) continue;
          if (j == 0) wall.a = {*x, *z};
          if (j == 1) wall.b = {*x, *z};
          top = std::max(top, *y);
        }
        wall.height = top;
      }
      wall.extra = Importer::without(w, {"id", "roomId", "empty"});
      h.walls.push_back(std::move(wall));
    }
  auto room_known = [&](const std::string& r) { return h.room_index(r) >= 0; };
  if (const Json* doors = check.array(json, "", "doors", true, 1000))
    for (std::size_t i = 0; i < doors->size(); ++i) {
      const Json& d = (*doors)[i];
      const std::string p = "/doors/" + std::to_string(i);
      if (!im.is_object(d, p)) continue;
      Door door;
      if (auto v = check.string(d, p, "id", true, 1, 200)) door.id = *v;
      if (auto v = check.string(d, p, "room0", true, 1, 100)) {
        door.room0 = *v;
        if (!room_known(*v)) check.add(p + "/room0", "names no room of this house");
      }
      if (auto v = check.string(d, p, "room1", true, 1, 100)) {
        door.room1 = *v;
        if (!room_known(*v)) check.add(p + "/room1", "names no room of this house");
      }
      if (auto v = check.string(d, p, "wall0", true, 1, 200)) door.wall0 = *v;
      if (auto v = check.string(d, p, "wall1", true, 1, 200)) door.wall1 = *v;
      if (auto v = check.string(d, p, "assetId", false, 1, 200)) door.asset_id = *v;
      if (const Json* hole = check.array(d, p, "holePolygon", true, 2)) {
        if (hole->size() != 2)
          check.add(p + "/holePolygon", "must hold the two corners of the opening");
        else {
          const Json& h0 = (*hole)[0];
          const Json& h1 = (*hole)[1];
          auto rd = [&](const Json& o, const std::string& pp, Vec3& out) {
            if (!im.is_object(o, pp)) return;
            auto x = check.number(o, pp, "x", true), y = check.number(o, pp, "y", true),
                 z = check.number(o, pp, "z", false);
            if (x && y) out = {*x, *y, z.value_or(0.0)};
          };
          rd(h0, p + "/holePolygon/0", door.hole_min);
          rd(h1, p + "/holePolygon/1", door.hole_max);
        }
      }
      if (auto ap = im.vec(d, p, "assetPosition", false)) door.asset_position = *ap;
      if (auto v = check.boolean(d, p, "openable", false)) door.openable = *v;
      if (auto v = check.number(d, p, "openness", false, 0.0, 1.0)) door.openness = *v;
      door.extra = Importer::without(d, {"id", "room0", "room1", "wall0", "wall1", "assetId", "holePolygon",
                                         "assetPosition", "openable", "openness"});
      h.doors.push_back(std::move(door));
    }
  if (const Json* w = check.array(json, "", "windows", false, 1000)) h.windows = *w;
  if (const Json* m = check.object(json, "", "metadata", false)) h.metadata = *m;
  if (const Json* m = check.object(json, "", "proceduralParameters", false)) h.procedural = *m;
  if (!check.ok()) return tl::unexpected(check.error("invalid ProcTHOR house"));
  if (const Json* objs = check.array(json, "", "objects", true, 20000)) im.objects(*objs, "/objects", -1, 0);
  if (!check.ok()) return tl::unexpected(check.error("invalid ProcTHOR house"));
  h.index();
  return std::move(h);
}

Json export_procthor(const House& h, const std::vector<int>* placement) {
  Json out = Json::object();
  Json rooms = Json::array();
  for (const auto& r : h.rooms) {
    Json j = r.extra;
    j["id"] = r.id;
    j["roomType"] = room_type_name(r.type);
    Json poly = Json::array();
    for (const auto& p : r.floor) poly.push_back(point_json(p.x, 0, p.z));
    j["floorPolygon"] = poly;
    rooms.push_back(std::move(j));
  }
  Json walls = Json::array();
  for (const auto& w : h.walls) {
    Json j = w.extra;
    j["id"] = w.id;
    j["roomId"] = w.room_id;
    if (!j.contains("polygon"))
      j["polygon"] = Json::array({point_json(w.a.x, 0, w.a.z), point_json(w.b.x, 0, w.b.z),
                                  point_json(w.a.x, w.height, w.a.z), point_json(w.b.x, w.height, w.b.z)});
    if (w.empty) j["empty"] = true;
    walls.push_back(std::move(j));
  }
  Json doors = Json::array();
  for (const auto& d : h.doors) {
    Json j = d.extra;
    j["id"] = d.id;
    j["room0"] = d.room0;
    j["room1"] = d.room1;
    j["wall0"] = d.wall0;
    j["wall1"] = d.wall1;
    if (!d.asset_id.empty()) j["assetId"] = d.asset_id;
    j["holePolygon"] = Json::array({point_json(d.hole_min.x, d.hole_min.y, d.hole_min.z),
                                    point_json(d.hole_max.x, d.hole_max.y, d.hole_max.z)});
    j["assetPosition"] = point_json(d.asset_position.x, d.asset_position.y, d.asset_position.z);
    j["openable"] = d.openable;
    j["openness"] = d.openness;
    doors.push_back(std::move(j));
  }
  // Effective parent of every entity (objects moved by `placement`), then the object tree.
  std::vector<int> parent(h.entities.size());
  std::vector<Vec3> position(h.entities.size());
  for (std::size_t i = 0; i < h.entities.size(); ++i) {
    parent[i] = h.entities[i].parent;
    position[i] = h.entities[i].position;
  }
  if (placement)
    for (std::size_t o = 0; o < h.objects.size() && o < placement->size(); ++o) {
      const auto idx = static_cast<std::size_t>(h.objects[o]);
      const int rec = (*placement)[o];
      if (rec < 0 || rec == parent[idx]) continue;
      const Entity& r = h.entities[static_cast<std::size_t>(rec)];
      parent[idx] = rec;
      position[idx] = {r.position.x, r.synthetic ? 0.05 : r.position.y * 2 + 0.05, r.position.z};
    }
  std::vector<std::vector<std::size_t>> children(h.entities.size());
  std::vector<std::size_t> top;
  for (std::size_t i = 0; i < h.entities.size(); ++i) {
    if (h.entities[i].synthetic) continue;
    const int p = parent[i];
    if (p < 0 || h.entities[static_cast<std::size_t>(p)].synthetic)
      top.push_back(i);
    else
      children[static_cast<std::size_t>(p)].push_back(i);
  }
  auto build = [&](auto&& self, std::size_t i) -> Json {
    const Entity& e = h.entities[i];
    Json j = e.extra;
    j["id"] = e.id;
    j["assetId"] = e.asset_id;
    j["position"] = point_json(position[i].x, position[i].y, position[i].z);
    j["rotation"] = point_json(e.rotation.x, e.rotation.y, e.rotation.z);
    if (!children[i].empty()) {
      Json c = Json::array();
      for (std::size_t k : children[i]) c.push_back(self(self, k));
      j["children"] = c;
    }
    return j;
  };
  Json objects = Json::array();
  for (std::size_t i : top) objects.push_back(build(build, i));
  out["rooms"] = rooms;
  out["walls"] = walls;
  out["doors"] = doors;
  out["windows"] = h.windows;
  out["objects"] = objects;
  out["metadata"] = h.metadata;
  out["proceduralParameters"] = h.procedural;
  return out;
}

}  // namespace socsim::household
