#include "core/common/json_schema.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string_view>

namespace socsim {
namespace {

constexpr int kMaxSchemaDepth = 200;  // nested subschemas + $ref hops on one evaluation path

const std::set<std::string_view>& unsupported_keywords() {
  static const std::set<std::string_view> k = {"prefixItems",
                                               "contains",
                                               "minContains",
                                               "maxContains",
                                               "additionalItems",
                                               "if",
                                               "then",
                                               "else",
                                               "dependentRequired",
                                               "dependentSchemas",
                                               "dependencies",
                                               "propertyNames",
                                               "unevaluatedProperties",
                                               "unevaluatedItems",
                                               "$dynamicRef",
                                               "$dynamicAnchor",
                                               "$recursiveRef",
                                               "$recursiveAnchor"};
  return k;
}

bool is_type_name(std::string_view t) {
  return t == "null" || t == "boolean" || t == "object" || t == "array" || t == "number" || t == "integer" ||
         t == "string";
}

std::string short_json(const Json& v, std::size_t limit = 80) {
  std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (s.size() > limit) s = s.substr(0, limit) + "…";
  return s;
}

std::string type_of(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "boolean";
    case Json::value_t::object:
      return "object";
    case Json::value_t::array:
      return "array";
    case Json::value_t::string:
      return "string";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
      return "integer";
    case Json::value_t::number_float:
      return "number";
    default:
      return "unknown";
  }
}

bool has_type(const Json& v, std::string_view t) {
  if (t == "null") return v.is_null();
  if (t == "boolean") return v.is_boolean();
  if (t == "object") return v.is_object();
  if (t == "array") return v.is_array();
  if (t == "string") return v.is_string();
  if (t == "number") return v.is_number();
  if (t == "integer") {
    if (v.is_number_integer()) return true;
    if (!v.is_number_float()) return false;
    const double d = v.get<double>();
    return std::isfinite(d) && std::floor(d) == d;
  }
  return false;
}

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return n;
}

// Resolves "#" or "#/a/b" (RFC 6901 with ~0 ~1) within the document; nullptr when absent.
const Json* resolve_ref(const Json& root, const std::string& ref) {
  if (ref.empty() || ref[0] != '#') return nullptr;
  if (ref.size() == 1) return &root;
  if (ref[1] != '/') return nullptr;
  try {
    Json::json_pointer p(ref.substr(1));
    if (!root.contains(p)) return nullptr;
    return &root.at(p);
  } catch (const Json::exception&) {
    return nullptr;
  }
}

std::string child(const std::string& ptr, std::string_view key) {
  return ptr + "/" + json_pointer_token(key);
}
std::string child(const std::string& ptr, std::size_t i) {
  return ptr + "/" + std::to_string(i);
}

// ---- compile-time checks of the schema document ----
class SchemaCompiler {
 public:
  SchemaCompiler(const Json& root, std::map<std::string, std::regex>& regexes)
      : root_(root), regexes_(regexes) {}

