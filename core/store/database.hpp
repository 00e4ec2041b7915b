#pragma once
// One SQLite connection with prepared statements and transactions. Not thread-safe: each
// thread uses its own (core/store/store.hpp hands them out). Errors are values.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace socsim::store {

struct OpenOptions {
  bool read_only = false;
  int busy_timeout_ms = 5000;
  bool create = true;
};

class Statement {
 public:
  Statement() = default;
  Statement(sqlite3* db, sqlite3_stmt* stmt) : db_(db), stmt_(stmt) {}
  Statement(Statement&& o) noexcept : db_(o.db_), stmt_(o.stmt_) { o.stmt_ = nullptr; }
  Statement& operator=(Statement&& o) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  ~Statement();

  // Parameters are 1-based, as in SQLite.
  Statement& bind(int idx, std::string_view text);
  Statement& bind(int idx, const std::string& text) { return bind(idx, std::string_view(text)); }
  Statement& bind(int idx, const char* text) { return bind(idx, std::string_view(text)); }
  Statement& bind(int idx, std::int64_t value);
  Statement& bind(int idx, int value) { return bind(idx, static_cast<std::int64_t>(value)); }
  Statement& bind(int idx, double value);
  Statement& bind_blob(int idx, std::string_view bytes);
  Statement& bind_null(int idx);
  Statement& bind(int idx, const std::optional<std::string>& text);

  // Advances: true when a row is available, false when done.
  Result<bool> step();
  // Runs to completion (for INSERT/UPDATE/DELETE).
  Status run();
  void reset();

  [[nodiscard]] bool is_null(int col) const;
  [[nodiscard]] std::string text(int col) const;
  [[nodiscard]] std::optional<std::string> optional_text(int col) const;
  [[nodiscard]] std::int64_t int64(int col) const;
  [[nodiscard]] double real(int col) const;
  [[nodiscard]] std::string blob(int col) const;

 private:
  sqlite3* db_ = nullptr;
  sqlite3_stmt* stmt_ = nullptr;
};

class Database {
 public:
  static Result<Database> open(const std::string& path, const OpenOptions& options = {});
  Database(Database&& o) noexcept : db_(o.db_), path_(std::move(o.path_)) { o.db_ = nullptr; }
  Database& operator=(Database&& o) noexcept;
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  ~Database();

  // Runs one or more statements with no parameters.
  Status exec(std::string_view sql);
  Result<Statement> prepare(std::string_view sql);
  [[nodiscard]] std::int64_t last_insert_rowid() const;
  [[nodiscard]] int changes() const;
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] sqlite3* handle() const { return db_; }
  // Closes now (checkpointing the WAL when this is the last connection).
  void close();

 private:
  Database(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}
  sqlite3* db_ = nullptr;
  std::string path_;
};

// A write transaction taken with BEGIN IMMEDIATE (a deferred one that later upgrades to a write
// cannot be rescued by the busy handler). Rolls back unless commit() succeeded.
class WriteTransaction {
 public:
  static Result<WriteTransaction> begin(Database& db);
  WriteTransaction(WriteTransaction&& o) noexcept : db_(o.db_) { o.db_ = nullptr; }
  WriteTransaction(const WriteTransaction&) = delete;
  WriteTransaction& operator=(const WriteTransaction&) = delete;
  WriteTransaction& operator=(WriteTransaction&&) = delete;
  ~WriteTransaction();
  Status commit();

 private:
  explicit WriteTransaction(Database* db) : db_(db) {}
  Database* db_;
};

// Maps a SQLite result code to the error table (SQLITE_BUSY → kStoreBusy, constraint → kConflict).
Error sqlite_error(sqlite3* db, int rc, std::string_view context);

}  // namespace socsim::store
