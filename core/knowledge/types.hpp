#pragma once
// The knowledge store's entries as typed values: building-code references (paper 001's schema,
// SI units) and behaviour-tree nodes with typed ports, converted to and from JSON.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"

namespace socsim::knowledge {

enum class Kind { kBuildingCode, kBehaviorNode };
std::string_view to_string(Kind kind);  // "building_code" | "behavior_node"
std::optional<Kind> kind_from_string(std::string_view s);

// Building types the classifier returns and constraints_for() accepts; entries may also use
// "general" (holds for every non-dwelling type).
std::span<const std::string_view> building_types();
inline constexpr std::string_view kGeneralBuildingType = "general";
bool is_building_type(std::string_view s);  // one of building_types()

// SI units a constraint may carry.
std::span<const std::string_view> si_units();

struct Source {
  std::string title;
  std::string url;
  std::string section;
};

enum class ConstraintType { kMin, kMax, kRecommended };
std::string_view to_string(ConstraintType type);

struct Constraint {
  std::string name;  // merge key across entries, e.g. corridor_clear_width
  ConstraintType type = ConstraintType::kMin;
  double value = 0.0;
  std::string unit;  // one of si_units()
  double confidence = 1.0;
  std::string applies_to;  // room or element, e.g. "corridor"
  std::string original;    // the figure as the source prints it, e.g. "44 in"
};

struct BuildingCode {
  std::string ref_id;
  std::string building_type;
  std::string jurisdiction;
  std::string title;
  std::string description;
  std::string keywords;
  std::vector<Source> sources;
  std::vector<Constraint> constraints;
};

enum class NodeKind { kAction, kCondition, kControl, kDecorator };
std::string_view to_string(NodeKind kind);

enum class PortDirection { kIn, kOut, kInOut };
std::string_view to_string(PortDirection direction);

struct Port {
  std::string name;
  PortDirection direction = PortDirection::kIn;
  std::string type;                          // int | unsigned | double | bool | string
  std::optional<std::string> default_value;  // XML attribute text; none when required
  std::string description;
};

struct BehaviorNode {
  std::string name;
  NodeKind kind = NodeKind::kAction;
  std::string origin;  // btcpp | hunavsim | socsim
  std::string category;
  std::string description;
  std::string when_to_use;
  std::string example;  // BT.CPP v4 XML snippet
  std::string keywords;
  std::vector<std::string> aliases;
  std::vector<Port> ports;
};

Json to_json(const Source& source);
Json to_json(const Constraint& constraint);
Json to_json(const BuildingCode& code);
Json to_json(const Port& port);
Json to_json(const BehaviorNode& node);

// Typed parsing with every bad field reported as kValidation with its JSON pointer (prefixed by
// `pointer`), following schemas/building_code.schema.json and schemas/behavior_node.schema.json.
Result<BuildingCode> building_code_from_json(const Json& j, const std::string& pointer = "");
Result<BehaviorNode> behavior_node_from_json(const Json& j, const std::string& pointer = "");

}  // namespace socsim::knowledge
