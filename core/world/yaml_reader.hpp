#pragma once
// Strict reading of untrusted YAML into JSON values, remembering where each value was in
// the text so validation errors can name line and column. Anchors, aliases, tags, complex
// keys, duplicate keys and several documents are refused; size and node count are capped
// (yaml-cpp would expand an alias bomb into millions of nodes).
#include <cstddef>
#include <map>
#include <string>
#include <string_view>

#include "core/common/json_io.hpp"

namespace socsim::world {

struct YamlLimits {
  std::size_t max_bytes = 8u << 20;
  std::size_t max_nodes = 500'000;
};

// 1-based line and column of every value, by JSON pointer.
class SourcePositions {
 public:
  void set(const std::string& pointer, int line, int column) { at_[pointer] = {line, column}; }
  // Position of the pointer, or of its nearest ancestor that has one (a missing field is
  // reported where its parent object starts). {0, 0} when unknown.
  [[nodiscard]] std::pair<int, int> find(std::string_view pointer) const;
  // Fills line/column of each field error from its pointer.
  void annotate(Error& error) const;

 private:
  std::map<std::string, std::pair<int, int>, std::less<>> at_;
};

// Plain scalars are resolved as YAML 1.2 core schema (null, true/false, integers, floats);
// quoted scalars are always strings. Errors: kBadRequest with line and column.
Result<Json> parse_yaml_untrusted(std::string_view text, SourcePositions* positions = nullptr,
                                  const YamlLimits& limits = {});

}  // namespace socsim::world
