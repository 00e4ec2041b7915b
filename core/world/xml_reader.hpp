#pragma once
// A small strict XML reader for the scenario formats we import (pedsim_ros) and for checking
// the XML we export: elements, attributes, text, comments, CDATA and the XML declaration.
// DOCTYPE (entity expansion), unknown entities, duplicate attributes and mismatched tags
// are errors with a line and column. Namespaces are kept as part of names.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::world {

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // in document order
  std::vector<XmlElement> children;
  std::string text;  // character data directly inside this element, entities resolved
  int line = 0;      // 1-based position of '<'
  int column = 0;

  [[nodiscard]] const std::string* attribute(std::string_view key) const;
  // Direct children with this name, in order.
  [[nodiscard]] std::vector<const XmlElement*> children_named(std::string_view child) const;
};

struct XmlLimits {
  std::size_t max_bytes = 8u << 20;
  int max_depth = 64;
  std::size_t max_elements = 200'000;
};

// The root element. Errors: kBadRequest with line and column in the message and FieldError.
Result<XmlElement> parse_xml(std::string_view text, const XmlLimits& limits = {});

// Escapes &, <, >, " and ' for attribute values and text.
std::string xml_escape(std::string_view text);

}  // namespace socsim::world
