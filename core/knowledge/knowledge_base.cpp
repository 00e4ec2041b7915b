#include "core/knowledge/knowledge_base.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <map>
#include <set>
#include <unordered_map>

#include <Eigen/Core>

#include "core/common/sha256.hpp"

namespace socsim::knowledge {
namespace {

using store::Database;
using store::Statement;

constexpr std::array<std::string_view, 56> kStopWords = {
    "a",     "an",    "the", "at",  "in",    "on",   "of",   "to",   "for",  "and",   "or",    "with",
    "by",    "is",    "are", "be",  "been",  "as",   "from", "into", "onto", "who",   "that",  "this",
    "these", "those", "it",  "its", "their", "them", "they", "some", "any",  "there", "where", "when",
    "what",  "which", "how", "i",   "we",    "you",  "he",   "she",  "his",  "her",   "our",   "your",
    "my",    "me",    "us",  "do",  "does",  "then", "than", "so"};
constexpr std::size_t kMaxTerms = 32;
constexpr double kRrfK = 60.0;  // reciprocal-rank fusion constant (Cormack et al. 2009)
constexpr std::size_t kEmbedBatch = 64;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

Result<Json> parse_stored(const std::string& text, const std::string& what) {
  Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded()) return fail(ErrorCode::kStore, "stored " + what + " is not valid JSON");
  return j;
}

// Columns: ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints.
constexpr std::string_view kCodeColumns =
    "ref_id, building_type, jurisdiction, title, description, keywords, sources, constraints";
constexpr std::string_view kNodeColumns =
    "name, kind, origin, category, description, when_to_use, example, keywords, aliases, ports";

Result<BuildingCode> code_from_row(const Statement& st) {
  const std::string id = st.text(0);
  auto sources = parse_stored(st.text(6), "sources of building code '" + id + "'");
  if (!sources) return tl::unexpected(sources.error());
  auto constraints = parse_stored(st.text(7), "constraints of building code '" + id + "'");
  if (!constraints) return tl::unexpected(constraints.error());
  Json j{{"ref_id", id},        {"building_type", st.text(1)}, {"jurisdiction", st.text(2)},
         {"title", st.text(3)}, {"description", st.text(4)},   {"keywords", st.text(5)},
         {"sources", *sources}, {"constraints", *constraints}};
  auto code = building_code_from_json(j);
  if (!code)
    return fail(ErrorCode::kStore, "stored building code '" + id + "' is invalid: " + code.error().message());
  return code;
}

Result<BehaviorNode> node_from_row(const Statement& st) {
  const std::string name = st.text(0);
  auto aliases = parse_stored(st.text(8), "aliases of behaviour node '" + name + "'");
  if (!aliases) return tl::unexpected(aliases.error());
  auto ports = parse_stored(st.text(9), "ports of behaviour node '" + name + "'");
  if (!ports) return tl::unexpected(ports.error());
  Json j{{"name", name},           {"kind", st.text(1)},        {"origin", st.text(2)},
         {"category", st.text(3)}, {"description", st.text(4)}, {"when_to_use", st.text(5)},
         {"example", st.text(6)},  {"keywords", st.text(7)},    {"aliases", *aliases},
         {"ports", *ports}};
  auto node = behavior_node_from_json(j);
  if (!node)
    return fail(ErrorCode::kStore,
                "stored behaviour node '" + name + "' is invalid: " + node.error().message());
  return node;
}

template <class T, class RowFn>
Result<std::vector<T>> collect(Database& db, const std::string& sql, const std::vector<std::string>& binds,
                               RowFn row_fn) {
  auto st = db.prepare(sql);
  if (!st) return tl::unexpected(st.error());
  for (std::size_t i = 0; i < binds.size(); ++i) st->bind(static_cast<int>(i + 1), binds[i]);
  std::vector<T> out;
  for (;;) {
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) break;
    auto value = row_fn(*st);
    if (!value) return tl::unexpected(value.error());
    out.push_back(std::move(*value));
  }
  return out;
}