  void schema(const Json& s, const std::string& ptr, int depth) {
    if (depth > kMaxSchemaDepth) return add(ptr, "schema nested too deeply");
    if (s.is_boolean()) return;
    if (!s.is_object()) return add(ptr, "a schema must be an object or a boolean");
    for (const auto& [key, value] : s.items()) {
      const std::string p = child(ptr, key);
      if (unsupported_keywords().count(key)) {
        add(p, "keyword \"" + key + "\" is not supported by socsim's validator");
        continue;
      }
      if (key == "$defs" || key == "definitions" || key == "properties" || key == "patternProperties") {
        if (!value.is_object()) {
          add(p, "must be an object of schemas");
          continue;
        }
        for (const auto& [name, sub] : value.items()) {
          if (key == "patternProperties") regex(name, p);
          schema(sub, child(p, name), depth + 1);
        }
      } else if (key == "additionalProperties" || key == "items" || key == "not") {
        schema(value, p, depth + 1);
      } else if (key == "allOf" || key == "anyOf" || key == "oneOf") {
        if (!value.is_array() || value.empty()) {
          add(p, "must be a non-empty array of schemas");
          continue;
        }
        for (std::size_t i = 0; i < value.size(); ++i) schema(value[i], child(p, i), depth + 1);
      } else if (key == "type") {
        type(value, p);
      } else if (key == "enum") {
        if (!value.is_array()) add(p, "must be an array");
      } else if (key == "required") {
        if (!value.is_array()) {
          add(p, "must be an array of property names");
          continue;
        }
        for (const Json& r : value)
          if (!r.is_string()) add(p, "must contain only strings");
      } else if (key == "minimum" || key == "maximum" || key == "exclusiveMinimum" ||
                 key == "exclusiveMaximum") {
        if (!value.is_number()) add(p, "must be a number");
      } else if (key == "multipleOf") {
        if (!value.is_number() || value.get<double>() <= 0) add(p, "must be a number > 0");
      } else if (key == "minLength" || key == "maxLength" || key == "minItems" || key == "maxItems" ||
                 key == "minProperties" || key == "maxProperties") {
        if (!value.is_number_integer() || value.get<std::int64_t>() < 0)
          add(p, "must be a non-negative integer");
      } else if (key == "uniqueItems") {
        if (!value.is_boolean()) add(p, "must be a boolean");
      } else if (key == "pattern") {
        if (!value.is_string())
          add(p, "must be a string");
        else
          regex(value.get<std::string>(), p);
      } else if (key == "$ref") {
        if (!value.is_string())
          add(p, "must be a string");
        else if (!resolve_ref(root_, value.get<std::string>()))
          add(p, "reference " + value.get<std::string>() + " does not resolve within this document");
      }
      // Annotations, "const" and unknown (extension) keywords need no check.
    }
  }

  std::vector<FieldError> errors;

 private:
  void add(const std::string& ptr, std::string msg) { errors.push_back(FieldError{ptr, std::move(msg)}); }

  void type(const Json& v, const std::string& ptr) {
    if (v.is_string()) {
      if (!is_type_name(v.get<std::string>())) add(ptr, "unknown type \"" + v.get<std::string>() + "\"");
    } else if (v.is_array() && !v.empty()) {
      for (const Json& t : v)
        if (!t.is_string() || !is_type_name(t.get<std::string>())) add(ptr, "unknown type " + short_json(t));
    } else {
      add(ptr, "must be a type name or a non-empty array of type names");
    }
  }

  void regex(const std::string& pattern, const std::string& ptr) {
    if (regexes_.count(pattern)) return;
    try {
      regexes_.emplace(pattern, std::regex(pattern, std::regex::ECMAScript));
    } catch (const std::regex_error& e) {
      add(ptr, "invalid regular expression " + short_json(Json(pattern)) + ": " + e.what());
    }
  }

  const Json& root_;
  std::map<std::string, std::regex>& regexes_;
};

}  // namespace

// ---- validation of an instance ----
class SchemaValidation {
 public:
  SchemaValidation(const JsonSchema& s, std::size_t max_errors) : schema_(s), max_errors_(max_errors) {}

  void run(const Json& schema, const Json& inst, const std::string& ptr, int depth);

  std::vector<FieldError> errors;
  std::size_t dropped = 0;

 private:
  void add(const std::string& ptr, std::string msg) {
    if (errors.size() < max_errors_)
      errors.push_back(FieldError{ptr, std::move(msg)});
    else
      ++dropped;
  }
  std::vector<FieldError> sub(const Json& schema, const Json& inst, const std::string& ptr, int depth) {
    SchemaValidation v(schema_, max_errors_);
    v.run(schema, inst, ptr, depth);
    return std::move(v.errors);
  }
  void object_keywords(const Json& s, const Json& inst, const std::string& ptr, int depth);
  void array_keywords(const Json& s, const Json& inst, const std::string& ptr, int depth);
  void number_keywords(const Json& s, const Json& inst, const std::string& ptr);
  void string_keywords(const Json& s, const Json& inst, const std::string& ptr);
  void combinators(const Json& s, const Json& inst, const std::string& ptr, int depth);

