// socsim-bench batch: scenarios per second through the shared job queue (issue 21). A batch of
// offline scenarios goes to the first of N daemons on one database; every daemon's job threads take
// items; the clock runs from the POST to the last item. Configurations: 1 daemon × 1 job thread,
// 2 daemons × 1, 1 daemon × 2; on a scratch SQLite file and, with --postgres URL, on PostgreSQL.
#include <httplib.h>

#include <filesystem>

#include "tests/bench/bench.hpp"
#include "tests/bench/bench_daemon.hpp"
#include "tests/bench/bench_pg.hpp"

namespace {
using socsim::bench::Args;
using socsim::bench::emit;

struct BatchConfig {
  int daemons;
  int threads;
};

// Seconds from the POST to the batch's end; negative on failure.
double batch_seconds(const std::string& db, const BatchConfig& config, int items, double duration) {
  std::vector<std::unique_ptr<socsim::bench::InProcessDaemon>> daemons;
  for (int i = 0; i < config.daemons; ++i) {
    auto d = socsim::bench::InProcessDaemon::start("batch" + std::to_string(i),
                                                   [&](socsim::server::ServerConfig& c) {
                                                     c.db = db;
                                                     c.job_workers = config.threads;
                                                     c.worker_id = "bench-" + std::to_string(i);
                                                   });
    if (!d) return -1;
    daemons.push_back(std::move(d));
  }
  httplib::Client c("127.0.0.1", daemons[0]->port());
  c.set_read_timeout(60, 0);
  const nlohmann::json body = {{"kind", "scenarios"},
                               {"prompts",
                                {"a small cafe with 6 customers and 2 baristas",
                                 "an office corridor with 10 workers walking to a meeting"}},
                               {"seeds", {{"first", 1}, {"count", items / 2}}},
                               {"parameters", {{"duration_s", duration}}}};
  const auto t0 = std::chrono::steady_clock::now();
  auto r = c.Post("/api/v1/batches", body.dump(), "application/json");
  if (!r || r->status != 202) {
    std::cerr << "batch refused: " << (r ? r->body : std::string("no answer")) << "\n";
    return -1;
  }
  const std::string id = nlohmann::json::parse(r->body)["id"];
  for (;;) {
    auto s = c.Get(("/api/v1/batches/" + id).c_str());
    if (s && s->status == 200) {
      auto j = nlohmann::json::parse(s->body);
      if (j["status"] != "running") {
        if (j["status"] != "succeeded") {
          std::cerr << "batch ended " << j.dump() << "\n";
          return -1;
        }
        return socsim::bench::seconds_since(t0);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

int run_batch_bench(const Args& a) {
  const int items = static_cast<int>(a.integer("items", 60)) / 2 * 2;
  const double duration = a.number("duration", 5.0);
  const std::string admin = socsim::bench::postgres_admin_url(a);
  const std::vector<BatchConfig> configs = {{1, 1}, {2, 1}, {1, 2}};
  std::cout.setstate(std::ios::failbit);  // the daemons' request log
  std::vector<nlohmann::json> rows;
  for (const std::string backend : {"sqlite", "postgresql"}) {
    if (backend == "postgresql" && admin.empty()) continue;
    for (const BatchConfig& cfg : configs) {
      double s = -1;
      if (backend == "sqlite") {
        const auto dir =
            std::filesystem::temp_directory_path() / ("socsim-bench-batchdb-" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        s = batch_seconds((dir / "batch.db").string(), cfg, items, duration);
        std::filesystem::remove_all(dir);
      } else {
        socsim::bench::ScratchPostgres pg(admin, "batch");
        if (pg.url().empty()) return 1;
        s = batch_seconds(pg.url(), cfg, items, duration);
      }
      if (s < 0) return 1;
      rows.push_back({{"bench", "batch"},
                      {"backend", backend},
                      {"daemons", cfg.daemons},
                      {"job_threads_each", cfg.threads},
                      {"scenarios", items},
                      {"duration_s", duration},
                      {"seconds", s},
                      {"scenarios_per_s", items / s}});
    }
  }
  std::cout.clear();
  for (const auto& r : rows) emit(r);
  if (admin.empty()) std::cerr << "(PostgreSQL skipped: give --postgres URL or $SOCSIM_BENCH_POSTGRES)\n";
  return 0;
}

SOCSIM_BENCH("batch",
             "scenarios per second through the shared job queue, 1-2 daemons on one database "
             "[--items 60] [--duration 5] [--postgres URL]",
             run_batch_bench);

}  // namespace
