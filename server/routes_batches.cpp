// /api/v1/batches: batch generation over the shared job queue (issue 21). A batch is split into
// jobs that every worker on the database takes; GET shows counts and progress, /items each item's
// outcome, /export the results as a dataset (tar), DELETE cancels what has not finished.
#include "server/batches.hpp"
#include "server/http_util.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

constexpr const char* kBatchPath = R"(/api/v1/batches/([^/]+))";

void batch_routes(Router& http, RouteContext& ctx) {
  post_with_body(http, "/api/v1/batches", ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   const std::string author = ctx.author(req);
                   auto plan = plan_batch(*body, [&](const std::string& kind, const Json& spec) -> Status {
                     auto built = ctx.jobs.build(kind, spec, author);
                     if (!built) return tl::unexpected(built.error());
                     return {};
                   });
                   if (!plan) return reply_problem(res, plan.error(), req.path);
                   auto id = store_batch(ctx.store, *plan, author, ctx.client(req));
                   if (!id) return reply_problem(res, id.error(), req.path);
                   ctx.jobs.wake();
                   auto status = batch_status(ctx.store, *id);
                   if (!status) return reply_problem(res, status.error(), req.path);
                   res.set_header("Location", "/api/v1/batches/" + *id);
                   reply_json(res, 202, *status);
                 });

  http.Get("/api/v1/batches", [&ctx](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    auto listed = list_batches(ctx.store, page->page_size, page->cursor);
    if (!listed) return reply_problem(res, listed.error(), req.path);
    reply_json(res, 200, *listed);
  });

  http.Get(kBatchPath, [&ctx](const Request& req, Response& res) {
    auto b = batch_status(ctx.store, req.matches[1].str());
    if (!b) return reply_problem(res, b.error(), req.path);
    if ((*b)["status"] == "running") res.set_header("Retry-After", "1");
    reply_json(res, 200, *b);
  });

  http.Get(std::string(kBatchPath) + "/items", [&ctx](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    std::size_t from = 0;
    if (page->cursor) {
      const std::string& c = *page->cursor;
      if (c.empty() || c.size() > 9 || c.find_first_not_of("0123456789") != std::string::npos)
        return reply_problem(res,
                             Error(ErrorCode::kBadRequest, "the cursor is not one this server issued",
                                   {{"", "use next_cursor from a previous page", "cursor", 0, 0}}),
                             req.path);
      from = static_cast<std::size_t>(std::stoul(c));
    }
    auto items = batch_items(ctx.store, req.matches[1].str(), page->page_size, from);
    if (!items) return reply_problem(res, items.error(), req.path);
    reply_json(res, 200, *items);
  });

  http.Get(std::string(kBatchPath) + "/export", [&ctx](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    auto tar = export_batch(ctx.store, id);
    if (!tar) return reply_problem(res, tar.error(), req.path);
    res.set_header("Content-Disposition", "attachment; filename=\"" + id + ".tar\"");
    res.set_content(std::move(*tar), "application/x-tar");
  });

  http.Delete(kBatchPath, [&ctx](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    auto n = cancel_batch(ctx.store, ctx.jobs, id, ctx.author(req), ctx.any_author());
    if (!n) return reply_problem(res, n.error(), req.path);
    auto b = batch_status(ctx.store, id);
    if (!b) return reply_problem(res, b.error(), req.path);
    (*b)["cancelled_items"] = *n;
    reply_json(res, 202, *b);
  });
}

}  // namespace

SOCSIM_ROUTES("batches", batch_routes);

}  // namespace socsim::server