  const JsonSchema& schema_;
  std::size_t max_errors_;
};

void SchemaValidation::run(const Json& s, const Json& inst, const std::string& ptr, int depth) {
  if (depth > kMaxSchemaDepth)
    return add(ptr, "schema recursion deeper than " + std::to_string(kMaxSchemaDepth) + " levels");
  if (s.is_boolean()) {
    if (!s.get<bool>()) add(ptr, "is not allowed here");
    return;
  }
  if (!s.is_object()) return;

  if (auto it = s.find("$ref"); it != s.end() && it->is_string()) {
    if (const Json* target = resolve_ref(schema_.document(), it->get<std::string>()))
      run(*target, inst, ptr, depth + 1);
  }
  if (auto it = s.find("type"); it != s.end()) {
    bool ok = false;
    std::string names;
    if (it->is_string()) {
      ok = has_type(inst, it->get<std::string>());
      names = it->get<std::string>();
    } else if (it->is_array()) {
      for (const Json& t : *it) {
        if (!t.is_string()) continue;
        ok = ok || has_type(inst, t.get<std::string>());
        names += (names.empty() ? "" : " or ") + t.get<std::string>();
      }
    }
    if (!ok) {
      add(ptr, "must be of type " + names + ", got " + type_of(inst));
      return;  // the other keywords would only repeat the same problem
    }
  }
  if (auto it = s.find("enum"); it != s.end() && it->is_array()) {
    if (std::find(it->begin(), it->end(), inst) == it->end())
      add(ptr, "must be one of " + short_json(*it, 200) + ", got " + short_json(inst));
  }
  if (auto it = s.find("const"); it != s.end()) {
    if (inst != *it) add(ptr, "must be " + short_json(*it) + ", got " + short_json(inst));
  }
  if (inst.is_object()) object_keywords(s, inst, ptr, depth);
  if (inst.is_array()) array_keywords(s, inst, ptr, depth);
  if (inst.is_number()) number_keywords(s, inst, ptr);
  if (inst.is_string()) string_keywords(s, inst, ptr);
  combinators(s, inst, ptr, depth);
}

void SchemaValidation::object_keywords(const Json& s, const Json& inst, const std::string& ptr, int depth) {
  if (auto it = s.find("required"); it != s.end() && it->is_array()) {
    for (const Json& name : *it)
      if (name.is_string() && !inst.contains(name.get<std::string>()))
        add(child(ptr, name.get<std::string>()), "is required");
  }
  if (auto it = s.find("minProperties");
      it != s.end() && it->is_number_integer() && inst.size() < it->get<std::size_t>())
    add(ptr, "must have at least " + it->dump() + " properties, got " + std::to_string(inst.size()));
  if (auto it = s.find("maxProperties");
      it != s.end() && it->is_number_integer() && inst.size() > it->get<std::size_t>())
    add(ptr, "must have at most " + it->dump() + " properties, got " + std::to_string(inst.size()));

  const auto props = s.find("properties");
  const auto patterns = s.find("patternProperties");
  const auto additional = s.find("additionalProperties");
  for (const auto& [key, value] : inst.items()) {
    const std::string p = child(ptr, key);
    bool matched = false;
    if (props != s.end() && props->is_object()) {
      if (auto ps = props->find(key); ps != props->end()) {
        matched = true;
        run(*ps, value, p, depth + 1);
      }
    }
    if (patterns != s.end() && patterns->is_object()) {
      for (const auto& [pattern, sub_schema] : patterns->items()) {
        auto rx = schema_.regexes_->find(pattern);
        if (rx == schema_.regexes_->end() || key.size() > JsonSchema::kMaxPatternSubjectBytes) continue;
        if (std::regex_search(key, rx->second)) {
          matched = true;
          run(sub_schema, value, p, depth + 1);
        }
      }
    }
    if (!matched && additional != s.end()) {
      if (additional->is_boolean() && !additional->get<bool>()) {
        std::string allowed;
        if (props != s.end() && props->is_object()) {
          std::size_t n = 0;
          for (const auto& [name, unused] : props->items()) {
            (void)unused;
            if (++n > 20) {
              allowed += ", …";
              break;
            }
            allowed += (allowed.empty() ? "" : ", ") + name;
          }
        }
        add(p,
            "is not an allowed property" + (allowed.empty() ? std::string() : " (allowed: " + allowed + ")"));
      } else {
        run(*additional, value, p, depth + 1);
      }
    }
  }
}

