#pragma once
// Validates JSON values against the JSON Schema subset our schemas use (2020-12 keywords that
// Draft-7 tools also understand), reporting every violation with its RFC 6901 pointer.
#include <map>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"

namespace socsim {

// Supported: type (name or array of names), enum, const, properties, required,
// additionalProperties (bool or schema), patternProperties, minProperties/maxProperties,
// items (schema or bool), minItems/maxItems, uniqueItems, minimum/maximum,
// exclusiveMinimum/exclusiveMaximum (numbers), multipleOf, minLength/maxLength (code points),
// pattern (ECMAScript, unanchored), $ref to "#" or "#/..." in the same document, allOf/anyOf/
// oneOf/not. Annotations (title, description, default, examples, format, $comment, …) are ignored.
// Keywords whose meaning we do not implement (prefixItems, contains, if/then/else,
// dependentRequired, unevaluated*, $dynamicRef, …) are refused when the schema is compiled, so a
// schema can never be silently under-checked.
class JsonSchema {
 public:
  // Checks the schema itself: keyword value types, regexes, $ref targets. Errors are
  // kValidation with pointers into the schema document.
  static Result<JsonSchema> compile(Json schema);

  // Every violation (object members in key order), at most max_errors (then one "… more" entry).
  [[nodiscard]] std::vector<FieldError> validate(const Json& instance, std::size_t max_errors = 100) const;

  // kValidation naming the first problems when the instance does not conform.
  [[nodiscard]] Status check(const Json& instance, const std::string& what) const;

  [[nodiscard]] const Json& document() const { return *document_; }

  // Strings longer than this are not run through `pattern` (libstdc++'s std::regex recurses per
  // character and can exhaust the stack); they are reported as too long to check instead.
  static constexpr std::size_t kMaxPatternSubjectBytes = 4096;

 private:
  explicit JsonSchema(Json schema) : document_(std::make_shared<Json>(std::move(schema))) {}
  std::shared_ptr<const Json> document_;
  std::shared_ptr<std::map<std::string, std::regex>> regexes_;  // compiled once, read-only after
  friend class SchemaValidation;
};

}  // namespace socsim
