#pragma once
// The thread-safe face of the database — an SQLite file, or a PostgreSQL server (issue 21): one
// serialised writer connection and a pool of reader connections (SQLite's WAL, PostgreSQL's MVCC
// let them read a consistent snapshot while a write is in progress).
#include <condition_variable>
#include <memory>
#include <mutex>
#include <type_traits>
#include <vector>

#include "core/store/database.hpp"
#include "core/store/migrations.hpp"

namespace socsim::store {

struct StoreOptions {
  int busy_timeout_ms = 5000;
  std::size_t max_readers = 8;
  const std::vector<Migration>* migrations = nullptr;  // nullptr → embedded_migrations()
};

class Store {
 public:
  // Opens (an SQLite file: creating it and its parent directory when missing; a postgresql://
  // URL: connecting) and migrates. Another URL scheme is kValidation naming it.
  static Result<std::unique_ptr<Store>> open(const std::string& path, const StoreOptions& options = {});
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;
  ~Store() = default;

  // Runs fn(Database&) inside a read transaction on a pooled connection; fn returns Result<T>.
  template <class F>
  auto read(F&& fn) -> std::invoke_result_t<F, Database&> {
    Lease lease(*this);
    if (auto s = lease.db().exec("BEGIN"); !s) return tl::unexpected(s.error());
    auto result = fn(lease.db());
    (void)lease.db().exec("COMMIT");
    return result;
  }

  // Runs fn(Database&) inside BEGIN IMMEDIATE … COMMIT on the writer connection. If fn returns an
  // error, or the commit fails, everything fn did is rolled back: the store is as it was.
  template <class F>
  auto write(F&& fn) -> std::invoke_result_t<F, Database&> {
    std::lock_guard<std::mutex> lock(writer_mutex_);
    auto tx = WriteTransaction::begin(*writer_);
    if (!tx) return tl::unexpected(tx.error());
    auto result = fn(*writer_);
    if (!result) return result;
    if (auto s = tx->commit(); !s) return tl::unexpected(s.error());
    return result;
  }

  // The file, or the URL without its password.
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] Dialect dialect() const { return writer_->dialect(); }
  // What open() was given (a URL with its password): for other connections of this process.
  [[nodiscard]] const std::string& target() const { return target_; }
  [[nodiscard]] int schema_version() const { return schema_version_; }
  [[nodiscard]] const MigrationReport& migration_report() const { return report_; }
  // Closes every connection (the last close checkpoints the WAL). Must not race with read/write.
  void close();

 private:
  Store(std::string path, StoreOptions options) : path_(std::move(path)), options_(options) {}

  class Lease {
   public:
    explicit Lease(Store& s);
    ~Lease();
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Database& db() { return *db_; }

   private:
    Store& store_;
    std::unique_ptr<Database> db_;
  };

  std::string path_;
  std::string target_;  // what open() was given (with a URL's password)
  StoreOptions options_;
  std::unique_ptr<Database> writer_;
  std::mutex writer_mutex_;
  std::mutex pool_mutex_;
  std::condition_variable pool_cv_;
  std::vector<std::unique_ptr<Database>> idle_readers_;
  std::size_t open_readers_ = 0;
  int schema_version_ = 0;
  MigrationReport report_;
};

}  // namespace socsim::store
