// socsim-bench interpret / scenario-api: the text-to-scenario endpoints against a real in-process
// daemon over loopback HTTP (the same ApiServer `socsim serve` runs, a fresh SQLite file).
//   interpret     POST /api/v1/scenarios/interpret over the fixture prompts (tests/fixtures/prompts)
//                 with C keep-alive clients: p50/p95/p99 ms. The first request (WordNet's data
//                 opened, nothing cached) is reported on its own as cold_ms; with --warm every
//                 prompt is read once before measuring (WordNet's per-word cache then holds them).
//   scenario-api  POST /api/v1/scenarios for the seven Table II prompts × seeds at the default
//                 duration (60 s simulated, unless --seconds), one at a time, each timed from the
//                 POST to its job's success (polled every 5 ms): p50/p95 ms. Where the time goes
//                 inside a job: `socsim-bench scenario --seconds 60` times the stages in-process.
#include <httplib.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "server/api_server.hpp"
#include "tests/bench/bench.hpp"

namespace {
using socsim::bench::Args;
using socsim::bench::emit;
using socsim::bench::percentile;
using Json = nlohmann::json;

// A daemon on a free loopback port with its own database, stopped and removed on destruction.
class Daemon {
 public:
  Daemon(const std::string& name, int threads) {
    dir_ =
        std::filesystem::temp_directory_path() / ("socsim-bench-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    socsim::server::ServerConfig cfg;
    cfg.host = "127.0.0.1";
    cfg.port = 0;
    cfg.db = (dir_ / "bench.db").string();
    cfg.web_root = dir_.string();
    cfg.rate_limit_rps = 0;
    cfg.threads = threads;
    store_ = std::move(socsim::store::Store::open(cfg.db).value());
    services_ = std::move(socsim::server::Services::create(cfg, *store_).value());
    api_ = std::make_unique<socsim::server::ApiServer>(*services_);
    port_ = api_->bind().value();
    thread_ = std::thread([this] { api_->run(); });
    std::cout.setstate(std::ios::failbit);  // silence the per-request log lines while measuring
  }
  ~Daemon() {
    std::cout.clear();
    api_->stop();
    thread_.join();
    services_->shutdown();
    store_->close();
    std::filesystem::remove_all(dir_);
  }
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

  [[nodiscard]] httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_keep_alive(true);
    c.set_tcp_nodelay(true);
    c.set_read_timeout(120, 0);
    return c;
  }

 private:
  std::filesystem::path dir_;
  std::unique_ptr<socsim::store::Store> store_;
  std::unique_ptr<socsim::server::Services> services_;
  std::unique_ptr<socsim::server::ApiServer> api_;
  std::thread thread_;
  int port_ = 0;
};

std::vector<std::string> fixture_prompts(const std::string& dir) {
  std::vector<std::string> prompts;
  for (const char* file : {"everyday.jsonl", "unseen.jsonl"}) {
    std::ifstream in(dir + "/" + file);
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) prompts.push_back(Json::parse(line).at("prompt"));
  }
  return prompts;
}

int interpret_bench(const Args& a) {
  const int clients = static_cast<int>(a.integer("clients", 4));
  const int requests = static_cast<int>(a.integer("requests", 2000));
  const auto prompts = fixture_prompts(a.str("fixtures", "tests/fixtures/prompts"));
  if (prompts.empty()) {
    std::cerr << "no prompts in tests/fixtures/prompts (run from the source tree or pass --fixtures DIR)\n";
    return 1;
  }
  Daemon daemon("interpret", static_cast<int>(a.integer("threads", 8)));
  auto body = [&](std::size_t i) { return Json{{"prompt", prompts[i % prompts.size()]}}.dump(); };
  double cold_ms = 0;
  {
    auto c = daemon.client();
    const auto t0 = std::chrono::steady_clock::now();
    auto r = c.Post("/api/v1/scenarios/interpret", body(0), "application/json");
    cold_ms = socsim::bench::ms_since(t0);
    if (!r || r->status != 200) {
      std::cerr << "interpret failed: " << (r ? r->body : httplib::to_string(r.error())) << "\n";
      return 1;
    }
    for (std::size_t i = 1; a.has("warm") && i < prompts.size(); ++i)
      c.Post("/api/v1/scenarios/interpret", body(i), "application/json");
  }
  std::vector<double> ms;
  std::mutex m;
  std::atomic<int> next{0};
  std::atomic<int> failures{0};
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  for (int k = 0; k < clients; ++k) {
    threads.emplace_back([&] {
      auto c = daemon.client();
      std::vector<double> local;
      for (int i = next++; i < requests; i = next++) {
        const auto s = std::chrono::steady_clock::now();
        auto r = c.Post("/api/v1/scenarios/interpret", body(static_cast<std::size_t>(i)), "application/json");
        local.push_back(socsim::bench::ms_since(s));
        if (!r || r->status != 200) ++failures;
      }
      std::lock_guard<std::mutex> lock(m);
      ms.insert(ms.end(), local.begin(), local.end());
    });
  }
  for (auto& t : threads) t.join();
  const double seconds = socsim::bench::seconds_since(t0);
  std::cout.clear();
  emit({{"bench", "interpret"},
        {"request", "POST /api/v1/scenarios/interpret"},
        {"prompts", prompts.size()},
        {"clients", clients},
        {"warm", a.has("warm")},
        {"requests", ms.size()},
        {"failures", failures.load()},
        {"cold_ms", cold_ms},
        {"requests_per_s", static_cast<double>(ms.size()) / seconds},
        {"p50_ms", percentile(ms, 50)},
        {"p95_ms", percentile(ms, 95)},
        {"p99_ms", percentile(ms, 99)}});
  return failures == 0 ? 0 : 1;
}

