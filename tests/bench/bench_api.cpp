// socsim-bench api: request latency percentiles against a real in-process daemon over loopback
// HTTP (card create, card get, search), with C concurrent clients.
#include <httplib.h>

#include <atomic>
#include <filesystem>
#include <mutex>
#include <thread>

#include "server/api_server.hpp"
#include "tests/bench/bench.hpp"
#include "tests/bench/bench_pg.hpp"

namespace {
using socsim::bench::Args;
using socsim::bench::emit;
using socsim::bench::percentile;

// The phases against one database (a scratch SQLite file, or an empty PostgreSQL database).
int run_api_on(const Args& a, const std::string& backend, const std::string& pg_url) {
  const int clients = static_cast<int>(a.integer("clients", 8));
  const int requests = static_cast<int>(a.integer("requests", 2000));
  const auto dir =
      std::filesystem::temp_directory_path() / ("socsim-bench-api-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  socsim::server::ServerConfig cfg;
  cfg.host = "127.0.0.1";
  cfg.port = 0;
  cfg.db = pg_url.empty() ? (dir / "bench.db").string() : pg_url;
  cfg.web_root = dir.string();
  cfg.rate_limit_rps = 0;
  cfg.threads = static_cast<int>(a.integer("threads", 8));
  auto store = socsim::store::Store::open(cfg.db);
  if (!store) {
    std::cerr << store.error().message() << "\n";
    return 1;
  }
  auto services = socsim::server::Services::create(cfg, **store);
  if (!services) {
    std::cerr << services.error().message() << "\n";
    return 1;
  }
  socsim::server::ApiServer api(**services);
  const int port = api.bind().value();
  std::thread server([&] { api.run(); });
  std::cout.setstate(std::ios::failbit);  // silence the per-request log lines while measuring

  const std::string card =
      R"({"title":"Bench card","description":"Visitors queue at the hospital reception while staff chat.",)"
      R"("tags":["queue","bench"],"prompt":"visitors queue at the reception desk","seed":1,)"
      R"("generator":{"name":"offline"},"domain":"hospital","world":{"zones":[]},"metrics":{"agents":30}})";

  struct Phase {
    std::string name;
    std::vector<double> ms;
    double seconds = 0;
  };
  std::vector<std::string> ids;
  std::mutex ids_mutex;
  auto measure = [&](const std::string& name, auto&& one_request) {
    Phase p{name, {}, 0};
    std::mutex m;
    std::atomic<int> next{0};
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> threads;
    for (int c = 0; c < clients; ++c) {
      threads.emplace_back([&] {
        httplib::Client client("127.0.0.1", port);
        client.set_keep_alive(true);
        client.set_tcp_nodelay(true);
        std::vector<double> local;
        for (int i = next++; i < requests; i = next++) {
          const auto s = std::chrono::steady_clock::now();
          one_request(client, i);
          local.push_back(
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s).count());
        }
        std::lock_guard<std::mutex> lock(m);
        p.ms.insert(p.ms.end(), local.begin(), local.end());
      });
    }
    for (auto& t : threads) t.join();
    p.seconds = socsim::bench::seconds_since(t0);
    return p;
  };
  std::vector<Phase> phases;
  phases.push_back(measure("POST /api/v1/cards", [&](httplib::Client& c, int) {
    auto r = c.Post("/api/v1/cards", card, "application/json");
    if (r && r->status == 201) {
      std::lock_guard<std::mutex> lock(ids_mutex);
      ids.push_back(nlohmann::json::parse(r->body)["id"]);
    }
  }));
  phases.push_back(measure("GET /api/v1/cards/{id}", [&](httplib::Client& c, int i) {
    c.Get(("/api/v1/cards/" + ids[static_cast<std::size_t>(i) % ids.size()]).c_str());
  }));
  phases.push_back(measure("GET /api/v1/cards?q=reception&page_size=20", [&](httplib::Client& c, int) {
    c.Get("/api/v1/cards?q=reception&page_size=20");
  }));
  std::cout.clear();
  for (const auto& p : phases) {
    emit({{"bench", "api"},
          {"backend", backend},
          {"request", p.name},
          {"clients", clients},
          {"requests", p.ms.size()},
          {"requests_per_s", static_cast<double>(p.ms.size()) / p.seconds},
          {"p50_ms", percentile(p.ms, 50)},
          {"p95_ms", percentile(p.ms, 95)},
          {"p99_ms", percentile(p.ms, 99)}});
  }
  api.stop();
  server.join();
  (*services)->shutdown();
  (*store)->close();
  std::filesystem::remove_all(dir);
  return 0;
}

// SQLite, then (with --postgres URL or $SOCSIM_BENCH_POSTGRES) PostgreSQL, in one run.
int run_api(const Args& a) {
  if (int rc = run_api_on(a, "sqlite", ""); rc != 0) return rc;
  const std::string admin = socsim::bench::postgres_admin_url(a);
  if (admin.empty()) {
    std::cerr << "(PostgreSQL skipped: give --postgres URL or $SOCSIM_BENCH_POSTGRES)\n";
    return 0;
  }
  socsim::bench::ScratchPostgres pg(admin, "api");
  if (pg.url().empty()) return 1;
  return run_api_on(a, "postgresql", pg.url());
}

SOCSIM_BENCH("api",
             "request latency percentiles over loopback HTTP, SQLite then PostgreSQL [--clients 8] "
             "[--requests 2000] [--threads 8] [--postgres URL]",
             run_api);

}  // namespace
