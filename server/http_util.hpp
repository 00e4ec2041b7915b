#pragma once
// Small helpers shared by the route files: JSON replies, problem+json errors, body parsing,
// query parameters. Only server/ includes httplib.
#include <functional>
#include <optional>
#include <string>

#include <httplib.h>

#include "core/common/error.hpp"
#include "core/common/json_io.hpp"

namespace socsim::server {

void reply_json(httplib::Response& res, int status, const Json& body);
void reply_problem(httplib::Response& res, const Error& error, const std::string& instance);
// The JSON body of a request: 400 with line/column for syntax errors, depth-limited.
Result<Json> json_body(const std::string& body);

// Registers a POST route whose body is read incrementally and refused with 413 past `max_bytes`,
// whether it comes with a Content-Length or chunked (httplib 0.11 does not cap chunked bodies).
// A body past the limit is read and dropped up to this many times the limit, so an ordinary
// client still receives its 413; beyond that the connection is cut.
inline constexpr std::size_t kBodyDrainFactor = 8;
using BodyHandler = std::function<void(const httplib::Request&, httplib::Response&, const std::string& body)>;
void post_with_body(httplib::Server& http, const std::string& pattern, std::size_t max_bytes,
                    BodyHandler handler);
std::optional<std::string> query(const httplib::Request& req, const std::string& name);
// An integer query parameter within [min, max]; 422 naming the parameter otherwise.
Result<std::int64_t> query_int(const httplib::Request& req, const std::string& name, std::int64_t fallback,
                               std::int64_t min, std::int64_t max);
ErrorCode code_for_status(int status);

}  // namespace socsim::server
