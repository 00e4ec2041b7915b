#include "core/store/migrations.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <string_view>

#include "core/common/sha256.hpp"

namespace socsim::store {

const std::map<std::string, std::string>& embedded_migration_files();  // generated from migrations/*.sql

namespace {

constexpr std::string_view kPostgresDir = "postgresql/";

std::string upper_word(std::string_view s, std::size_t at) {
  std::string w;
  while (at < s.size() && std::isalpha(static_cast<unsigned char>(s[at])))
    w += static_cast<char>(std::toupper(static_cast<unsigned char>(s[at++])));
  return w;
}

std::size_t skip_space_and_comments(std::string_view s, std::size_t i) {
  for (;;) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i + 1 < s.size() && s[i] == '-' && s[i + 1] == '-') {
      const auto end = s.find('\n', i);
      i = end == std::string_view::npos ? s.size() : end + 1;
    } else {
      return i;
    }
  }
}

std::vector<Migration> build(Dialect dialect) {
  const auto& files = embedded_migration_files();
  std::vector<Migration> v;
  for (const auto& [name, sql] : files) {
    if (name.find('/') != std::string::npos) continue;
    if (dialect == Dialect::kPostgres) {
      const auto own = files.find(std::string(kPostgresDir) + name);
      if (own != files.end()) {
        // "shared-data-skip: TABLE" in the PostgreSQL file leaves out the shared data statements
        // that write TABLE (a table only SQLite's form of the change has).
        std::vector<std::string> skip;
        const std::string marker = "shared-data-skip:";
        for (auto at = own->second.find(marker); at != std::string::npos;
             at = own->second.find(marker, at + 1)) {
          std::size_t i = at + marker.size();
          while (i < own->second.size() && own->second[i] == ' ') ++i;
          std::size_t j = i;
          while (j < own->second.size() &&
                 (std::isalnum(static_cast<unsigned char>(own->second[j])) || own->second[j] == '_'))
            ++j;
          skip.push_back(own->second.substr(i, j - i));
        }
        std::string data;
        for (const std::string& st : split_sql_statements(data_statements(sql))) {
          const bool skipped = std::any_of(skip.begin(), skip.end(), [&](const std::string& t) {
            return !t.empty() && (st.find("INTO " + t + " ") != std::string::npos ||
                                  st.find("INTO " + t + "(") != std::string::npos ||
                                  st.find("UPDATE " + t + " ") != std::string::npos);
          });
          if (!skipped) data += st + "\n";
        }
        v.push_back(migration_from_file(name, own->second + "\n" + data));
        continue;
      }
    }
    v.push_back(migration_from_file(name, sql));
  }
  std::sort(v.begin(), v.end(), [](const Migration& a, const Migration& b) { return a.version < b.version; });
  return v;
}

}  // namespace

std::vector<std::string> split_sql_statements(std::string_view sql) {
  std::vector<std::string> out;
  std::size_t i = skip_space_and_comments(sql, 0);
  while (i < sql.size()) {
    const std::size_t start = i;
    // CREATE [TEMP] TRIGGER … BEGIN … END; holds semicolons of its own.
    bool trigger = false;
    if (upper_word(sql, i) == "CREATE") {
      const std::string_view head = sql.substr(i, std::min<std::size_t>(64, sql.size() - i));
      std::string up;
      for (char c : head) up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      trigger = up.find("TRIGGER") != std::string::npos && up.find("TRIGGER") < up.find('(');
    }
    int depth = 0;  // BEGIN … END nesting inside a trigger
    for (; i < sql.size(); ++i) {
      const char c = sql[i];
      if (c == '\'' || c == '"') {
        for (++i; i < sql.size(); ++i)
          if (sql[i] == c) {
            if (i + 1 < sql.size() && sql[i + 1] == c)
              ++i;
            else
              break;
          }
      } else if (c == '-' && i + 1 < sql.size() && sql[i + 1] == '-') {
        const auto end = sql.find('\n', i);
        i = (end == std::string_view::npos ? sql.size() : end) - 1;
      } else if (trigger && std::isalpha(static_cast<unsigned char>(c)) &&
                 (i == 0 || !std::isalnum(static_cast<unsigned char>(sql[i - 1])))) {
        const std::string w = upper_word(sql, i);
        if (w == "BEGIN") ++depth;
        if (w == "END") --depth;
        i += w.size() - 1;
      } else if (c == ';' && depth <= 0) {
        break;
      }
    }
    out.emplace_back(sql.substr(start, std::min(i + 1, sql.size()) - start));
    i = skip_space_and_comments(sql, i + 1);
  }
  return out;
}

std::string data_statements(std::string_view sql) {
  std::string out;
  for (const std::string& st : split_sql_statements(sql)) {
    const std::string w = upper_word(st, 0);
    if (w == "INSERT" || w == "UPDATE" || w == "DELETE" || w == "REPLACE") out += st + "\n";
  }
  return out;
}

const std::vector<Migration>& embedded_migrations(Dialect dialect) {
  static const std::vector<Migration> sqlite = build(Dialect::kSqlite);
  static const std::vector<Migration> postgres = build(Dialect::kPostgres);
  return dialect == Dialect::kPostgres ? postgres : sqlite;
}

