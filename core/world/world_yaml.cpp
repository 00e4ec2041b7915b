#include "core/world/world_yaml.hpp"

#include <charconv>
#include <sstream>

#include "core/world/world_document.hpp"

namespace socsim::world {

Result<World> world_from_yaml(std::string_view text, const BuildOptions& options, const YamlLimits& limits) {
  SourcePositions positions;
  auto doc = parse_yaml_untrusted(text, &positions, limits);
  if (!doc) return tl::unexpected(doc.error());
  if (doc->is_null()) {
    return fail(ErrorCode::kValidation, "world.yaml is empty", {FieldError{"/zones", "is required", {}, 1, 1}});
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
  static std::string flow(const Json& v) {
    if (v.is_string()) return quoted(v.get<std::string>());
    if (v.is_number()) return number(v.get<double>());
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_null()) return "null";
    std::string out;
    if (v.is_array()) {
      out = "[";
      for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + flow(v[i]);
      return out + "]";
    }
    out = "{";
    bool first = true;
    // Keys in the order the format documents them, not alphabetical.
    for (const char* key : {"type", "name", "kind", "material", "pose", "width", "connects", "start", "end", "height",
                            "style", "length", "angle", "polygon", "affordances"}) {
      auto it = v.find(key);
      if (it == v.end()) continue;
      out += (first ? "" : ", ") + std::string(key) + ": " + flow(*it);
      first = false;
    }
    return out + "}";
  }
};

}  // namespace

std::string world_to_yaml(const World& world) {
  const Json doc = world_to_document(world);
  std::ostringstream out;
  out << "# socsim world (world.yaml): lengths in metres, angles in radians\n";
  if (doc.contains("name")) out << "name: " << FlowWriter::quoted(doc["name"].get<std::string>()) << "\n";
  out << "units: " << FlowWriter::flow(doc["units"]) << "\n";
  out << "origin: " << FlowWriter::flow(doc["origin"]) << "\n";
  if (doc.contains("floor")) out << "floor: {material: " << FlowWriter::quoted(doc["floor"]["material"].get<std::string>()) << "}\n";
  for (const char* list : {"zones", "walls", "doors", "segmentation", "entities"}) {
    const Json& items = doc[list];
    if (items.empty()) {
      out << list << ": []\n";
      continue;
    }
    out << list << ":\n";
    for (const auto& item : items) out << "  - " << FlowWriter::flow(item) << "\n";
  }
  return out.str();
}

}  // namespace socsim::world
