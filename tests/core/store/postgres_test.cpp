// The PostgreSQL backend (issue 21): placeholders, URL handling, the migrations of both dialects
// (same curated rows), bytea and doubles, on a real server (SOCSIM_TEST_POSTGRES; skipped without
// one, saying so). The store's guarantees on both backends: store_test.cpp, StoreOnBoth.
#include <gtest/gtest.h>

#include "core/store/migrations.hpp"
#include "core/store/store.hpp"
#include "tests/support/test_database.hpp"

namespace socsim::store {
namespace {

using testing::Backend;
using testing::TestDatabase;

TEST(Database, SqlitePlaceholdersBecomePostgresNumbers) {
  using detail::postgres_placeholders;
  EXPECT_EQ(postgres_placeholders("SELECT a FROM t WHERE b = ? AND c = ?"),
            "SELECT a FROM t WHERE b = $1 AND c = $2");
  EXPECT_EQ(postgres_placeholders("WHERE name = ?1 OR alias = ?1 LIMIT ?2"),
            "WHERE name = $1 OR alias = $1 LIMIT $2");
  EXPECT_EQ(postgres_placeholders("WHERE seq < :before AND x = :tag AND y = :before LIMIT :limit"),
            "WHERE seq < $1 AND x = $2 AND y = $1 LIMIT $3");
  // Not inside literals, quoted names or comments; casts stay casts.
  EXPECT_EQ(postgres_placeholders("SELECT '?', \"a?\", x::jsonb FROM t -- why?\nWHERE y = ?"),
            "SELECT '?', \"a?\", x::jsonb FROM t -- why?\nWHERE y = $1");
  EXPECT_EQ(postgres_placeholders("SELECT 'it''s ?' WHERE a = ?"), "SELECT 'it''s ?' WHERE a = $1");
}

TEST(Database, UrlsOfOtherSchemesAreAClearError) {
  EXPECT_TRUE(is_postgres_url("postgresql://u@h:5432/db"));
  EXPECT_TRUE(is_postgres_url("postgres://h/db"));
  EXPECT_FALSE(is_postgres_url("socsim.db"));
  EXPECT_TRUE(check_database_target("data/socsim.db"));
  EXPECT_TRUE(check_database_target("file:socsim.db"));
  auto bad = check_database_target("mysql://root@localhost/socsim");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().detail.find("mysql://"), std::string::npos) << bad.error().detail;
  auto opened = Store::open("mysql://root@localhost/socsim");
  ASSERT_FALSE(opened);
  EXPECT_EQ(opened.error().code, ErrorCode::kValidation);
  auto refused = Database::open("postgresql://nobody@127.0.0.1:1/none?connect_timeout=2");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().detail.find("cannot connect to PostgreSQL"), std::string::npos)
      << refused.error().detail;
}

TEST(Migrations, TriggerBodiesStayWholeAndOnlyDataStatementsAreShared) {
  const std::string sql =
      "-- a comment; with a semicolon\nCREATE TABLE t(a TEXT);\n"
      "CREATE TRIGGER t_ins AFTER INSERT ON t BEGIN\n  INSERT INTO u VALUES (new.a);\n  DELETE FROM "
      "v;\nEND;\n"
      "INSERT INTO t VALUES ('x;y');\nUPDATE t SET a = 'b';\n";
  const auto statements = split_sql_statements(sql);
  ASSERT_EQ(statements.size(), 4u);
  EXPECT_EQ(statements[1].rfind("CREATE TRIGGER", 0), 0u);
  EXPECT_NE(statements[1].find("END;"), std::string::npos);
  EXPECT_EQ(data_statements(sql), "INSERT INTO t VALUES ('x;y');\nUPDATE t SET a = 'b';\n");
  // Every PostgreSQL migration is the embedded SQLite one's version, in the same order.
  const auto& lite = embedded_migrations(Dialect::kSqlite);
  const auto& pg = embedded_migrations(Dialect::kPostgres);
  ASSERT_EQ(lite.size(), pg.size());
  for (std::size_t i = 0; i < lite.size(); ++i) EXPECT_EQ(lite[i].version, pg[i].version);
}

