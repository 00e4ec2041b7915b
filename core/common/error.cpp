#include "core/common/error.hpp"

#include <array>

namespace socsim {
namespace {
struct Row {
  ErrorCode code;
  ErrorInfo info;
};
constexpr std::array kTable = {
    Row{ErrorCode::kBadRequest, {"bad-request", "Malformed request", 400}},
    Row{ErrorCode::kValidation, {"validation", "The request is not valid", 422}},
    Row{ErrorCode::kNotFound, {"not-found", "Not found", 404}},
    Row{ErrorCode::kMethodNotAllowed, {"method-not-allowed", "Method not allowed", 405}},
    Row{ErrorCode::kConflict, {"conflict", "Conflict with the current state", 409}},
    Row{ErrorCode::kUnauthorized, {"unauthorized", "A valid API key is required", 401}},
    Row{ErrorCode::kForbidden, {"forbidden", "This key may not do that", 403}},
    Row{ErrorCode::kPayloadTooLarge, {"payload-too-large", "Request body too large", 413}},
    Row{ErrorCode::kRateLimited, {"rate-limited", "Too many requests", 429}},
    Row{ErrorCode::kPreconditionFailed, {"precondition-failed", "Precondition failed", 412}},
    Row{ErrorCode::kUnsupportedMediaType, {"unsupported-media-type", "Unsupported media type", 415}},
    Row{ErrorCode::kStoreBusy, {"store-busy", "The store is busy, retry later", 503}},
    Row{ErrorCode::kStoreSchemaTooNew,
        {"store-schema-too-new", "Database was migrated by a newer build", 500}},
    Row{ErrorCode::kStore, {"store", "Store failure", 500}},
    Row{ErrorCode::kUpstream, {"upstream", "The generator endpoint failed", 502}},
    Row{ErrorCode::kUpstreamTimeout, {"upstream-timeout", "The generator endpoint timed out", 504}},
    Row{ErrorCode::kCancelled, {"cancelled", "The job was cancelled", 409}},
    Row{ErrorCode::kInternal, {"internal", "Internal error", 500}},
};
}  // namespace

const ErrorInfo& error_info(ErrorCode code) {
  for (const Row& r : kTable)
    if (r.code == code) return r.info;
  return kTable.back().info;
}

nlohmann::json Error::to_problem(std::string_view instance) const {
  const ErrorInfo& info = error_info(code);
  nlohmann::json p = {{"type", std::string(kProblemTypeBase) + std::string(info.slug)},
                      {"title", info.title},
                      {"status", info.http_status},
                      {"detail", detail}};
  if (!instance.empty()) p["instance"] = instance;
  nlohmann::json list = nlohmann::json::array();
  for (const FieldError& e : errors) {
    nlohmann::json j = {{"pointer", e.pointer}, {"message", e.message}};
    if (!e.parameter.empty()) j["parameter"] = e.parameter;
    if (e.line > 0) {
      j["line"] = e.line;
      j["column"] = e.column;
    }
    list.push_back(std::move(j));
  }
  p["errors"] = std::move(list);
  if (retry_after_s > 0) p["retry_after"] = retry_after_s;
  return p;
}

std::string Error::message() const {
  std::string s(error_info(code).title);
  if (!detail.empty()) s += ": " + detail;
  for (const FieldError& e : errors) {
    s += "\n  ";
    if (!e.pointer.empty()) s += e.pointer + ": ";
    if (!e.parameter.empty()) s += "?" + e.parameter + ": ";
    if (e.line > 0) s += "line " + std::to_string(e.line) + ":" + std::to_string(e.column) + ": ";
    s += e.message;
  }
  return s;
}

}  // namespace socsim