Result<std::vector<BuildingCode>> load_codes(Database& db, std::string_view where,
                                             const std::vector<std::string>& binds) {
  return collect<BuildingCode>(db,
                               "SELECT " + std::string(kCodeColumns) + " FROM building_codes " +
                                   std::string(where) + " ORDER BY ref_id",
                               binds, code_from_row);
}

Result<std::vector<BehaviorNode>> load_nodes(Database& db, std::string_view where,
                                             const std::vector<std::string>& binds) {
  return collect<BehaviorNode>(
      db,
      "SELECT " + std::string(kNodeColumns) + " FROM behavior_nodes " + std::string(where) + " ORDER BY name",
      binds, node_from_row);
}

std::string split_camel_case(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (i > 0 && std::isupper(static_cast<unsigned char>(c)) &&
        !std::isupper(static_cast<unsigned char>(name[i - 1])))
      out.push_back(' ');
    out.push_back(c == '_' ? ' ' : c);
  }
  return out;
}

std::string replace_underscores(std::string s) {
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

// The text that represents an entry for dense retrieval.
std::string embedding_text(const BuildingCode& b) {
  std::string t = b.title + ". " + b.description + " " + b.keywords + ". " + b.building_type + ".";
  for (const auto& c : b.constraints)
    t += " " + replace_underscores(c.name) + (c.applies_to.empty() ? "" : " " + c.applies_to) + ".";
  return t;
}

std::string embedding_text(const BehaviorNode& n) {
  std::string t = split_camel_case(n.name) + " (" + std::string(to_string(n.kind)) + "). " + n.description +
                  " " + n.when_to_use + " " + n.keywords + ".";
  for (const auto& a : n.aliases) t += " " + split_camel_case(a) + ".";
  return t;
}

struct Entry {
  std::string id;
  std::string text;
};

Result<std::vector<Entry>> entries_for_embedding(Database& db, Kind kind) {
  std::vector<Entry> out;
  if (kind == Kind::kBuildingCode) {
    auto codes = load_codes(db, "", {});
    if (!codes) return tl::unexpected(codes.error());
    for (const auto& c : *codes) out.push_back({c.ref_id, embedding_text(c)});
  } else {
    auto nodes = load_nodes(db, "", {});
    if (!nodes) return tl::unexpected(nodes.error());
    for (const auto& n : *nodes) out.push_back({n.name, embedding_text(n)});
  }
  return out;
}

struct Ranked {
  std::string id;
  double score = 0.0;
};

// SQL that is true when the JSON array of strings in `column` holds the parameter `param`.
std::string alias_is(const Database& db, const std::string& column, const std::string& param) {
  if (db.dialect() == store::Dialect::kPostgres)
    return "EXISTS (SELECT 1 FROM jsonb_array_elements_text(" + column + "::jsonb) a WHERE a = " + param +
           ")";
  return "EXISTS (SELECT 1 FROM json_each(" + column + ") WHERE value = " + param + ")";
}

// PostgreSQL's counterpart of FTS5's bm25 ranking: the entries whose weighted tsvector (the
// columns' weights in FTS5's order, migrations/postgresql/0010) matches any of the terms, by
// ts_rank normalised by document length (bm25's length normalisation, roughly), ties by id.
Result<std::vector<Ranked>> ts_ranking(Database& db, Kind kind, const std::string& match, std::size_t limit) {
  // The FTS5 expression "a" OR "b" → the tsquery a | b (terms are letters and digits only).
  std::string terms;
  for (char c : match) {
    if (c == '"') continue;
    terms += c;
  }
  std::string query;
  for (std::size_t at = 0;;) {
    const auto next = terms.find(" OR ", at);
    query += (query.empty() ? "" : " | ") +
             terms.substr(at, next == std::string::npos ? std::string::npos : next - at);
    if (next == std::string::npos) break;
    at = next + 4;
  }
  const std::string sql =
      kind == Kind::kBuildingCode
          ? "SELECT ref_id, ts_rank(fts, q, 1) AS s FROM building_codes, to_tsquery('english', ?1) q "
            "WHERE fts @@ q ORDER BY s DESC, ref_id LIMIT ?2"
          : "SELECT name, ts_rank(fts, q, 1) AS s FROM behavior_nodes, to_tsquery('english', ?1) q "
            "WHERE fts @@ q ORDER BY s DESC, name LIMIT ?2";
  auto st = db.prepare(sql);
  if (!st) return tl::unexpected(st.error());
  st->bind(1, query).bind(2, static_cast<std::int64_t>(limit));
  std::vector<Ranked> out;
  for (;;) {
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) break;
    out.push_back({st->text(0), st->real(1)});
  }
  return out;
}

