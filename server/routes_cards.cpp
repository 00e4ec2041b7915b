// The scenario-card catalogue over HTTP: /api/v1/cards …
#include "server/http_util.hpp"
#include "server/pagination.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

constexpr const char* kCardPath = R"(/api/v1/cards/(crd_[0-9a-z]{20}|[^/]+))";

std::string etag(const cards::Card& c) {
  return "\"" + c.content_hash + "\"";
}

bool etag_matches(const std::string& if_none_match, const std::string& tag) {
  if (if_none_match.empty()) return false;
  if (if_none_match == "*") return true;
  std::size_t pos = 0;
  while (pos < if_none_match.size()) {
    std::size_t comma = if_none_match.find(',', pos);
    std::string item =
        if_none_match.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    if (item.rfind("W/", 0) == 0) item = item.substr(2);
    if (item == tag) return true;
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return false;
}

void reply_card(Response& res, int status, const cards::Card& card) {
  res.set_header("ETag", etag(card));
  res.set_header("Cache-Control", "no-cache");
  if (status == 201) res.set_header("Location", "/api/v1/cards/" + card.id);
  reply_json(res, status, cards::to_json(card));
}

Json event(const char* type, const cards::Card& card) {
  return {{"type", type}, {"card", cards::summary_json(card)}};
}

void card_routes(Router& http, RouteContext& ctx) {
  const std::size_t max_body = ctx.config.max_body_bytes;
  post_with_body(http, "/api/v1/cards", max_body,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   auto content = cards::parse_card_content(*body, ctx.catalogue.limits());
                   if (!content) return reply_problem(res, content.error(), req.path);
                   auto card = ctx.catalogue.create(*content, ctx.author(req));
                   if (!card) return reply_problem(res, card.error(), req.path);
                   ctx.events.publish("cards", event("card.created", *card));
                   reply_card(res, 201, *card);
                 });

  http.Get("/api/v1/cards", [&ctx](const Request& req, Response& res) {
    cards::CardQuery q;
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    q.page_size = page->page_size;
    q.text = query(req, "q");
    q.tag = query(req, "tag");
    q.author = query(req, "author");
    q.domain = query(req, "domain");
    q.cursor = page->cursor;
    if (q.text && q.text->size() > 500)
      return reply_problem(
          res, Error(ErrorCode::kValidation, "search text too long", {{"", "at most 500 bytes", "q", 0, 0}}),
          req.path);
    auto listed = ctx.catalogue.list(q);
    if (!listed) return reply_problem(res, listed.error(), req.path);
    Json items = Json::array();
    for (const auto& c : listed->items) items.push_back(cards::summary_json(c));
    Json out = {{"items", items},
                {"next_cursor", listed->next_cursor ? Json(*listed->next_cursor) : Json(nullptr)}};
    reply_json(res, 200, out);
  });

  http.Get(kCardPath, [&ctx](const Request& req, Response& res) {
    auto card = ctx.catalogue.get(req.matches[1].str());
    if (!card) return reply_problem(res, card.error(), req.path);
    if (etag_matches(req.get_header_value("If-None-Match"), etag(*card))) {
      res.status = 304;
      res.set_header("ETag", etag(*card));
      return;
    }
    reply_card(res, 200, *card);
  });

  http.Delete(kCardPath, [&ctx](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    auto card = ctx.catalogue.get(id);
    if (!card) return reply_problem(res, card.error(), req.path);
    if (auto s = ctx.catalogue.remove(id, ctx.author(req), ctx.any_author()); !s)
      return reply_problem(res, s.error(), req.path);
    ctx.events.publish("cards", event("card.deleted", *card));
    res.status = 204;
  });

  post_with_body(http, std::string(kCardPath) + "/versions", max_body,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   auto card = ctx.catalogue.create_version(req.matches[1].str(), *body, ctx.author(req));
                   if (!card) return reply_problem(res, card.error(), req.path);
                   ctx.events.publish("cards", event("card.created", *card));
                   reply_card(res, 201, *card);
                 });

  // GET /api/v1/cards/{id}/export (the card's own document, and the simulator formats) is served
  // by routes_scenario_exports.cpp.

  post_with_body(http, "/api/v1/cards/import", max_body,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto outcome = ctx.catalogue.import_card(text, ctx.author(req));
                   if (!outcome) return reply_problem(res, outcome.error(), req.path);
                   if (outcome->created) ctx.events.publish("cards", event("card.created", outcome->card));
                   reply_card(res, outcome->created ? 201 : 200, outcome->card);
                 });
}

}  // namespace

SOCSIM_ROUTES("cards", card_routes);

}  // namespace socsim::server
