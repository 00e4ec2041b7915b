#pragma once
// Schema migrations: the numbered SQL files of migrations/ (embedded in the binary at build time),
// each applied once, in order, in its own transaction, and recorded in schema_migrations.
#include <string>
#include <vector>

#include "core/store/database.hpp"

namespace socsim::store {

struct Migration {
  int version = 0;   // from the file name: 0003_cards.sql → 3
  std::string name;  // "cards"
  std::string sql;
};

// The migrations compiled into this build for a dialect, sorted by version. migrations/NNNN_*.sql
// are SQLite's. PostgreSQL runs the same files, except where migrations/postgresql/ has a file of
// the same name: that file gives the schema change in PostgreSQL's SQL, followed by the data
// statements (INSERT, UPDATE, DELETE, REPLACE) of the shared file, so curated data is written once.
const std::vector<Migration>& embedded_migrations(Dialect dialect = Dialect::kSqlite);

// The statements of an SQL script (quotes, comments and trigger bodies respected), and of those
// the ones that change data rather than the schema.
std::vector<std::string> split_sql_statements(std::string_view sql);
std::string data_statements(std::string_view sql);

// Parses "NNNN_name.sql" into version and name; returns version 0 when the name does not match.
Migration migration_from_file(const std::string& file_name, std::string sql);

struct MigrationReport {
  int from_version = 0;
  int to_version = 0;
  std::vector<int> applied;
};

// Applies what is missing. Refuses (kStoreSchemaTooNew) a database whose recorded version is newer
// than the newest migration known here, and (kStore) one where an applied migration's content
// differs from this build's (migrations are append-only). A failing migration leaves the database
// at the previous version.
Result<MigrationReport> migrate(Database& db, const std::vector<Migration>& migrations);

// Highest version recorded in the database (0 when none).
Result<int> schema_version(Database& db);

}  // namespace socsim::store
