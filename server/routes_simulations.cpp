// /api/v1/simulations: live sessions that run a scenario program in real time × speed or play back
// a card's recorded trajectories; frames stream on the WebSocket port at /ws/simulations/{id}.
#include <cmath>

#include "core/crowd/program.hpp"
#include "core/scenario/trajectory_store.hpp"
#include "core/world/world_document.hpp"
#include "core/world/world_yaml.hpp"
#include "server/http_util.hpp"
#include "server/pagination.hpp"
#include "server/routes.hpp"
#include "server/scenario_inputs.hpp"

namespace socsim::server {
namespace {

constexpr const char* kSimulationRoute = R"(/api/v1/simulations/([^/]+))";

Json with_urls(RouteContext& ctx, const Request& req, Json status) {
  status["ws_port"] = ctx.config.ws_port;
  status["websocket_url"] = "ws://" + ctx.public_host(req) + ":" + std::to_string(ctx.config.ws_port) +
                            status["ws_url"].get<std::string>();
  status["links"] = {{"self", "/api/v1/simulations/" + status["id"].get<std::string>()},
                     {"control", "/api/v1/simulations/" + status["id"].get<std::string>() + "/control"}};
  return status;
}

Result<std::shared_ptr<SimulationSession>> start_session(RouteContext& ctx, const Json& body,
                                                         const std::string& author) {
  if (!body.is_object())
    return fail(ErrorCode::kValidation, "the body must be a JSON object",
                {FieldError{"", "must be an object"}});
  std::vector<FieldError> errors;
  auto add = [&](const std::string& pointer, const std::string& message) {
    errors.push_back({pointer, message});
  };
  for (const auto& [key, v] : body.items())
    if (key != "program" && key != "world" && key != "world_id" && key != "seed" && key != "speed" &&
        key != "duration_s" && key != "card_id")
      add("/" + json_pointer_token(key),
          "unknown field (expected program, world, world_id, seed, speed, duration_s or card_id)");
  const bool card = body.contains("card_id");
  if (card == body.contains("program"))
    add("", "give either 'program' (with 'world' or 'world_id' when it names places) or 'card_id'");
  if (card)
    for (const char* k : {"world", "world_id", "seed", "duration_s"})
      if (body.contains(k)) add(std::string("/") + k, "not used when playing a card (the card has its own)");
  if (body.contains("world") && body.contains("world_id"))
    add("/world_id", "give 'world' or 'world_id', not both");
  if (body.contains("world") && !body["world"].is_object() && !body["world"].is_string())
    add("/world", "must be a world document (object) or world.yaml text (string)");
  if (body.contains("world_id") && !body["world_id"].is_string()) add("/world_id", "must be a string");
  if (card && !body["card_id"].is_string()) add("/card_id", "must be a string");
  if (body.contains("program") && !body["program"].is_object())
    add("/program", "must be a scenario program object");
  if (body.contains("speed") && !body["speed"].is_number()) add("/speed", "must be a number");
  if (body.contains("duration_s") && !body["duration_s"].is_number()) add("/duration_s", "must be a number");
  if (body.contains("seed") && !body["seed"].is_number_unsigned()) add("/seed", "must be a whole number ≥ 0");
  if (!errors.empty()) return fail(ErrorCode::kValidation, "bad simulation request", std::move(errors));

  auto& sessions = *ctx.services.simulations;
  const double speed = body.value("speed", 1.0);
  if (auto s = check_speed(speed, sessions.limits(), "/speed"); !s) return tl::unexpected(s.error());
  if (auto s = sessions.check_capacity(); !s) return tl::unexpected(s.error());

  if (card) {
    const std::string id = body["card_id"].get<std::string>();
    auto c = ctx.catalogue.get(id);
    if (!c) {
      if (c.error().code == ErrorCode::kNotFound)
        return fail(ErrorCode::kNotFound, "no card with id '" + id + "'",
                    {FieldError{"/card_id", "names no card in the catalogue"}});
      return tl::unexpected(c.error());
    }
    const Json& recorded = c->content.trajectory_log;
    if (!recorded.is_object() || !recorded.contains("sha256") || !recorded["sha256"].is_string())
      return fail(ErrorCode::kValidation, "the card has no trajectory log to play",
                  {FieldError{"/card_id", "card '" + id + "' records no trajectories"}});
    auto log = scenario::load_trajectory_log(ctx.store, recorded["sha256"].get<std::string>());
    if (!log) {
      if (log.error().code == ErrorCode::kNotFound)
        return fail(
            ErrorCode::kNotFound, "the card's trajectory log is not stored here",
            {FieldError{"/card_id", "its log " + recorded["sha256"].get<std::string>() + " is missing"}});
      return tl::unexpected(log.error());
    }
    RecordingSessionRequest r;
    r.log = std::move(*log);
    r.card_id = id;
    if (c->content.world.is_object())
      if (auto w = world::world_from_document(c->content.world))
        r.world = std::make_shared<const world::World>(std::move(*w));
    if (c->content.provenance.is_object() && c->content.provenance.contains("world_id") &&
        c->content.provenance["world_id"].is_string())
      r.world_id = c->content.provenance["world_id"].get<std::string>();
    r.speed = speed;
    r.author = author;
    return sessions.start_recording(std::move(r));
  }

  auto world = session_world(ctx, body);
  if (!world) return tl::unexpected(world.error());
  auto program = crowd::program_from_json(body["program"]);
  if (!program) return tl::unexpected(Error(program.error()).under("/program"));
  if (auto s = no_tree_files(*program); !s) return tl::unexpected(s.error());
  ProgramSessionRequest r;
  r.world = std::move(*world);
  if (body.contains("world_id")) r.world_id = body["world_id"].get<std::string>();
  r.program = std::move(*program);
  r.seed = body.value("seed", std::uint64_t{0});
  r.speed = speed;
  if (body.contains("duration_s")) r.duration_s = body["duration_s"].get<double>();
  r.author = author;
  return sessions.start_program(std::move(r));
}

// Controls and deletion are the author's when the server has API keys.
Status may_change(RouteContext& ctx, const Request& req, const SimulationSession& s) {
  if (may_act_for(ctx.keys, ctx.author(req), s.info().author)) return {};
  return fail(ErrorCode::kForbidden, "simulation '" + s.id() + "' was started by another author");
}

void simulation_routes(Router& http, RouteContext& ctx) {
  post_with_body(http, "/api/v1/simulations", ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   auto session = start_session(ctx, *body, ctx.author(req));
                   if (!session) return reply_problem(res, session.error(), req.path);
                   log_line({{"level", "info"},
                             {"event", "simulation.started"},
                             {"simulation", (*session)->id()},
                             {"kind", (*session)->info().kind}});
                   res.set_header("Location", "/api/v1/simulations/" + (*session)->id());
                   reply_json(res, 201, with_urls(ctx, req, (*session)->status()));
                 });

