#include "core/store/store.hpp"

#include <filesystem>
#include <stdexcept>

namespace socsim::store {

Result<std::unique_ptr<Store>> Store::open(const std::string& path, const StoreOptions& options) {
  if (auto ok = check_database_target(path); !ok) return tl::unexpected(ok.error());
  std::unique_ptr<Store> s(new Store(path, options));
  if (path != ":memory:" && !path.empty() && !is_postgres_url(path)) {
    std::error_code ec;
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    if (ec)
      return fail(ErrorCode::kStore, "cannot create directory '" + parent.string() + "': " + ec.message());
  }
  auto db = Database::open(path, {false, options.busy_timeout_ms, true});
  if (!db) return tl::unexpected(db.error());
  s->writer_ = std::make_unique<Database>(std::move(*db));
  s->path_ = s->writer_->path();  // a URL without its password
  s->target_ = path;
  const auto& migrations =
      options.migrations ? *options.migrations : embedded_migrations(s->writer_->dialect());
  auto report = migrate(*s->writer_, migrations);
  if (!report) return tl::unexpected(report.error());
  s->report_ = *report;
  s->schema_version_ = report->to_version;
  return s;
}

Store::Lease::Lease(Store& s) : store_(s) {
  std::unique_lock<std::mutex> lock(s.pool_mutex_);
  s.pool_cv_.wait(lock, [&] { return !s.idle_readers_.empty() || s.open_readers_ < s.options_.max_readers; });
  if (!s.idle_readers_.empty()) {
    db_ = std::move(s.idle_readers_.back());
    s.idle_readers_.pop_back();
    return;
  }
  ++s.open_readers_;
  lock.unlock();
  const bool postgres = is_postgres_url(s.target_);
  auto db = Database::open(s.target_, {postgres, s.options_.busy_timeout_ms, false});
  if (!db) {
    std::lock_guard<std::mutex> relock(s.pool_mutex_);
    --s.open_readers_;
    s.pool_cv_.notify_one();
    throw std::runtime_error("store: cannot open a reader connection: " + db.error().message());
  }
  if (!postgres) (void)db->exec("PRAGMA query_only=ON");
  db_ = std::make_unique<Database>(std::move(*db));
}

Store::Lease::~Lease() {
  std::lock_guard<std::mutex> lock(store_.pool_mutex_);
  store_.idle_readers_.push_back(std::move(db_));
  store_.pool_cv_.notify_one();
}

void Store::close() {
  {
    std::lock_guard<std::mutex> lock(pool_mutex_);
    idle_readers_.clear();
    open_readers_ = 0;
  }
  std::lock_guard<std::mutex> lock(writer_mutex_);
  if (writer_) writer_->close();
}

}  // namespace socsim::store
