#pragma once
// The one error table of socsim: every failure the API or CLI can report has a code here,
// with its problem type, title and HTTP status (RFC 9457). Expected failures travel as values
// (tl::expected<T, Error>); exceptions are kept for broken invariants and I/O.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <tl/expected.hpp>

namespace socsim {

enum class ErrorCode {
  kBadRequest,  // malformed syntax (JSON, YAML, query)
  kValidation,  // well-formed but violates the schema or a rule
  kNotFound,
  kMethodNotAllowed,
  kConflict,      // id exists with other content, version clash
  kUnauthorized,  // no or unknown API key
  kForbidden,     // key known but not allowed (e.g. not the author)
  kPayloadTooLarge,
  kRateLimited,
  kPreconditionFailed,
  kUnsupportedMediaType,
  kStoreBusy,          // database locked past busy_timeout
  kStoreSchemaTooNew,  // database migrated by a newer build
  kStore,              // other database failure
  kUpstream,           // LLM endpoint failed or answered badly
  kUpstreamTimeout,
  kCancelled,  // the job was cancelled by its owner
  kInternal,
};

struct ErrorInfo {
  std::string_view slug;   // last part of the problem type URI
  std::string_view title;  // short, human, stable per code
  int http_status;
};

const ErrorInfo& error_info(ErrorCode code);

// One bad field: a JSON pointer (RFC 6901) into the request body, or a query parameter name,
// or a line/column in an uploaded document.
struct FieldError {
  std::string pointer;
  std::string message;
  std::string parameter;  // query parameter name, when the error is about one
  int line = 0;           // 1-based, when known (JSON or YAML text)
  int column = 0;

  FieldError() = default;
  // The usual case: a pointer into the body and what is wrong there.
  FieldError(std::string pointer_, std::string message_)
      : pointer(std::move(pointer_)), message(std::move(message_)) {}
  FieldError(std::string pointer_, std::string message_, std::string parameter_, int line_, int column_)
      : pointer(std::move(pointer_)),
        message(std::move(message_)),
        parameter(std::move(parameter_)),
        line(line_),
        column(column_) {}
  // About a query parameter.
  static FieldError query(std::string name, std::string message_) {
    return FieldError{{}, std::move(message_), std::move(name), 0, 0};
  }
  // At a line and column of a document (JSON or YAML text).
  static FieldError at(std::string pointer_, std::string message_, int line_, int column_) {
    return FieldError{std::move(pointer_), std::move(message_), {}, line_, column_};
  }
};

struct Error {
  ErrorCode code = ErrorCode::kInternal;
  std::string detail;
  std::vector<FieldError> errors;
  int retry_after_s = 0;  // for kRateLimited

  Error() = default;
  Error(ErrorCode c, std::string d, std::vector<FieldError> e = {})
      : code(c), detail(std::move(d)), errors(std::move(e)) {}

  // The same error one level down: every field pointer gets `prefix` in front ("/world" + "/zones/0").
  Error& under(std::string_view prefix) & {
    for (FieldError& f : errors) f.pointer.insert(0, prefix);
    return *this;
  }
  Error under(std::string_view prefix) && {
    under(prefix);
    return std::move(*this);
  }
  // As under(), and an error without fields gets one at `prefix` saying its detail (a nested
  // document that failed as a whole).
  Error& within(std::string_view prefix) & {
    under(prefix);
    if (errors.empty()) errors.emplace_back(std::string(prefix), detail);
    return *this;
  }
  Error within(std::string_view prefix) && {
    within(prefix);
    return std::move(*this);
  }

  [[nodiscard]] int status() const { return error_info(code).http_status; }
  // RFC 9457 problem document.
  [[nodiscard]] nlohmann::json to_problem(std::string_view instance = {}) const;
  [[nodiscard]] std::string message() const;  // one line for logs and the CLI
};

template <class T>
using Result = tl::expected<T, Error>;
using Status = tl::expected<void, Error>;

inline tl::unexpected<Error> fail(ErrorCode code, std::string detail, std::vector<FieldError> errors = {}) {
  return tl::unexpected<Error>(Error(code, std::move(detail), std::move(errors)));
}

// Problem type URIs are relative to this base, and each is documented in docs/API.md.
inline constexpr std::string_view kProblemTypeBase = "https://socsim.dev/problems/";

}  // namespace socsim
