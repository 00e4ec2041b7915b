#include "server/batches.hpp"

#include <map>
#include <set>

#include "core/cards/catalogue.hpp"
#include "core/common/ids.hpp"
#include "core/common/json_check.hpp"
#include "core/household/household_document.hpp"
#include "core/interop/tar_archive.hpp"
#include "core/scenario/trajectory_store.hpp"
#include "server/pagination.hpp"

namespace socsim::server {
namespace {
using store::Database;

constexpr std::string_view kBatchCursorPrefix = "b1.";

Error not_found(const std::string& id) {
  return Error(ErrorCode::kNotFound, "no batch with id '" + id + "'");
}

// SplitMix64: the batch's own seeded sampling of household sizes (one draw per item and field).
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Seeds as a list, or {"first": F, "count": N}.
std::vector<std::int64_t> read_seeds(JsonChecker& c, const Json& body, const std::string& key) {
  std::vector<std::int64_t> seeds;
  if (!JsonChecker::given(body, key)) {
    c.add("/" + key, "required: a list of seeds or {\"first\": 1, \"count\": 100}");
    return seeds;
  }
  const Json& s = body[key];
  if (s.is_array()) {
    if (s.empty()) c.add("/" + key, "must list at least one seed");
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (!s[i].is_number_integer() || s[i].get<std::int64_t>() < 0)
        c.add("/" + key + "/" + std::to_string(i), "must be a non-negative integer");
      else
        seeds.push_back(s[i].get<std::int64_t>());
    }
  } else if (s.is_object()) {
    c.only_keys(s, "/" + key, {"first", "count"});
    const auto first = c.integer(s, "/" + key, "first", false, 0, INT64_MAX / 2).value_or(1);
    const auto n = c.integer(s, "/" + key, "count", true, 1, static_cast<std::int64_t>(kMaxBatchItems));
    if (n)
      for (std::int64_t i = 0; i < *n; ++i) seeds.push_back(first + i);
  } else {
    c.add("/" + key, "must be a list of seeds or {\"first\": 1, \"count\": 100}");
  }
  return seeds;
}

// [lo, hi] within [min, max].
std::optional<std::pair<int, int>> read_range(JsonChecker& c, const Json& body, const std::string& key,
                                              int min, int max, std::pair<int, int> fallback) {
  if (!JsonChecker::given(body, key)) return fallback;
  const Json& r = body[key];
  if (r.is_number_integer()) {
    const auto v = r.get<std::int64_t>();
    if (v >= min && v <= max) return std::pair<int, int>(static_cast<int>(v), static_cast<int>(v));
  } else if (r.is_array() && r.size() == 2 && r[0].is_number_integer() && r[1].is_number_integer()) {
    const auto lo = r[0].get<std::int64_t>(), hi = r[1].get<std::int64_t>();
    if (lo >= min && hi <= max && lo <= hi)
      return std::pair<int, int>(static_cast<int>(lo), static_cast<int>(hi));
  }
  c.add("/" + key,
        "must be an integer or [low, high] within " + std::to_string(min) + "-" + std::to_string(max));
  return std::nullopt;
}

// An item's problem, pointed into the batch request.
Error item_error(Error e, const std::string& prompt_ptr) {
  for (auto& f : e.errors) {
    if (f.pointer.rfind("/splits/", 0) == 0) continue;  // already the batch's
    if (f.pointer.rfind("/prompt", 0) == 0 && !prompt_ptr.empty())
      f.pointer = prompt_ptr;
    else if (f.pointer == "/seed" || f.pointer == "/split" || f.pointer == "/rooms" ||
             f.pointer == "/residents")
      f.pointer = f.pointer == "/seed" ? "/seeds" : f.pointer == "/split" ? "/splits" : f.pointer;
    else
      f.pointer = "/parameters" + f.pointer;
  }
  if (e.errors.empty()) e.errors.push_back({"/parameters", e.detail});
  return e;
}

Json parameters_of(JsonChecker& c, const Json& body, std::initializer_list<std::string_view> reserved) {
  Json p = Json::object();
  if (const Json* given = c.object(body, "", "parameters", false)) p = *given;
  for (auto k : reserved)
    if (p.contains(std::string(k)))
      c.add("/parameters/" + std::string(k), "is set by the batch (use the batch's own field)");
  return p;
}

Result<Json> batch_row(Database& db, const std::string& id) {
  auto st = db.prepare("SELECT id, kind, author, request, total, created_at FROM batches WHERE id = ?");
  if (!st) return tl::unexpected(st.error());
  st->bind(1, id);
  auto row = st->step();
  if (!row) return tl::unexpected(row.error());
  if (!*row) return tl::unexpected(not_found(id));
  return Json{{"id", st->text(0)},
              {"kind", st->text(1)},
              {"author", st->text(2)},
              {"request", Json::parse(st->text(3))},
              {"total", st->int64(4)},
              {"created_at", st->text(5)},
              {"links",
               {{"self", "/api/v1/batches/" + st->text(0)},
                {"items", "/api/v1/batches/" + st->text(0) + "/items"},
                {"export", "/api/v1/batches/" + st->text(0) + "/export"}}}};
}

// Adds counts, progress, status and per-worker counts to a batch row.
Status add_counts(Database& db, Json& b) {
  const std::string id = b["id"];
  auto st = db.prepare(
      "SELECT status, count(*), sum(progress) FROM jobs WHERE batch_id = ? GROUP BY status ORDER BY status");
  if (!st) return tl::unexpected(st.error());
  st->bind(1, id);
  Json counts = {{"queued", 0}, {"running", 0}, {"succeeded", 0}, {"failed", 0}, {"cancelled", 0}};
  double done = 0;
  for (;;) {
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) break;
    const std::string status = st->text(0);
    const std::int64_t n = st->int64(1);
    counts[status] = n;
    done += status == "running" ? st->real(2) : status == "queued" ? 0.0 : static_cast<double>(n);
  }
  auto w = db.prepare(
      "SELECT worker, count(*) FROM jobs WHERE batch_id = ? AND status = 'succeeded' GROUP BY worker ORDER "
      "BY "
      "worker");
  if (!w) return tl::unexpected(w.error());
  w->bind(1, id);
  Json workers = Json::object();
  for (;;) {
    auto row = w->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) break;
    workers[w->is_null(0) ? "" : w->text(0)] = w->int64(1);
  }
  const std::int64_t total = b["total"];
  const std::int64_t pending = counts["queued"].get<std::int64_t>() + counts["running"].get<std::int64_t>();
  b["counts"] = counts;
  b["progress"] = total > 0 ? std::min(1.0, done / static_cast<double>(total)) : 1.0;
  b["status"] = pending > 0                                        ? "running"
                : counts["succeeded"].get<std::int64_t>() == total ? "succeeded"
                : counts["cancelled"].get<std::int64_t>() > 0      ? "cancelled"
                                                                   : "failed";
  b["succeeded_by_worker"] = workers;
  return {};
}
}  // namespace

