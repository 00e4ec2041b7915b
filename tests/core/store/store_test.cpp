// The thread-safe store: WAL + busy_timeout + foreign keys, writes that fail change nothing,
// concurrent writers lose nothing and readers never see half a write.
#include "core/store/store.hpp"
#include "tests/core/store/ledger.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "tests/support/temp_dir.hpp"
#include "tests/support/test_database.hpp"

namespace socsim::store {
namespace {

const std::vector<Migration>& ledger_schema() {
  return ledger::schema();
}

using ledger::scalar;
using ledger::transfer;

TEST(Store, OpensWithWalAndForeignKeysAndCreatesTheDirectory) {
  testing::TempDir dir;
  StoreOptions opts;
  opts.migrations = &ledger_schema();
  auto s = Store::open(dir.file("nested/deeper/x.db"), opts);
  ASSERT_TRUE(s) << s.error().message();
  auto mode = (*s)->read([](Database& db) -> Result<std::string> {
    auto st = db.prepare("PRAGMA journal_mode");
    if (!st) return tl::unexpected(st.error());
    (void)st->step();
    return st->text(0);
  });
  EXPECT_EQ(mode.value(), "wal");
  auto fk = (*s)->write([](Database& db) -> Result<bool> {
    auto st = db.prepare("INSERT INTO entry(account, amount) VALUES (99, 1)");
    if (!st) return tl::unexpected(st.error());
    if (auto r = st->run(); !r) return tl::unexpected(r.error());
    return true;
  });
  ASSERT_FALSE(fk) << "a dangling foreign key must be refused";
  EXPECT_EQ(fk.error().code, ErrorCode::kConflict);
}

// On either backend (issue 21): SQLite's file, PostgreSQL's scratch server (skipped without one).
class StoreOnBoth : public ::testing::TestWithParam<testing::Backend> {};

TEST_P(StoreOnBoth, AFailedWriteLeavesTheStoreAsItWasAndReadersCannotWrite) {
  testing::TestDatabase target(GetParam(), false);
  SOCSIM_REQUIRE_DATABASE(target);
  StoreOptions opts;
  opts.migrations = &ledger_schema();
  auto s = Store::open(target.target(), opts);
  ASSERT_TRUE(s) << s.error().message();
  // The first update succeeds inside the transaction, the second violates the CHECK.
  auto r = (*s)->write([](Database& db) -> Result<bool> {
    if (auto t = transfer(db, 150); !t) return tl::unexpected(t.error());
    return true;
  });
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::kConflict) << r.error().message();
  auto total =
      (*s)->read([](Database& db) { return scalar(db, "SELECT balance FROM account WHERE id = 2"); });
  EXPECT_EQ(total.value(), 100) << "half of the failed transfer leaked into the store";
  auto fk = (*s)->write([](Database& d) -> Result<bool> {
    auto st = d.prepare("INSERT INTO entry(account, amount) VALUES (99, 1)");
    if (!st) return tl::unexpected(st.error());
    if (auto x = st->run(); !x) return tl::unexpected(x.error());
    return true;
  });
  ASSERT_FALSE(fk) << "a dangling foreign key must be refused";
  EXPECT_EQ(fk.error().code, ErrorCode::kConflict);
  auto sneaky = (*s)->read([](Database& d) -> Result<bool> {
    if (auto x = d.exec("UPDATE account SET balance = 0"); !x) return tl::unexpected(x.error());
    return true;
  });
  EXPECT_FALSE(sneaky) << "a reader connection wrote";
}

TEST_P(StoreOnBoth, ConcurrentWritersLoseNothingAndReadersSeeWholeTransactions) {
  testing::TestDatabase target(GetParam(), false);
  SOCSIM_REQUIRE_DATABASE(target);
  StoreOptions opts;
  opts.migrations = &ledger_schema();
  auto s = Store::open(target.target(), opts);
  ASSERT_TRUE(s) << s.error().message();
  Store& store = **s;
  std::atomic<bool> done{false};
  std::atomic<int> torn{0};
  std::thread reader([&] {
    while (!done) {
      auto sum = store.read([](Database& db) { return scalar(db, "SELECT SUM(balance) FROM account"); });
      if (!sum || *sum != 200) ++torn;
    }
  });
  std::vector<std::thread> writers;
  for (int w = 0; w < 4; ++w) {
    writers.emplace_back([&] {
      for (int i = 0; i < 25; ++i) {
        auto r = store.write([](Database& db) -> Result<bool> {
          auto st = db.prepare("INSERT INTO entry(account, amount) VALUES (1, 1)");
          if (!st) return tl::unexpected(st.error());
          if (auto x = st->run(); !x) return tl::unexpected(x.error());
          if (auto t = transfer(db, 1); !t) return tl::unexpected(t.error());
          if (auto t = transfer(db, -1); !t) return tl::unexpected(t.error());
          return true;
        });
        EXPECT_TRUE(r);
      }
    });
  }
  for (auto& t : writers) t.join();
  done = true;
  reader.join();
  EXPECT_EQ(torn.load(), 0);
  EXPECT_EQ(store.read([](Database& db) { return scalar(db, "SELECT COUNT(*) FROM entry"); }).value(), 100);
}

INSTANTIATE_TEST_SUITE_P(Backends, StoreOnBoth,
                         ::testing::Values(testing::Backend::kSqlite, testing::Backend::kPostgres),
                         testing::backend_name);

TEST(Store, ASecondProcessStyleConnectionWaitsInsteadOfFailing) {
  testing::TempDir dir;
  StoreOptions opts;
  opts.migrations = &ledger_schema();
  auto s = Store::open(dir.file("x.db"), opts);
  ASSERT_TRUE(s);
  // Another connection (as another socsim worker would hold) keeps a write lock briefly.
  auto other = Database::open(dir.file("x.db"));
  ASSERT_TRUE(other);
  ASSERT_TRUE(other->exec("BEGIN IMMEDIATE; UPDATE account SET balance = balance WHERE id = 1;"));
  std::thread release([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    (void)other->exec("COMMIT");
  });
  auto r = (*s)->write([](Database& db) -> Result<bool> {
    if (auto t = transfer(db, 5); !t) return tl::unexpected(t.error());
    return true;
  });
  release.join();
  EXPECT_TRUE(r) << "busy_timeout should have waited for the other writer";
}

TEST(Store, ReopeningKeepsCommittedData) {
  testing::TempDir dir;
  StoreOptions opts;
  opts.migrations = &ledger_schema();
  {
    auto s = Store::open(dir.file("x.db"), opts);
    ASSERT_TRUE(s);
    ASSERT_TRUE((*s)->write([](Database& db) -> Result<bool> {
      if (auto t = transfer(db, 30); !t) return tl::unexpected(t.error());
      return true;
    }));
    (*s)->close();
  }
  auto s = Store::open(dir.file("x.db"), opts);
  ASSERT_TRUE(s);
  EXPECT_TRUE((*s)->migration_report().applied.empty());
  EXPECT_EQ(
      (*s)->read([](Database& db) { return scalar(db, "SELECT balance FROM account WHERE id = 2"); }).value(),
      130);
}

}  // namespace
}  // namespace socsim::store
