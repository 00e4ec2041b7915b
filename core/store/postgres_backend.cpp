// The PostgreSQL connection behind store::Database (issue 21): libpq, text results, parameters
// sent as typed text (bytea as binary). Statements are not prepared on the server: each step()
// of a fresh statement runs PQexecParams once and walks its rows.
#include <libpq-fe.h>

#include <cstdlib>
#include <cstring>

#include "core/store/database.hpp"

namespace socsim::store::detail {
namespace {

constexpr Oid kInt8Oid = 20, kFloat8Oid = 701, kTextOid = 25, kByteaOid = 17;

Error pg_error(const PGresult* res, PGconn* conn, std::string_view context) {
  const char* state = res ? PQresultErrorField(res, PG_DIAG_SQLSTATE) : nullptr;
  std::string message = res ? PQresultErrorMessage(res) : PQerrorMessage(conn);
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  const std::string text = std::string(context) + ": " + message;
  const std::string_view code = state ? state : "";
  // Integrity constraints (23…) and JSON that does not parse in a CHECK (22P02) are the writer's
  // conflicts, as SQLite's constraint errors are; serialisation failures, deadlocks and lock
  // timeouts are "busy", worth a retry.
  if (code.starts_with("23") || code == "22P02") return Error(ErrorCode::kConflict, text);
  if (code == "40001" || code == "40P01" || code == "55P03") return Error(ErrorCode::kStoreBusy, text);
  return Error(ErrorCode::kStore, text);
}

struct ResultDeleter {
  void operator()(PGresult* r) const { PQclear(r); }
};
using ResultPtr = std::unique_ptr<PGresult, ResultDeleter>;

class PgConnection;

class PgStatement final : public StatementImpl {
 public:
  PgStatement(PgConnection& conn, std::string sql) : conn_(conn), sql_(std::move(sql)) {}

  void bind_text(int idx, std::string_view text) override { set(idx, std::string(text), kTextOid, 0); }
  void bind_int(int idx, std::int64_t value) override { set(idx, std::to_string(value), kInt8Oid, 0); }
  void bind_real(int idx, double value) override {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", value);
    set(idx, buf, kFloat8Oid, 0);
  }
  void bind_blob(int idx, std::string_view bytes) override { set(idx, std::string(bytes), kByteaOid, 1); }
  void bind_null(int idx) override {
    grow(idx);
    values_[idx - 1].reset();
    types_[idx - 1] = 0;
    formats_[idx - 1] = 0;
  }
  Result<bool> step() override;
  void reset() override {
    result_.reset();
    row_ = -1;
    values_.clear();
    types_.clear();
    formats_.clear();
  }
  [[nodiscard]] bool is_null(int col) const override { return PQgetisnull(result_.get(), row_, col) != 0; }
  [[nodiscard]] std::string text(int col) const override {
    return std::string(PQgetvalue(result_.get(), row_, col),
                       static_cast<std::size_t>(PQgetlength(result_.get(), row_, col)));
  }
  [[nodiscard]] std::int64_t int64(int col) const override {
    const char* v = PQgetvalue(result_.get(), row_, col);
    if (v[0] == 't' || v[0] == 'f') return v[0] == 't' ? 1 : 0;  // a boolean expression
    return std::strtoll(v, nullptr, 10);
  }
  [[nodiscard]] double real(int col) const override {
    return std::strtod(PQgetvalue(result_.get(), row_, col), nullptr);
  }
  [[nodiscard]] std::string blob(int col) const override {
    if (PQftype(result_.get(), col) != kByteaOid) return text(col);
    std::size_t n = 0;
    unsigned char* raw =
        PQunescapeBytea(reinterpret_cast<const unsigned char*>(PQgetvalue(result_.get(), row_, col)), &n);
    if (!raw) return {};
    std::string out(reinterpret_cast<const char*>(raw), n);
    PQfreemem(raw);
    return out;
  }

 private:
  void grow(int idx) {
    const auto n = static_cast<std::size_t>(idx);
    if (values_.size() < n) {
      values_.resize(n);
      types_.resize(n, 0);
      formats_.resize(n, 0);
    }
  }
  void set(int idx, std::string value, Oid type, int format) {
    grow(idx);
    values_[idx - 1] = std::move(value);
    types_[idx - 1] = type;
    formats_[idx - 1] = format;
  }

