// /api/v1/knowledge: building codes and behaviour nodes — search (BM25, fused with embeddings
// when available), look-ups, merged floor-plan constraints, building-type classification.
#include "core/knowledge/building_type.hpp"
#include "server/http_util.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

Result<std::vector<knowledge::Kind>> kinds_of(const Request& req) {
  auto k = query(req, "kind");
  if (!k) return std::vector<knowledge::Kind>{knowledge::Kind::kBuildingCode, knowledge::Kind::kBehaviorNode};
  auto kind = knowledge::kind_from_string(*k);
  if (!kind)
    return fail(ErrorCode::kValidation, "unknown knowledge kind '" + *k + "'",
                {{"", "one of building_code, behavior_node", "kind", 0, 0}});
  return std::vector<knowledge::Kind>{*kind};
}

void knowledge_routes(Router& http, RouteContext& ctx) {
  http.Get("/api/v1/knowledge/search", [&ctx](const Request& req, Response& res) {
    auto q = query(req, "q");
    if (!q || q->empty())
      return reply_problem(
          res, Error(ErrorCode::kValidation, "say what to look for", {{"", "is required", "q", 0, 0}}),
          req.path);
    auto kinds = kinds_of(req);
    if (!kinds) return reply_problem(res, kinds.error(), req.path);
    auto k = query_int(req, "k", 5, 1, 50);
    if (!k) return reply_problem(res, k.error(), req.path);
    Json out = {{"query", *q}, {"results", Json::object()}};
    for (auto kind : *kinds) {
      auto r = ctx.knowledge.search(*q, kind, static_cast<std::size_t>(*k));
      if (!r) return reply_problem(res, r.error(), req.path);
      out["results"][std::string(knowledge::to_string(kind))] = knowledge::to_json(*r);
    }
    reply_json(res, 200, out);
  });

  http.Get("/api/v1/knowledge/building-codes", [&ctx](const Request& req, Response& res) {
    auto list = ctx.knowledge.building_codes(query(req, "building_type").value_or(""));
    if (!list) return reply_problem(res, list.error(), req.path);
    Json items = Json::array();
    for (const auto& c : *list) items.push_back(knowledge::to_json(c));
    reply_json(res, 200, {{"items", items}});
  });

  http.Get(R"(/api/v1/knowledge/building-codes/([^/]+))", [&ctx](const Request& req, Response& res) {
    auto c = ctx.knowledge.building_code(req.matches[1].str());
    if (!c) return reply_problem(res, c.error(), req.path);
    reply_json(res, 200, knowledge::to_json(*c));
  });

  http.Get("/api/v1/knowledge/behavior-nodes", [&ctx](const Request& req, Response& res) {
    auto list = ctx.knowledge.behavior_nodes();
    if (!list) return reply_problem(res, list.error(), req.path);
    Json items = Json::array();
    for (const auto& n : *list) items.push_back(knowledge::to_json(n));
    reply_json(res, 200, {{"items", items}});
  });

  http.Get(R"(/api/v1/knowledge/behavior-nodes/([^/]+))", [&ctx](const Request& req, Response& res) {
    auto n = ctx.knowledge.behavior_node(req.matches[1].str());
    if (!n) return reply_problem(res, n.error(), req.path);
    reply_json(res, 200, knowledge::to_json(*n));
  });

  http.Get("/api/v1/knowledge/constraints", [&ctx](const Request& req, Response& res) {
    auto type = query(req, "building_type");
    if (!type)
      return reply_problem(
          res,
          Error(ErrorCode::kValidation, "name a building type", {{"", "is required", "building_type", 0, 0}}),
          req.path);
    auto list = ctx.knowledge.constraints_for(*type, query(req, "jurisdiction").value_or(""));
    if (!list) return reply_problem(res, list.error(), req.path);
    Json items = Json::array();
    for (const auto& c : *list) items.push_back(knowledge::to_json(c));
    reply_json(res, 200, {{"building_type", *type}, {"constraints", items}});
  });

  http.Get("/api/v1/knowledge/classify", [](const Request& req, Response& res) {
    auto text = query(req, "text");
    auto rooms = query(req, "rooms");
    if (!text && !rooms)
      return reply_problem(
          res,
          Error(ErrorCode::kValidation, "give a prompt (?text=) or room names (?rooms=a,b,c)",
                {{"", "text or rooms is required", "text", 0, 0}}),
          req.path);
    if ((text && text->size() > 4000) || (rooms && rooms->size() > 4000))
      return reply_problem(res,
                           Error(ErrorCode::kValidation, "too long",
                                 {{"", "at most 4000 bytes", text ? "text" : "rooms", 0, 0}}),
                           req.path);
    if (text) return reply_json(res, 200, knowledge::to_json(knowledge::classify_building_type(*text)));
    std::vector<std::string> names;
    std::size_t start = 0;
    while (start <= rooms->size()) {
      const std::size_t comma = rooms->find(',', start);
      std::string name = rooms->substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (!name.empty()) names.push_back(name);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    reply_json(res, 200, knowledge::to_json(knowledge::classify_building_type(names)));
  });
}

}  // namespace

SOCSIM_ROUTES("knowledge", knowledge_routes);

}  // namespace socsim::server
