#pragma once
// Small helpers shared by the route files: JSON replies, problem+json errors, body parsing,
// query parameters, the request log.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"
#include "server/http_server.hpp"

namespace socsim::server {

void reply_json(Response& res, int status, const Json& body);
void reply_problem(Response& res, const Error& error, const std::string& instance);
// Field notes (warnings) in the shape of a problem's `errors`: {pointer, message, line?, column?}.
Json field_errors_json(const std::vector<FieldError>& errors);
// The JSON body of a request: 400 with line/column for syntax errors, depth-limited.
Result<Json> json_body(const std::string& body);

// Registers a POST route that takes a body of at most `max_bytes` (larger ones, with a
// Content-Length or chunked, are refused with 413 before the handler runs).
using BodyHandler = std::function<void(const Request&, Response&, const std::string& body)>;
void post_with_body(Router& http, const std::string& pattern, std::size_t max_bytes, BodyHandler handler);
std::optional<std::string> query(const Request& req, const std::string& name);
// An integer query parameter within [min, max]; 422 naming the parameter otherwise.
Result<std::int64_t> query_int(const Request& req, const std::string& name, std::int64_t fallback,
                               std::int64_t min, std::int64_t max);
// A boolean query parameter ("true" or "false"); 422 naming the parameter otherwise.
Result<bool> query_bool(const Request& req, const std::string& name, bool fallback);
ErrorCode code_for_status(int status);

// One structured log line on stdout.
void log_line(const Json& line);

}  // namespace socsim::server
