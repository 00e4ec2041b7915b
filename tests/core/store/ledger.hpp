#pragma once
// A two-account ledger for the store tests (SQLite's and PostgreSQL's): money moves between the
// accounts in transactions, so a torn or half-applied write shows as a wrong sum.
#include <string>
#include <utility>
#include <vector>

#include "core/store/store.hpp"

namespace socsim::store::ledger {

// Two accounts of 100 and their entries, in SQL both backends read (CHECK and a foreign key).
inline const std::vector<Migration>& schema() {
  static const std::vector<Migration> m = {migration_from_file(
      "0001_ledger.sql",
      "CREATE TABLE account(id INTEGER PRIMARY KEY, balance INTEGER NOT NULL CHECK (balance >= 0));"
      "CREATE TABLE entry(account INTEGER NOT NULL REFERENCES account(id), amount INTEGER NOT NULL);"
      "INSERT INTO account(id, balance) VALUES (1, 100), (2, 100);")};
  return m;
}

inline Result<std::int64_t> scalar(Database& db, const std::string& sql) {
  auto st = db.prepare(sql);
  if (!st) return tl::unexpected(st.error());
  if (auto r = st->step(); !r) return tl::unexpected(r.error());
  return st->int64(0);
}

// Moves `amount` from account 1 to account 2, one UPDATE each.
inline Status transfer(Database& db, std::int64_t amount) {
  for (auto [acct, delta] : {std::pair{1, -amount}, std::pair{2, amount}}) {
    auto st = db.prepare("UPDATE account SET balance = balance + ? WHERE id = ?");
    if (!st) return tl::unexpected(st.error());
    st->bind(1, delta).bind(2, acct);
    if (auto s = st->run(); !s) return s;
  }
  return {};
}

}  // namespace socsim::store::ledger
