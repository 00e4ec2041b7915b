// Text to scenario over HTTP: POST /api/v1/scenarios (a job whose result is a scenario card),
// POST /api/v1/scenarios/interpret (what a prompt says, at once), GET /api/v1/trajectories/{sha256}
// (a card's trajectory log), POST /api/v1/cards/{id}/replay. A prompt that cannot become a scenario
// (scenario::check_prompt) is refused on both before anything is queued or stored.
#include "core/cards/world_store.hpp"
#include "core/common/json_check.hpp"
#include "core/floorplan/compliance.hpp"
#include "core/scenario/pipeline.hpp"
#include "core/scenario/prompt_check.hpp"
#include "core/scenario/scenario_intent.hpp"
#include "core/scenario/trajectory_store.hpp"
#include "core/scenario/wordnet.hpp"
#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"
#include "server/http_util.hpp"
#include "server/prompt_gate.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

constexpr const char* kTrajectoryPath = R"(/api/v1/trajectories/([0-9a-f]{64}|[^/]+))";
constexpr const char* kScenarioJobKind = "scenario.generate";
constexpr const char* kReplayPath = R"(/api/v1/cards/(crd_[0-9a-z]{20}|[^/]+)/replay)";

scenario::ScenarioConfig scenario_config(const ServerConfig& config) {
  scenario::ScenarioConfig c;
  c.max_prompt_bytes = config.max_prompt_bytes;
  c.limits.max_agents = config.max_scenario_agents;
  c.limits.max_duration_s = config.max_scenario_seconds;
  return c;
}

// The world the request names (inline or by id); nullopt when it is to be laid out.
Result<std::optional<scenario::ScenarioWorld>> given_world(RouteContext& ctx,
                                                           const scenario::ScenarioRequest& r) {
  if (r.world) {
    Result<world::WorldReading> w = r.world->is_string()
                                        ? world::read_world_yaml(r.world->get<std::string>())
                                        : world::world_from_document(*r.world).map([](world::World built) {
                                            return world::WorldReading{std::move(built), {}};
                                          });
    if (!w) return tl::unexpected(Error(w.error()).within("/world"));
    std::string domain = r.domain ? *r.domain : floorplan::building_type_of(w->world);
    Json source{{"source", "request"}};
    // What reading the world assumed (a zone's region inferred …) stays with the card.
    if (!w->warnings.empty()) source["warnings"] = field_errors_json(w->warnings);
    return scenario::ScenarioWorld{std::move(w->world), domain, std::move(source)};
  }
  if (r.world_id) {
    auto stored = cards::WorldStore(ctx.store).get(*r.world_id);
    if (!stored) {
      Error e = stored.error();
      if (e.code == ErrorCode::kNotFound) {
        e.code = ErrorCode::kValidation;
        e.errors = {{"/world_id", "no world with this id"}};
      }
      return tl::unexpected(e);
    }
    auto w = world::world_from_yaml(stored->world_yaml);
    if (!w)
      return fail(ErrorCode::kInternal,
                  "stored world '" + *r.world_id + "' no longer validates: " + w.error().message());
    return scenario::ScenarioWorld{std::move(*w), r.domain.value_or(stored->domain),
                                   Json{{"source", "world_id"}, {"world_id", *r.world_id}}};
  }
  return std::optional<scenario::ScenarioWorld>{};
}

// Everything POST /api/v1/scenarios checks, then the work. The queue runs it again from the stored
// request on whichever worker takes the job (a batch item, or a job whose worker died), so the
// card's id is the job's: a second run finds the card instead of making another.
Result<JobFn> scenario_job(RouteContext& ctx, const Json& body, const std::string& author) {
  const auto config = scenario_config(ctx.config);
  auto request = scenario::scenario_request_from_json(body, config);
  if (!request) return tl::unexpected(request.error());
  if (auto intent = checked_prompt(request->prompt, ctx.config.max_prompt_bytes); !intent)
    return tl::unexpected(intent.error());
  if (auto s = ctx.check_model(request->model); !s) return tl::unexpected(s.error());
  if (request->generator == "llm" && !ctx.llm)
    return fail(ErrorCode::kValidation,
                "no LLM endpoint is configured (set SOCSIM_LLM_URL), so only the offline generator is "
                "available",
                {{"/generator", "must be offline on this server"}});
  auto world = given_world(ctx, *request);
  if (!world) return tl::unexpected(world.error());
  return JobFn([&ctx, request = std::move(*request), world = std::move(*world), config,
                author](const JobContext& job) -> Result<Json> {
    std::optional<llm::StructuredGenerator> gen;
    if (ctx.llm) gen.emplace(*ctx.llm, &ctx.store);
    scenario::ScenarioServices s{
        ctx.knowledge, gen ? &*gen : nullptr, config,
        job.id(),      job.cancel_token(),    [&job](double f, const std::string& m) { job.progress(f, m); }};
    auto outcome = scenario::run_scenario(request, world, s);
    if (!outcome) return tl::unexpected(outcome.error());
    if (auto saved = scenario::save_trajectory_log(ctx.store, outcome->log); !saved)
      return tl::unexpected(saved.error());
    auto card = ctx.catalogue.create_once("crd_" + job.id().substr(4), outcome->card, author);
    if (!card) return tl::unexpected(card.error());
    ctx.events.publish("cards", {{"type", "card.created"}, {"card", cards::summary_json(*card)}});
    return Json{{"card_id", card->id},
                {"location", "/api/v1/cards/" + card->id},
                {"title", card->content.title},
                {"categories", outcome->card.provenance.value("categories", Json::array())},
                {"trajectory_log", outcome->card.trajectory_log}};
  });
}

