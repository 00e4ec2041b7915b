#include "core/knowledge/types.hpp"

#include <algorithm>
#include <array>
#include <set>

#include "core/common/json_check.hpp"

namespace socsim::knowledge {
namespace {

// Order matters for ties in classification: the earlier type wins.
constexpr std::array<std::string_view, 22> kBuildingTypes = {
    "residential", "office",  "hospital",      "canteen",       "retail",      "warehouse",
    "school",      "airport", "train_station", "hotel",         "library",     "museum",
    "theatre",     "arena",   "factory",       "mall",          "supermarket", "restaurant",
    "university",  "gym",     "care_home",     "community_hall"};
// "ratio": a dimensionless fraction (e.g. of a plan's diagonal).
constexpr std::array<std::string_view, 9> kSiUnits = {
    "m", "m²", "m³/person", "m²/person", "m/person", "persons/m²", "m/s", "persons", "ratio"};
constexpr std::array<std::string_view, 3> kOrigins = {"btcpp", "hunavsim", "socsim"};
constexpr std::array<std::string_view, 5> kPortTypes = {"int", "unsigned", "double", "bool", "string"};

bool identifier(std::string_view s, bool allow_upper, std::size_t min_len, std::size_t max_len) {
  if (s.size() < min_len || s.size() > max_len) return false;
  return std::all_of(s.begin(), s.end(), [&](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           (allow_upper && c >= 'A' && c <= 'Z');
  });
}

bool xml_name(std::string_view s) {
  return identifier(s, true, 2, 64) && ((s[0] >= 'A' && s[0] <= 'Z') || (s[0] >= 'a' && s[0] <= 'z'));
}

template <std::size_t N>
bool one_of(const std::array<std::string_view, N>& values, std::string_view s) {
  return std::find(values.begin(), values.end(), s) != values.end();
}

template <std::size_t N>
std::string list(const std::array<std::string_view, N>& values) {
  std::string out;
  for (std::string_view v : values) out += (out.empty() ? "" : ", ") + std::string(v);
  return out;
}

std::optional<ConstraintType> constraint_type_from(std::string_view s) {
  if (s == "min") return ConstraintType::kMin;
  if (s == "max") return ConstraintType::kMax;
  if (s == "recommended") return ConstraintType::kRecommended;
  return std::nullopt;
}

std::optional<NodeKind> node_kind_from(std::string_view s) {
  if (s == "action") return NodeKind::kAction;
  if (s == "condition") return NodeKind::kCondition;
  if (s == "control") return NodeKind::kControl;
  if (s == "decorator") return NodeKind::kDecorator;
  return std::nullopt;
}

std::optional<PortDirection> direction_from(std::string_view s) {
  if (s == "in") return PortDirection::kIn;
  if (s == "out") return PortDirection::kOut;
  if (s == "inout") return PortDirection::kInOut;
  return std::nullopt;
}

}  // namespace

std::string_view to_string(Kind kind) {
  return kind == Kind::kBuildingCode ? "building_code" : "behavior_node";
}

std::optional<Kind> kind_from_string(std::string_view s) {
  if (s == "building_code") return Kind::kBuildingCode;
  if (s == "behavior_node") return Kind::kBehaviorNode;
  return std::nullopt;
}

std::span<const std::string_view> building_types() {
  return kBuildingTypes;
}
bool is_building_type(std::string_view s) {
  return one_of(kBuildingTypes, s);
}
std::span<const std::string_view> si_units() {
  return kSiUnits;
}

std::string_view to_string(ConstraintType type) {
  switch (type) {
    case ConstraintType::kMin:
      return "min";
    case ConstraintType::kMax:
      return "max";
    case ConstraintType::kRecommended:
      return "recommended";
  }
  return "min";
}

std::string_view to_string(NodeKind kind) {
  switch (kind) {
    case NodeKind::kAction:
      return "action";
    case NodeKind::kCondition:
      return "condition";
    case NodeKind::kControl:
      return "control";
    case NodeKind::kDecorator:
      return "decorator";
  }
  return "action";
}

std::string_view to_string(PortDirection direction) {
  switch (direction) {
    case PortDirection::kIn:
      return "in";
    case PortDirection::kOut:
      return "out";
    case PortDirection::kInOut:
      return "inout";
  }
  return "in";
}

Json to_json(const Source& s) {
  return Json{{"title", s.title}, {"url", s.url}, {"section", s.section}};
}

Json to_json(const Constraint& c) {
  Json j{{"name", c.name},
         {"type", to_string(c.type)},
         {"value", c.value},
         {"unit", c.unit},
         {"confidence", c.confidence}};
  if (!c.applies_to.empty()) j["applies_to"] = c.applies_to;
  if (!c.original.empty()) j["original"] = c.original;
  return j;
}

Json to_json(const BuildingCode& b) {
  Json sources = Json::array();
  for (const auto& s : b.sources) sources.push_back(to_json(s));
  Json constraints = Json::array();
  for (const auto& c : b.constraints) constraints.push_back(to_json(c));
  Json j{{"ref_id", b.ref_id},
         {"building_type", b.building_type},
         {"jurisdiction", b.jurisdiction},
         {"title", b.title},
         {"description", b.description},
         {"sources", std::move(sources)},
         {"constraints", std::move(constraints)}};
  if (!b.keywords.empty()) j["keywords"] = b.keywords;
  return j;
}

Json to_json(const Port& p) {
  return Json{{"name", p.name},
              {"direction", to_string(p.direction)},
              {"type", p.type},
              {"default", p.default_value ? Json(*p.default_value) : Json(nullptr)},
              {"description", p.description}};
}

Json to_json(const BehaviorNode& n) {
  Json ports = Json::array();
  for (const auto& p : n.ports) ports.push_back(to_json(p));
  Json j{{"name", n.name},         {"kind", to_string(n.kind)},    {"origin", n.origin},
         {"category", n.category}, {"description", n.description}, {"when_to_use", n.when_to_use},
         {"example", n.example},   {"aliases", n.aliases},         {"ports", std::move(ports)}};
  if (!n.keywords.empty()) j["keywords"] = n.keywords;
  return j;
}

Result<BuildingCode> building_code_from_json(const Json& j, const std::string& pointer) {
  if (!j.is_object())
    return fail(ErrorCode::kValidation, "a building code must be a JSON object",
                {{pointer, "must be an object"}});
  JsonChecker ck;
  ck.only_keys(j, pointer,
               {"ref_id", "building_type", "jurisdiction", "title", "description", "keywords", "sources",
                "constraints"});
  BuildingCode b;
  if (auto v = ck.string(j, pointer, "ref_id", true, 3, 80)) {
    if (!identifier(*v, false, 3, 80))
      ck.add(JsonChecker::child(pointer, "ref_id"), "must use only a-z, 0-9 and _");
    b.ref_id = *v;
  }
  if (auto v = ck.string(j, pointer, "building_type", true, 1, 40)) {
    if (!is_building_type(*v) && *v != kGeneralBuildingType)
      ck.add(JsonChecker::child(pointer, "building_type"), "must be one of general, " + list(kBuildingTypes));
    b.building_type = *v;
  }
  if (auto v = ck.string(j, pointer, "jurisdiction", true, 1, 100)) b.jurisdiction = *v;
  if (auto v = ck.string(j, pointer, "title", true, 1, 200)) b.title = *v;
  if (auto v = ck.string(j, pointer, "description", true, 1, 2000)) b.description = *v;
  if (auto v = ck.string(j, pointer, "keywords", false, 0, 500)) b.keywords = *v;

  if (const Json* sources = ck.array(j, pointer, "sources", true, 16)) {
    const std::string sp = JsonChecker::child(pointer, "sources");
    if (sources->empty()) ck.add(sp, "must name at least one source");
    for (std::size_t i = 0; i < sources->size(); ++i) {
      const Json& s = (*sources)[i];
      const std::string p = JsonChecker::child(sp, i);
      if (!s.is_object()) {
        ck.add(p, "must be an object");
        continue;
      }
      ck.only_keys(s, p, {"title", "url", "section"});
      Source src;
      if (auto v = ck.string(s, p, "title", true, 1, 300)) src.title = *v;
      if (auto v = ck.string(s, p, "url", true, 1, 500)) {
        const bool https =
            v->rfind("https://", 0) == 0 && v->size() > 8 && v->find_first_of(" \t\r\n") == std::string::npos;
        if (!https) ck.add(JsonChecker::child(p, "url"), "must be an https:// URL without spaces");
        src.url = *v;
      }
      if (auto v = ck.string(s, p, "section", true, 1, 200)) src.section = *v;
      b.sources.push_back(std::move(src));
    }
  }

  if (const Json* constraints = ck.array(j, pointer, "constraints", true, 64)) {
    const std::string cp = JsonChecker::child(pointer, "constraints");
    if (constraints->empty()) ck.add(cp, "must hold at least one constraint");
    for (std::size_t i = 0; i < constraints->size(); ++i) {
      const Json& c = (*constraints)[i];
      const std::string p = JsonChecker::child(cp, i);
      if (!c.is_object()) {
        ck.add(p, "must be an object");
        continue;
      }
      ck.only_keys(c, p, {"name", "type", "value", "unit", "confidence", "applies_to", "original"});
      Constraint con;
      if (auto v = ck.string(c, p, "name", true, 2, 80)) {
        if (!identifier(*v, false, 2, 80))
          ck.add(JsonChecker::child(p, "name"), "must use only a-z, 0-9 and _");
        con.name = *v;
      }
      if (auto v = ck.string(c, p, "type", true, 1, 20)) {
        if (auto t = constraint_type_from(*v))
          con.type = *t;
        else
          ck.add(JsonChecker::child(p, "type"), "must be min, max or recommended");
      }
      if (auto v = ck.number(c, p, "value", true, 0.0, 1e9)) {
        if (*v <= 0.0) ck.add(JsonChecker::child(p, "value"), "must be greater than 0");
        con.value = *v;
      }
      if (auto v = ck.string(c, p, "unit", true, 1, 20)) {
        if (!one_of(kSiUnits, *v))
          ck.add(JsonChecker::child(p, "unit"), "must be an SI unit: " + list(kSiUnits));
        con.unit = *v;
      }
      if (auto v = ck.number(c, p, "confidence", true, 0.0, 1.0)) {
        if (*v <= 0.0) ck.add(JsonChecker::child(p, "confidence"), "must be greater than 0");
        con.confidence = *v;
      }
      if (auto v = ck.string(c, p, "applies_to", false, 0, 100)) con.applies_to = *v;
      if (auto v = ck.string(c, p, "original", false, 0, 100)) con.original = *v;
      b.constraints.push_back(std::move(con));
    }
  }
  if (!ck.ok()) return tl::unexpected(ck.error("invalid building code"));
  return b;
}

Result<BehaviorNode> behavior_node_from_json(const Json& j, const std::string& pointer) {
  if (!j.is_object())
    return fail(ErrorCode::kValidation, "a behaviour node must be a JSON object",
                {{pointer, "must be an object"}});
  JsonChecker ck;
  ck.only_keys(j, pointer,
               {"name", "kind", "origin", "category", "description", "when_to_use", "example", "keywords",
                "aliases", "ports"});
  BehaviorNode n;
  if (auto v = ck.string(j, pointer, "name", true, 2, 64)) {
    if (!xml_name(*v))
      ck.add(JsonChecker::child(pointer, "name"),
             "must be an XML tag name (letters, digits, _; starting with a letter)");
    n.name = *v;
  }
  if (auto v = ck.string(j, pointer, "kind", true, 1, 20)) {
    if (auto k = node_kind_from(*v))
      n.kind = *k;
    else
      ck.add(JsonChecker::child(pointer, "kind"), "must be action, condition, control or decorator");
  }
  if (auto v = ck.string(j, pointer, "origin", true, 1, 20)) {
    if (!one_of(kOrigins, *v))
      ck.add(JsonChecker::child(pointer, "origin"), "must be one of " + list(kOrigins));
    n.origin = *v;
  }
  if (auto v = ck.string(j, pointer, "category", true, 1, 40)) n.category = *v;
  if (auto v = ck.string(j, pointer, "description", true, 1, 2000)) n.description = *v;
  if (auto v = ck.string(j, pointer, "when_to_use", true, 1, 1000)) n.when_to_use = *v;
  if (auto v = ck.string(j, pointer, "example", true, 1, 4000)) n.example = *v;
  if (auto v = ck.string(j, pointer, "keywords", false, 0, 500)) n.keywords = *v;
  if (const Json* aliases = ck.array(j, pointer, "aliases", false, 8)) {
    const std::string ap = JsonChecker::child(pointer, "aliases");
    std::set<std::string> seen;
    for (std::size_t i = 0; i < aliases->size(); ++i) {
      const Json& a = (*aliases)[i];
      if (!a.is_string() || !xml_name(a.get_ref<const std::string&>())) {
        ck.add(JsonChecker::child(ap, i), "must be an XML tag name");
        continue;
      }
      if (!seen.insert(a.get<std::string>()).second || a.get<std::string>() == n.name) {
        ck.add(JsonChecker::child(ap, i), "repeats a name already given");
        continue;
      }
      n.aliases.push_back(a.get<std::string>());
    }
  }
  if (const Json* ports = ck.array(j, pointer, "ports", true, 32)) {
    const std::string pp = JsonChecker::child(pointer, "ports");
    std::set<std::string> seen;
    for (std::size_t i = 0; i < ports->size(); ++i) {
      const Json& pj = (*ports)[i];
      const std::string p = JsonChecker::child(pp, i);
      if (!pj.is_object()) {
        ck.add(p, "must be an object");
        continue;
      }
      ck.only_keys(pj, p, {"name", "direction", "type", "default", "description"});
      Port port;
      if (auto v = ck.string(pj, p, "name", true, 1, 64)) {
        const bool ok = identifier(*v, true, 1, 64) && !((*v)[0] >= '0' && (*v)[0] <= '9');
        if (!ok) ck.add(JsonChecker::child(p, "name"), "must be a port name (letters, digits, _)");
        if (!seen.insert(*v).second)
          ck.add(JsonChecker::child(p, "name"), "duplicates another port of this node");
        port.name = *v;
      }
      if (auto v = ck.string(pj, p, "direction", true, 1, 10)) {
        if (auto d = direction_from(*v))
          port.direction = *d;
        else
          ck.add(JsonChecker::child(p, "direction"), "must be in, out or inout");
      }
      if (auto v = ck.string(pj, p, "type", true, 1, 20)) {
        if (!one_of(kPortTypes, *v))
          ck.add(JsonChecker::child(p, "type"), "must be one of " + list(kPortTypes));
        port.type = *v;
      }
      if (auto v = ck.string(pj, p, "default", false, 0, 200)) port.default_value = *v;
      if (auto v = ck.string(pj, p, "description", true, 1, 500)) port.description = *v;
      n.ports.push_back(std::move(port));
    }
  }
  if (!ck.ok()) return tl::unexpected(ck.error("invalid behaviour node"));
  return n;
}

}  // namespace socsim::knowledge