const std::vector<std::pair<std::string, std::string>> kCategoryPrompts = {
    {"queuing", "About twenty patients queue at the reception desk of a clinic"},
    {"emergency", "Fire alarm in the office: everyone evacuates"},
    {"coffee_break", "Staff take a coffee break around the coffee machine of the office"},
    {"reception", "Visitors check in at the front desk of the office and then leave"},
    {"bottleneck", "A crowd squeezes through the narrow door into the canteen"},
    {"social_party", "A birthday party at home: guests chat in the living room"},
    {"normal_operation", "Normal daily traffic in a hospital ward: nurses and visitors walk between rooms"},
};

int scenario_api_bench(const Args& a) {
  const auto seeds = a.integer("seeds", 3);
  Daemon daemon("scenario-api", 8);
  auto c = daemon.client();
  std::vector<double> total_ms, agents;
  std::size_t failures = 0;
  for (const auto& [category, prompt] : kCategoryPrompts) {
    for (std::int64_t seed = 1; seed <= seeds; ++seed) {
      Json body = {{"prompt", prompt}, {"seed", seed}};
      if (a.has("seconds")) body["duration_s"] = a.number("seconds", 60.0);
      const auto t0 = std::chrono::steady_clock::now();
      auto r = c.Post("/api/v1/scenarios", body.dump(), "application/json");
      if (!r || r->status != 202) {
        std::cerr << category << ": " << (r ? r->body : httplib::to_string(r.error())) << "\n";
        ++failures;
        continue;
      }
      const std::string path = "/api/v1/jobs/" + Json::parse(r->body)["id"].get<std::string>();
      Json job;
      for (;;) {
        auto j = c.Get(path.c_str());
        job = Json::parse(j->body);
        const std::string status = job.value("status", "");
        if (status == "succeeded" || status == "failed" || status == "cancelled") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      const double total = socsim::bench::ms_since(t0);
      if (job["status"] != "succeeded") {
        std::cerr << category << " seed " << seed << ": " << job.dump() << "\n";
        ++failures;
        continue;
      }
      total_ms.push_back(total);
      agents.push_back(job["result"]["trajectory_log"].value("agents", 0.0));
    }
  }
  std::cout.clear();
  emit({{"bench", "scenario-api"},
        {"request", "POST /api/v1/scenarios → job succeeded"},
        {"duration_s", a.has("seconds") ? a.number("seconds", 60.0) : 60.0},
        {"scenarios", total_ms.size()},
        {"failures", failures},
        {"agents_p50", percentile(agents, 50)},
        {"agents_max", percentile(agents, 100)},
        {"p50_ms", percentile(total_ms, 50)},
        {"p95_ms", percentile(total_ms, 95)},
        {"max_ms", percentile(total_ms, 100)}});
  return failures == 0 ? 0 : 1;
}

SOCSIM_BENCH("interpret",
             "POST /api/v1/scenarios/interpret latency over loopback HTTP, fixture prompts [--clients 4] "
             "[--requests 2000] [--threads 8] [--fixtures tests/fixtures/prompts] [--warm]",
             interpret_bench);
SOCSIM_BENCH("scenario-api",
             "POST /api/v1/scenarios to job success over loopback HTTP, 7 categories × --seeds 3, default "
             "duration unless --seconds",
             scenario_api_bench);

}  // namespace
