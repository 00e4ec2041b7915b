// /api/v1/jobs: progress, result or problem of long-running work, its LLM calls, cancellation.
#include "core/llm/call_log.hpp"
#include "server/http_util.hpp"
#include "server/pagination.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

constexpr const char* kJobPath = R"(/api/v1/jobs/([^/]+))";

void job_routes(Router& http, RouteContext& ctx) {
  http.Get("/api/v1/jobs", [&ctx](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    auto status = query(req, "status");
    if (status && *status != "queued" && *status != "running" && *status != "succeeded" &&
        *status != "failed" && *status != "cancelled")
      return reply_problem(
          res,
          Error(ErrorCode::kValidation, "unknown job status",
                {{"", "one of queued, running, succeeded, failed, cancelled", "status", 0, 0}}),
          req.path);
    auto listed = ctx.jobs.list(page->page_size, page->cursor, query(req, "kind"), status);
    if (!listed) return reply_problem(res, listed.error(), req.path);
    reply_json(res, 200,
               {{"items", listed->items},
                {"next_cursor", listed->next_cursor ? Json(*listed->next_cursor) : Json(nullptr)}});
  });

  http.Get(kJobPath, [&ctx](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    auto job = ctx.jobs.get(id);
    if (!job) return reply_problem(res, job.error(), req.path);
    // Token counts, latency and cache hits of every LLM call the job made; the prompts and answers
    // (which carry the author's request and what the model made of it) only for the job's author,
    // authenticated by key. A server without keys authenticates nobody, so it shows them to nobody.
    auto calls = llm::job_llm_calls(ctx.store, id);
    (*job)["llm"] = calls ? *calls : Json(nullptr);
    const bool owner = !ctx.any_author() && (*job)["author"] == ctx.author(req);
    if (calls && !owner) {
      for (auto& call : (*job)["llm"]["calls"])
        for (const char* k : {"prompt", "response", "error"}) call[k] = nullptr;
      (*job)["llm"]["redacted"] = "prompts and answers are shown to the job's author's key only";
    }
    const std::string status = (*job)["status"];
    if (status == "queued" || status == "running") res.set_header("Retry-After", "1");
    reply_json(res, 200, *job);
  });

  http.Delete(kJobPath, [&ctx](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    if (auto s = ctx.jobs.cancel(id, ctx.author(req), ctx.any_author()); !s)
      return reply_problem(res, s.error(), req.path);
    auto job = ctx.jobs.get(id);
    if (!job) return reply_problem(res, job.error(), req.path);
    reply_json(res, 202, *job);
  });
}

}  // namespace

SOCSIM_ROUTES("jobs", job_routes);

}  // namespace socsim::server