Result<std::vector<Ranked>> bm25_ranking(Database& db, Kind kind, const std::string& match,
                                         std::size_t limit) {
  if (db.dialect() == store::Dialect::kPostgres) return ts_ranking(db, kind, match, limit);
  const std::string sql =
      kind == Kind::kBuildingCode
          ? "SELECT b.ref_id, bm25(building_codes_fts, 4.0, 1.0, 2.0, 1.0, 0.5, 1.0, 1.5) AS s "
            "FROM building_codes_fts JOIN building_codes b ON b.seq = building_codes_fts.rowid "
            "WHERE building_codes_fts MATCH ?1 ORDER BY s, b.ref_id LIMIT ?2"
          : "SELECT n.name, bm25(behavior_nodes_fts, 4.0, 1.0, 1.0, 2.0, 1.0, 0.5, 0.5) AS s "
            "FROM behavior_nodes_fts JOIN behavior_nodes n ON n.seq = behavior_nodes_fts.rowid "
            "WHERE behavior_nodes_fts MATCH ?1 ORDER BY s, n.name LIMIT ?2";
  auto st = db.prepare(sql);
  if (!st) return tl::unexpected(st.error());
  st->bind(1, match).bind(2, static_cast<std::int64_t>(limit));
  std::vector<Ranked> out;
  for (;;) {
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) break;
    out.push_back({st->text(0), -st->real(1)});  // FTS5's bm25() is lower-is-better
  }
  return out;
}

struct StoredVector {
  std::string id;
  std::string text_hash;
  std::size_t dim = 0;
  std::string blob;
};

Result<std::vector<StoredVector>> stored_vectors(Database& db, Kind kind, const std::string& model) {
  return collect<StoredVector>(
      db,
      "SELECT item_id, text_hash, dim, vector FROM knowledge_embeddings WHERE kind = ?1 AND model = ?2 ORDER "
      "BY item_id",
      {std::string(to_string(kind)), model}, [](const Statement& st) -> Result<StoredVector> {
        return StoredVector{st.text(0), st.text(1), static_cast<std::size_t>(st.int64(2)), st.blob(3)};
      });
}

