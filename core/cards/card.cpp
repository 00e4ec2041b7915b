#include "core/cards/card.hpp"

#include <algorithm>
#include <array>

#include "core/common/ids.hpp"
#include "core/common/json_check.hpp"
#include "core/common/sha256.hpp"

namespace socsim::cards {
namespace {

constexpr int kExportFormat = 1;

bool valid_tag(const std::string& t) {
  if (t.empty() || t.size() > 64) return false;
  for (char c : t) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.' || c == ':';
    if (!ok) return false;
  }
  return true;
}

bool valid_domain(const std::string& d) {
  if (d.empty() || d.size() > 32) return false;
  for (char c : d)
    if (!((c >= 'a' && c <= 'z') || c == '_')) return false;
  return true;
}

bool valid_generator_name(const std::string& g) {
  return g == "offline" || g == "llm" || g == "import" || g == "manual";
}

// Reads every client field present in `body` into `out`; `required` marks a POST (title needed).
void read_content(JsonChecker& c, const Json& body, const CardLimits& limits, bool required,
                  CardContent& out) {
  if (auto v = c.string(body, "", "title", required, 1, limits.max_title_bytes)) out.title = *v;
  if (auto v = c.string(body, "", "description", false, 0, limits.max_description_bytes))
    out.description = *v;
  if (auto v = c.string(body, "", "prompt", false, 0, limits.max_prompt_bytes)) out.prompt = *v;
  if (const Json* tags = c.array(body, "", "tags", false, limits.max_tags)) {
    out.tags.clear();
    for (std::size_t i = 0; i < tags->size(); ++i) {
      const Json& t = (*tags)[i];
      const std::string ptr = JsonChecker::child("/tags", i);
      if (!t.is_string() || !valid_tag(t.get<std::string>())) {
        c.add(ptr, "a tag is 1–64 characters of a–z, 0–9, '-', '_', '.', ':'");
        continue;
      }
      out.tags.push_back(t.get<std::string>());
    }
    std::sort(out.tags.begin(), out.tags.end());
    out.tags.erase(std::unique(out.tags.begin(), out.tags.end()), out.tags.end());
  }
  if (body.contains("seed")) {
    const Json& s = body["seed"];
    if (s.is_number_unsigned())
      out.seed = s.get<std::uint64_t>();
    else if (s.is_number_integer() && s.get<std::int64_t>() >= 0)
      out.seed = static_cast<std::uint64_t>(s.get<std::int64_t>());
    else
      c.add("/seed", "must be an integer between 0 and 18446744073709551615");
  }
  if (const Json* g = c.object(body, "", "generator", false)) {
    c.only_keys(*g, "/generator", {"name", "model"});
    if (auto n = c.string(*g, "/generator", "name", true)) {
      if (valid_generator_name(*n))
        out.generator.name = *n;
      else
        c.add("/generator/name", "must be one of offline, llm, import, manual");
    }
    if (auto m = c.string(*g, "/generator", "model", false, 1, 200)) out.generator.model = *m;
  }
  if (body.contains("domain")) {
    if (body["domain"].is_null()) {
      out.domain.reset();
    } else if (auto d = c.string(body, "", "domain", false)) {
      if (valid_domain(*d))
        out.domain = *d;
      else
        c.add("/domain", "a domain is 1–32 characters of a–z and '_' (e.g. hospital, office, residential)");
    }
  }
  for (const char* key : {"world", "program"}) {
    if (!body.contains(key)) continue;
    const Json& v = body[key];
    if (!v.is_null() && !v.is_object())
      c.add(std::string("/") + key, "must be an object or null");
    else
      (std::string_view(key) == "world" ? out.world : out.program) = v;
  }
  if (body.contains("intent")) {
    const Json& v = body["intent"];
    if (!v.is_null() && !v.is_object())
      c.add("/intent", "must be an object (schemas/intent.schema.json) or null");
    else
      out.intent = v;
  }
  for (const char* key : {"metrics", "provenance"}) {
    if (const Json* o = c.object(body, "", key, false))
      (std::string_view(key) == "metrics" ? out.metrics : out.provenance) = *o;
  }
  if (body.contains("trajectory_log")) {
    const Json& t = body["trajectory_log"];
    if (t.is_null()) {
      out.trajectory_log = nullptr;
    } else if (!t.is_object()) {
      c.add("/trajectory_log", "must be an object or null");
    } else {
      c.only_keys(t, "/trajectory_log",
                  {"uri", "format", "frames", "rate_hz", "agents", "duration_s", "sha256"});
      c.string(t, "/trajectory_log", "uri", true, 1, 2048);
      c.string(t, "/trajectory_log", "format", true, 1, 64);
      c.integer(t, "/trajectory_log", "frames", false, 0);
      c.number(t, "/trajectory_log", "rate_hz", false, 0.0, 1000.0);
      c.integer(t, "/trajectory_log", "agents", false, 0);
      if (auto d = c.number(t, "/trajectory_log", "duration_s", false, 0.0, 86400.0); d && *d <= 0.0)
        c.add("/trajectory_log/duration_s", "must be greater than 0");
      if (auto h = c.string(t, "/trajectory_log", "sha256", false); h && h->size() != 64)
        c.add("/trajectory_log/sha256", "must be 64 hex characters");
      out.trajectory_log = t;
    }
  }
}

constexpr std::array<std::string_view, 13> kContentKeys = {
    "title", "description", "tags",    "prompt",         "seed",       "generator", "domain",
    "world", "program",     "metrics", "trajectory_log", "provenance", "intent"};

}  // namespace

