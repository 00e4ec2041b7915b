// /api/v1/personas and /api/v1/households: residents (built-in, posted, generated offline or by
// the LLM as a job) and dynamic household scenes (made by a job, stored in SQLite, queried by time).
#include <list>
#include <mutex>
#include <set>

#include "core/household/household_document.hpp"
#include "core/household/llm_generators.hpp"
#include "core/household/persona_generator.hpp"
#include "core/household/procthor.hpp"
#include "core/household/statistics.hpp"
#include "server/http_util.hpp"
#include "server/pagination.hpp"
#include "server/routes.hpp"

namespace socsim::server {
namespace {

namespace hh = socsim::household;

// The curated knowledge (loaded once) and the last few scenes rebuilt from their documents.
class HouseholdState {
 public:
  explicit HouseholdState(store::Store& store) : store_(store) {}

  Result<std::shared_ptr<const hh::HouseholdKnowledge>> knowledge() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!knowledge_) {
      auto k = hh::load_household_knowledge(store_);
      if (!k) return tl::unexpected(k.error());
      knowledge_ = std::make_shared<const hh::HouseholdKnowledge>(std::move(*k));
    }
    return knowledge_;
  }

  struct Loaded {
    hh::HouseholdDocument document;
    hh::DynamicScene scene;
  };
  Result<std::shared_ptr<const Loaded>> household(const std::string& id) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto it = cache_.begin(); it != cache_.end(); ++it)
        if (it->first == id) {
          cache_.splice(cache_.begin(), cache_, it);
          return cache_.front().second;
        }
    }
    auto k = knowledge();
    if (!k) return tl::unexpected(k.error());
    auto json = hh::load_household_document(store_, id);
    if (!json) return tl::unexpected(json.error());
    auto doc = hh::household_document_from_json(*json, **k);
    if (!doc)
      return fail(ErrorCode::kStore, "household '" + id + "' cannot be read back: " + doc.error().message());
    auto scene = hh::instantiate_household(*doc, **k);
    if (!scene)
      return fail(ErrorCode::kStore, "household '" + id + "' cannot be rebuilt: " + scene.error().message());
    auto loaded = std::make_shared<const Loaded>(Loaded{std::move(*doc), std::move(*scene)});
    std::lock_guard<std::mutex> lock(mutex_);
    cache_.emplace_front(id, loaded);
    if (cache_.size() > kCacheSize) cache_.pop_back();
    return loaded;
  }

 private:
  static constexpr std::size_t kCacheSize = 16;
  store::Store& store_;
  std::mutex mutex_;
  std::shared_ptr<const hh::HouseholdKnowledge> knowledge_;
  std::list<std::pair<std::string, std::shared_ptr<const Loaded>>> cache_;
};

Json persona_item(const hh::Persona& p, bool builtin) {
  Json j = hh::to_json(p);
  j["id"] = hh::persona_id(p);
  j["builtin"] = builtin;
  return j;
}

Result<std::vector<hh::Persona>> all_personas(store::Store& store) {
  return hh::list_stored_personas(store, true);
}

Result<std::int64_t> seconds_param(const Request& req, const std::string& name, std::int64_t fallback,
                                   std::int64_t max) {
  return query_int(req, name, fallback, 0, max);
}

hh::LlmSettings llm_settings(RouteContext& ctx, llm::StructuredGenerator& gen, const JobContext& job,
                             const std::optional<std::string>& model) {
  hh::LlmSettings s;
  s.generator = &gen;
  s.model = model;
  s.job_id = job.id();
  s.cancel = job.cancel_token();
  (void)ctx;
  return s;
}

constexpr const char* kHouseholdJobKind = "household";