Result<std::vector<Ranked>> dense_ranking(Database& db, Kind kind, const EmbeddingProvider& provider,
                                          const Embedding& query, std::size_t limit) {
  auto rows = stored_vectors(db, kind, provider.model);
  if (!rows) return tl::unexpected(rows.error());
  const auto dim = static_cast<Eigen::Index>(query.size());
  Eigen::MatrixXf matrix(static_cast<Eigen::Index>(rows->size()), dim);
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const StoredVector& r = (*rows)[i];
    if (r.dim != query.size()) {
      return fail(ErrorCode::kUpstream, "embeddings of model '" + provider.model + "' have dimension " +
                                            std::to_string(r.dim) + " but the query's has " +
                                            std::to_string(query.size()));
    }
    auto v = embedding_from_blob(r.blob, r.dim);
    if (!v) return tl::unexpected(v.error());
    matrix.row(static_cast<Eigen::Index>(i)) = Eigen::Map<const Eigen::RowVectorXf>(v->data(), dim);
  }
  const Eigen::Map<const Eigen::VectorXf> q(query.data(), dim);
  const float qn = q.norm();
  std::vector<Ranked> out;
  if (qn == 0.0f || rows->empty()) return out;
  const Eigen::VectorXf dots = matrix * q;
  const Eigen::VectorXf norms = matrix.rowwise().norm();
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const auto ii = static_cast<Eigen::Index>(i);
    if (norms(ii) == 0.0f) continue;
    const double cosine = static_cast<double>(dots(ii)) / (static_cast<double>(norms(ii)) * qn);
    if (cosine > 0.0) out.push_back({(*rows)[i].id, cosine});
  }
  std::sort(out.begin(), out.end(), [](const Ranked& a, const Ranked& b) {
    return a.score != b.score ? a.score > b.score : a.id < b.id;
  });
  if (out.size() > limit) out.resize(limit);
  return out;
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

bool stricter(const Constraint& a, const std::string& a_ref, const Constraint& b, const std::string& b_ref) {
  switch (a.type) {
    case ConstraintType::kMin:
      if (a.value != b.value) return a.value > b.value;
      break;
    case ConstraintType::kMax:
      if (a.value != b.value) return a.value < b.value;
      break;
    case ConstraintType::kRecommended:
      if (a.confidence != b.confidence) return a.confidence > b.confidence;
      if (a.value != b.value) return a.value > b.value;
      break;
  }
  if (a.confidence != b.confidence) return a.confidence > b.confidence;
  return a_ref < b_ref;
}

bool equals_ignore_case(std::string_view a, std::string_view b) {
  return lower(a) == lower(b);
}

}  // namespace

std::string fts_match_expression(std::string_view text) {
  std::vector<std::string> terms;
  std::set<std::string> seen;
  std::string term;
  auto flush = [&] {
    if (term.empty()) return;
    std::string t = lower(term);
    term.clear();
    if (std::find(kStopWords.begin(), kStopWords.end(), t) != kStopWords.end()) return;
    if (terms.size() < kMaxTerms && seen.insert(t).second) terms.push_back(std::move(t));
  };
  for (char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    if (std::isalnum(u) || u >= 0x80)
      term.push_back(ch);
    else
      flush();
  }
  flush();
  std::string out;
  for (const auto& t : terms) out += (out.empty() ? "\"" : " OR \"") + t + "\"";
  return out;
}

Json to_json(const Provenance& p) {
  return Json{{"kind", to_string(p.kind)}, {"id", p.id},   {"title", p.title}, {"source", p.source},
              {"section", p.section},      {"url", p.url}, {"score", p.score}, {"method", p.method}};
}

Json to_json(const SearchHit& hit) {
  Json entry = std::visit([](const auto& e) { return to_json(e); }, hit.entry);
  return Json{{"provenance", to_json(hit.provenance)}, {"entry", std::move(entry)}};
}

Json to_json(const SearchResult& result) {
  Json hits = Json::array();
  for (const auto& h : result.hits) hits.push_back(to_json(h));
  Json j{{"method", result.method}, {"hits", std::move(hits)}};
  if (result.dense_error) j["dense_error"] = result.dense_error->message();
  return j;
}

Json to_json(const MergedConstraint& c) {
  Json sources = Json::array();
  for (const auto& s : c.sources) sources.push_back(to_json(s));
  return Json{{"constraint", to_json(c.constraint)}, {"ref_id", c.ref_id}, {"building_type", c.building_type},
              {"jurisdiction", c.jurisdiction},      {"title", c.title},   {"sources", std::move(sources)},
              {"also_considered", c.also_considered}};
}