bool is_batch_id(std::string_view s) {
  return is_random_id(s, "bat_");
}

Result<BatchPlan> plan_batch(
    const Json& body, const std::function<Status(const std::string& job_kind, const Json& spec)>& check) {
  JsonChecker c;
  if (!body.is_object())
    return fail(ErrorCode::kValidation, "the batch request must be a JSON object",
                {{"", "expected an object"}});
  BatchPlan plan;
  plan.kind = c.string(body, "", "kind", true, 1, 20).value_or("");
  if (!c.ok()) return tl::unexpected(c.error("invalid batch request"));
  const auto title = c.string(body, "", "title", false, 1, 200);
  if (plan.kind == "scenarios") {
    plan.job_kind = "scenario.generate";
    c.only_keys(body, "", {"kind", "title", "prompts", "prompt", "seeds", "parameters"});
    std::vector<std::string> prompts;
    if (JsonChecker::given(body, "prompt") == JsonChecker::given(body, "prompts"))
      c.add("/prompts", "give prompts (a list) or prompt, one of them");
    if (auto p = c.string(body, "", "prompt", false, 1, 1u << 16)) prompts.push_back(*p);
    if (const Json* list = c.array(body, "", "prompts", false, kMaxBatchItems)) {
      if (list->empty()) c.add("/prompts", "must list at least one prompt");
      for (std::size_t i = 0; i < list->size(); ++i)
        if (!(*list)[i].is_string() || (*list)[i].get_ref<const std::string&>().empty())
          c.add("/prompts/" + std::to_string(i), "must be a non-empty prompt");
        else
          prompts.push_back((*list)[i].get<std::string>());
    }
    const auto seeds = read_seeds(c, body, "seeds");
    Json params = parameters_of(c, body, {"prompt", "seed"});
    if (!c.ok()) return tl::unexpected(c.error("invalid batch request"));
    if (prompts.size() * seeds.size() > kMaxBatchItems)
      return fail(ErrorCode::kValidation,
                  "a batch holds at most " + std::to_string(kMaxBatchItems) + " items",
                  {{"/seeds", std::to_string(prompts.size()) + " prompts × " + std::to_string(seeds.size()) +
                                  " seeds is too many"}});
    for (std::size_t p = 0; p < prompts.size(); ++p) {
      const std::string ptr =
          JsonChecker::given(body, "prompts") ? "/prompts/" + std::to_string(p) : "/prompt";
      for (std::size_t s = 0; s < seeds.size(); ++s) {
        Json spec = params;
        spec["prompt"] = prompts[p];
        spec["seed"] = seeds[s];
        // The prompt and parameters decide validity; one seed of each prompt is checked.
        if (s == 0)
          if (auto ok = check(plan.job_kind, spec); !ok) return tl::unexpected(item_error(ok.error(), ptr));
        plan.items.push_back({Json{{"prompt", prompts[p]}, {"seed", seeds[s]}}, std::move(spec)});
      }
    }
    plan.request = {{"kind", plan.kind}, {"prompts", prompts}, {"seeds", seeds}, {"parameters", params}};
  } else if (plan.kind == "households") {
    plan.job_kind = "household";
    c.only_keys(body, "", {"kind", "title", "count", "rooms", "residents", "seed", "parameters"});
    const auto n = c.integer(body, "", "count", true, 1, static_cast<std::int64_t>(kMaxBatchItems));
    const auto rooms = read_range(c, body, "rooms", 1, 10, {3, 8});
    const auto residents = read_range(c, body, "residents", 1, 4, {1, 3});
    const auto seed = c.integer(body, "", "seed", false, 0, INT64_MAX / 2).value_or(0);
    Json params = parameters_of(c, body, {"rooms", "house", "residents", "seed"});
    if (!c.ok() || !n || !rooms || !residents) return tl::unexpected(c.error("invalid batch request"));
    for (std::int64_t i = 0; i < *n; ++i) {
      const std::uint64_t key =
          mix(static_cast<std::uint64_t>(seed) * 0x100000001b3ULL + static_cast<std::uint64_t>(i));
      const int r =
          rooms->first + static_cast<int>(key % static_cast<std::uint64_t>(rooms->second - rooms->first + 1));
      int people =
          residents->first +
          static_cast<int>(mix(key) % static_cast<std::uint64_t>(residents->second - residents->first + 1));
      Json spec = params;
      spec["rooms"] = r;
      spec["seed"] = seed + i;
      // A house has room for one resident per bedroom: fewer people where the plan has fewer.
      for (;;) {
        spec["residents"] = people;
        auto ok = check(plan.job_kind, spec);
        if (ok) break;
        const bool beds = std::any_of(ok.error().errors.begin(), ok.error().errors.end(),
                                      [](const FieldError& f) { return f.pointer == "/residents"; });
        if (!beds || people <= 1) return tl::unexpected(item_error(ok.error(), ""));
        --people;
      }
      plan.items.push_back({Json{{"rooms", r}, {"residents", people}, {"seed", seed + i}}, std::move(spec)});
    }
    plan.request = {{"kind", plan.kind},
                    {"count", *n},
                    {"rooms", {rooms->first, rooms->second}},
                    {"residents", {residents->first, residents->second}},
                    {"seed", seed},
                    {"parameters", params}};
  } else if (plan.kind == "navbench") {
    plan.job_kind = "navbench";
    c.only_keys(body, "", {"kind", "title", "splits", "seeds", "parameters"});
    std::vector<std::string> splits;
    if (const Json* list = c.array(body, "", "splits", true, 2)) {
      for (std::size_t i = 0; i < list->size(); ++i)
        if (!(*list)[i].is_string())
          c.add("/splits/" + std::to_string(i), "must be normal or hard");
        else
          splits.push_back((*list)[i].get<std::string>());
      if (list->empty()) c.add("/splits", "must list normal, hard or both");
    }
    const auto seeds = read_seeds(c, body, "seeds");
    Json params = parameters_of(c, body, {"split", "seed"});
    if (!c.ok()) return tl::unexpected(c.error("invalid batch request"));
    for (std::size_t i = 0; i < splits.size(); ++i)
      for (std::size_t s = 0; s < seeds.size(); ++s) {
        Json spec = params;
        spec["split"] = splits[i];
        spec["seed"] = seeds[s];
        if (auto ok = check(plan.job_kind, spec); !ok) {
          Error e = ok.error();
          for (auto& f : e.errors)
            if (f.pointer == "/split") f.pointer = "/splits/" + std::to_string(i);
          return tl::unexpected(item_error(e, ""));
        }
        plan.items.push_back({Json{{"split", splits[i]}, {"seed", seeds[s]}}, std::move(spec)});
      }
    plan.request = {{"kind", plan.kind}, {"splits", splits}, {"seeds", seeds}, {"parameters", params}};
  } else {
    return fail(ErrorCode::kValidation, "unknown batch kind '" + plan.kind + "'",
                {{"/kind", "one of scenarios, households, navbench"}});
  }
  if (title) plan.request["title"] = *title;
  if (plan.items.size() > kMaxBatchItems)
    return fail(ErrorCode::kValidation, "a batch holds at most " + std::to_string(kMaxBatchItems) + " items",
                {{"", std::to_string(plan.items.size()) + " items"}});
  return plan;
}