void scenario_routes(Router& http, RouteContext& ctx) {
  ctx.jobs.define(kScenarioJobKind, [&ctx](const Json& spec, const std::string& author) {
    return scenario_job(ctx, spec, author);
  });
  post_with_body(http, "/api/v1/scenarios", ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   const std::string author = ctx.author(req);
                   // Checked here, so that a bad request is a 4xx now rather than a failed job.
                   if (auto checked = scenario_job(ctx, *body, author); !checked)
                     return reply_problem(res, checked.error(), req.path);
                   auto id = ctx.jobs.submit_spec(kScenarioJobKind, *body, *body, author, ctx.client(req));
                   ctx.reply_job_accepted(res, id, req.path);
                 });

  post_with_body(http, "/api/v1/scenarios/interpret", ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   JsonChecker c;
                   if (!body->is_object())
                     return reply_problem(res,
                                          Error(ErrorCode::kValidation, "the request must be a JSON object",
                                                {{"", "expected an object"}}),
                                          req.path);
                   c.only_keys(*body, "", {"prompt"});
                   // Emptiness and length are the prompt check's, with its messages.
                   auto prompt = c.string(*body, "", "prompt", true, 0, std::string::npos);
                   if (!c.ok())
                     return reply_problem(res, c.error("the interpret request is not valid"), req.path);
                   auto intent = checked_prompt(*prompt, ctx.config.max_prompt_bytes);
                   if (!intent) return reply_problem(res, intent.error(), req.path);
                   reply_json(res, 200, scenario::to_json(*intent));
                 });

  http.Get(kTrajectoryPath, [&ctx](const Request& req, Response& res) {
    const std::string sha = req.matches[1];
    if (sha.size() != 64 || sha.find_first_not_of("0123456789abcdef") != std::string::npos)
      return reply_problem(res, Error(ErrorCode::kNotFound, "no trajectory log '" + sha + "'"), req.path);
    const std::string tag = "\"" + sha + "\"";
    if (req.get_header_value("If-None-Match") == tag) {
      res.status = 304;
      res.set_header("ETag", tag);
      return;
    }
    auto blob = scenario::load_trajectory_blob(ctx.store, sha);
    if (!blob) return reply_problem(res, blob.error(), req.path);
    res.set_header("ETag", tag);
    res.set_header("Cache-Control", "public, max-age=31536000, immutable");
    res.set_header("Content-Disposition", "attachment; filename=\"" + sha + ".socsim-traj\"");
    res.set_content(*blob, "application/vnd.socsim.trajectory+zlib");
  });

  post_with_body(http, kReplayPath, ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string&) {
                   const std::string card_id = req.matches[1];
                   auto card = ctx.catalogue.get(card_id);
                   if (!card) return reply_problem(res, card.error(), req.path);
                   if (!card->content.trajectory_log.is_object())
                     return reply_problem(
                         res,
                         Error(ErrorCode::kValidation, "the card has no trajectory log to replay",
                               {{"/trajectory_log", "only scenario cards (POST /api/v1/scenarios) replay"}}),
                         req.path);
                   auto id = ctx.jobs.submit(
                       "scenario.replay", Json{{"card_id", card_id}}, ctx.author(req),
                       [content = card->content, card_id](const JobContext& job) -> Result<Json> {
                         auto out = scenario::replay_card(
                             content, [&job](double f, const std::string& m) { job.progress(f, m); },
                             job.cancel_token());
                         if (!out) return tl::unexpected(out.error());
                         const std::string expected = content.trajectory_log.value("sha256", "");
                         return Json{{"card_id", card_id},
                                     {"expected_sha256", expected},
                                     {"sha256", out->log.sha256()},
                                     {"identical", out->log.sha256() == expected},
                                     {"frames", out->log.frame_count()}};
                       },
                       ctx.client(req));
                   ctx.reply_job_accepted(res, id, req.path);
                 });
}

}  // namespace

SOCSIM_ROUTES("scenarios", scenario_routes);

}  // namespace socsim::server
