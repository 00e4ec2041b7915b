// /api/v1/worlds: floor plans from a scene graph or a prompt (offline at once, LLM as a job),
// stored as world.yaml with their compliance report and knowledge provenance; exports to SDF,
// pedsim_ros, ROS map and SVG; validation of a posted world.yaml.
#include "core/cards/world_store.hpp"
#include "core/floorplan/llm.hpp"
#include "core/floorplan/request.hpp"
#include "core/knowledge/building_type.hpp"
#include "core/world/world_document.hpp"
#include "core/world/world_export.hpp"
#include "core/world/world_yaml.hpp"
#include "server/http_util.hpp"
#include "server/pagination.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

constexpr const char* kWorldPath = R"(/api/v1/worlds/(wld_[0-9a-z]{20}|[^/]+))";
constexpr std::string_view kWorldCursorPrefix = "w1.";

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto b = [&](std::size_t k) {
      return i + k < bytes.size() ? static_cast<unsigned char>(bytes[i + k]) : 0u;
    };
    const unsigned v = (b(0) << 16) | (b(1) << 8) | b(2);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

using cards::StoredWorld;

Json summary(const StoredWorld& w) {
  return Json{
      {"id", w.id},
      {"name", w.name},
      {"domain", w.domain},
      {"generator", w.generator},
      {"seed", w.seed},
      {"author", w.author},
      {"created_at", w.created_at},
      {"compliant", w.compliance.value("passed", false)},
      {"links",
       {{"self", "/api/v1/worlds/" + w.id},
        {"world_yaml", "/api/v1/worlds/" + w.id + "/world.yaml"},
        {"export", "/api/v1/worlds/" + w.id + "/export?format={sdf|pedsim|map|map-pgm|map-yaml|svg}"}}}};
}

// Stores a generated plan.
Result<StoredWorld> store_world(store::Store& db, const floorplan::FloorPlan& plan, const Json& request,
                                const std::string& author, const std::string& generator, std::uint64_t seed) {
  StoredWorld w;
  w.name = plan.world.name();
  w.domain = plan.scene_graph.domain;
  w.generator = generator;
  w.seed = static_cast<std::int64_t>(seed);
  w.author = author;
  w.request = request;
  w.scene_graph = floorplan::to_json(plan.scene_graph);
  w.world_yaml = world::world_to_yaml(plan.world);
  w.compliance = floorplan::to_json(plan.compliance);
  w.provenance = plan.provenance;
  return cards::WorldStore(db).add(std::move(w));
}

Result<StoredWorld> load_world(store::Store& db, const std::string& id) {
  return cards::WorldStore(db).get(id);
}

// The stored text always built before it was stored; a failure here is a broken invariant.
Result<world::World> world_of(const StoredWorld& w) {
  auto world = world::world_from_yaml(w.world_yaml);
  if (!world)
    return fail(ErrorCode::kInternal,
                "stored world '" + w.id + "' no longer validates: " + world.error().message());
  return world;
}

Json world_json(const StoredWorld& w, const world::World& world) {
  Json j = summary(w);
  j["world"] = world::world_to_document(world);
  j["compliance"] = w.compliance;
  j["provenance"] = w.provenance;
  j["scene_graph"] = w.scene_graph;
  j["request"] = w.request;
  j["content_hash"] = w.content_hash;
  return j;
}

Result<std::vector<knowledge::MergedConstraint>> constraints(RouteContext& ctx, const std::string& domain,
                                                             const std::string& jurisdiction) {
  return ctx.knowledge.constraints_for(domain, jurisdiction);
}

// Building type for checking a posted world: ?domain=, else classified from zone names and types.
Result<std::string> domain_for(const Request& req, const world::World& w) {
  if (auto d = query(req, "domain")) {
    if (!knowledge::is_building_type(*d))
      return fail(ErrorCode::kValidation, "unknown building type",
                  {FieldError::query("domain", "not a building type: '" + *d + "'")});
    return *d;
  }
  return floorplan::building_type_of(w);
}