  http.Get("/api/v1/simulations", [&ctx](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    std::size_t first = 0;  // sessions are few and short-lived: the cursor is an offset
    if (page->cursor) {
      auto at = parse_sequence_cursor(*page->cursor, "sim1.");
      if (!at) return reply_problem(res, at.error(), req.path);
      first = static_cast<std::size_t>(*at);
    }
    Json items = Json::array();
    std::size_t running = 0, index = 0;
    Json next = nullptr;
    for (const auto& s : ctx.services.simulations->list()) {
      Json st = with_urls(ctx, req, s->status());
      running += st["status"] != "ended" ? 1 : 0;
      if (index >= first && items.size() < page->page_size)
        items.push_back(std::move(st));
      else if (index >= first && next.is_null())
        next = "sim1." + std::to_string(index);
      ++index;
    }
    const auto& l = ctx.services.simulations->limits();
    reply_json(res, 200,
               {{"items", items},
                {"running", running},
                {"next_cursor", next},
                {"limits",
                 {{"max_sessions", l.max_sessions},
                  {"max_viewers", l.max_viewers},
                  {"max_agents", l.max_agents},
                  {"min_speed", l.min_speed},
                  {"max_speed", l.max_speed},
                  {"stream_hz", l.stream_hz},
                  {"idle_s", l.idle_s},
                  {"max_duration_s", l.max_duration_s}}}});
  });

  http.Get(kSimulationRoute, [&ctx](const Request& req, Response& res) {
    auto s = ctx.services.simulations->find(req.matches[1].str());
    if (!s) return reply_problem(res, s.error(), req.path);
    reply_json(res, 200, with_urls(ctx, req, (*s)->status()));
  });

  post_with_body(http, std::string(kSimulationRoute) + "/control", ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto s = ctx.services.simulations->find(req.matches[1].str());
                   if (!s) return reply_problem(res, s.error(), req.path);
                   if (auto ok = may_change(ctx, req, **s); !ok)
                     return reply_problem(res, ok.error(), req.path);
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   auto st = (*s)->control(*body);
                   if (!st) return reply_problem(res, st.error(), req.path);
                   reply_json(res, 200, with_urls(ctx, req, *st));
                 });

  http.Delete(kSimulationRoute, [&ctx](const Request& req, Response& res) {
    auto s = ctx.services.simulations->find(req.matches[1].str());
    if (!s) return reply_problem(res, s.error(), req.path);
    if (auto ok = may_change(ctx, req, **s); !ok) return reply_problem(res, ok.error(), req.path);
    if (auto ok = ctx.services.simulations->remove((*s)->id()); !ok)
      return reply_problem(res, ok.error(), req.path);
    reply_json(res, 200, with_urls(ctx, req, (*s)->status()));
  });
}

}  // namespace

SOCSIM_ROUTES("simulations", simulation_routes);

}  // namespace socsim::server
