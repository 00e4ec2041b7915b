#include "core/cards/world_store.hpp"

#include "core/common/ids.hpp"
#include "core/common/sha256.hpp"

namespace socsim::cards {
namespace {

using store::Database;

constexpr const char* kColumns =
    "id, name, domain, generator, seed, author, request, scene_graph, world_yaml, compliance, provenance, "
    "content_hash, created_at";
constexpr int kSeqColumn = 13;  // after kColumns in list()

StoredWorld row(store::Statement& st) {
  StoredWorld w;
  w.id = st.text(0);
  w.name = st.text(1);
  w.domain = st.text(2);
  w.generator = st.text(3);
  w.seed = st.int64(4);
  w.author = st.text(5);
  w.request = Json::parse(st.text(6));
  w.scene_graph = Json::parse(st.text(7));
  w.world_yaml = st.text(8);
  w.compliance = Json::parse(st.text(9));
  w.provenance = Json::parse(st.text(10));
  w.content_hash = st.text(11);
  w.created_at = st.text(12);
  return w;
}

}  // namespace

Result<StoredWorld> WorldStore::add(StoredWorld w) {
  w.id = random_id("wld_");
  w.content_hash = sha256_hex(w.world_yaml);
  w.created_at = utc_now_rfc3339();
  auto s = store_.write([&](Database& d) -> Status {
    auto st =
        d.prepare(std::string("INSERT INTO worlds (") + kColumns + ") VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?)");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, w.id)
        .bind(2, w.name)
        .bind(3, w.domain)
        .bind(4, w.generator)
        .bind(5, w.seed)
        .bind(6, w.author);
    st->bind(7, canonical_json(w.request)).bind(8, canonical_json(w.scene_graph)).bind(9, w.world_yaml);
    st->bind(10, canonical_json(w.compliance))
        .bind(11, canonical_json(w.provenance))
        .bind(12, w.content_hash);
    st->bind(13, w.created_at);
    return st->run();
  });
  if (!s) return tl::unexpected(s.error());
  return w;
}

Result<StoredWorld> WorldStore::get(const std::string& id) {
  return store_.read([&](Database& d) -> Result<StoredWorld> {
    auto st = d.prepare(std::string("SELECT ") + kColumns + " FROM worlds WHERE id = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, id);
    auto r = st->step();
    if (!r) return tl::unexpected(r.error());
    if (!*r) return fail(ErrorCode::kNotFound, "no world with id '" + id + "'");
    return row(*st);
  });
}

Result<WorldPage> WorldStore::list(std::size_t limit, std::optional<std::int64_t> before,
                                   const std::optional<std::string>& domain) {
  std::string sql = std::string("SELECT ") + kColumns + ", seq FROM worlds WHERE TRUE";
  if (before) sql += " AND seq < :before";
  if (domain) sql += " AND domain = :domain";
  sql += " ORDER BY seq DESC LIMIT :limit";
  return store_.read([&](Database& d) -> Result<WorldPage> {
    auto st = d.prepare(sql);
    if (!st) return tl::unexpected(st.error());
    int i = 1;
    if (before) st->bind(i++, *before);
    if (domain) st->bind(i++, *domain);
    st->bind(i, static_cast<std::int64_t>(limit) + 1);
    WorldPage page;
    std::int64_t last = 0;
    for (;;) {
      auto r = st->step();
      if (!r) return tl::unexpected(r.error());
      if (!*r) break;
      if (page.items.size() == limit) {
        page.next_before = last;
        break;
      }
      last = st->int64(kSeqColumn);
      page.items.push_back(row(*st));
    }
    return page;
  });
}

}  // namespace socsim::cards
