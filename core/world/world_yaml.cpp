#include "core/world/world_yaml.hpp"

#include <charconv>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/world/world_document.hpp"

namespace socsim::world {

Result<World> world_from_yaml(std::string_view text, const BuildOptions& options, const YamlLimits& limits) {
  SourcePositions positions;
  auto doc = parse_yaml_untrusted(text, &positions, limits);
  if (!doc) return tl::unexpected(doc.error());
  if (doc->is_null()) {
    return fail(ErrorCode::kValidation, "world.yaml is empty",
                {FieldError{"/zones", "is required", {}, 1, 1}});
  }
  auto world = world_from_document(*doc, options);
  if (!world) {
    Error e = world.error();
    positions.annotate(e);
    return tl::unexpected(std::move(e));
  }
  return world;
}

namespace {

// YAML text from the document form; only the shapes world_to_document produces.
class FlowWriter {
 public:
  static std::string number(double v) {
    if (v == 0.0) return "0";  // also for -0.0
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
  }
  static std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
    return out + "\"";
  }
  static std::string flow(const Json& v, const std::vector<std::string_view>& order = {}) {
    if (v.is_string()) return quoted(v.get<std::string>());
    if (v.is_number()) return number(v.get<double>());
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_null()) return "null";
    std::string out;
    if (v.is_array()) {
      out = "[";
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) out += ", ";
        out += flow(v[i]);
      }
      return out + "]";
    }
    out = "{";
    bool first = true;
    // Keys in the order the format documents them, not alphabetical.
    for (std::string_view key : order) {
      auto it = v.find(std::string(key));
      if (it == v.end()) continue;
      if (!first) out += ", ";
      out += key;
      out += ": ";
      out += flow(*it);
      first = false;
    }
    return out + "}";
  }
};

// Keys in the order the format documents them (Fig. 3), not alphabetical.
std::vector<std::string_view> key_order(std::string_view list) {
  if (list == "zones") return {"name", "type", "material", "polygon"};
  if (list == "walls") return {"start", "end", "height", "style"};
  if (list == "doors") return {"name", "pose", "width", "connects"};
  if (list == "segmentation") return {"name", "kind", "polygon"};
  return {"type", "name", "pose", "affordances"};
}

}  // namespace

std::string world_to_yaml(const World& world) {
  const Json doc = world_to_document(world);
  std::ostringstream out;
  out << "# socsim world (world.yaml): lengths in metres, angles in radians\n";
  if (doc.contains("name")) out << "name: " << FlowWriter::quoted(doc["name"].get<std::string>()) << "\n";
  out << "units: {length: " << doc["units"]["length"].get<std::string>()
      << ", angle: " << doc["units"]["angle"].get<std::string>() << "}\n";
  out << "origin: " << FlowWriter::flow(doc["origin"]) << "\n";
  if (doc.contains("floor"))
    out << "floor: {material: " << FlowWriter::quoted(doc["floor"]["material"].get<std::string>()) << "}\n";
  for (const char* list : {"zones", "walls", "doors", "segmentation", "entities"}) {
    const Json& items = doc[list];
    if (items.empty()) {
      out << list << ": []\n";
      continue;
    }
    out << list << ":\n";
    for (const auto& item : items) out << "  - " << FlowWriter::flow(item, key_order(list)) << "\n";
  }
  return out.str();
}

}  // namespace socsim::world