std::string describe(const MergedConstraint& m) {
  const Constraint& c = m.constraint;
  std::string line = replace_underscores(c.name);
  if (!c.applies_to.empty()) line += " (" + c.applies_to + ")";
  line += ": ";
  switch (c.type) {
    case ConstraintType::kMin:
      line += "at least ";
      break;
    case ConstraintType::kMax:
      line += "at most ";
      break;
    case ConstraintType::kRecommended:
      line += "recommended ";
      break;
  }
  line += format_number(c.value) + " " + c.unit;
  if (!c.original.empty()) line += " [" + c.original + "]";
  line += " — " + m.title;
  if (!m.sources.empty()) line += ", " + m.sources.front().section;
  if (c.confidence < 1.0) line += " (confidence " + format_number(c.confidence) + ")";
  return line;
}

KnowledgeBase::KnowledgeBase(store::Store& store, EmbeddingProvider embeddings)
    : store_(store), embeddings_(std::move(embeddings)) {}

void KnowledgeBase::set_embedding_provider(EmbeddingProvider embeddings) {
  embeddings_ = std::move(embeddings);
  for (auto& g : indexed_generation_) g = kNeverIndexed;
}

Result<BuildingCode> KnowledgeBase::building_code(const std::string& ref_id) const {
  auto codes = store_.read([&](Database& db) { return load_codes(db, "WHERE ref_id = ?1", {ref_id}); });
  if (!codes) return tl::unexpected(codes.error());
  if (codes->empty()) return fail(ErrorCode::kNotFound, "no building code with ref_id '" + ref_id + "'");
  return std::move(codes->front());
}

Result<std::vector<BuildingCode>> KnowledgeBase::building_codes(std::string_view building_type) const {
  if (!building_type.empty() && !is_building_type(building_type) && building_type != kGeneralBuildingType) {
    return fail(ErrorCode::kValidation, "unknown building type '" + std::string(building_type) + "'",
                {{"", "must be general or one of the building types", "building_type", 0, 0}});
  }
  return store_.read([&](Database& db) {
    if (building_type.empty()) return load_codes(db, "", {});
    return load_codes(db, "WHERE building_type = ?1", {std::string(building_type)});
  });
}

Result<BehaviorNode> KnowledgeBase::behavior_node(const std::string& name_or_alias) const {
  auto nodes = store_.read([&](Database& db) {
    return load_nodes(db, "WHERE name = ?1 OR " + alias_is(db, "aliases", "?1"), {name_or_alias});
  });
  if (!nodes) return tl::unexpected(nodes.error());
  if (nodes->empty()) return fail(ErrorCode::kNotFound, "no behaviour node named '" + name_or_alias + "'");
  return std::move(nodes->front());
}

Result<std::vector<BehaviorNode>> KnowledgeBase::behavior_nodes() const {
  return store_.read([&](Database& db) { return load_nodes(db, "", {}); });
}

Status KnowledgeBase::upsert(const BuildingCode& code) {
  auto checked = building_code_from_json(to_json(code));
  if (!checked) return tl::unexpected(checked.error());
  Json sources = Json::array();
  for (const auto& s : checked->sources) sources.push_back(to_json(s));
  Json constraints = Json::array();
  for (const auto& c : checked->constraints) constraints.push_back(to_json(c));
  auto written = store_.write([&](Database& db) -> Status {
    auto st = db.prepare(
        "INSERT INTO building_codes (ref_id, building_type, jurisdiction, title, description, keywords, "
        "sources, constraints) "
        "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8) ON CONFLICT(ref_id) DO UPDATE SET building_type = "
        "excluded.building_type, "
        "jurisdiction = excluded.jurisdiction, title = excluded.title, description = excluded.description, "
        "keywords = excluded.keywords, sources = excluded.sources, constraints = excluded.constraints");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, checked->ref_id)
        .bind(2, checked->building_type)
        .bind(3, checked->jurisdiction)
        .bind(4, checked->title);
    st->bind(5, checked->description)
        .bind(6, checked->keywords)
        .bind(7, sources.dump())
        .bind(8, constraints.dump());
    return st->run();
  });
  if (written) ++generation_[static_cast<std::size_t>(Kind::kBuildingCode)];
  return written;
}

