#include "core/cards/catalogue.hpp"

#include <cctype>

namespace socsim::cards {
namespace {
using store::Database;

Status insert_card(Database& db, const Card& card) {
  const Json body = to_json(card);
  auto st = db.prepare(
      "INSERT INTO cards(id, title, description, prompt, domain, author, version, parent_id, content_hash,"
      " created_at, tags, body) VALUES (?,?,?,?,?,?,?,?,?,?,?,?)");
  if (!st) return tl::unexpected(st.error());
  st->bind(1, card.id)
      .bind(2, card.content.title)
      .bind(3, card.content.description)
      .bind(4, card.content.prompt)
      .bind(5, card.content.domain)
      .bind(6, card.author)
      .bind(7, card.version)
      .bind(8, card.parent_id)
      .bind(9, card.content_hash)
      .bind(10, card.created_at)
      .bind(11, canonical_json(Json(card.content.tags)))
      .bind(12, canonical_json(body));
  if (auto s = st->run(); !s) return s;
  const std::int64_t seq = db.last_insert_rowid();
  auto tag = db.prepare("INSERT INTO card_tags(tag, card_seq) VALUES (?, ?)");
  if (!tag) return tl::unexpected(tag.error());
  for (const auto& t : card.content.tags) {
    tag->reset();
    tag->bind(1, t).bind(2, seq);
    if (auto s = tag->run(); !s) return s;
  }
  return {};
}

Result<Card> card_from_body(const std::string& body_text) {
  auto j = parse_json_untrusted(body_text);
  if (!j) return fail(ErrorCode::kStore, "stored card is not valid JSON");
  // Stored cards were validated on the way in; only the limits of this build could differ.
  CardLimits unlimited{1u << 30, 1u << 30, 1u << 30, 1u << 20};
  auto c = parse_card(*j, unlimited);
  if (!c) return fail(ErrorCode::kStore, "stored card fails validation: " + c.error().message());
  return c;
}

Result<std::optional<Card>> find(Database& db, const std::string& id) {
  auto st = db.prepare("SELECT body FROM cards WHERE id = ?");
  if (!st) return tl::unexpected(st.error());
  st->bind(1, id);
  auto row = st->step();
  if (!row) return tl::unexpected(row.error());
  if (!*row) return std::optional<Card>{};
  auto c = card_from_body(st->text(0));
  if (!c) return tl::unexpected(c.error());
  return std::optional<Card>(std::move(*c));
}

Error not_found(const std::string& id) {
  return Error(ErrorCode::kNotFound, "no card with id '" + id + "'");
}

constexpr std::string_view kCursorPrefix = "s1.";

std::optional<std::int64_t> decode_cursor(const std::string& c) {
  if (c.rfind(kCursorPrefix, 0) != 0 || c.size() > 24) return std::nullopt;
  std::int64_t v = 0;
  const std::string digits = c.substr(kCursorPrefix.size());
  if (digits.empty()) return std::nullopt;
  for (char ch : digits) {
    if (!std::isdigit(static_cast<unsigned char>(ch))) return std::nullopt;
    v = v * 10 + (ch - '0');
  }
  return v;
}
}  // namespace

std::string fts_query(std::string_view text) {
  std::string out;
  std::string term;
  auto flush = [&] {
    if (term.empty()) return;
    if (!out.empty()) out += ' ';
    out += '"' + term + '"';
    term.clear();
  };
  for (char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    if (std::isalnum(u) || u >= 0x80 || ch == '_')
      term.push_back(ch);
    else
      flush();
  }
  flush();
  return out;
}

// The FTS5 query's words without their quotes, for plainto_tsquery.
std::string plain_words(std::string match) {
  std::erase(match, '"');
  return match;
}

Result<Card> CardCatalogue::create(const CardContent& content, const std::string& author) {
  Card card;
  card.id = new_card_id();
  card.content = content;
  card.author = author;
  card.created_at = utc_now_rfc3339();
  card.content_hash = content_hash(card.content, card.version, card.parent_id);
  return store_.write([&](Database& db) -> Result<Card> {
    if (auto s = insert_card(db, card); !s) return tl::unexpected(s.error());
    return card;
  });
}

Result<Card> CardCatalogue::create_once(const std::string& id, const CardContent& content,
                                        const std::string& author) {
  if (!is_card_id(id)) return fail(ErrorCode::kInternal, "'" + id + "' is not a card id");
  if (auto existing = get(id); existing) return existing;
  Card card;
  card.id = id;
  card.content = content;
  card.author = author;
  card.created_at = utc_now_rfc3339();
  card.content_hash = content_hash(card.content, card.version, card.parent_id);
  return store_.write([&](Database& db) -> Result<Card> {
    if (auto s = insert_card(db, card); !s) return tl::unexpected(s.error());
    return card;
  });
}

Result<Card> CardCatalogue::create_version(const std::string& parent_id, const Json& patch,
                                           const std::string& author) {
  return store_.write([&](Database& db) -> Result<Card> {
    auto parent = find(db, parent_id);
    if (!parent) return tl::unexpected(parent.error());
    if (!*parent) return tl::unexpected(not_found(parent_id));
    auto content = merge_card_content((*parent)->content, patch, limits_);
    if (!content) return tl::unexpected(content.error());
    Card card;
    card.id = new_card_id();
    card.content = std::move(*content);
    card.author = author;
    card.version = (*parent)->version + 1;
    card.parent_id = parent_id;
    card.created_at = utc_now_rfc3339();
    card.content_hash = content_hash(card.content, card.version, card.parent_id);
    if (auto s = insert_card(db, card); !s) return tl::unexpected(s.error());
    return card;
  });
}

Result<Card> CardCatalogue::get(const std::string& id) {
  if (!is_card_id(id)) return tl::unexpected(not_found(id));
  return store_.read([&](Database& db) -> Result<Card> {
    auto c = find(db, id);
    if (!c) return tl::unexpected(c.error());
    if (!*c) return tl::unexpected(not_found(id));
    return std::move(**c);
  });
}

Result<CardPage> CardCatalogue::list(const CardQuery& q) {
  std::optional<std::int64_t> before;
  if (q.cursor) {
    before = decode_cursor(*q.cursor);
    if (!before)
      return fail(ErrorCode::kBadRequest, "the cursor is not one this server issued",
                  {{"", "use next_cursor from a previous page", "cursor", 0, 0}});
  }
  std::string match;
  if (q.text) {
    match = fts_query(*q.text);
    if (match.empty())
      return fail(ErrorCode::kBadRequest, "the search text has no words",
                  {{"", "no searchable words", "q", 0, 0}});
  }
  const bool postgres = store_.dialect() == store::Dialect::kPostgres;
  std::string sql = "SELECT c.seq, c.body FROM cards c WHERE TRUE";
  if (before) sql += " AND c.seq < :before";
  // Every word must match (FTS5's implicit AND; PostgreSQL: the stemmed words ANDed).
  if (q.text && postgres) sql += " AND c.fts @@ plainto_tsquery('english', :match)";
  if (q.text && !postgres) sql += " AND c.seq IN (SELECT rowid FROM cards_fts WHERE cards_fts MATCH :match)";
  if (q.tag) sql += " AND c.seq IN (SELECT card_seq FROM card_tags WHERE tag = :tag)";
  if (q.author) sql += " AND c.author = :author";
  if (q.domain) sql += " AND c.domain = :domain";
  sql += " ORDER BY c.seq DESC LIMIT :limit";
  return store_.read([&](Database& db) -> Result<CardPage> {
    auto st = db.prepare(sql);
    if (!st) return tl::unexpected(st.error());
    int i = 1;
    if (before) st->bind(i++, *before);
    if (q.text) st->bind(i++, postgres ? plain_words(match) : match);
    if (q.tag) st->bind(i++, *q.tag);
    if (q.author) st->bind(i++, *q.author);
    if (q.domain) st->bind(i++, *q.domain);
    st->bind(i, static_cast<std::int64_t>(q.page_size + 1));
    CardPage page;
    std::int64_t last_seq = 0;
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      if (page.items.size() == q.page_size) {
        page.next_cursor = std::string(kCursorPrefix) + std::to_string(last_seq);
        break;
      }
      last_seq = st->int64(0);
      auto c = card_from_body(st->text(1));
      if (!c) return tl::unexpected(c.error());
      page.items.push_back(std::move(*c));
    }
    return page;
  });
}

