#pragma once
// A scratch PostgreSQL database for the benchmarks that compare backends: created on the server
// that --postgres URL (or $SOCSIM_BENCH_POSTGRES) names, dropped at the end.
#include <unistd.h>
#include <cstdlib>
#include <iostream>
#include <string>

#include "core/store/database.hpp"
#include "tests/bench/bench.hpp"

namespace socsim::bench {

inline std::string postgres_admin_url(const Args& a) {
  const char* env = std::getenv("SOCSIM_BENCH_POSTGRES");
  return a.str("postgres", env ? env : "");
}

class ScratchPostgres {
 public:
  ScratchPostgres(const std::string& admin, const std::string& tag) : admin_(admin) {
    name_ = "socsim_bench_" + tag + "_" + std::to_string(::getpid());
    const auto slash = admin.rfind('/');
    const auto query = admin.find('?', slash == std::string::npos ? 0 : slash);
    url_ = admin.substr(0, slash + 1) + name_ + (query == std::string::npos ? "" : admin.substr(query));
    if (!run("DROP DATABASE IF EXISTS " + name_ + " WITH (FORCE)") || !run("CREATE DATABASE " + name_))
      url_.clear();
  }
  ~ScratchPostgres() { run("DROP DATABASE IF EXISTS " + name_ + " WITH (FORCE)"); }
  ScratchPostgres(const ScratchPostgres&) = delete;
  ScratchPostgres& operator=(const ScratchPostgres&) = delete;
  // Empty when the database could not be made (the reason went to stderr).
  [[nodiscard]] const std::string& url() const { return url_; }

 private:
  bool run(const std::string& sql) {
    auto db = store::Database::open(admin_);
    if (!db) {
      std::cerr << "postgres: " << db.error().message() << "\n";
      return false;
    }
    if (auto s = db->exec(sql); !s) {
      std::cerr << "postgres: " << s.error().message() << "\n";
      return false;
    }
    return true;
  }
  std::string admin_, name_, url_;
};

}  // namespace socsim::bench