Status KnowledgeBase::upsert(const BehaviorNode& node) {
  auto checked = behavior_node_from_json(to_json(node));
  if (!checked) return tl::unexpected(checked.error());
  Json ports = Json::array();
  for (const auto& p : checked->ports) ports.push_back(to_json(p));
  auto written = store_.write([&](Database& db) -> Status {
    // Every tag name (name or alias) must resolve to one node only.
    auto others = db.prepare("SELECT n.name FROM behavior_nodes n WHERE n.name <> ?1 AND (n.name = ?2 OR " +
                             alias_is(db, "n.aliases", "?2") + ")");
    if (!others) return tl::unexpected(others.error());
    std::vector<std::string> tags = checked->aliases;
    tags.push_back(checked->name);
    for (const auto& tag : tags) {
      others->reset();
      others->bind(1, checked->name).bind(2, tag);
      auto row = others->step();
      if (!row) return tl::unexpected(row.error());
      if (*row) {
        return fail(
            ErrorCode::kConflict, "tag '" + tag + "' already names behaviour node '" + others->text(0) + "'",
            {{tag == checked->name ? "/name" : "/aliases", "clashes with node '" + others->text(0) + "'"}});
      }
    }
    auto st = db.prepare(
        "INSERT INTO behavior_nodes (name, kind, origin, category, description, when_to_use, example, "
        "keywords, aliases, ports) "
        "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10) ON CONFLICT(name) DO UPDATE SET kind = "
        "excluded.kind, "
        "origin = excluded.origin, category = excluded.category, description = excluded.description, "
        "when_to_use = excluded.when_to_use, example = excluded.example, keywords = excluded.keywords, "
        "aliases = excluded.aliases, ports = excluded.ports");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, checked->name).bind(2, std::string(to_string(checked->kind))).bind(3, checked->origin);
    st->bind(4, checked->category)
        .bind(5, checked->description)
        .bind(6, checked->when_to_use)
        .bind(7, checked->example);
    st->bind(8, checked->keywords).bind(9, Json(checked->aliases).dump()).bind(10, ports.dump());
    return st->run();
  });
  if (written) ++generation_[static_cast<std::size_t>(Kind::kBehaviorNode)];
  return written;
}

Result<std::size_t> KnowledgeBase::index_embeddings(Kind kind) const {
  if (!embeddings_.available()) return std::size_t{0};
  const std::uint64_t generation = generation_[static_cast<std::size_t>(kind)].load();
  auto entries = store_.read([&](Database& db) { return entries_for_embedding(db, kind); });
  if (!entries) return tl::unexpected(entries.error());
  auto stored = store_.read([&](Database& db) { return stored_vectors(db, kind, embeddings_.model); });
  if (!stored) return tl::unexpected(stored.error());
  std::unordered_map<std::string, std::string> hash_of;
  for (const auto& s : *stored) hash_of[s.id] = s.text_hash;

  std::vector<const Entry*> stale;
  std::vector<std::string> hashes;
  for (const auto& e : *entries) {
    const std::string h = sha256_hex(e.text);
    auto it = hash_of.find(e.id);
    if (it == hash_of.end() || it->second != h) {
      stale.push_back(&e);
      hashes.push_back(h);
    }
  }
  for (std::size_t begin = 0; begin < stale.size(); begin += kEmbedBatch) {
    const std::size_t end = std::min(stale.size(), begin + kEmbedBatch);
    std::vector<std::string> texts;
    for (std::size_t i = begin; i < end; ++i) texts.push_back(stale[i]->text);
    auto vectors = embeddings_.embed(texts);
    if (!vectors) return tl::unexpected(vectors.error());
    if (auto s = check_embeddings(*vectors, texts.size(), embeddings_.model); !s)
      return tl::unexpected(s.error());
    auto written = store_.write([&](Database& db) -> Status {
      auto st = db.prepare(
          "INSERT INTO knowledge_embeddings (kind, item_id, model, text_hash, dim, vector) "
          "VALUES (?1, ?2, ?3, ?4, ?5, ?6) ON CONFLICT (kind, model, item_id) DO UPDATE SET "
          "text_hash = excluded.text_hash, dim = excluded.dim, vector = excluded.vector");
      if (!st) return tl::unexpected(st.error());
      for (std::size_t i = begin; i < end; ++i) {
        const Embedding& v = (*vectors)[i - begin];
        st->reset();
        st->bind(1, std::string(to_string(kind)))
            .bind(2, stale[i]->id)
            .bind(3, embeddings_.model)
            .bind(4, hashes[i]);
        st->bind(5, static_cast<std::int64_t>(v.size())).bind_blob(6, embedding_to_blob(v));
        if (auto s = st->run(); !s) return s;
      }
      return {};
    });
    if (!written) return tl::unexpected(written.error());
  }
  indexed_generation_[static_cast<std::size_t>(kind)] = generation;
  return stale.size();
}

