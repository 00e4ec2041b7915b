#pragma once
// One database connection with prepared statements and transactions — an SQLite file (the
// embedded default) or a PostgreSQL server (`postgresql://…`, the shared deployment; issue 21).
// Not thread-safe: each thread uses its own (core/store/store.hpp hands them out). Errors are values.
//
// SQL is written once with SQLite's placeholders (`?`, `?N`, `:name`); on PostgreSQL they become
// `$N`. Statements whose SQL differs between the two ask dialect().
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::store {

enum class Dialect : std::uint8_t { kSqlite, kPostgres };

struct OpenOptions {
  bool read_only = false;
  int busy_timeout_ms = 5000;
  bool create = true;
};

// Whether a --db value names a PostgreSQL server (postgresql:// or postgres://).
bool is_postgres_url(std::string_view target);
// A --db value that is a URL of another scheme (mysql://, http://…): kValidation naming it. Plain
// paths (and file:… names) are SQLite files.
Status check_database_target(std::string_view target);

namespace detail {
class StatementImpl {
 public:
  virtual ~StatementImpl() = default;
  virtual void bind_text(int idx, std::string_view text) = 0;
  virtual void bind_int(int idx, std::int64_t value) = 0;
  virtual void bind_real(int idx, double value) = 0;
  virtual void bind_blob(int idx, std::string_view bytes) = 0;
  virtual void bind_null(int idx) = 0;
  virtual Result<bool> step() = 0;
  virtual void reset() = 0;
  [[nodiscard]] virtual bool is_null(int col) const = 0;
  [[nodiscard]] virtual std::string text(int col) const = 0;
  [[nodiscard]] virtual std::int64_t int64(int col) const = 0;
  [[nodiscard]] virtual double real(int col) const = 0;
  [[nodiscard]] virtual std::string blob(int col) const = 0;
};

class ConnectionImpl {
 public:
  virtual ~ConnectionImpl() = default;
  [[nodiscard]] virtual Dialect dialect() const = 0;
  virtual Status exec(std::string_view sql) = 0;
  virtual Result<std::unique_ptr<StatementImpl>> prepare(std::string_view sql) = 0;
  [[nodiscard]] virtual std::int64_t last_insert_rowid() = 0;
  [[nodiscard]] virtual int changes() const = 0;
  virtual Status begin_write() = 0;
  virtual void close() = 0;
};

std::unique_ptr<ConnectionImpl> open_sqlite(const std::string& path, const OpenOptions& options,
                                            Error& error);
std::unique_ptr<ConnectionImpl> open_postgres(const std::string& url, const OpenOptions& options,
                                              Error& error);
// SQLite parameters (?, ?N, :name, @name) → PostgreSQL's $N, outside quotes and comments.
std::string postgres_placeholders(std::string_view sql);
}  // namespace detail

class Statement {
 public:
  Statement() = default;
  explicit Statement(std::unique_ptr<detail::StatementImpl> impl) : impl_(std::move(impl)) {}

  // Parameters are 1-based, as in SQLite.
  Statement& bind(int idx, std::string_view text) {
    impl_->bind_text(idx, text);
    return *this;
  }
  Statement& bind(int idx, const std::string& text) { return bind(idx, std::string_view(text)); }
  Statement& bind(int idx, const char* text) { return bind(idx, std::string_view(text)); }
  Statement& bind(int idx, std::int64_t value) {
    impl_->bind_int(idx, value);
    return *this;
  }
  Statement& bind(int idx, int value) { return bind(idx, static_cast<std::int64_t>(value)); }
  Statement& bind(int idx, double value) {
    impl_->bind_real(idx, value);
    return *this;
  }
  Statement& bind_blob(int idx, std::string_view bytes) {
    impl_->bind_blob(idx, bytes);
    return *this;
  }
  Statement& bind_null(int idx) {
    impl_->bind_null(idx);
    return *this;
  }
  Statement& bind(int idx, const std::optional<std::string>& text) {
    return text ? bind(idx, std::string_view(*text)) : bind_null(idx);
  }

  // Advances: true when a row is available, false when done.
  Result<bool> step() { return impl_->step(); }
  // Runs to completion (for INSERT/UPDATE/DELETE).
  Status run();
  void reset() { impl_->reset(); }

  [[nodiscard]] bool is_null(int col) const { return impl_->is_null(col); }
  [[nodiscard]] std::string text(int col) const { return impl_->text(col); }
  [[nodiscard]] std::optional<std::string> optional_text(int col) const;
  [[nodiscard]] std::int64_t int64(int col) const { return impl_->int64(col); }
  [[nodiscard]] double real(int col) const { return impl_->real(col); }
  [[nodiscard]] std::string blob(int col) const { return impl_->blob(col); }

 private:
  std::unique_ptr<detail::StatementImpl> impl_;
};

class Database {
 public:
  // `target`: an SQLite file path (":memory:" too), or a postgresql:// URL.
  static Result<Database> open(const std::string& target, const OpenOptions& options = {});
  Database(Database&&) noexcept = default;
  Database& operator=(Database&&) noexcept = default;
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  ~Database();

  [[nodiscard]] Dialect dialect() const { return impl_->dialect(); }
  // Runs one or more statements with no parameters.
  Status exec(std::string_view sql) { return impl_->exec(sql); }
  Result<Statement> prepare(std::string_view sql);
  // The key of the row the last INSERT made (SQLite's rowid; PostgreSQL's lastval()).
  [[nodiscard]] std::int64_t last_insert_rowid() const { return impl_->last_insert_rowid(); }
  // Rows the last INSERT/UPDATE/DELETE changed.
  [[nodiscard]] int changes() const { return impl_->changes(); }
  [[nodiscard]] const std::string& path() const { return path_; }
  // Closes now (SQLite: checkpointing the WAL when this is the last connection).
  void close();

 private:
  friend class WriteTransaction;
  Database(std::unique_ptr<detail::ConnectionImpl> impl, std::string path)
      : impl_(std::move(impl)), path_(std::move(path)) {}
  std::unique_ptr<detail::ConnectionImpl> impl_;
  std::string path_;  // the file, or the URL without its password
};

// A write transaction: SQLite's BEGIN IMMEDIATE (a deferred one that later upgrades to a write
// cannot be rescued by the busy handler); PostgreSQL's BEGIN. Rolls back unless commit() succeeded.
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

}  // namespace socsim::store