// What POST /api/v1/households checks (the house imports, the personas exist, they fit the
// bedrooms), then the work; any worker rebuilds it from the stored request. The household's id is
// derived from the job's, and storing it again is a no-op, so a second run adds nothing.
Result<JobFn> household_job(RouteContext& ctx, const std::shared_ptr<HouseholdState>& state, const Json& body,
                            const std::string& author) {
  auto request = hh::household_request_from_json(body);
  if (!request) return tl::unexpected(request.error());
  if (auto s = ctx.check_model(request->model); !s) return tl::unexpected(s.error());
  if (request->generator == "llm")
    if (auto s = ctx.llm_available(); !s) return tl::unexpected(s.error());
  auto k = state->knowledge();
  if (!k) return tl::unexpected(k.error());
  auto house = hh::household_house(*request, **k);
  if (!house) return tl::unexpected(house.error());
  auto personas = all_personas(ctx.store);
  if (!personas) return tl::unexpected(personas.error());
  Error problems(ErrorCode::kValidation, "invalid household request");
  for (std::size_t i = 0; i < request->resident_ids.size(); ++i)
    if (std::none_of(personas->begin(), personas->end(),
                     [&](const hh::Persona& p) { return hh::persona_id(p) == request->resident_ids[i]; }))
      problems.errors.push_back(
          {"/residents/" + std::to_string(i), "no persona '" + request->resident_ids[i] + "'"});
  const int bedrooms = std::min<int>(4, static_cast<int>(house->rooms_of(hh::RoomType::kBedroom).size()));
  if (request->resident_count > bedrooms)
    problems.errors.push_back({"/residents", "this house has room for " + std::to_string(bedrooms) +
                                                 " residents (one bedroom each)"});
  if (!problems.errors.empty()) return tl::unexpected(problems);
  return JobFn([&ctx, state, r = std::move(*request), author,
                personas = std::move(*personas)](const JobContext& job) -> Result<Json> {
    auto knowledge = state->knowledge();
    if (!knowledge) return tl::unexpected(knowledge.error());
    std::unique_ptr<llm::StructuredGenerator> gen;
    std::unique_ptr<hh::LlmDayPlanner> planner;
    std::unique_ptr<hh::LlmDecomposer> decomposer;
    std::unique_ptr<hh::LlmActivityDatabaseGenerator> dbgen;
    hh::ProfileGenerators gens;
    if (r.generator == "llm") {
      gen = std::make_unique<llm::StructuredGenerator>(*ctx.llm, &ctx.store);
      const auto settings = llm_settings(ctx, *gen, job, r.model);
      planner = std::make_unique<hh::LlmDayPlanner>(**knowledge, settings);
      decomposer = std::make_unique<hh::LlmDecomposer>(**knowledge, settings);
      dbgen = std::make_unique<hh::LlmActivityDatabaseGenerator>(**knowledge, settings);
      gens = {planner.get(), decomposer.get(), dbgen.get()};
    }
    const std::string household = hh::household_id(r, job.id());
    auto doc = hh::generate_household(
        r, **knowledge, personas, gens, [&job](double f, const std::string& m) { job.progress(f * 0.95, m); },
        household);
    if (!doc) return tl::unexpected(doc.error());
    if (job.cancelled()) return fail(ErrorCode::kCancelled, "cancelled");
    auto scene = hh::instantiate_household(*doc, **knowledge);
    if (!scene) return tl::unexpected(scene.error());
    Json summary = hh::household_summary_json(*doc, *scene);
    summary.erase("schedules");
    if (auto s = hh::store_household(ctx.store, *doc, summary, author, job.id()); !s)
      return tl::unexpected(s.error());
    job.progress(1.0, "stored as " + household);
    return Json{{"household_id", household},
                {"summary", summary},
                {"links", {{"household", "/api/v1/households/" + household}}}};
  });
}