void SchemaValidation::array_keywords(const Json& s, const Json& inst, const std::string& ptr, int depth) {
  if (auto it = s.find("minItems");
      it != s.end() && it->is_number_integer() && inst.size() < it->get<std::size_t>())
    add(ptr, "must have at least " + it->dump() + " items, got " + std::to_string(inst.size()));
  if (auto it = s.find("maxItems");
      it != s.end() && it->is_number_integer() && inst.size() > it->get<std::size_t>())
    add(ptr, "must have at most " + it->dump() + " items, got " + std::to_string(inst.size()));
  if (auto it = s.find("uniqueItems"); it != s.end() && it->is_boolean() && it->get<bool>()) {
    bool reported = false;
    for (std::size_t i = 0; i < inst.size() && !reported; ++i)
      for (std::size_t j = i + 1; j < inst.size(); ++j)
        if (inst[i] == inst[j]) {
          add(ptr, "items " + std::to_string(i) + " and " + std::to_string(j) +
                       " are equal; items must be unique");
          reported = true;
          break;
        }
  }
  if (auto it = s.find("items"); it != s.end()) {
    for (std::size_t i = 0; i < inst.size(); ++i) run(*it, inst[i], child(ptr, i), depth + 1);
  }
}

void SchemaValidation::number_keywords(const Json& s, const Json& inst, const std::string& ptr) {
  const double v = inst.get<double>();
  const std::string got = ", got " + short_json(inst);
  if (auto it = s.find("minimum"); it != s.end() && it->is_number() && v < it->get<double>())
    add(ptr, "must be >= " + it->dump() + got);
  if (auto it = s.find("maximum"); it != s.end() && it->is_number() && v > it->get<double>())
    add(ptr, "must be <= " + it->dump() + got);
  if (auto it = s.find("exclusiveMinimum"); it != s.end() && it->is_number() && v <= it->get<double>())
    add(ptr, "must be > " + it->dump() + got);
  if (auto it = s.find("exclusiveMaximum"); it != s.end() && it->is_number() && v >= it->get<double>())
    add(ptr, "must be < " + it->dump() + got);
  if (auto it = s.find("multipleOf"); it != s.end() && it->is_number()) {
    bool ok;
    if (inst.is_number_integer() && it->is_number_integer()) {
      const auto m = it->get<std::int64_t>();
      ok = m == 0 || inst.get<std::int64_t>() % m == 0;
    } else {
      const double q = v / it->get<double>();
      ok = std::isfinite(q) && std::fabs(q - std::round(q)) <= 1e-9 * std::max(1.0, std::fabs(q));
    }
    if (!ok) add(ptr, "must be a multiple of " + it->dump() + got);
  }
}

void SchemaValidation::string_keywords(const Json& s, const Json& inst, const std::string& ptr) {
  const auto& str = inst.get_ref<const std::string&>();
  const std::size_t len = code_points(str);
  if (auto it = s.find("minLength"); it != s.end() && it->is_number_integer() && len < it->get<std::size_t>())
    add(ptr, "must have at least " + it->dump() + " characters, got " + std::to_string(len));
  if (auto it = s.find("maxLength"); it != s.end() && it->is_number_integer() && len > it->get<std::size_t>())
    add(ptr, "must have at most " + it->dump() + " characters, got " + std::to_string(len));
  if (auto it = s.find("pattern"); it != s.end() && it->is_string()) {
    auto rx = schema_.regexes_->find(it->get<std::string>());
    if (rx == schema_.regexes_->end()) return;
    if (str.size() > JsonSchema::kMaxPatternSubjectBytes)
      add(ptr, "is too long (" + std::to_string(str.size()) + " bytes) to check against the pattern " +
                   it->get<std::string>());
    else if (!std::regex_search(str, rx->second))
      add(ptr, "must match the pattern " + it->get<std::string>() + ", got " + short_json(inst));
  }
}

