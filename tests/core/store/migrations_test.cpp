// The migration runner: order, idempotence, one transaction per file, refusing newer databases
// and edited migrations.
#include "core/store/migrations.hpp"

#include <gtest/gtest.h>

#include "tests/support/temp_dir.hpp"

namespace socsim::store {
namespace {

std::vector<Migration> two_steps() {
  return {migration_from_file("0001_people.sql", "CREATE TABLE people(name TEXT NOT NULL) STRICT;"),
          migration_from_file("0002_ages.sql", "ALTER TABLE people ADD COLUMN age INTEGER;")};
}

int count_rows(Database& db, const std::string& table) {
  auto st = db.prepare("SELECT COUNT(*) FROM " + table);
  EXPECT_TRUE(st.has_value());
  EXPECT_TRUE(st->step().value());
  return static_cast<int>(st->int64(0));
}

TEST(Migrations, FileNamesGiveVersionAndName) {
  auto m = migration_from_file("0012_building_codes.sql", "x");
  EXPECT_EQ(m.version, 12);
  EXPECT_EQ(m.name, "building_codes");
  EXPECT_EQ(migration_from_file("readme.sql", "").version, 0);
  EXPECT_EQ(migration_from_file("0003_x.txt", "").version, 0);
}

TEST(Migrations, AppliesInOrderOnceAndRecordsVersions) {
  testing::TempDir dir;
  auto db = Database::open(dir.file("a.db"));
  ASSERT_TRUE(db);
  auto r = migrate(*db, two_steps());
  ASSERT_TRUE(r) << r.error().message();
  EXPECT_EQ(r->from_version, 0);
  EXPECT_EQ(r->to_version, 2);
  EXPECT_EQ(r->applied, (std::vector<int>{1, 2}));
  ASSERT_TRUE(db->exec("INSERT INTO people(name, age) VALUES ('Ada', 36)"));
  auto again = migrate(*db, two_steps());
  ASSERT_TRUE(again);
  EXPECT_TRUE(again->applied.empty());
  EXPECT_EQ(count_rows(*db, "people"), 1);
  EXPECT_EQ(schema_version(*db).value(), 2);
}

TEST(Migrations, AFailingMigrationLeavesThePreviousVersion) {
  testing::TempDir dir;
  auto db = Database::open(dir.file("b.db"));
  ASSERT_TRUE(db);
  auto steps = two_steps();
  steps.push_back(migration_from_file("0003_broken.sql",
                                      "CREATE TABLE half(x INTEGER); INSERT INTO nowhere VALUES (1);"));
  auto r = migrate(*db, steps);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().detail.find("migration 3 (broken)"), std::string::npos);
  EXPECT_EQ(schema_version(*db).value(), 2);
  auto st = db->prepare("SELECT COUNT(*) FROM sqlite_master WHERE name = 'half'");
  ASSERT_TRUE(st && st->step().value());
  EXPECT_EQ(st->int64(0), 0) << "the half-applied migration must be rolled back";
}

TEST(Migrations, RefusesADatabaseMigratedByANewerBuild) {
  testing::TempDir dir;
  auto db = Database::open(dir.file("c.db"));
  ASSERT_TRUE(db);
  auto steps = two_steps();
  steps.push_back(migration_from_file("0003_future.sql", "CREATE TABLE future(x INTEGER);"));
  ASSERT_TRUE(migrate(*db, steps));
  auto r = migrate(*db, two_steps());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kStoreSchemaTooNew);
  EXPECT_NE(r.error().detail.find("schema version 3"), std::string::npos);
  EXPECT_NE(r.error().detail.find("up to 2"), std::string::npos);
}

TEST(Migrations, RefusesAnEditedMigration) {
  testing::TempDir dir;
  auto db = Database::open(dir.file("d.db"));
  ASSERT_TRUE(db);
  ASSERT_TRUE(migrate(*db, two_steps()));
  auto edited = two_steps();
  edited[0].sql += " -- edited";
  auto r = migrate(*db, edited);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().detail.find("append-only"), std::string::npos);
}

TEST(Migrations, EmbeddedMigrationsAreNumberedUniquelyAndApplyCleanly) {
  const auto& all = embedded_migrations();
  ASSERT_FALSE(all.empty());
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_GT(all[i].version, 0) << all[i].name;
    if (i > 0) {
      EXPECT_LT(all[i - 1].version, all[i].version) << "duplicate or unsorted migration numbers";
    }
  }
  testing::TempDir dir;
  auto db = Database::open(dir.file("e.db"));
  ASSERT_TRUE(db);
  auto r = migrate(*db, all);
  ASSERT_TRUE(r) << r.error().message();
  EXPECT_EQ(r->to_version, all.back().version);
}

}  // namespace
}  // namespace socsim::store
