// /api/v1/evaluations: the built-in robot planners over cards × seeds as a job (issue 19,
// docs/cosim.md "Evaluation jobs"); the episodes run in-process (crowd::run_evaluation), the result
// is the table of crowd::evaluation_table, stored with the job and listed like other jobs.
#include <algorithm>
#include <chrono>
#include <map>
#include <mutex>
#include <thread>

#include "core/crowd/robot_evaluation.hpp"
#include "core/crowd/robot_planners.hpp"
#include "server/cosim_sessions.hpp"
#include "server/http_util.hpp"
#include "server/routes.hpp"
#include "server/scenario_inputs.hpp"

namespace socsim::server {
namespace {

constexpr std::size_t kMaxEvaluationEpisodes = 1000;  // cards × seeds × planners
constexpr std::size_t kMaxEvaluationCards = 100;
constexpr std::size_t kMaxEvaluationSeeds = 100;
constexpr const char* kEvaluationKind = "evaluation";
// "client": "external": every card × seed becomes a lock-step /ws/cosim session, one after the
// other, that the caller's own planner drives (docs/cosim.md "External clients").
constexpr const char* kExternalClient = "external";
constexpr auto kExternalPoll = std::chrono::milliseconds(200);

// "builtin:<planner>" → the make_planner() name ("builtin:straight" stands for straight_line).
std::optional<std::string> builtin_planner(const Json& label) {
  if (!label.is_string()) return std::nullopt;
  const std::string text = label.get<std::string>();
  const std::string prefix = "builtin:";
  if (text.rfind(prefix, 0) != 0) return std::nullopt;
  std::string name = text.substr(prefix.size());
  if (name == "straight") name = "straight_line";
  for (std::string_view known : crowd::planner_names())
    if (known == name) return name;
  return std::nullopt;
}

// The request read and checked, the cards loaded: 404 at /cards/k for an unknown card, 422 with
// pointers for everything else (the job is queued only when all of it holds).
Result<crowd::EvaluationPlan> evaluation_plan(RouteContext& ctx, const Json& body, Json& normalised) {
  if (!body.is_object())
    return fail(ErrorCode::kValidation, "the body must be a JSON object",
                {FieldError{"", "must be an object"}});
  std::vector<FieldError> errors;
  for (const auto& [key, v] : body.items())
    if (key != "cards" && key != "seeds" && key != "planners" && key != "client" && key != "time_limit_s" &&
        key != "robot")
      errors.push_back({"/" + json_pointer_token(key),
                        "unknown field (expected cards, seeds, planners or client, time_limit_s, robot)"});
  crowd::EvaluationPlan plan;
  const Json* cards = body.contains("cards") ? &body["cards"] : nullptr;
  if (!cards || !cards->is_array() || cards->empty() || cards->size() > kMaxEvaluationCards)
    errors.push_back(
        {"/cards", "must be an array of 1 to " + std::to_string(kMaxEvaluationCards) + " card ids"});
  else
    for (std::size_t k = 0; k < cards->size(); ++k) {
      const std::string at = "/cards/" + std::to_string(k);
      if (!(*cards)[k].is_string())
        errors.push_back({at, "must be a card id"});
      else if (std::find(cards->begin(), cards->begin() + static_cast<std::ptrdiff_t>(k), (*cards)[k]) !=
               cards->begin() + static_cast<std::ptrdiff_t>(k))
        errors.push_back({at, "names the same card twice"});
    }
  const Json* seeds = body.contains("seeds") ? &body["seeds"] : nullptr;
  if (!seeds || !seeds->is_array() || seeds->empty() || seeds->size() > kMaxEvaluationSeeds) {
    errors.push_back(
        {"/seeds", "must be an array of 1 to " + std::to_string(kMaxEvaluationSeeds) + " seeds"});
  } else {
    for (std::size_t k = 0; k < seeds->size(); ++k) {
      const Json& s = (*seeds)[k];
      if (!s.is_number_unsigned())
        errors.push_back({"/seeds/" + std::to_string(k), "must be a whole number ≥ 0"});
      else if (std::find(plan.seeds.begin(), plan.seeds.end(), s.get<std::uint64_t>()) != plan.seeds.end())
        errors.push_back({"/seeds/" + std::to_string(k), "repeats a seed"});
      else
        plan.seeds.push_back(s.get<std::uint64_t>());
    }
  }
  const std::string expected =
      "\"builtin:straight\", \"builtin:social_force\", \"builtin:orca\" (or \"client\": \"external\")";
  const auto add_planner = [&](const Json& label, const std::string& at) {
    auto name = builtin_planner(label);
    if (label == kExternalClient && at == "/client") {
      plan.planners.push_back(kExternalClient);
      plan.planner_names.push_back(kExternalClient);
    } else if (label == kExternalClient)
      errors.push_back({at, "an external client is given as \"client\": \"external\", alone"});
    else if (!name)
      errors.push_back({at, "must be " + expected});
    else if (std::find(plan.planner_names.begin(), plan.planner_names.end(), *name) !=
             plan.planner_names.end())
      errors.push_back({at, "names the same planner twice"});
    else {
      plan.planners.push_back(label.get<std::string>());
      plan.planner_names.push_back(*name);
    }
  };
  if (body.contains("planners") == body.contains("client")) {
    errors.push_back({"", "give 'planners' (a list) or 'client' (one planner), not both and not neither"});
  } else if (body.contains("client")) {
    add_planner(body["client"], "/client");
  } else if (!body["planners"].is_array() || body["planners"].empty()) {
    errors.push_back({"/planners", "must be a non-empty array of " + expected});
  } else {
    for (std::size_t k = 0; k < body["planners"].size(); ++k)
      add_planner(body["planners"][k], "/planners/" + std::to_string(k));
  }
  // The robot and the time limit are read as POST /api/v1/cosim reads them.
  Json settings = Json::object();
  if (body.contains("robot")) settings["robot"] = body["robot"];
  if (body.contains("time_limit_s")) settings["time_limit"] = body["time_limit_s"];
  auto read = cosim_settings_from_json(settings, ctx.services.cosim->limits());
  if (!read) {
    for (FieldError f : read.error().errors) {
      if (f.pointer == "/time_limit") f.pointer = "/time_limit_s";
      errors.push_back(std::move(f));
    }
  } else {
    if (read->episode.time_limit > 600.0) errors.push_back({"/time_limit_s", "must be at most 600 s"});
    if (!read->robots.empty() && !read->robots[0].goal)
      errors.push_back({"/robot/goal", "is required in an evaluation"});
    plan.robots = read->robots;
    plan.episode = read->episode;
  }
  if (errors.empty()) {
    const std::size_t episodes = cards->size() * plan.seeds.size() * plan.planners.size();
    if (episodes > kMaxEvaluationEpisodes)
      errors.push_back({"", std::to_string(episodes) + " episodes (cards × seeds × planners); at most " +
                                std::to_string(kMaxEvaluationEpisodes) + " per evaluation"});
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "bad evaluation request", std::move(errors));

  for (std::size_t k = 0; k < cards->size(); ++k) {
    const std::string id = (*cards)[k].get<std::string>(), at = "/cards/" + std::to_string(k);
    auto scenario = card_scenario(ctx, id);
    if (!scenario) {
      Error e = scenario.error();
      for (FieldError& f : e.errors)
        if (f.pointer == "/card_id") f.pointer = at;
      return tl::unexpected(e);
    }
    if (auto s = no_tree_files(scenario->program); !s) return tl::unexpected(Error(s.error()).within(at));
    if (plan.robots.empty() && (!scenario->program.robot || scenario->program.robot->goals.empty()))
      errors.push_back({at, "card '" + id + "' has no robot with a start and a goal: give a 'robot' block"});
    plan.scenarios.push_back({id, std::move(scenario->world),
                              std::make_shared<const crowd::Program>(std::move(scenario->program))});
  }
  if (!errors.empty()) return fail(ErrorCode::kValidation, "cards without a robot", std::move(errors));

  normalised = {{"cards", *cards},
                {"seeds", plan.seeds},
                {"planners", plan.planners},
                {"time_limit_s", plan.episode.time_limit}};
  if (body.contains("robot")) normalised["robot"] = body["robot"];
  return plan;
}

// The episodes of running external evaluations that wait for (or are driven by) the client: the
// evaluation id → {episode, episodes, card, seed, cosim, ws_url}. GET /api/v1/evaluations/{id}
// shows it as "current".
class ExternalBoard {
 public:
  void set(const std::string& id, Json current) {
    std::lock_guard<std::mutex> lock(mutex_);
    current_[id] = std::move(current);
  }
  void erase(const std::string& id) {
    std::lock_guard<std::mutex> lock(mutex_);
    current_.erase(id);
  }
  std::optional<Json> get(const std::string& id) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = current_.find(id);
    if (it == current_.end()) return std::nullopt;
    return it->second;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, Json> current_;
};

Json episode_row(const crowd::EvaluationPlan& plan, const crowd::EvaluationEpisode& e) {
  return {{"card", plan.scenarios[e.scenario].id},
          {"planner", plan.planners[e.planner]},
          {"seed", plan.seeds[e.seed]},
          {"outcome", std::string(crowd::outcome_name(e.metrics.outcome))},
          {"steps", e.steps}};
}

// An external evaluation as a job: one lock-step co-simulation per card × seed, opened when the
// previous one has ended, waited for while the client drives it. A session nobody connects to
// within idle_s stops the evaluation (a kConflict problem naming the session); cancelling the job ends the
// session under way.
Result<Json> run_external(const crowd::EvaluationPlan& plan, CosimSessions& sessions, ExternalBoard& board,
                          const std::string& author, const JobContext& job) {
  const std::size_t total = plan.scenarios.size() * plan.seeds.size();
  std::vector<crowd::EvaluationEpisode> episodes;
  Json rows = Json::array();
  const auto cancelled = [&] { return fail(ErrorCode::kCancelled, "the evaluation was cancelled"); };
  for (std::size_t s = 0; s < plan.scenarios.size(); ++s)
    for (std::size_t k = 0; k < plan.seeds.size(); ++k) {
      const crowd::EvaluationScenario& scenario = plan.scenarios[s];
      const std::size_t index = s * plan.seeds.size() + k;
      CosimRequest request;
      request.world = scenario.world;
      request.program = *scenario.program;
      request.settings.seed = plan.seeds[k];
      request.settings.mode = CosimMode::kLockStep;
      request.settings.robots = plan.robots;
      request.settings.episode = plan.episode;
      request.author = author;
      request.card_id = scenario.id;
      std::shared_ptr<CosimSession> session;
      while (!session) {  // every session slot busy: wait for one, as a queued job would
        auto created = sessions.create(request);
        if (created) {
          session = *created;
        } else if (created.error().code != ErrorCode::kRateLimited) {
          return tl::unexpected(Error(created.error()).within("/cards/" + std::to_string(s)));
        } else {
          if (job.cancelled()) return cancelled();
          std::this_thread::sleep_for(kExternalPoll);
        }
      }
      const std::string ws_url = "/ws/cosim/" + session->id();
      board.set(job.id(), {{"episode", index + 1},
                           {"episodes", total},
                           {"card", scenario.id},
                           {"seed", plan.seeds[k]},
                           {"cosim", session->id()},
                           {"ws_url", ws_url}});
      job.progress(static_cast<double>(index) / static_cast<double>(total),
                   "episode " + std::to_string(index + 1) + " of " + std::to_string(total) + " (card " +
                       scenario.id + ", seed " + std::to_string(plan.seeds[k]) + "): driven at " + ws_url);
      while (!session->wait_ended(kExternalPoll))
        if (job.cancelled()) {
          session->stop("cancelled");
          board.erase(job.id());
          return cancelled();
        }
      const std::string reason = session->end_reason().value_or("");
      if (reason == "no_client" || reason == "server_stopping") {
        board.erase(job.id());
        if (reason == "server_stopping") return cancelled();
        return fail(ErrorCode::kConflict, "no client connected to " + ws_url + " within " +
                                              std::to_string(static_cast<int>(sessions.limits().idle_s)) +
                                              " s (episode " + std::to_string(index + 1) + " of " +
                                              std::to_string(total) + ")");
      }
      const crowd::EpisodeMetrics m = session->metrics();
      crowd::EvaluationEpisode e{s, 0, k, m.steps, m.robots.at(0)};
      Json row = episode_row(plan, e);
      row["end_reason"] = reason;
      row["cosim"] = session->id();
      rows.push_back(std::move(row));
      episodes.push_back(std::move(e));
    }
  board.erase(job.id());
  job.progress(1.0, std::to_string(total) + " of " + std::to_string(total) + " episodes");
  return Json{{"table", crowd::evaluation_table(plan, episodes)}, {"episodes", rows}};
}

Json evaluation_view(Json job, ExternalBoard& board) {
  const std::string id = job["id"];
  job["links"] = {{"self", "/api/v1/evaluations/" + id}, {"job", "/api/v1/jobs/" + id}};
  if (auto current = board.get(id)) job["current"] = std::move(*current);
  return job;
}

void evaluation_routes(Router& http, RouteContext& ctx) {
  auto board = std::make_shared<ExternalBoard>();
  post_with_body(
      http, "/api/v1/evaluations", ctx.config.max_body_bytes,
      [&ctx, board](const Request& req, Response& res, const std::string& text) {
        auto body = json_body(text);
        if (!body) return reply_problem(res, body.error(), req.path);
        Json normalised;
        auto plan = evaluation_plan(ctx, *body, normalised);
        if (!plan) return reply_problem(res, plan.error(), req.path);
        auto shared = std::make_shared<const crowd::EvaluationPlan>(std::move(*plan));
        JobFn work;
        if (shared->planner_names == std::vector<std::string>{kExternalClient}) {
          normalised["client"] = kExternalClient;
          normalised.erase("planners");
          work = [shared, board, sessions = ctx.services.cosim.get(),
                  author = ctx.author(req)](const JobContext& job) -> Result<Json> {
            return run_external(*shared, *sessions, *board, author, job);
          };
        } else {
          work = [shared](const JobContext& job) -> Result<Json> {
            crowd::EvaluationHooks hooks;
            hooks.progress = [&job](std::size_t done, std::size_t total) {
              job.progress(static_cast<double>(done) / static_cast<double>(total),
                           std::to_string(done) + " of " + std::to_string(total) + " episodes");
            };
            hooks.cancelled = [&job] { return job.cancelled(); };
            auto episodes = crowd::run_evaluation(*shared, hooks);
            if (!episodes) return tl::unexpected(episodes.error());
            Json list = Json::array();
            for (const crowd::EvaluationEpisode& e : *episodes) list.push_back(episode_row(*shared, e));
            return Json{{"table", crowd::evaluation_table(*shared, *episodes)}, {"episodes", list}};
          };
        }
        auto id =
            ctx.jobs.submit(kEvaluationKind, normalised, ctx.author(req), std::move(work), ctx.client(req));
        ctx.reply_job_accepted(res, id, req.path);
      });

  http.Get("/api/v1/evaluations", [&ctx, board](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    auto listed = ctx.jobs.list(page->page_size, page->cursor, std::string(kEvaluationKind), std::nullopt);
    if (!listed) return reply_problem(res, listed.error(), req.path);
    Json items = Json::array();
    for (Json& j : listed->items) items.push_back(evaluation_view(std::move(j), *board));
    reply_json(res, 200,
               {{"items", items},
                {"next_cursor", listed->next_cursor ? Json(*listed->next_cursor) : Json(nullptr)}});
  });

  http.Get(R"(/api/v1/evaluations/([^/]+))", [&ctx, board](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    auto job = ctx.jobs.get(id);
    if (!job || (*job)["kind"] != kEvaluationKind)
      return reply_problem(res, Error(ErrorCode::kNotFound, "no evaluation with id '" + id + "'"), req.path);
    const std::string status = (*job)["status"];
    if (status == "queued" || status == "running") res.set_header("Retry-After", "1");
    reply_json(res, 200, evaluation_view(std::move(*job), *board));
  });
}

}  // namespace

SOCSIM_ROUTES("evaluations", evaluation_routes);

}  // namespace socsim::server