Result<std::string> store_batch(store::Store& store, const BatchPlan& plan, const std::string& author,
                                const std::string& client) {
  const std::string id = random_id("bat_");
  auto r = store.write([&](Database& db) -> Result<bool> {
    auto st = db.prepare(
        "INSERT INTO batches(id, kind, author, request, total, created_at) VALUES (?, ?, ?, ?, ?, ?)");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id).bind(2, plan.kind).bind(3, author).bind(4, canonical_json(plan.request));
    st->bind(5, static_cast<std::int64_t>(plan.items.size())).bind(6, utc_now_rfc3339());
    if (auto s = st->run(); !s) return tl::unexpected(s.error());
    auto ids = JobRunner::insert_items(db, plan.job_kind, author, client, id, plan.items);
    if (!ids) return tl::unexpected(ids.error());
    return true;
  });
  if (!r) return tl::unexpected(r.error());
  return id;
}

Result<Json> batch_status(store::Store& store, const std::string& id) {
  if (!is_batch_id(id)) return tl::unexpected(not_found(id));
  return store.read([&](Database& db) -> Result<Json> {
    auto b = batch_row(db, id);
    if (!b) return b;
    if (auto s = add_counts(db, *b); !s) return tl::unexpected(s.error());
    return b;
  });
}

Result<Json> list_batches(store::Store& store, std::size_t page_size,
                          const std::optional<std::string>& cursor) {
  std::optional<std::int64_t> before;
  if (cursor) {
    auto seq = parse_sequence_cursor(*cursor, kBatchCursorPrefix);
    if (!seq) return tl::unexpected(seq.error());
    before = *seq;
  }
  return store.read([&](Database& db) -> Result<Json> {
    auto st = db.prepare(std::string("SELECT id, seq FROM batches") + (before ? " WHERE seq < ?" : "") +
                         " ORDER BY seq DESC LIMIT ?");
    if (!st) return tl::unexpected(st.error());
    int i = 1;
    if (before) st->bind(i++, *before);
    st->bind(i, static_cast<std::int64_t>(page_size + 1));
    std::vector<std::pair<std::string, std::int64_t>> rows;
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      rows.emplace_back(st->text(0), st->int64(1));
    }
    Json items = Json::array();
    Json next = nullptr;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (k == page_size) {
        next = std::string(kBatchCursorPrefix) + std::to_string(rows[k - 1].second);
        break;
      }
      auto b = batch_row(db, rows[k].first);
      if (!b) return b;
      if (auto s = add_counts(db, *b); !s) return tl::unexpected(s.error());
      b->erase("request");
      items.push_back(std::move(*b));
    }
    return Json{{"items", std::move(items)}, {"next_cursor", std::move(next)}};
  });
}