void household_routes(Router& http, RouteContext& ctx) {
  auto state = std::make_shared<HouseholdState>(ctx.store);
  const std::size_t max_body = ctx.config.max_body_bytes;

  // ---- personas ----
  http.Get("/api/v1/personas", [&ctx](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    const std::size_t size = page->page_size;
    auto all = all_personas(ctx.store);
    if (!all) return reply_problem(res, all.error(), req.path);
    auto posted = hh::list_stored_personas(ctx.store, false);
    if (!posted) return reply_problem(res, posted.error(), req.path);
    std::set<std::string> posted_ids;
    for (const auto& p : *posted) posted_ids.insert(hh::persona_id(p));
    std::size_t start = 0;
    if (const auto& cursor = page->cursor) {
      auto it = std::find_if(all->begin(), all->end(),
                             [&](const hh::Persona& p) { return hh::persona_id(p) == *cursor; });
      if (it == all->end()) return reply_problem(res, bad_cursor(), req.path);
      start = static_cast<std::size_t>(it - all->begin()) + 1;
    }
    Json items = Json::array();
    const std::size_t end = std::min(all->size(), start + size);
    for (std::size_t i = start; i < end; ++i)
      items.push_back(persona_item((*all)[i], !posted_ids.count(hh::persona_id((*all)[i]))));
    Json next = end < all->size() ? Json(hh::persona_id((*all)[end - 1])) : Json(nullptr);
    reply_json(res, 200, {{"items", items}, {"total", all->size()}, {"next_cursor", next}});
  });

  http.Get(R"(/api/v1/personas/([^/]+))", [&ctx](const Request& req, Response& res) {
    const std::string id = req.matches[1].str();
    auto all = all_personas(ctx.store);
    if (!all) return reply_problem(res, all.error(), req.path);
    auto posted = hh::list_stored_personas(ctx.store, false);
    if (!posted) return reply_problem(res, posted.error(), req.path);
    for (const auto& p : *all)
      if (hh::persona_id(p) == id) {
        const bool builtin = std::none_of(posted->begin(), posted->end(),
                                          [&](const hh::Persona& q) { return hh::persona_id(q) == id; });
        return reply_json(res, 200, persona_item(p, builtin));
      }
    reply_problem(res, Error(ErrorCode::kNotFound, "no persona '" + id + "'"), req.path);
  });

  post_with_body(http, "/api/v1/personas", max_body,
                 [&ctx](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   auto p = hh::persona_from_json(*body);
                   if (!p) return reply_problem(res, p.error(), req.path);
                   if (auto s = hh::store_persona(ctx.store, *p); !s)
                     return reply_problem(res, s.error(), req.path);
                   res.set_header("Location", "/api/v1/personas/" + hh::persona_id(*p));
                   reply_json(res, 201, persona_item(*p, false));
                 });

  post_with_body(
      http, "/api/v1/personas/generate", max_body,
      [&ctx, state](const Request& req, Response& res, const std::string& text) {
        auto body = json_body(text);
        if (!body) return reply_problem(res, body.error(), req.path);
        auto parsed = hh::persona_generate_request_from_json(*body);
        if (!parsed) return reply_problem(res, parsed.error(), req.path);
        if (auto s = ctx.check_model(parsed->model); !s) return reply_problem(res, s.error(), req.path);
        const hh::PersonaRequest& request = parsed->personas;
        const std::string generator = parsed->generator;
        const bool store = parsed->store;
        const std::optional<std::string> model = parsed->model;
        auto existing = all_personas(ctx.store);
        if (!existing) return reply_problem(res, existing.error(), req.path);

        auto finish = [&ctx, store](std::vector<hh::Persona> personas) -> Result<Json> {
          Json items = Json::array();
          for (const auto& p : personas) {
            if (store)
              if (auto s = hh::store_persona(ctx.store, p); !s) return tl::unexpected(s.error());
            items.push_back(persona_item(p, false));
          }
          return Json{{"personas", items}, {"stored", store}};
        };
        if (generator == "offline") {
          auto knowledge = state->knowledge();
          if (!knowledge) return reply_problem(res, knowledge.error(), req.path);
          auto personas = hh::generate_personas_offline(request, *existing, (*knowledge)->persona_parts);
          if (!personas) return reply_problem(res, personas.error(), req.path);
          auto out = finish(std::move(*personas));
          if (!out) return reply_problem(res, out.error(), req.path);
          return reply_json(res, store ? 201 : 200, *out);
        }
        if (auto s = ctx.llm_available(); !s) return reply_problem(res, s.error(), req.path);
        const hh::PersonaRequest r = request;
        auto id = ctx.jobs.submit(
            "personas", *body, ctx.author(req),
            [&ctx, r, model, finish, existing = *existing](const JobContext& job) -> Result<Json> {
              llm::StructuredGenerator gen(*ctx.llm, &ctx.store);
              job.progress(0.0, "asking the LLM for " + std::to_string(r.count) + " personas");
              auto personas = hh::generate_personas_llm(r, existing, llm_settings(ctx, gen, job, model));
              if (!personas) return tl::unexpected(personas.error());
              return finish(std::move(*personas));
            },
            ctx.client(req));
        ctx.reply_job_accepted(res, id, req.path);
      });

  // ---- households ----
  ctx.jobs.define(kHouseholdJobKind, [&ctx, state](const Json& spec, const std::string& author) {
    return household_job(ctx, state, spec, author);
  });
  post_with_body(http, "/api/v1/households", max_body,
                 [&ctx, state](const Request& req, Response& res, const std::string& text) {
                   auto body = json_body(text);
                   if (!body) return reply_problem(res, body.error(), req.path);
                   const std::string author = ctx.author(req);
                   auto checked = household_job(ctx, state, *body, author);
                   if (!checked) return reply_problem(res, checked.error(), req.path);
                   Json shown = *body;
                   if (shown.contains("house") && shown["house"].is_object())
                     shown["house"] = "(ProcTHOR house, " +
                                      std::to_string(shown["house"].value("rooms", Json::array()).size()) +
                                      " rooms)";
                   auto id = ctx.jobs.submit_spec(kHouseholdJobKind, shown, *body, author, ctx.client(req));
                   ctx.reply_job_accepted(res, id, req.path);
                 });

  http.Get("/api/v1/households", [&ctx](const Request& req, Response& res) {
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    const std::size_t size = page->page_size;
    auto rows = hh::list_households(ctx.store, size + 1, page->cursor);
    if (!rows) {
      if (rows.error().code == ErrorCode::kNotFound) return reply_problem(res, bad_cursor(), req.path);
      return reply_problem(res, rows.error(), req.path);
    }
    Json items = Json::array();
    for (std::size_t i = 0; i < rows->size() && i < size; ++i) {
      const auto& r = (*rows)[i];
      items.push_back({{"id", r.id},
                       {"job_id", r.job_id ? Json(*r.job_id) : Json(nullptr)},
                       {"author", r.author},
                       {"generator", r.generator},
                       {"created_at", r.created_at},
                       {"summary", r.summary}});
    }
    Json next = rows->size() > size ? Json(items.back()["id"]) : Json(nullptr);
    reply_json(res, 200, {{"items", items}, {"next_cursor", next}});
  });

  const std::string base = R"(/api/v1/households/(hh_[0-9a-f]{1,36}|[^/]+))";
  auto with_household = [state](const Request& req,
                                Response& res) -> std::shared_ptr<const HouseholdState::Loaded> {
    auto loaded = state->household(req.matches[1].str());
    if (!loaded) {
      reply_problem(res, loaded.error(), req.path);
      return nullptr;
    }
    return *loaded;
  };

  http.Get(base, [with_household](const Request& req, Response& res) {
    auto h = with_household(req, res);
    if (!h) return;
    Json out = hh::household_summary_json(h->document, h->scene);
    out["house"] = hh::house_plan_json(h->scene.house());
    out["links"] = {{"objects", req.path + "/objects?t=0"},
                    {"events", req.path + "/events"},
                    {"statistics", req.path + "/statistics"},
                    {"export", req.path + "/export?format=procthor"}};
    reply_json(res, 200, out);
  });

  http.Get(base + "/objects", [with_household](const Request& req, Response& res) {
    auto h = with_household(req, res);
    if (!h) return;
    if (!query(req, "t"))
      return reply_problem(res,
                           Error(ErrorCode::kValidation, "say when",
                                 {{"", "is required (seconds from 00:00 of the first day)", "t", 0, 0}}),
                           req.path);
    auto t = seconds_param(req, "t", 0, h->scene.end());
    if (!t) return reply_problem(res, t.error(), req.path);
    reply_json(res, 200, hh::objects_at_json(h->scene, *t));
  });

  http.Get(base + "/events", [&ctx, with_household](const Request& req, Response& res) {
    auto h = with_household(req, res);
    if (!h) return;
    const auto end = h->scene.end();
    auto from = seconds_param(req, "from", 0, end);
    if (!from) return reply_problem(res, from.error(), req.path);
    auto to = seconds_param(req, "to", end, end);
    if (!to) return reply_problem(res, to.error(), req.path);
    if (*to < *from)
      return reply_problem(
          res, Error(ErrorCode::kValidation, "empty window", {{"", "must not be before from", "to", 0, 0}}),
          req.path);
    auto resident =
        query_int(req, "resident", -1, -1, static_cast<std::int64_t>(h->scene.residents().size()) - 1);
    if (!resident) return reply_problem(res, resident.error(), req.path);
    auto page = ctx.page(req);
    if (!page) return reply_problem(res, page.error(), req.path);
    const std::size_t size = page->page_size;
    std::size_t first = 0;  // the cursor is the index of the next event
    if (page->cursor) {
      auto at = parse_sequence_cursor(*page->cursor, "");
      if (!at) return reply_problem(res, at.error(), req.path);
      first = static_cast<std::size_t>(*at);
    }
    std::vector<int> picked;
    for (int e : h->scene.events_between(*from, *to))
      if (*resident < 0 || h->scene.events()[static_cast<std::size_t>(e)].resident == *resident)
        picked.push_back(e);
    Json items = Json::array();
    if (first > picked.size()) return reply_problem(res, bad_cursor(), req.path);
    const std::size_t last = std::min(picked.size(), first + size);
    for (std::size_t i = first; i < last; ++i) items.push_back(hh::event_json(h->scene, picked[i]));
    reply_json(res, 200,
               {{"items", items},
                {"total", picked.size()},
                {"next_cursor", last < picked.size() ? Json(std::to_string(last)) : Json(nullptr)}});
  });

  http.Get(base + "/hint", [&ctx, with_household](const Request& req, Response& res) {
    auto h = with_household(req, res);
    if (!h) return;
    auto resident =
        query_int(req, "resident", 0, 0, static_cast<std::int64_t>(h->scene.residents().size()) - 1);
    if (!resident) return reply_problem(res, resident.error(), req.path);
    auto object = query(req, "object");
    if (!object || object->empty() || object->size() > 200)
      return reply_problem(res,
                           Error(ErrorCode::kValidation, "name the object",
                                 {{"", "an object type (Mug) or id is required", "object", 0, 0}}),
                           req.path);
    auto t = seconds_param(req, "t", h->scene.end(), h->scene.end());
    if (!t) return reply_problem(res, t.error(), req.path);
    auto lookback = query_int(req, "lookback", hh::kSecondsPerDay, 60, 28 * hh::kSecondsPerDay);
    if (!lookback) return reply_problem(res, lookback.error(), req.path);
    const std::string generator = query(req, "generator").value_or("offline");
    if (generator != "offline" && generator != "llm")
      return reply_problem(res,
                           Error(ErrorCode::kValidation, "unknown generator",
                                 {{"", "must be offline or llm", "generator", 0, 0}}),
                           req.path);
    hh::HintQuery q{&h->scene, static_cast<int>(*resident), *object, *t, *lookback};
    Result<hh::Hint> hint = fail(ErrorCode::kInternal, "no hint");
    if (generator == "llm") {
      if (auto s = ctx.llm_available(); !s) return reply_problem(res, s.error(), req.path);
      llm::StructuredGenerator gen(*ctx.llm, &ctx.store);
      hh::LlmSettings settings;
      settings.generator = &gen;
      hint = hh::LlmHintGenerator(settings).hint(q);
    } else {
      hint = hh::OfflineHintGenerator().hint(q);
    }
    if (!hint) return reply_problem(res, hint.error(), req.path);
    const auto& house = h->scene.house();
    reply_json(res, 200,
               {{"resident", *resident},
                {"object", *object},
                {"t", *t},
                {"generator", generator},
                {"used", hint->used},
                {"text", hint->text},
                {"activity", hint->activity},
                {"room", hint->room_id},
                {"receptacle", hint->receptacle_id},
                {"when", hint->used || hint->event >= 0 ? Json(hint->when) : Json(nullptr)},
                {"object_id", hint->object >= 0
                                  ? Json(house
                                             .entities[static_cast<std::size_t>(
                                                 house.objects[static_cast<std::size_t>(hint->object)])]
                                             .id)
                                  : Json(nullptr)}});
  });

  http.Get(base + "/export", [with_household](const Request& req, Response& res) {
    auto h = with_household(req, res);
    if (!h) return;
    const std::string format = query(req, "format").value_or("procthor");
    if (format != "procthor")
      return reply_problem(
          res,
          Error(ErrorCode::kValidation, "unknown export format", {{"", "must be procthor", "format", 0, 0}}),
          req.path);
    Json out;
    if (query(req, "t")) {
      auto t = seconds_param(req, "t", 0, h->scene.end());
      if (!t) return reply_problem(res, t.error(), req.path);
      const auto placement = h->scene.placement_at(*t);
      out = hh::export_procthor(h->scene.house(), &placement);
    } else {
      out = hh::export_procthor(h->scene.house());
    }
    res.set_header("Content-Disposition", "attachment; filename=\"" + h->document.id + ".procthor.json\"");
    reply_json(res, 200, out);
  });

  http.Get(base + "/statistics", [with_household](const Request& req, Response& res) {
    auto h = with_household(req, res);
    if (!h) return;
    std::vector<hh::ResidentProfile> profiles;
    for (const auto& r : h->document.residents) profiles.push_back(*r);
    Json out = hh::statistics_report(profiles, h->document.scene_seed);
    out["household_id"] = h->document.id;
    out["paper"] = hh::paper_statistics();
    reply_json(res, 200, out);
  });
}

}  // namespace

SOCSIM_ROUTES("household", household_routes);

}  // namespace socsim::server
