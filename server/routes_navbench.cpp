// /api/v1/navbench: the object-goal navigation benchmark (paper 000 §VI) as a job, and the replay
// of one episode (the house, the agent's path step by step, the receptacles visited, the target).
#include <deque>
#include <mutex>

#include "core/navbench/benchmark.hpp"
#include "server/http_util.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

// The knowledge (built-in personas only) is read once; resident pools and scene-prior counts
// depend on the seeds and are kept for the last few requests, so replays do not rebuild them.
class NavbenchInputs {
 public:
  explicit NavbenchInputs(store::Store& store) : store_(store) {}

  Result<std::shared_ptr<const household::HouseholdKnowledge>> knowledge() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!knowledge_) {
      auto k = navbench::load_benchmark_knowledge(store_);
      if (!k) return tl::unexpected(k.error());
      knowledge_ = std::make_shared<const household::HouseholdKnowledge>(std::move(*k));
    }
    return knowledge_;
  }

  Result<std::shared_ptr<const navbench::BenchmarkInputs>> inputs(const navbench::BenchmarkRequest& request) {
    auto k = knowledge();
    if (!k) return tl::unexpected(k.error());
    const auto key = std::make_tuple(request.seed, request.training_houses, request.training_seed);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& [held, value] : cache_)
        if (held == key) return value;
    }
    auto built = navbench::prepare_inputs(**k, request);
    if (!built) return tl::unexpected(built.error());
    auto value = std::make_shared<const navbench::BenchmarkInputs>(std::move(*built));
    std::lock_guard<std::mutex> lock(mutex_);
    cache_.emplace_back(key, value);
    if (cache_.size() > 4) cache_.pop_front();
    return value;
  }

 private:
  store::Store& store_;
  std::mutex mutex_;
  std::shared_ptr<const household::HouseholdKnowledge> knowledge_;
  std::deque<std::pair<std::tuple<std::uint64_t, int, std::uint64_t>,
                       std::shared_ptr<const navbench::BenchmarkInputs>>>
      cache_;
};

void navbench_routes(Router& http, RouteContext& ctx) {
  auto inputs = std::make_shared<NavbenchInputs>(ctx.store);

  // Any worker runs a benchmark from its stored (normalised) request.
  const auto navbench_job = [inputs](const Json& spec, const std::string&) -> Result<JobFn> {
    auto request = navbench::benchmark_request_from_json(spec);
    if (!request) return tl::unexpected(request.error());
    return JobFn([r = *request, inputs](const JobContext& job) -> Result<Json> {
      job.progress(0.0, "preparing residents and the scene prior");
      auto k = inputs->knowledge();
      if (!k) return tl::unexpected(k.error());
      auto in = inputs->inputs(r);
      if (!in) return tl::unexpected(in.error());
      navbench::RunHooks hooks;
      hooks.progress = [&job](double f, const std::string& m) { job.progress(f, m); };
      hooks.cancelled = [&job] { return job.cancelled(); };
      auto result = navbench::run_benchmark(r, **k, (*in)->pool, (*in)->counts, hooks);
      if (!result) return tl::unexpected(result.error());
      Json out = navbench::to_json(*result, true);
      out["table"] = navbench::format_table(*result);
      return out;
    });
  };
  ctx.jobs.define("navbench", navbench_job);

  post_with_body(http, "/api/v1/navbench", ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   auto request = navbench::benchmark_request_from_json(*body);
                   if (!request) return reply_problem(res, request.error(), req.path);
                   const Json normalised = navbench::to_json(*request);
                   auto id = ctx.jobs.submit_spec("navbench", normalised, normalised, ctx.author(req),
                                                  ctx.client(req));
                   ctx.reply_job_accepted(res, id, req.path);
                 });

  http.Get(R"(/api/v1/navbench/([^/]+)/episodes/([^/]+))", [&ctx, inputs](const Request& req, Response& res) {
    const std::string id = req.matches[1].str(), n_text = req.matches[2].str();
    auto job = ctx.jobs.get(id);
    if (!job) return reply_problem(res, job.error(), req.path);
    if ((*job)["kind"] != "navbench")
      return reply_problem(res, Error(ErrorCode::kNotFound, "job " + id + " is not a navigation benchmark"),
                           req.path);
    if ((*job)["status"] != "succeeded")
      return reply_problem(res,
                           Error(ErrorCode::kConflict, "the benchmark has not finished (status " +
                                                           (*job)["status"].get<std::string>() + ")"),
                           req.path);
    int n = -1;
    try {
      std::size_t used = 0;
      n = std::stoi(n_text, &used);
      if (used != n_text.size()) n = -1;
    } catch (const std::exception&) {
      n = -1;
    }
    if (n < 0)
      return reply_problem(res,
                           Error(ErrorCode::kValidation, "the episode number must be a non-negative integer",
                                 {{"", "not a number", "n", 0, 0}}),
                           req.path);
    const auto method = query(req, "method");
    if (method) {
      bool known = false;
      for (const auto& m : navbench::methods()) known = known || m.key == *method;
      if (!known)
        return reply_problem(res,
                             Error(ErrorCode::kValidation, "unknown method",
                                   {{"", "one of the keys of the result's methods", "method", 0, 0}}),
                             req.path);
    }
    auto request = navbench::benchmark_request_from_json((*job)["request"]);
    if (!request) return reply_problem(res, request.error(), req.path);
    const auto tasks = (*job)["result"].value("tasks", 0);
    if (n >= tasks)
      return reply_problem(res,
                           Error(ErrorCode::kNotFound, "the benchmark has " + std::to_string(tasks) +
                                                           " episodes; there is no episode " + n_text),
                           req.path);
    auto k = inputs->knowledge();
    if (!k) return reply_problem(res, k.error(), req.path);
    auto in = inputs->inputs(*request);
    if (!in) return reply_problem(res, in.error(), req.path);
    auto replay = navbench::replay_task(*request, n, **k, (*in)->pool, (*in)->counts);
    if (!replay) return reply_problem(res, replay.error(), req.path);
    (*replay)["job"] = id;
    if (method) {
      Json only = Json::object();
      only[*method] = (*replay)["methods"][*method];
      (*replay)["methods"] = only;
    }
    reply_json(res, 200, *replay);
  });
}

}  // namespace

SOCSIM_ROUTES("navbench", navbench_routes);

}  // namespace socsim::server