void SchemaValidation::combinators(const Json& s, const Json& inst, const std::string& ptr, int depth) {
  if (auto it = s.find("allOf"); it != s.end() && it->is_array())
    for (const Json& sub_schema : *it) run(sub_schema, inst, ptr, depth + 1);

  // For anyOf/oneOf with no match, the alternative with the fewest problems is quoted: usually
  // the one the author meant, so its errors are the useful ones.
  const auto alternatives = [&](const Json& list, std::string_view keyword) {
    std::vector<std::size_t> matches;
    std::vector<FieldError> closest;
    bool have_closest = false;
    for (std::size_t i = 0; i < list.size(); ++i) {
      auto errs = sub(list[i], inst, ptr, depth + 1);
      if (errs.empty())
        matches.push_back(i);
      else if (!have_closest || errs.size() < closest.size()) {
        closest = std::move(errs);
        have_closest = true;
      }
    }
    if (matches.empty()) {
      add(ptr, "matches none of the " + std::to_string(list.size()) + " alternatives of " +
                   std::string(keyword) + (have_closest ? "; closest alternative's problems follow" : ""));
      for (auto& e : closest) add(e.pointer, std::move(e.message));
    }
    return matches;
  };
  if (auto it = s.find("anyOf"); it != s.end() && it->is_array()) alternatives(*it, "anyOf");
  if (auto it = s.find("oneOf"); it != s.end() && it->is_array()) {
    auto matches = alternatives(*it, "oneOf");
    if (matches.size() > 1)
      add(ptr, "matches alternatives " + std::to_string(matches[0]) + " and " + std::to_string(matches[1]) +
                   " of oneOf; exactly one must match");
  }
  if (auto it = s.find("not"); it != s.end()) {
    if (sub(*it, inst, ptr, depth + 1).empty()) add(ptr, "must not match the schema under \"not\"");
  }
}

Result<JsonSchema> JsonSchema::compile(Json schema) {
  JsonSchema out(std::move(schema));
  auto regexes = std::make_shared<std::map<std::string, std::regex>>();
  SchemaCompiler compiler(*out.document_, *regexes);
  compiler.schema(*out.document_, "", 0);
  if (!compiler.errors.empty()) {
    std::string detail =
        "invalid JSON Schema: " + compiler.errors.front().pointer + ": " + compiler.errors.front().message;
    return fail(ErrorCode::kValidation, std::move(detail), std::move(compiler.errors));
  }
  out.regexes_ = std::move(regexes);
  return out;
}

std::vector<FieldError> JsonSchema::validate(const Json& instance, std::size_t max_errors) const {
  SchemaValidation v(*this, std::max<std::size_t>(1, max_errors));
  v.run(*document_, instance, "", 0);
  if (v.dropped > 0)
    v.errors.push_back(FieldError{"", "… and " + std::to_string(v.dropped) + " more problems"});
  return std::move(v.errors);
}

Status JsonSchema::check(const Json& instance, const std::string& what) const {
  auto errors = validate(instance);
  if (errors.empty()) return {};
  std::string detail = what + " does not match its schema: ";
  for (std::size_t i = 0; i < errors.size() && i < 3; ++i)
    detail += (i ? "; " : "") + (errors[i].pointer.empty() ? std::string("(root)") : errors[i].pointer) +
              " " + errors[i].message;
  if (errors.size() > 3) detail += "; (" + std::to_string(errors.size() - 3) + " more)";
  return fail(ErrorCode::kValidation, std::move(detail), std::move(errors));
}

}  // namespace socsim
