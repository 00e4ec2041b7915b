// The SQLite connection behind store::Database: WAL, a busy timeout, foreign keys.
#include <sqlite3.h>

#include "core/store/database.hpp"

namespace socsim::store::detail {
namespace {

// Maps a SQLite result code to the error table (SQLITE_BUSY → kStoreBusy, constraint → kConflict).
Error sqlite_error(sqlite3* db, int rc, std::string_view context) {
  const int primary = rc & 0xff;
  std::string msg = std::string(context) + ": " + (db ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
  switch (primary) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return Error(ErrorCode::kStoreBusy, msg);
    case SQLITE_CONSTRAINT:
      return Error(ErrorCode::kConflict, msg);
    default:
      return Error(ErrorCode::kStore, msg);
  }
}

class SqliteStatement final : public StatementImpl {
 public:
  SqliteStatement(sqlite3* db, sqlite3_stmt* stmt) : db_(db), stmt_(stmt) {}
  ~SqliteStatement() override { sqlite3_finalize(stmt_); }
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  void bind_text(int idx, std::string_view text) override {
    sqlite3_bind_text64(stmt_, idx, text.data(), text.size(), SQLITE_TRANSIENT, SQLITE_UTF8);
  }
  void bind_int(int idx, std::int64_t value) override { sqlite3_bind_int64(stmt_, idx, value); }
  void bind_real(int idx, double value) override { sqlite3_bind_double(stmt_, idx, value); }
  void bind_blob(int idx, std::string_view bytes) override {
    sqlite3_bind_blob64(stmt_, idx, bytes.data(), bytes.size(), SQLITE_TRANSIENT);
  }
  void bind_null(int idx) override { sqlite3_bind_null(stmt_, idx); }
  Result<bool> step() override {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    return tl::unexpected(sqlite_error(db_, rc, "step"));
  }
  void reset() override {
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
  }
  [[nodiscard]] bool is_null(int col) const override {
    return sqlite3_column_type(stmt_, col) == SQLITE_NULL;
  }
  [[nodiscard]] std::string text(int col) const override {
    const auto* p = sqlite3_column_text(stmt_, col);
    const int n = sqlite3_column_bytes(stmt_, col);
    return p ? std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(n)) : std::string();
  }
  [[nodiscard]] std::int64_t int64(int col) const override { return sqlite3_column_int64(stmt_, col); }
  [[nodiscard]] double real(int col) const override { return sqlite3_column_double(stmt_, col); }
  [[nodiscard]] std::string blob(int col) const override {
    const void* p = sqlite3_column_blob(stmt_, col);
    const int n = sqlite3_column_bytes(stmt_, col);
    return p ? std::string(static_cast<const char*>(p), static_cast<std::size_t>(n)) : std::string();
  }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_;
};

class SqliteConnection final : public ConnectionImpl {
 public:
  explicit SqliteConnection(sqlite3* db) : db_(db) {}
  ~SqliteConnection() override { close(); }
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  [[nodiscard]] Dialect dialect() const override { return Dialect::kSqlite; }
  Status exec(std::string_view sql) override {
    std::string owned(sql);
    char* err = nullptr;
    const int rc = sqlite3_exec(db_, owned.c_str(), nullptr, nullptr, &err);
    if (rc == SQLITE_OK) return {};
    Error e = sqlite_error(db_, rc, "exec");
    if (err) {
      e.detail = std::string("exec: ") + err;
      sqlite3_free(err);
    }
    return tl::unexpected(e);
  }
  Result<std::unique_ptr<StatementImpl>> prepare(std::string_view sql) override {
    sqlite3_stmt* stmt = nullptr;
    const int rc = sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt, nullptr);
    if (rc != SQLITE_OK) return tl::unexpected(sqlite_error(db_, rc, "prepare"));
    return std::unique_ptr<StatementImpl>(std::make_unique<SqliteStatement>(db_, stmt));
  }
  [[nodiscard]] std::int64_t last_insert_rowid() override { return sqlite3_last_insert_rowid(db_); }
  [[nodiscard]] int changes() const override { return sqlite3_changes(db_); }
  Status begin_write() override { return exec("BEGIN IMMEDIATE"); }
  void close() override {
    if (db_) {
      sqlite3_close_v2(db_);
      db_ = nullptr;
    }
  }

 private:
  sqlite3* db_;
};

}  // namespace

std::unique_ptr<ConnectionImpl> open_sqlite(const std::string& path, const OpenOptions& options,
                                            Error& error) {
  sqlite3* db = nullptr;
  int flags = SQLITE_OPEN_NOMUTEX | (options.read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE);
  if (!options.read_only && options.create) flags |= SQLITE_OPEN_CREATE;
  const int rc = sqlite3_open_v2(path.c_str(), &db, flags, nullptr);
  if (rc != SQLITE_OK) {
    error = sqlite_error(db, rc, "cannot open database '" + path + "'");
    sqlite3_close(db);
    return nullptr;
  }
  auto conn = std::make_unique<SqliteConnection>(db);
  sqlite3_busy_timeout(db, options.busy_timeout_ms);
  sqlite3_extended_result_codes(db, 1);
  // WAL lets readers proceed during a write; synchronous=NORMAL is durable across process
  // crashes in WAL mode (a power loss may drop the last commits, never corrupt).
  std::string pragmas = "PRAGMA foreign_keys=ON;";
  if (!options.read_only) pragmas += "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;";
  if (auto s = conn->exec(pragmas); !s) {
    error = s.error();
    return nullptr;
  }
  return conn;
}

}  // namespace socsim::store::detail
