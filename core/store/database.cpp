#include "core/store/database.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace socsim::store {

bool is_postgres_url(std::string_view target) {
  return target.starts_with("postgresql://") || target.starts_with("postgres://");
}

Status check_database_target(std::string_view target) {
  if (is_postgres_url(target)) return {};
  const auto colon = target.find("://");
  if (colon == std::string_view::npos || colon == 0) return {};
  for (char c : target.substr(0, colon))
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return {};
  return fail(ErrorCode::kValidation,
              "--db '" + std::string(target.substr(0, colon + 3)) +
                  "…' is a URL socsim cannot open: give an SQLite file path or a postgresql:// URL",
              {FieldError::query("db", "an SQLite file path or postgresql://user@host:port/database")});
}

namespace detail {

std::string postgres_placeholders(std::string_view sql) {
  std::string out;
  out.reserve(sql.size() + 8);
  std::vector<std::pair<std::string, int>> names;  // named parameters and their numbers
  int next = 0;
  const auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t i = 0; i < sql.size();) {
    const char c = sql[i];
    if (c == '\'' || c == '"') {  // a literal or a quoted identifier ('' and "" escape themselves)
      const std::size_t start = i++;
      while (i < sql.size()) {
        if (sql[i] != c) {
          ++i;
        } else if (i + 1 < sql.size() && sql[i + 1] == c) {
          i += 2;
        } else {
          ++i;
          break;
        }
      }
      out.append(sql.substr(start, i - start));
    } else if (c == '-' && i + 1 < sql.size() && sql[i + 1] == '-') {
      const std::size_t end = sql.find('\n', i);
      const std::size_t stop = end == std::string_view::npos ? sql.size() : end;
      out.append(sql.substr(i, stop - i));
      i = stop;
    } else if (c == '?') {
      std::size_t j = i + 1;
      while (j < sql.size() && std::isdigit(static_cast<unsigned char>(sql[j]))) ++j;
      if (j > i + 1) {
        const int n = std::stoi(std::string(sql.substr(i + 1, j - i - 1)));
        next = std::max(next, n);
        out += "$" + std::to_string(n);
      } else {
        out += "$" + std::to_string(++next);
      }
      i = j;
    } else if ((c == ':' || c == '@') && i + 1 < sql.size() && is_word(sql[i + 1]) &&
               !std::isdigit(static_cast<unsigned char>(sql[i + 1])) && (i == 0 || sql[i - 1] != ':') &&
               !(c == ':' && i + 1 < sql.size() && sql[i + 1] == ':')) {
      std::size_t j = i + 1;
      while (j < sql.size() && is_word(sql[j])) ++j;
      const std::string name(sql.substr(i + 1, j - i - 1));
      // SQLite numbers a repeated name once: the number of its first appearance.
      auto it = std::find_if(names.begin(), names.end(), [&](const auto& n) { return n.first == name; });
      const int number = it != names.end() ? it->second : ++next;
      if (it == names.end()) names.emplace_back(name, number);
      out += "$" + std::to_string(number);
      i = j;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

}  // namespace detail

Status Statement::run() {
  for (;;) {
    auto r = step();
    if (!r) return tl::unexpected(r.error());
    if (!*r) return {};
  }
}

std::optional<std::string> Statement::optional_text(int col) const {
  if (is_null(col)) return std::nullopt;
  return text(col);
}

Result<Database> Database::open(const std::string& target, const OpenOptions& options) {
  Error error;
  std::unique_ptr<detail::ConnectionImpl> impl;
  std::string shown = target;
  if (is_postgres_url(target)) {
    impl = detail::open_postgres(target, options, error);
    // The URL as logs and errors show it: without a password.
    const auto at = shown.find('@'), scheme = shown.find("://");
    if (at != std::string::npos && scheme != std::string::npos) {
      const auto colon = shown.find(':', scheme + 3);
      if (colon != std::string::npos && colon < at) shown.replace(colon, at - colon, ":***");
    }
  } else {
    if (auto ok = check_database_target(target); !ok) return tl::unexpected(ok.error());
    impl = detail::open_sqlite(target, options, error);
  }
  if (!impl) return tl::unexpected(error);
  return Database(std::move(impl), shown);
}

Database::~Database() {
  close();
}

void Database::close() {
  if (impl_) impl_->close();
}

Result<Statement> Database::prepare(std::string_view sql) {
  auto st = impl_->prepare(sql);
  if (!st) return tl::unexpected(st.error());
  return Statement(std::move(*st));
}

Result<WriteTransaction> WriteTransaction::begin(Database& db) {
  if (auto s = db.impl_->begin_write(); !s) return tl::unexpected(s.error());
  return WriteTransaction(&db);
}

WriteTransaction::~WriteTransaction() {
  if (db_) (void)db_->exec("ROLLBACK");
}

Status WriteTransaction::commit() {
  if (!db_) return fail(ErrorCode::kInternal, "transaction already finished");
  auto s = db_->exec("COMMIT");
  if (s) db_ = nullptr;  // on failure the destructor rolls back
  return s;
}

}  // namespace socsim::store