void world_routes(Router& http, RouteContext& ctx) {
  const std::size_t max_body = ctx.config.max_body_bytes;

  post_with_body(
      http, "/api/v1/worlds", max_body, [&ctx](const Request& req, Response& res, const std::string& text) {
        auto body = json_body(text);
        if (!body) return reply_problem(res, body.error(), req.path);
        auto request = floorplan::floor_plan_request_from_json(*body);
        if (!request) return reply_problem(res, request.error(), req.path);
        if (auto s = ctx.check_model(request->model); !s) return reply_problem(res, s.error(), req.path);
        auto resolved = floorplan::resolve_scene_graph(*request);
        if (!resolved) return reply_problem(res, resolved.error(), req.path);
        auto cs = constraints(ctx, resolved->graph.domain, request->jurisdiction);
        if (!cs) return reply_problem(res, cs.error(), req.path);

        if (request->generator == "offline") {
          floorplan::OfflineOptions o;
          o.seed = request->seed;
          o.requirements = request->requirements;
          auto plan = floorplan::generate_floor_plan(resolved->graph, *cs, o);
          if (!plan) return reply_problem(res, plan.error(), req.path);
          plan->provenance["classification"] = resolved->classification;
          auto w = store_world(ctx.store, *plan, *body, ctx.author(req), "offline", request->seed);
          if (!w) return reply_problem(res, w.error(), req.path);
          ctx.events.publish("worlds", {{"type", "world.created"}, {"world", summary(*w)}});
          res.set_header("Location", "/api/v1/worlds/" + w->id);
          Json out = summary(*w);
          out["compliance"] = w->compliance;
          return reply_json(res, 201, out);
        }

        if (auto s = ctx.llm_available(); !s) return reply_problem(res, s.error(), req.path);
        const std::string author = ctx.author(req);
        auto id = ctx.jobs.submit(
            "world.generate", *body, author,
            [&ctx, request = *request, resolved = *resolved, cs = *cs, body = *body,
             author](const JobContext& job) -> Result<Json> {
              llm::StructuredGenerator gen(*ctx.llm, &ctx.store);
              job.progress(0.0, "asking the LLM for a " + resolved.graph.domain + " floor plan of " +
                                    std::to_string(resolved.graph.rooms.size()) + " rooms");
              floorplan::LlmFloorPlanOptions o;
              o.model = request.model;
              o.seed = static_cast<std::int64_t>(request.seed);
              o.job_id = job.id();
              o.cancel = job.cancel_token();
              auto plan =
                  floorplan::generate_floor_plan_llm(gen, request.prompt.value_or(""), resolved.graph, cs, o);
              if (!plan) return tl::unexpected(plan.error());
              plan->provenance["classification"] = resolved.classification;
              auto w = store_world(ctx.store, *plan, body, author, "llm", request.seed);
              if (!w) return tl::unexpected(w.error());
              ctx.events.publish("worlds", {{"type", "world.created"}, {"world", summary(*w)}});
              return Json{{"world_id", w->id},
                          {"location", "/api/v1/worlds/" + w->id},
                          {"compliant", w->compliance["passed"]}};
            },
            ctx.client(req));
        ctx.reply_job_accepted(res, id, req.path);
      });

  http.Get("/api/v1/worlds", [&ctx](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    std::optional<std::int64_t> before;
    if (page->cursor) {
      auto seq = parse_sequence_cursor(*page->cursor, kWorldCursorPrefix);
      if (!seq) return reply_problem(res, seq.error(), req.path);
      before = *seq;
    }
    auto listed = cards::WorldStore(ctx.store).list(page->page_size, before, query(req, "domain"));
    if (!listed) return reply_problem(res, listed.error(), req.path);
    Json items = Json::array();
    for (const StoredWorld& w : listed->items) items.push_back(summary(w));
    Json next = nullptr;
    if (listed->next_before) next = std::string(kWorldCursorPrefix) + std::to_string(*listed->next_before);
    reply_json(res, 200, {{"items", std::move(items)}, {"next_cursor", std::move(next)}});
  });

  http.Get(kWorldPath, [&ctx](const Request& req, Response& res) {
    auto w = load_world(ctx.store, req.matches[1].str());
    if (!w) return reply_problem(res, w.error(), req.path);
    auto world = world_of(*w);
    if (!world) return reply_problem(res, world.error(), req.path);
    res.set_header("ETag", "\"" + w->content_hash + "\"");
    reply_json(res, 200, world_json(*w, *world));
  });

  http.Get(std::string(kWorldPath) + "/world.yaml", [&ctx](const Request& req, Response& res) {
    auto w = load_world(ctx.store, req.matches[1].str());
    if (!w) return reply_problem(res, w.error(), req.path);
    res.set_header("ETag", "\"" + w->content_hash + "\"");
    res.set_header("Content-Disposition", "inline; filename=\"" + w->id + ".world.yaml\"");
    res.set_content(w->world_yaml, "application/yaml");
  });

  http.Get(std::string(kWorldPath) + "/export", [&ctx](const Request& req, Response& res) {
    const auto format = query(req, "format");
    static const std::vector<std::string> kFormats = {"sdf",     "usda",     "pedsim", "map",
                                                      "map-pgm", "map-yaml", "svg"};
    if (!format || std::find(kFormats.begin(), kFormats.end(), *format) == kFormats.end())
      return reply_problem(
          res,
          Error(ErrorCode::kValidation, "choose an export format",
                {FieldError::query("format", "one of sdf, usda, pedsim, map, map-pgm, map-yaml, svg")}),
          req.path);
    auto w = load_world(ctx.store, req.matches[1].str());
    if (!w) return reply_problem(res, w.error(), req.path);
    auto world = world_of(*w);
    if (!world) return reply_problem(res, world.error(), req.path);
    const std::string file = w->id;
    auto attach = [&](const std::string& name) {
      res.set_header("Content-Disposition", "attachment; filename=\"" + name + "\"");
    };
    if (*format == "sdf") {
      attach(file + ".sdf");
      return res.set_content(world::export_sdf(*world), "application/xml");
    }
    if (*format == "usda") {
      attach(file + ".usda");
      return res.set_content(world::export_usda(*world), "model/vnd.usda");
    }
    if (*format == "pedsim") {
      attach(file + ".pedsim.xml");
      return res.set_content(world::export_pedsim(*world), "application/xml");
    }
    if (*format == "svg") return res.set_content(world::export_svg(*world), "image/svg+xml");
    world::RosMapOptions mo;
    mo.image_file = file + ".pgm";
    const world::RosMap map = world::export_ros_map(*world, mo);
    if (*format == "map-pgm") {
      attach(mo.image_file);
      return res.set_content(map.pgm, "image/x-portable-graymap");
    }
    if (*format == "map-yaml") {
      attach(file + ".yaml");
      return res.set_content(map.yaml, "application/yaml");
    }
    reply_json(res, 200,
               {{"image_file", mo.image_file}, {"pgm_base64", base64(map.pgm)}, {"yaml", map.yaml}});
  });

  post_with_body(http, "/api/v1/worlds/validate", max_body,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto reading = world::read_world_yaml(text);
                   if (!reading) {
                     // Everything wrong with the posted document is a validation finding, syntax included.
                     Error e = reading.error();
                     if (e.code == ErrorCode::kBadRequest) e.code = ErrorCode::kValidation;
                     return reply_problem(res, e, req.path);
                   }
                   const world::World* world = &reading->world;
                   auto domain = domain_for(req, *world);
                   if (!domain) return reply_problem(res, domain.error(), req.path);
                   auto cs = constraints(ctx, *domain, query(req, "jurisdiction").value_or(""));
                   if (!cs) return reply_problem(res, cs.error(), req.path);
                   const floorplan::ComplianceReport report =
                       floorplan::check_compliance(*world, *domain, *cs);
                   reply_json(res, 200,
                              {{"valid", true},
                               {"name", world->name()},
                               {"zones", world->zones().size()},
                               {"doors", world->doors().size()},
                               {"walls", world->walls().size()},
                               {"rois", world->rois().size()},
                               {"entities", world->entities().size()},
                               {"area", world->area()},
                               {"compliance", floorplan::to_json(report)},
                               {"knowledge", floorplan::knowledge_provenance(*cs)},
                               {"warnings", field_errors_json(reading->warnings)}});
                 });
}

}  // namespace

SOCSIM_ROUTES("worlds", world_routes);

}  // namespace socsim::server