Result<SearchResult> KnowledgeBase::search(std::string_view query, Kind kind, std::size_t k) const {
  if (query.size() > kMaxQueryBytes) {
    return fail(ErrorCode::kBadRequest,
                "the search text is longer than " + std::to_string(kMaxQueryBytes) + " bytes",
                {{"", "too long", "q", 0, 0}});
  }
  if (k == 0 || k > kMaxSearchResults) {
    return fail(ErrorCode::kValidation, "k must be between 1 and " + std::to_string(kMaxSearchResults),
                {{"", "must be between 1 and " + std::to_string(kMaxSearchResults), "k", 0, 0}});
  }
  const std::string match = fts_match_expression(query);
  if (match.empty()) {
    return fail(ErrorCode::kBadRequest, "the search text has no searchable words",
                {{"", "no searchable words", "q", 0, 0}});
  }
  const std::size_t pool = std::max<std::size_t>(50, 4 * k);
  auto lexical = store_.read([&](Database& db) { return bm25_ranking(db, kind, match, pool); });
  if (!lexical) return tl::unexpected(lexical.error());

  SearchResult result;
  std::vector<Ranked> dense;
  bool dense_used = false;
  if (embeddings_.available()) {
    auto run_dense = [&]() -> Result<std::vector<Ranked>> {
      const auto k_index = static_cast<std::size_t>(kind);
      if (indexed_generation_[k_index].load() != generation_[k_index].load()) {
        if (auto indexed = index_embeddings(kind); !indexed) return tl::unexpected(indexed.error());
      }
      auto q = embeddings_.embed({std::string(query)});
      if (!q) return tl::unexpected(q.error());
      if (auto s = check_embeddings(*q, 1, embeddings_.model); !s) return tl::unexpected(s.error());
      return store_.read(
          [&](Database& db) { return dense_ranking(db, kind, embeddings_, q->front(), pool); });
    };
    if (auto d = run_dense()) {
      dense = std::move(*d);
      dense_used = true;
    } else {
      result.dense_error = d.error();
    }
  }

  // Fuse: RRF over the two rankings, or BM25 alone.
  struct Fused {
    double score = 0.0;
    bool lexical = false;
    bool dense = false;
  };
  std::map<std::string, Fused> fused;
  std::vector<Ranked> order;
  if (dense_used) {
    result.method = "bm25+dense";
    for (std::size_t i = 0; i < lexical->size(); ++i) {
      auto& f = fused[(*lexical)[i].id];
      f.score += 1.0 / (kRrfK + static_cast<double>(i + 1));
      f.lexical = true;
    }
    for (std::size_t i = 0; i < dense.size(); ++i) {
      auto& f = fused[dense[i].id];
      f.score += 1.0 / (kRrfK + static_cast<double>(i + 1));
      f.dense = true;
    }
    for (const auto& [id, f] : fused) order.push_back({id, f.score});
    std::sort(order.begin(), order.end(), [](const Ranked& a, const Ranked& b) {
      return a.score != b.score ? a.score > b.score : a.id < b.id;
    });
  } else {
    order = *lexical;
    for (const auto& r : order) fused[r.id].lexical = true;
  }
  if (order.size() > k) order.resize(k);

  for (const Ranked& r : order) {
    const Fused& f = fused[r.id];
    Provenance p;
    p.kind = kind;
    p.id = r.id;
    p.score = r.score;
    p.method = f.lexical && f.dense ? "bm25+dense" : (f.dense ? "dense" : "bm25");
    if (kind == Kind::kBuildingCode) {
      auto code = building_code(r.id);
      if (!code) return tl::unexpected(code.error());
      p.title = code->title;
      p.source = code->sources.front().title;
      p.url = code->sources.front().url;
      for (const auto& s : code->sources) p.section += (p.section.empty() ? "" : "; ") + s.section;
      result.hits.push_back({std::move(p), std::move(*code)});
    } else {
      auto node = behavior_node(r.id);
      if (!node) return tl::unexpected(node.error());
      p.title = node->name;
      p.source = node->origin == "hunavsim" ? "HuNavSim behaviour-tree nodes"
                 : node->origin == "btcpp"  ? "BehaviorTree.CPP v4 built-in nodes"
                                            : "socsim behaviour-node library";
      p.section = node->category;
      result.hits.push_back({std::move(p), std::move(*node)});
    }
  }
  return result;
}

