#include "server/http_util.hpp"

#include <charconv>
#include <iostream>
#include <mutex>

namespace socsim::server {

void log_line(const Json& line) {
  static std::mutex mutex;
  const std::string text = line.dump(-1, ' ', false, Json::error_handler_t::replace);
  std::lock_guard<std::mutex> lock(mutex);
  std::cout << text << '\n' << std::flush;
}

void reply_json(Response& res, int status, const Json& body) {
  res.status = status;
  res.set_content(body.dump(-1, ' ', false, Json::error_handler_t::replace), "application/json");
}

void reply_problem(Response& res, const Error& error, const std::string& instance) {
  res.status = error.status();
  if (error.retry_after_s > 0) res.set_header("Retry-After", std::to_string(error.retry_after_s));
  if (error.code == ErrorCode::kUnauthorized) res.set_header("WWW-Authenticate", "Bearer realm=\"socsim\"");
  res.set_content(error.to_problem(instance).dump(-1, ' ', false, Json::error_handler_t::replace),
                  "application/problem+json");
}

Json field_errors_json(const std::vector<FieldError>& errors) {
  Json out = Json::array();
  for (const FieldError& e : errors) {
    Json j = {{"pointer", e.pointer}, {"message", e.message}};
    if (e.line > 0) {
      j["line"] = e.line;
      j["column"] = e.column;
    }
    out.push_back(std::move(j));
  }
  return out;
}

Result<Json> json_body(const std::string& body) {
  if (body.empty())
    return fail(ErrorCode::kBadRequest, "the request needs a JSON body", {{"", "empty body"}});
  return parse_json_untrusted(body);
}

void post_with_body(Router& http, const std::string& pattern, std::size_t max_bytes, BodyHandler handler) {
  http.Post(pattern, max_bytes, [handler = std::move(handler)](const Request& req, Response& res) {
    handler(req, res, req.body);
  });
}

std::optional<std::string> query(const Request& req, const std::string& name) {
  if (!req.has_param(name.c_str())) return std::nullopt;
  return req.get_param_value(name.c_str());
}

Result<std::int64_t> query_int(const Request& req, const std::string& name, std::int64_t fallback,
                               std::int64_t min, std::int64_t max) {
  auto v = query(req, name);
  if (!v) return fallback;
  std::int64_t out = 0;
  auto [p, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
  if (ec != std::errc() || p != v->data() + v->size() || out < min || out > max) {
    return fail(ErrorCode::kValidation, "query parameter '" + name + "' is out of range",
                {{"", "must be an integer between " + std::to_string(min) + " and " + std::to_string(max),
                  name, 0, 0}});
  }
  return out;
}

Result<bool> query_bool(const Request& req, const std::string& name, bool fallback) {
  auto v = query(req, name);
  if (!v) return fallback;
  if (*v == "true" || *v == "false") return *v == "true";
  return fail(ErrorCode::kValidation, "query parameter '" + name + "' must be true or false",
              {{"", "must be true or false, not '" + *v + "'", name, 0, 0}});
}

ErrorCode code_for_status(int status) {
  switch (status) {
    case 400:
      return ErrorCode::kBadRequest;
    case 401:
      return ErrorCode::kUnauthorized;
    case 403:
      return ErrorCode::kForbidden;
    case 404:
      return ErrorCode::kNotFound;
    case 405:
      return ErrorCode::kMethodNotAllowed;
    case 409:
      return ErrorCode::kConflict;
    case 412:
      return ErrorCode::kPreconditionFailed;
    case 413:
      return ErrorCode::kPayloadTooLarge;
    case 415:
      return ErrorCode::kUnsupportedMediaType;
    case 422:
      return ErrorCode::kValidation;
    case 429:
      return ErrorCode::kRateLimited;
    case 503:
      return ErrorCode::kStoreBusy;
    default:
      return status >= 500 ? ErrorCode::kInternal : ErrorCode::kBadRequest;
  }
}

}  // namespace socsim::server
