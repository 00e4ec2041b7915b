// /api/v1/cosim: co-simulation sessions (issue 19, docs/cosim.md). A client opens an episode on a
// card or a program with its robots; it then drives them over the WebSocket port at
// /ws/cosim/{id} (subprotocol socsim.cosim.v1) and receives the metrics report at the end.
#include <cstdint>
#include <limits>

#include "core/crowd/program.hpp"
#include "server/cosim_sessions.hpp"
#include "server/http_util.hpp"
#include "server/routes.hpp"
#include "server/scenario_inputs.hpp"

namespace socsim::server {
namespace {

constexpr const char* kCosimPath = R"(/api/v1/cosim/([^/]+))";

Json cosim_with_urls(RouteContext& ctx, const Request& req, Json status) {
  status["ws_port"] = ctx.config.ws_port;
  status["websocket_url"] = "ws://" + ctx.public_host(req) + ":" + std::to_string(ctx.config.ws_port) +
                            status["ws_url"].get<std::string>();
  status["links"] = {{"self", "/api/v1/cosim/" + status["id"].get<std::string>()}};
  return status;
}

Result<std::shared_ptr<CosimSession>> start_cosim(RouteContext& ctx, const Json& body,
                                                  const std::string& author) {
  if (!body.is_object())
    return fail(ErrorCode::kValidation, "the body must be a JSON object",
                {FieldError{"", "must be an object"}});
  std::vector<FieldError> errors;
  for (const auto& [key, v] : body.items())
    if (key != "program" && key != "world" && key != "world_id" && key != "card_id" && key != "seed" &&
        key != "mode" && key != "rate_hz" && key != "robot" && key != "robots" && key != "time_limit" &&
        key != "success_radius" && key != "stuck_time")
      errors.push_back(
          {"/" + json_pointer_token(key),
           "unknown field (expected card_id or program with world/world_id, seed, mode, rate_hz, "
           "robot or robots, time_limit, success_radius, stuck_time)"});
  const bool card = body.contains("card_id");
  if (card == body.contains("program"))
    errors.push_back(
        {"", "give either 'card_id' or 'program' (with 'world' or 'world_id' when it names places)"});
  if (card && !body["card_id"].is_string()) errors.push_back({"/card_id", "must be a string"});
  if (card && (body.contains("world") || body.contains("world_id")))
    errors.push_back({"/card_id", "a card brings its own world: give no 'world' or 'world_id' with it"});
  if (body.contains("world") && body.contains("world_id"))
    errors.push_back({"/world_id", "give 'world' or 'world_id', not both"});
  if (body.contains("world") && !body["world"].is_object() && !body["world"].is_string())
    errors.push_back({"/world", "must be a world document (object) or world.yaml text (string)"});
  if (body.contains("world_id") && !body["world_id"].is_string())
    errors.push_back({"/world_id", "must be a string"});
  if (body.contains("program") && !body["program"].is_object())
    errors.push_back({"/program", "must be a scenario program object"});
  if (!errors.empty()) return fail(ErrorCode::kValidation, "bad co-simulation request", std::move(errors));

  auto& sessions = *ctx.services.cosim;
  auto settings = cosim_settings_from_json(body, sessions.limits());
  if (!settings) return tl::unexpected(settings.error());
  CosimRequest request;
  request.settings = std::move(*settings);
  request.author = author;
  if (card) {
    const std::string id = body["card_id"].get<std::string>();
    auto scenario = card_scenario(ctx, id);
    if (!scenario) return tl::unexpected(scenario.error());
    request.world = std::move(scenario->world);
    request.program = std::move(scenario->program);
    request.card_id = id;
  } else {
    auto world = session_world(ctx, body);
    if (!world) return tl::unexpected(world.error());
    auto program = crowd::program_from_json(body["program"]);
    if (!program) return tl::unexpected(Error(program.error()).under("/program"));
    request.world = std::move(*world);
    request.program = std::move(*program);
  }
  if (auto s = no_tree_files(request.program); !s) return tl::unexpected(s.error());
  return sessions.create(std::move(request));
}

void cosim_routes(Router& http, RouteContext& ctx) {
  post_with_body(http, "/api/v1/cosim", ctx.config.max_body_bytes,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   auto session = start_cosim(ctx, *body, ctx.author(req));
                   if (!session) return reply_problem(res, session.error(), req.path);
                   log_line({{"level", "info"}, {"event", "cosim.started"}, {"cosim", (*session)->id()}});
                   res.set_header("Location", "/api/v1/cosim/" + (*session)->id());
                   reply_json(res, 201, cosim_with_urls(ctx, req, (*session)->status()));
                 });

  http.Get("/api/v1/cosim", [&ctx](const Request& req, Response& res) {
    Json items = Json::array();
    for (const auto& s : ctx.services.cosim->list()) items.push_back(cosim_with_urls(ctx, req, s->status()));
    reply_json(res, 200, {{"items", std::move(items)}, {"next_cursor", nullptr}});
  });

  // What the co-simulation view (web/cosim.html) polls: people now, the robots' paths and contacts
  // since frame ?since= (0: from the start), the world document with ?world=true.
  http.Get(R"(/api/v1/cosim/([^/]+)/view)", [&ctx](const Request& req, Response& res) {
    auto since = query_int(req, "since", 0, 0, std::numeric_limits<std::int32_t>::max());
    if (!since) return reply_problem(res, since.error(), req.path);
    auto world = query_bool(req, "world", false);
    if (!world) return reply_problem(res, world.error(), req.path);
    auto s = ctx.services.cosim->find(req.matches[1].str());
    if (!s) return reply_problem(res, s.error(), req.path);
    reply_json(res, 200, (*s)->view(static_cast<std::size_t>(*since), *world));
  });

  http.Get(kCosimPath, [&ctx](const Request& req, Response& res) {
    auto s = ctx.services.cosim->find(req.matches[1].str());
    if (!s) return reply_problem(res, s.error(), req.path);
    reply_json(res, 200, cosim_with_urls(ctx, req, (*s)->status()));
  });
}

}  // namespace

SOCSIM_ROUTES("cosim", cosim_routes);

}  // namespace socsim::server