Result<Json> batch_items(store::Store& store, const std::string& id, std::size_t page_size,
                         std::size_t from) {
  if (!is_batch_id(id)) return tl::unexpected(not_found(id));
  return store.read([&](Database& db) -> Result<Json> {
    auto b = batch_row(db, id);
    if (!b) return b;
    auto st = db.prepare(
        "SELECT id, batch_index, status, request, result, error, worker, attempts FROM jobs WHERE batch_id = "
        "? "
        "AND batch_index >= ? ORDER BY batch_index LIMIT ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id)
        .bind(2, static_cast<std::int64_t>(from))
        .bind(3, static_cast<std::int64_t>(page_size + 1));
    Json items = Json::array();
    Json next = nullptr;
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      if (items.size() == page_size) {
        next = std::to_string(st->int64(1));
        break;
      }
      items.push_back({{"job_id", st->text(0)},
                       {"index", st->int64(1)},
                       {"status", st->text(2)},
                       {"item", Json::parse(st->text(3))},
                       {"result", st->is_null(4) ? Json(nullptr) : Json::parse(st->text(4))},
                       {"error", st->is_null(5) ? Json(nullptr) : Json::parse(st->text(5))},
                       {"worker", st->is_null(6) ? Json(nullptr) : Json(st->text(6))},
                       {"attempts", st->int64(7)}});
    }
    return Json{{"items", std::move(items)}, {"next_cursor", std::move(next)}};
  });
}

