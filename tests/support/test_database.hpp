#pragma once
// A fresh database for one test, on either backend (issue 21): an SQLite file in a temp folder, or
// a new database on the scratch PostgreSQL server named by SOCSIM_TEST_POSTGRES (a URL; the
// README's test command starts one, tests/pg/postgres.sh), dropped when the test ends. Without
// SOCSIM_TEST_POSTGRES the PostgreSQL variant is unavailable and tests skip saying so.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <mutex>
#include <string>

#include <unistd.h>

#include "core/store/store.hpp"
#include "tests/support/temp_dir.hpp"

namespace socsim::testing {

enum class Backend { kSqlite, kPostgres };

inline std::string backend_name(const ::testing::TestParamInfo<Backend>& info) {
  return info.param == Backend::kSqlite ? "Sqlite" : "Postgres";
}

inline const char* postgres_admin_url() {
  const char* url = std::getenv("SOCSIM_TEST_POSTGRES");
  return url && *url ? url : nullptr;
}

// The URL of `admin` with its database name replaced.
inline std::string with_database(const std::string& admin, const std::string& name) {
  const auto slash = admin.find('/', admin.find("://") + 3);
  const auto query = admin.find('?');
  std::string out = admin.substr(0, slash == std::string::npos ? admin.size() : slash) + "/" + name;
  if (query != std::string::npos) out += admin.substr(query);
  return out;
}

class TestDatabase {
 public:
  // migrated: PostgreSQL databases are copied from a template that has every embedded migration
  // (applying them takes a second; copying, a few milliseconds); false gives an empty database.
  explicit TestDatabase(Backend backend, bool migrated = true) : backend_(backend) {
    if (backend == Backend::kSqlite) {
      target_ = dir_.file("socsim.db");
      return;
    }
    const char* admin = postgres_admin_url();
    if (!admin) {
      skip_ = "SOCSIM_TEST_POSTGRES is not set (tests/run-all.sh starts a scratch PostgreSQL server)";
      return;
    }
    static std::atomic<int> counter{0};
    name_ = "socsim_t" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
    std::string sql = "CREATE DATABASE " + name_;
    if (migrated) {
      const std::string tpl = migrated_template(admin);
      if (tpl.empty()) {
        skip_ = "could not make the migrated template database";
        return;
      }
      sql += " TEMPLATE " + tpl;
    }
    auto db = store::Database::open(admin);
    if (!db || !db->exec(sql)) {
      skip_ = "cannot create a database on " + std::string(admin) + (db ? "" : ": " + db.error().message());
      return;
    }
    target_ = with_database(admin, name_);
  }
  ~TestDatabase() {
    if (name_.empty() || target_.empty()) return;
    if (auto db = store::Database::open(postgres_admin_url()))
      (void)db->exec("DROP DATABASE IF EXISTS " + name_ + " WITH (FORCE)");
  }
  TestDatabase(const TestDatabase&) = delete;
  TestDatabase& operator=(const TestDatabase&) = delete;

  // Empty when the backend is not available here (then skip_reason() says why).
  [[nodiscard]] const std::string& target() const { return target_; }
  [[nodiscard]] const std::string& skip_reason() const { return skip_; }
  [[nodiscard]] Backend backend() const { return backend_; }

 private:
  static std::string migrated_template(const std::string& admin) {
    static std::once_flag once;
    static std::string name;
    std::call_once(once, [&] {
      const std::string tpl = "socsim_tpl" + std::to_string(::getpid());
      auto db = store::Database::open(admin);
      if (!db || !db->exec("DROP DATABASE IF EXISTS " + tpl + " WITH (FORCE)") ||
          !db->exec("CREATE DATABASE " + tpl))
        return;
      {
        auto store = store::Store::open(with_database(admin, tpl));
        if (!store) return;
        (*store)->close();
      }
      name = tpl;
    });
    return name;
  }

  Backend backend_;
  TempDir dir_;
  std::string target_, name_, skip_;
};

// In a test body: skips (with the reason) when the backend is not available.
#define SOCSIM_REQUIRE_DATABASE(db) \
  if ((db).target().empty()) GTEST_SKIP() << (db).skip_reason()

}  // namespace socsim::testing
