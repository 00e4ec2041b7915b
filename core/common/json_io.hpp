#pragma once
// Parsing untrusted JSON safely (depth limit, positions in errors) and the canonical form
// used for content hashes and byte-stable exports.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/common/error.hpp"

namespace socsim {

using Json = nlohmann::json;

inline constexpr int kMaxJsonDepth = 64;

// Parses text from outside the process. Syntax errors → kBadRequest with line/column; nesting
// deeper than max_depth → kBadRequest (nlohmann's dump() would overflow the stack on such input).
Result<Json> parse_json_untrusted(std::string_view text, int max_depth = kMaxJsonDepth);

// Canonical serialisation: object keys sorted, no insignificant whitespace, numbers in
// shortest round-trip form, UTF-8 kept as is. Equal values give equal bytes.
std::string canonical_json(const Json& value);

// RFC 6901 escaping of one reference token ("a/b~c" → "a~1b~0c").
std::string json_pointer_token(std::string_view token);

// Line and column (1-based) of a byte offset in text.
std::pair<int, int> line_column(std::string_view text, std::size_t byte_offset);

}  // namespace socsim