Result<std::int64_t> cancel_batch(store::Store& store, JobRunner& jobs, const std::string& id,
                                  const std::string& author, bool any_author) {
  auto b = batch_status(store, id);
  if (!b) return tl::unexpected(b.error());
  if (!any_author && (*b)["author"] != author)
    return fail(ErrorCode::kForbidden, "only the batch's author may cancel it");
  if ((*b)["status"] != "running")
    return fail(ErrorCode::kConflict,
                "the batch has already finished (" + (*b)["status"].get<std::string>() + ")");
  auto pending = store.read([&](Database& db) -> Result<std::vector<std::string>> {
    auto st = db.prepare(
        "SELECT id FROM jobs WHERE batch_id = ? AND status IN ('queued', 'running') ORDER BY batch_index");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id);
    std::vector<std::string> ids;
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      ids.push_back(st->text(0));
    }
    return ids;
  });
  if (!pending) return tl::unexpected(pending.error());
  std::int64_t reached = 0;
  for (const auto& job : *pending)
    if (jobs.cancel(job, author, true)) ++reached;  // an item that finished meanwhile is left as it is
  return reached;
}

Result<std::string> export_batch(store::Store& store, const std::string& id) {
  auto b = batch_status(store, id);
  if (!b) return tl::unexpected(b.error());
  if ((*b)["status"] == "running")
    return fail(ErrorCode::kConflict, "the batch is still running (" +
                                          std::to_string((*b)["counts"]["queued"].get<std::int64_t>() +
                                                         (*b)["counts"]["running"].get<std::int64_t>()) +
                                          " items to go); export it when it has finished");
  auto items = batch_items(store, id, kMaxBatchItems, 0);
  if (!items) return tl::unexpected(items.error());
  const std::string kind = (*b)["kind"];
  // batch.json: the request and each item's outcome, without volatile fields (times, workers).
  Json listing = Json::array();
  for (const auto& it : (*items)["items"])
    listing.push_back({{"index", it["index"]},
                       {"item", it["item"]},
                       {"status", it["status"]},
                       {"result", it["result"]},
                       {"error", it["error"]},
                       {"job_id", it["job_id"]}});
  Json manifest = {{"id", id},
                   {"kind", kind},
                   {"request", (*b)["request"]},
                   {"total", (*b)["total"]},
                   {"counts", (*b)["counts"]},
                   {"items", listing}};
  std::vector<interop::ExportFile> files;
  files.push_back({"batch.json", manifest.dump(2) + "\n"});
  std::string lines;
  std::vector<interop::ExportFile> logs;
  std::set<std::string> seen_logs;
  cards::CardCatalogue catalogue(store);
  for (const auto& it : (*items)["items"]) {
    if (it["status"] != "succeeded") continue;
    const Json& result = it["result"];
    if (kind == "scenarios") {
      auto card = catalogue.get(result.value("card_id", ""));
      if (!card) return tl::unexpected(card.error());
      Json line = cards::to_json(*card);
      line["batch_index"] = it["index"];
      lines += canonical_json(line) + "\n";
      const std::string sha = card->content.trajectory_log.is_object()
                                  ? card->content.trajectory_log.value("sha256", "")
                                  : std::string();
      if (!sha.empty() && seen_logs.insert(sha).second) {
        auto blob = scenario::load_trajectory_blob(store, sha);
        if (!blob) return tl::unexpected(blob.error());
        logs.push_back({"logs/" + sha + ".socsim-traj", std::move(*blob)});
      }
    } else if (kind == "households") {
      auto doc = household::load_household_document(store, result.value("household_id", ""));
      if (!doc) return tl::unexpected(doc.error());
      lines += canonical_json(Json{{"batch_index", it["index"]},
                                   {"household_id", result.value("household_id", "")},
                                   {"summary", result.value("summary", Json::object())},
                                   {"document", *doc}}) +
               "\n";
    } else {
      lines +=
          canonical_json(Json{{"batch_index", it["index"]}, {"item", it["item"]}, {"result", result}}) + "\n";
    }
  }
  files.push_back({kind == "scenarios"    ? "cards.jsonl"
                   : kind == "households" ? "households.jsonl"
                                          : "results.jsonl",
                   std::move(lines)});
  for (auto& f : logs) files.push_back(std::move(f));
  return interop::tar_archive(files);
}

}  // namespace socsim::server