  PgConnection& conn_;
  std::string sql_;
  std::vector<std::optional<std::string>> values_;
  std::vector<Oid> types_;
  std::vector<int> formats_;
  ResultPtr result_;
  int row_ = -1;
};

class PgConnection final : public ConnectionImpl {
 public:
  explicit PgConnection(PGconn* conn) : conn_(conn) {}
  ~PgConnection() override { close(); }
  PgConnection(const PgConnection&) = delete;
  PgConnection& operator=(const PgConnection&) = delete;

  [[nodiscard]] Dialect dialect() const override { return Dialect::kPostgres; }
  Status exec(std::string_view sql) override {
    if (!conn_) return fail(ErrorCode::kStore, "the PostgreSQL connection is closed");
    ResultPtr res(PQexec(conn_, std::string(sql).c_str()));
    const ExecStatusType st = res ? PQresultStatus(res.get()) : PGRES_FATAL_ERROR;
    if (st != PGRES_COMMAND_OK && st != PGRES_TUPLES_OK && st != PGRES_EMPTY_QUERY)
      return tl::unexpected(pg_error(res.get(), conn_, "exec"));
    changes_ = std::atoi(PQcmdTuples(res.get()));
    return {};
  }
  Result<std::unique_ptr<StatementImpl>> prepare(std::string_view sql) override {
    if (!conn_) return fail(ErrorCode::kStore, "the PostgreSQL connection is closed");
    return std::unique_ptr<StatementImpl>(std::make_unique<PgStatement>(*this, postgres_placeholders(sql)));
  }
  [[nodiscard]] std::int64_t last_insert_rowid() override {
    ResultPtr res(PQexec(conn_, "SELECT lastval()"));
    if (!res || PQresultStatus(res.get()) != PGRES_TUPLES_OK || PQntuples(res.get()) != 1) return 0;
    return std::strtoll(PQgetvalue(res.get(), 0, 0), nullptr, 10);
  }
  [[nodiscard]] int changes() const override { return changes_; }
  Status begin_write() override { return exec("BEGIN"); }
  void close() override {
    if (conn_) {
      PQfinish(conn_);
      conn_ = nullptr;
    }
  }

  PGconn* handle() const { return conn_; }
  void set_changes(int n) { changes_ = n; }

 private:
  PGconn* conn_;
  int changes_ = 0;
};

Result<bool> PgStatement::step() {
  if (!result_) {
    std::vector<const char*> values(values_.size());
    std::vector<int> lengths(values_.size(), 0);
    for (std::size_t i = 0; i < values_.size(); ++i)
      if (values_[i]) {
        values[i] = values_[i]->data();
        lengths[i] = static_cast<int>(values_[i]->size());
      }
    result_.reset(PQexecParams(conn_.handle(), sql_.c_str(), static_cast<int>(values_.size()), types_.data(),
                               values.data(), lengths.data(), formats_.data(), 0));
    const ExecStatusType st = result_ ? PQresultStatus(result_.get()) : PGRES_FATAL_ERROR;
    if (st != PGRES_COMMAND_OK && st != PGRES_TUPLES_OK) {
      Error e = pg_error(result_.get(), conn_.handle(), "step");
      result_.reset();
      return tl::unexpected(e);
    }
    conn_.set_changes(std::atoi(PQcmdTuples(result_.get())));
    row_ = -1;
  }
  return ++row_ < PQntuples(result_.get());
}

void ignore_notice(void*, const char*) {}

}  // namespace

std::unique_ptr<ConnectionImpl> open_postgres(const std::string& url, const OpenOptions& options,
                                              Error& error) {
  PGconn* conn = PQconnectdb(url.c_str());
  if (!conn || PQstatus(conn) != CONNECTION_OK) {
    std::string message = conn ? PQerrorMessage(conn) : "out of memory";
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    error = Error(ErrorCode::kStore, "cannot connect to PostgreSQL: " + message);
    if (conn) PQfinish(conn);
    return nullptr;
  }
  PQsetNoticeProcessor(conn, ignore_notice, nullptr);
  auto c = std::make_unique<PgConnection>(conn);
  // A writer waits for a row lock at most busy_timeout_ms (then "busy", as SQLite's busy timeout);
  // timestamps in UTC; a reader connection refuses writes.
  std::string settings = "SET lock_timeout = " + std::to_string(options.busy_timeout_ms) +
                         "; SET TIME ZONE 'UTC'; SET client_min_messages = warning;";
  if (options.read_only) settings += " SET default_transaction_read_only = on;";
  if (auto s = c->exec(settings); !s) {
    error = s.error();
    return nullptr;
  }
  return c;
}

}  // namespace socsim::store::detail
