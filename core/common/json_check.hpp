#pragma once
// Typed reading of JSON request bodies that collects every problem with its JSON pointer,
// so a client sees all bad fields at once (422 with errors[]).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/common/json_io.hpp"

namespace socsim {

class JsonChecker {
 public:
  // Records a problem at `pointer`.
  void add(std::string pointer, std::string message) {
    errors_.push_back(FieldError{std::move(pointer), std::move(message)});
  }
  [[nodiscard]] bool ok() const { return errors_.empty(); }
  [[nodiscard]] const std::vector<FieldError>& errors() const { return errors_; }
  [[nodiscard]] Error error(std::string detail) const {
    return Error(ErrorCode::kValidation, std::move(detail), errors_);
  }

  // Checks that `obj` has only the listed keys; each other key is reported.
  void only_keys(const Json& obj, const std::string& ptr, std::span<const std::string_view> allowed);
  void only_keys(const Json& obj, const std::string& ptr, std::initializer_list<std::string_view> allowed) {
    only_keys(obj, ptr, std::span<const std::string_view>(allowed.begin(), allowed.size()));
  }

  // Each reader returns the value when present and well-typed; records an error and returns
  // nullopt otherwise. `required` decides whether absence is an error.
  std::optional<std::string> string(const Json& obj, const std::string& ptr, std::string_view key,
                                    bool required, std::size_t min_len = 0, std::size_t max_len = 1u << 20);
  std::optional<std::int64_t> integer(const Json& obj, const std::string& ptr, std::string_view key,
                                      bool required, std::int64_t min = INT64_MIN,
                                      std::int64_t max = INT64_MAX);
  std::optional<double> number(const Json& obj, const std::string& ptr, std::string_view key, bool required,
                               double min = -1e300, double max = 1e300);
  std::optional<bool> boolean(const Json& obj, const std::string& ptr, std::string_view key, bool required);
  const Json* object(const Json& obj, const std::string& ptr, std::string_view key, bool required);
  const Json* array(const Json& obj, const std::string& ptr, std::string_view key, bool required,
                    std::size_t max_items = 1u << 20);

  // Whether `key` carries a value: present and not null. The readers treat an explicit null as an
  // absent optional field, so "was it given?" must be asked this way, never with contains().
  static bool given(const Json& obj, std::string_view key) {
    if (!obj.is_object()) return false;
    auto it = obj.find(std::string(key));
    return it != obj.end() && !it->is_null();
  }

  static std::string child(const std::string& ptr, std::string_view key) {
    return ptr + "/" + json_pointer_token(key);
  }
  static std::string child(const std::string& ptr, std::size_t index) {
    return ptr + "/" + std::to_string(index);
  }

 private:
  const Json* find(const Json& obj, const std::string& ptr, std::string_view key, bool required);
  std::vector<FieldError> errors_;
};

}  // namespace socsim