Result<std::vector<MergedConstraint>> KnowledgeBase::constraints_for(std::string_view building_type,
                                                                     std::string_view jurisdiction) const {
  if (!is_building_type(building_type) && building_type != kGeneralBuildingType) {
    std::string allowed;
    for (auto t : building_types()) allowed += (allowed.empty() ? "" : ", ") + std::string(t);
    return fail(ErrorCode::kValidation, "unknown building type '" + std::string(building_type) + "'",
                {{"", "must be one of " + allowed + " or general", "building_type", 0, 0}});
  }
  auto codes = store_.read([&](Database& db) {
    return load_codes(db, "WHERE building_type = ?1 OR (building_type = 'general' AND ?1 <> 'residential')",
                      {std::string(building_type)});
  });
  if (!codes) return tl::unexpected(codes.error());

  struct Candidate {
    const BuildingCode* code;
    const Constraint* constraint;
    bool specific;
  };
  std::map<std::pair<std::string, int>, std::vector<Candidate>> groups;
  for (const auto& code : *codes) {
    if (!jurisdiction.empty() && !equals_ignore_case(code.jurisdiction, jurisdiction)) continue;
    const bool specific = code.building_type == building_type;
    for (const auto& c : code.constraints)
      groups[{c.name, static_cast<int>(c.type)}].push_back({&code, &c, specific});
  }

  std::vector<MergedConstraint> out;
  for (auto& [key, candidates] : groups) {
    const bool any_specific =
        std::any_of(candidates.begin(), candidates.end(), [](const Candidate& c) { return c.specific; });
    const Candidate* best = nullptr;
    for (const auto& c : candidates) {
      if (any_specific && !c.specific) continue;
      if (!best || stricter(*c.constraint, c.code->ref_id, *best->constraint, best->code->ref_id)) best = &c;
    }
    MergedConstraint m;
    m.constraint = *best->constraint;
    m.ref_id = best->code->ref_id;
    m.building_type = best->code->building_type;
    m.jurisdiction = best->code->jurisdiction;
    m.title = best->code->title;
    m.sources = best->code->sources;
    for (const auto& c : candidates) {
      if (&c != best && std::find(m.also_considered.begin(), m.also_considered.end(), c.code->ref_id) ==
                            m.also_considered.end())
        m.also_considered.push_back(c.code->ref_id);
    }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace socsim::knowledge
