#include "core/store/migrations.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include "core/common/sha256.hpp"

namespace socsim::store {

const std::map<std::string, std::string>& embedded_migration_files();  // generated from migrations/*.sql

const std::vector<Migration>& embedded_migrations() {
  static const std::vector<Migration> all = [] {
    std::vector<Migration> v;
    for (const auto& [name, sql] : embedded_migration_files()) v.push_back(migration_from_file(name, sql));
    std::sort(v.begin(), v.end(),
              [](const Migration& a, const Migration& b) { return a.version < b.version; });
    return v;
  }();
  return all;
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
  auto st = db.prepare("SELECT name FROM sqlite_master WHERE type='table' AND name='schema_migrations'");
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
  if (auto s = db.exec("CREATE TABLE IF NOT EXISTS schema_migrations ("
                       " version INTEGER PRIMARY KEY, name TEXT NOT NULL, checksum TEXT NOT NULL,"
                       " applied_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now'))) STRICT");
      !s)
    return tl::unexpected(s.error());

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
