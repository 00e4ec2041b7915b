#include "core/common/json_check.hpp"

#include <cmath>

namespace socsim {
namespace {
std::string type_name(const Json& j) {
  return j.type_name();
}
}  // namespace

void JsonChecker::only_keys(const Json& obj, const std::string& ptr,
                            std::span<const std::string_view> allowed) {
  if (!obj.is_object()) return;
  for (const auto& [k, v] : obj.items()) {
    bool known = false;
    for (std::string_view a : allowed) known = known || a == k;
    if (!known) add(child(ptr, k), "unknown field '" + k + "'");
  }
}

const Json* JsonChecker::find(const Json& obj, const std::string& ptr, std::string_view key, bool required) {
  if (!obj.is_object()) return nullptr;
  auto it = obj.find(std::string(key));
  if (it == obj.end() || (it->is_null() && required)) {
    if (required) add(child(ptr, key), "is required");
    return nullptr;
  }
  if (it->is_null()) return nullptr;
  return &*it;
}

std::optional<std::string> JsonChecker::string(const Json& obj, const std::string& ptr, std::string_view key,
                                               bool required, std::size_t min_len, std::size_t max_len) {
  const Json* v = find(obj, ptr, key, required);
  if (!v) return std::nullopt;
  if (!v->is_string()) {
    add(child(ptr, key), "must be a string, not " + type_name(*v));
    return std::nullopt;
  }
  const auto& s = v->get_ref<const std::string&>();
  if (s.size() < min_len) {
    add(child(ptr, key),
        min_len == 1 ? "must not be empty" : "must be at least " + std::to_string(min_len) + " characters");
    return std::nullopt;
  }
  if (s.size() > max_len) {
    add(child(ptr, key),
        "must be at most " + std::to_string(max_len) + " bytes (got " + std::to_string(s.size()) + ")");
    return std::nullopt;
  }
  return s;
}

std::optional<std::int64_t> JsonChecker::integer(const Json& obj, const std::string& ptr,
                                                 std::string_view key, bool required, std::int64_t min,
                                                 std::int64_t max) {
  const Json* v = find(obj, ptr, key, required);
  if (!v) return std::nullopt;
  std::int64_t value = 0;
  if (v->is_number_unsigned()) {
    const auto u = v->get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(INT64_MAX)) {
      add(child(ptr, key), "is too large");
      return std::nullopt;
    }
    value = static_cast<std::int64_t>(u);
  } else if (v->is_number_integer()) {
    value = v->get<std::int64_t>();
  } else {
    add(child(ptr, key), "must be an integer, not " + type_name(*v));
    return std::nullopt;
  }
  if (value < min || value > max) {
    add(child(ptr, key), "must be between " + std::to_string(min) + " and " + std::to_string(max));
    return std::nullopt;
  }
  return value;
}

std::optional<double> JsonChecker::number(const Json& obj, const std::string& ptr, std::string_view key,
                                          bool required, double min, double max) {
  const Json* v = find(obj, ptr, key, required);
  if (!v) return std::nullopt;
  if (!v->is_number()) {
    add(child(ptr, key), "must be a number, not " + type_name(*v));
    return std::nullopt;
  }
  const double d = v->get<double>();
  if (!std::isfinite(d) || d < min || d > max) {
    add(child(ptr, key),
        "must be a finite number between " + std::to_string(min) + " and " + std::to_string(max));
    return std::nullopt;
  }
  return d;
}

std::optional<bool> JsonChecker::boolean(const Json& obj, const std::string& ptr, std::string_view key,
                                         bool required) {
  const Json* v = find(obj, ptr, key, required);
  if (!v) return std::nullopt;
  if (!v->is_boolean()) {
    add(child(ptr, key), "must be true or false, not " + type_name(*v));
    return std::nullopt;
  }
  return v->get<bool>();
}

const Json* JsonChecker::object(const Json& obj, const std::string& ptr, std::string_view key,
                                bool required) {
  const Json* v = find(obj, ptr, key, required);
  if (!v) return nullptr;
  if (!v->is_object()) {
    add(child(ptr, key), "must be an object, not " + type_name(*v));
    return nullptr;
  }
  return v;
}

const Json* JsonChecker::array(const Json& obj, const std::string& ptr, std::string_view key, bool required,
                               std::size_t max_items) {
  const Json* v = find(obj, ptr, key, required);
  if (!v) return nullptr;
  if (!v->is_array()) {
    add(child(ptr, key), "must be an array, not " + type_name(*v));
    return nullptr;
  }
  if (v->size() > max_items) {
    add(child(ptr, key), "must have at most " + std::to_string(max_items) + " items");
    return nullptr;
  }
  return v;
}

}  // namespace socsim