Migration migration_from_file(const std::string& file_name, std::string sql) {
  Migration m;
  m.sql = std::move(sql);
  std::size_t i = 0;
  while (i < file_name.size() && std::isdigit(static_cast<unsigned char>(file_name[i]))) ++i;
  if (i == 0 || i >= file_name.size() || file_name[i] != '_') return m;
  const auto dot = file_name.rfind(".sql");
  if (dot == std::string::npos || dot <= i + 1) return m;
  m.version = std::stoi(file_name.substr(0, i));
  m.name = file_name.substr(i + 1, dot - i - 1);
  return m;
}

Result<int> schema_version(Database& db) {
  auto st =
      db.prepare(db.dialect() == Dialect::kPostgres
                     ? "SELECT 1 WHERE to_regclass('schema_migrations') IS NOT NULL"
                     : "SELECT name FROM sqlite_master WHERE type='table' AND name='schema_migrations'");
  if (!st) return tl::unexpected(st.error());
  auto has = st->step();
  if (!has) return tl::unexpected(has.error());
  if (!*has) return 0;
  auto v = db.prepare("SELECT COALESCE(MAX(version), 0) FROM schema_migrations");
  if (!v) return tl::unexpected(v.error());
  if (auto row = v->step(); !row) return tl::unexpected(row.error());
  return static_cast<int>(v->int64(0));
}

Result<MigrationReport> migrate(Database& db, const std::vector<Migration>& migrations) {
  const char* create =
      db.dialect() == Dialect::kPostgres
          ? "CREATE TABLE IF NOT EXISTS schema_migrations ("
            " version INTEGER PRIMARY KEY, name TEXT NOT NULL, checksum TEXT NOT NULL,"
            " applied_at TEXT NOT NULL DEFAULT (to_char(now() AT TIME ZONE 'UTC', "
            "'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"')))"
          : "CREATE TABLE IF NOT EXISTS schema_migrations ("
            " version INTEGER PRIMARY KEY, name TEXT NOT NULL, checksum TEXT NOT NULL,"
            " applied_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now'))) STRICT";
  // Several daemons starting at once on one PostgreSQL database: one migrates, the others wait
  // for it here and then find nothing left to do (released when this function returns).
  struct AdvisoryLock {
    Database* db = nullptr;
    ~AdvisoryLock() {
      if (db) (void)db->exec("SELECT pg_advisory_unlock(7418790621)");
    }
  } lock;
  if (db.dialect() == Dialect::kPostgres) {
    if (auto s = db.exec("SELECT pg_advisory_lock(7418790621)"); !s) return tl::unexpected(s.error());
    lock.db = &db;
  }
  if (auto s = db.exec(create); !s) return tl::unexpected(s.error());

  MigrationReport report;
  auto current = schema_version(db);
  if (!current) return tl::unexpected(current.error());
  report.from_version = report.to_version = *current;

  const int newest_known = migrations.empty() ? 0 : migrations.back().version;
  if (*current > newest_known) {
    return fail(ErrorCode::kStoreSchemaTooNew,
                "database '" + db.path() + "' is at schema version " + std::to_string(*current) +
                    " but this build of socsim knows migrations up to " + std::to_string(newest_known) +
                    "; run a newer socsim or point --db at another file");
  }

  std::map<int, std::string> recorded;
  {
    auto st = db.prepare("SELECT version, checksum FROM schema_migrations");
    if (!st) return tl::unexpected(st.error());
    for (;;) {
      auto row = st->step();
      if (!row) return tl::unexpected(row.error());
      if (!*row) break;
      recorded[static_cast<int>(st->int64(0))] = st->text(1);
    }
  }

  for (const Migration& m : migrations) {
    const std::string checksum = sha256_hex(m.sql);
    if (auto it = recorded.find(m.version); it != recorded.end()) {
      if (it->second != checksum) {
        return fail(ErrorCode::kStore, "migration " + std::to_string(m.version) + " (" + m.name +
                                           ") was applied with different content; migrations are "
                                           "append-only — add a new numbered file instead of editing one");
      }
      continue;
    }
    auto tx = WriteTransaction::begin(db);
    if (!tx) return tl::unexpected(tx.error());
    if (auto s = db.exec(m.sql); !s) {
      Error e = s.error();
      e.detail = "migration " + std::to_string(m.version) + " (" + m.name + ") failed: " + e.detail;
      return tl::unexpected(e);
    }
    auto ins = db.prepare("INSERT INTO schema_migrations(version, name, checksum) VALUES (?, ?, ?)");
    if (!ins) return tl::unexpected(ins.error());
    ins->bind(1, m.version).bind(2, m.name).bind(3, checksum);
    if (auto s = ins->run(); !s) return tl::unexpected(s.error());
    if (auto s = tx->commit(); !s) return tl::unexpected(s.error());
    report.applied.push_back(m.version);
    report.to_version = m.version;
  }
  return report;
}

}  // namespace socsim::store