Result<CardContent> parse_card_content(const Json& body, const CardLimits& limits) {
  if (!body.is_object())
    return fail(ErrorCode::kValidation, "the card must be a JSON object", {{"", "must be an object"}});
  JsonChecker c;
  c.only_keys(body, "", kContentKeys);
  CardContent out;
  read_content(c, body, limits, true, out);
  if (!c.ok()) return tl::unexpected(c.error("the card does not match schemas/card.schema.json"));
  return out;
}

Result<CardContent> merge_card_content(const CardContent& base, const Json& patch, const CardLimits& limits) {
  if (!patch.is_object())
    return fail(ErrorCode::kValidation, "the new version must be a JSON object", {{"", "must be an object"}});
  JsonChecker c;
  c.only_keys(patch, "", kContentKeys);
  CardContent out = base;
  read_content(c, patch, limits, false, out);
  if (!c.ok()) return tl::unexpected(c.error("the new version does not match schemas/card.schema.json"));
  return out;
}

Json content_to_json(const CardContent& c) {
  Json g = {{"name", c.generator.name}};
  if (c.generator.model) g["model"] = *c.generator.model;
  Json j{{"title", c.title},
         {"description", c.description},
         {"tags", c.tags},
         {"prompt", c.prompt},
         {"seed", c.seed},
         {"generator", g},
         {"domain", c.domain ? Json(*c.domain) : Json(nullptr)},
         {"world", c.world},
         {"program", c.program},
         {"metrics", c.metrics},
         {"trajectory_log", c.trajectory_log},
         {"provenance", c.provenance}};
  // Absent rather than null when there is none, so cards from before the field keep their hash.
  if (!c.intent.is_null()) j["intent"] = c.intent;
  return j;
}

std::string content_hash(const CardContent& content, std::int64_t version,
                         const std::optional<std::string>& parent) {
  Json j = content_to_json(content);
  j["version"] = version;
  j["parent_id"] = parent ? Json(*parent) : Json(nullptr);
  return sha256_hex(canonical_json(j));
}

Json to_json(const Card& card) {
  Json j = content_to_json(card.content);
  j["id"] = card.id;
  j["author"] = card.author;
  j["version"] = card.version;
  j["parent_id"] = card.parent_id ? Json(*card.parent_id) : Json(nullptr);
  j["created_at"] = card.created_at;
  j["content_hash"] = card.content_hash;
  return j;
}

Json summary_json(const Card& card) {
  Json j = to_json(card);
  for (const char* k : {"world", "program", "metrics", "provenance", "trajectory_log", "intent"}) j.erase(k);
  return j;
}

Result<Card> parse_card(const Json& json, const CardLimits& limits) {
  if (!json.is_object())
    return fail(ErrorCode::kValidation, "a card must be a JSON object", {{"", "must be an object"}});
  JsonChecker c;
  c.only_keys(json, "",
              {"title", "description", "tags", "prompt", "seed", "generator", "domain", "world", "program",
               "metrics", "trajectory_log", "provenance", "intent", "id", "author", "version", "parent_id",
               "created_at", "content_hash"});
  Card card;
  read_content(c, json, limits, true, card.content);
  if (auto v = c.string(json, "", "id", true); v && !is_card_id(*v))
    c.add("/id", "not a card id (crd_ + 20 base32 characters)");
  else if (v)
    card.id = *v;
  if (auto v = c.string(json, "", "author", true, 1, 200)) card.author = *v;
  if (auto v = c.integer(json, "", "version", true, 1)) card.version = *v;
  if (auto v = c.string(json, "", "parent_id", false)) {
    if (is_card_id(*v))
      card.parent_id = *v;
    else
      c.add("/parent_id", "not a card id");
  }
  if (auto v = c.string(json, "", "created_at", true, 20, 40)) card.created_at = *v;
  auto hash = c.string(json, "", "content_hash", true, 64, 64);
  if (!c.ok()) return tl::unexpected(c.error("the card does not match schemas/card.schema.json"));
  card.content_hash = content_hash(card.content, card.version, card.parent_id);
  if (*hash != card.content_hash) {
    return fail(ErrorCode::kValidation, "content hash mismatch: the card was changed after it was exported",
                {{"/content_hash", "expected " + card.content_hash}});
  }
  return card;
}

std::string new_card_id() {
  return random_id("crd_");
}

bool is_card_id(std::string_view s) {
  return is_random_id(s, "crd_");
}

std::string export_document(const Card& card) {
  return canonical_json(Json{{"socsim_card_export", kExportFormat}, {"card", to_json(card)}}) + "\n";
}

Result<Card> parse_export_document(std::string_view text, const CardLimits& limits) {
  auto doc = parse_json_untrusted(text);
  if (!doc) return tl::unexpected(doc.error());
  if (!doc->is_object() || !doc->contains("socsim_card_export") || !doc->contains("card"))
    return fail(ErrorCode::kValidation,
                "not a socsim card export (expected {\"socsim_card_export\": 1, \"card\": {...}})",
                {{"", "missing socsim_card_export or card"}});
  for (const auto& [key, value] : doc->items())
    if (key != "socsim_card_export" && key != "card")
      return fail(ErrorCode::kValidation, "unknown field in a card export",
                  {{"/" + json_pointer_token(key), "unknown field (expected socsim_card_export and card)"}});
  if ((*doc)["socsim_card_export"] != kExportFormat)
    return fail(ErrorCode::kValidation, "unsupported export format",
                {{"/socsim_card_export", "this build reads format 1"}});
  auto card = parse_card((*doc)["card"], limits);
  if (!card) {
    Error e = card.error();
    e.under("/card");
    return tl::unexpected(e);
  }
  return card;
}

}  // namespace socsim::cards