Status CardCatalogue::remove(const std::string& id, const std::string& author, bool any_author) {
  if (!is_card_id(id)) return tl::unexpected(not_found(id));
  auto r = store_.write([&](Database& db) -> Result<bool> {
    auto st = db.prepare("SELECT author FROM cards WHERE id = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id);
    auto row = st->step();
    if (!row) return tl::unexpected(row.error());
    if (!*row) return tl::unexpected(not_found(id));
    if (!any_author && st->text(0) != author)
      return fail(ErrorCode::kForbidden, "only the card's author ('" + st->text(0) + "') may delete it");
    auto del = db.prepare("DELETE FROM cards WHERE id = ?");
    if (!del) return tl::unexpected(del.error());
    del->bind(1, id);
    if (auto s = del->run(); !s) return tl::unexpected(s.error());
    return true;
  });
  if (!r) return tl::unexpected(r.error());
  return {};
}

Result<std::string> CardCatalogue::export_card(const std::string& id) {
  auto c = get(id);
  if (!c) return tl::unexpected(c.error());
  return export_document(*c);
}

Result<ImportOutcome> CardCatalogue::import_card(std::string_view document, const std::string& importer) {
  auto card = parse_export_document(document, limits_);
  if (!card) return tl::unexpected(card.error());
  card->author = importer;
  return import_card(*card);
}

Result<ImportOutcome> CardCatalogue::import_card(const Card& card) {
  return store_.write([&](Database& db) -> Result<ImportOutcome> {
    auto existing = find(db, card.id);
    if (!existing) return tl::unexpected(existing.error());
    if (*existing) {
      if ((*existing)->content_hash == card.content_hash) return ImportOutcome{std::move(**existing), false};
      return fail(ErrorCode::kConflict,
                  "a different card with id '" + card.id + "' is already in the catalogue",
                  {{"/card/id", "already used by a card with another content hash"}});
    }
    if (auto s = insert_card(db, card); !s) return tl::unexpected(s.error());
    return ImportOutcome{card, true};
  });
}

Result<std::int64_t> CardCatalogue::count() {
  return store_.read([](Database& db) -> Result<std::int64_t> {
    auto st = db.prepare("SELECT COUNT(*) FROM cards");
    if (!st) return tl::unexpected(st.error());
    if (auto r = st->step(); !r) return tl::unexpected(r.error());
    return st->int64(0);
  });
}

}  // namespace socsim::cards