Result<std::string> rows(Store& store, const std::string& sql) {
  return store.read([&](Database& db) -> Result<std::string> {
    auto st = db.prepare(sql);
    if (!st) return tl::unexpected(st.error());
    std::string out;
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      out += st->text(0) + "\n";
    }
    return out;
  });
}

TEST(PostgresStore, MigratesToTheSameCuratedRowsAsSqliteAndOnlyOnce) {
  TestDatabase pg(Backend::kPostgres, false);
  SOCSIM_REQUIRE_DATABASE(pg);
  TestDatabase lite(Backend::kSqlite);
  auto p = Store::open(pg.target());
  ASSERT_TRUE(p) << p.error().message();
  auto s = Store::open(lite.target());
  ASSERT_TRUE(s) << s.error().message();
  EXPECT_EQ((*p)->schema_version(), (*s)->schema_version());
  EXPECT_EQ((*p)->migration_report().applied, (*s)->migration_report().applied);
  EXPECT_EQ((*p)->dialect(), Dialect::kPostgres);
  for (const char* sql :
       {"SELECT ref_id || ' ' || building_type || ' ' || constraints FROM building_codes ORDER BY ref_id",
        "SELECT name || ' ' || kind || ' ' || aliases || ' ' || ports FROM behavior_nodes ORDER BY name",
        "SELECT id || ' ' || body FROM household_personas ORDER BY id",
        "SELECT name || ' ' || role || ' ' || body FROM household_activities ORDER BY name",
        "SELECT type || ' ' || body FROM household_receptacle_types ORDER BY type",
        "SELECT type || ' ' || kind FROM household_object_types ORDER BY type",
        "SELECT room_type || ' ' || body FROM household_room_programs ORDER BY room_type",
        "SELECT kind || ' ' || position || ' ' || name || ' ' || body FROM household_persona_parts "
        "ORDER BY kind, position, name"}) {
    auto a = rows(**p, sql), b = rows(**s, sql);
    ASSERT_TRUE(a) << a.error().message();
    ASSERT_TRUE(b) << b.error().message();
    EXPECT_FALSE(b->empty()) << sql;
    EXPECT_EQ(*a, *b) << sql;
  }
  (*p)->close();
  auto again = Store::open(pg.target());
  ASSERT_TRUE(again) << again.error().message();
  EXPECT_TRUE((*again)->migration_report().applied.empty());
}

TEST(PostgresStore, BlobsAndRealsRoundTripExactly) {
  TestDatabase pg(Backend::kPostgres);
  SOCSIM_REQUIRE_DATABASE(pg);
  auto s = Store::open(pg.target());
  ASSERT_TRUE(s) << s.error().message();
  std::string bytes;
  for (int i = 0; i < 256; ++i) bytes += static_cast<char>(i);
  bytes += std::string("\0\\x00'", 6);
  const double tricky = 0.1 + 0.2;
  auto w = (*s)->write([&](Database& db) -> Result<bool> {
    auto st = db.prepare(
        "INSERT INTO trajectory_logs(sha256, format, frames, agents, frame_interval, raw_bytes, data, "
        "created_at) "
        "VALUES (?, 'f', 1, 2, ?, 3, ?, 'now')");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, std::string(64, 'a')).bind(2, tricky).bind_blob(3, bytes);
    if (auto x = st->run(); !x) return tl::unexpected(x.error());
    return true;
  });
  ASSERT_TRUE(w) << w.error().message();
  auto back = (*s)->read([](Database& db) -> Result<std::pair<std::string, double>> {
    auto st = db.prepare("SELECT data, frame_interval FROM trajectory_logs");
    if (!st) return tl::unexpected(st.error());
    if (auto r = st->step(); !r || !*r) return fail(ErrorCode::kStore, "no row");
    return std::pair{st->blob(0), st->real(1)};
  });
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(back->first, bytes);
  EXPECT_EQ(back->second, tricky);
}

}  // namespace
}  // namespace socsim::store
