#include "core/world/world_yaml.hpp"

#include <charconv>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/world/world_document.hpp"

namespace socsim::world {

namespace {

// U+21B3 DOWNWARDS ARROW WITH TIP RIGHTWARDS, which listings print where they wrap a line.
constexpr std::string_view kWrapMark = "\xE2\x86\xB3";

// Replaces each wrap mark that begins a line (after blanks, before a blank or the end of the
// line) by as many spaces, so that columns stay; returns the 1-based lines where it did.
std::vector<int> blank_wrap_marks(std::string& text) {
  std::vector<int> lines;
  int line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::size_t first = text.find_first_not_of(" \t", start);
    const std::size_t after = first + kWrapMark.size();
    if (first < end && text.compare(first, kWrapMark.size(), kWrapMark) == 0 &&
        (after >= end || text[after] == ' ' || text[after] == '\t' || text[after] == '\r')) {
      text.replace(first, kWrapMark.size(), kWrapMark.size(), ' ');
      lines.push_back(line);
    }
    start = end + 1;
  }
  return lines;
}

std::string line_list(const std::vector<int>& lines) {
  std::string s;
  for (std::size_t i = 0; i < lines.size(); ++i) s += (i ? ", " : "") + std::to_string(lines[i]);
  return s;
}

}  // namespace

Result<WorldReading> read_world_yaml(std::string_view text, const BuildOptions& options,
                                     const YamlLimits& limits) {
  std::vector<int> wrapped;
  std::string unwrapped;
  if (text.size() <= limits.max_bytes && text.find(kWrapMark) != std::string_view::npos) {
    unwrapped = text;
    wrapped = blank_wrap_marks(unwrapped);
    text = unwrapped;
  }
  SourcePositions positions;
  auto doc = parse_yaml_untrusted(text, &positions, limits);
  if (!doc) return tl::unexpected(doc.error());
  if (doc->is_null()) {
    return fail(ErrorCode::kValidation, "world.yaml is empty",
                {FieldError{"/zones", "is required", {}, 1, 1}});
  }
  std::vector<FieldError> warnings;
  auto builder = builder_from_document(*doc);
  Result<World> world = builder ? builder->build(options, &warnings) : tl::unexpected(builder.error());
  if (!world) {
    Error e = world.error();
    positions.annotate(e);
    return tl::unexpected(std::move(e));
  }
  Error notes(ErrorCode::kValidation, "", std::move(warnings));
  positions.annotate(notes);
  if (!wrapped.empty()) {
    notes.errors.insert(
        notes.errors.begin(),
        FieldError{"",
                   (wrapped.size() == 1 ? "line " : "lines ") + line_list(wrapped) +
                       (wrapped.size() == 1 ? " begins" : " begin") + " with '" + std::string(kWrapMark) +
                       "', the mark a printed listing puts where it wraps a line; read as "
                       "the continuation of the line before",
                   {},
                   wrapped.front(),
                   1});
  }
  return WorldReading{std::move(*world), std::move(notes.errors)};
}

Result<World> world_from_yaml(std::string_view text, const BuildOptions& options, const YamlLimits& limits) {
  auto reading = read_world_yaml(text, options, limits);
  if (!reading) return tl::unexpected(reading.error());
  return std::move(reading->world);
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
