// `socsim serve`: opens the store, starts HTTP and WebSocket, and shuts down cleanly on
// SIGINT/SIGTERM (in-flight requests finish, then the database is closed).
#include <pthread.h>

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <thread>

#include "server/api_server.hpp"
#include "server/cli/cli.hpp"
#include "server/pg_event_relay.hpp"
#include "server/registry.hpp"
#include "server/routes.hpp"
#include "server/ws_server.hpp"
#include "socsim/buildinfo.hpp"

namespace socsim::server {

namespace {
void print_serve_help() {
  std::cout
      << "usage: socsim serve [options]\n\nEvery option can also be set by its environment variable.\n\n";
  for (const auto& f : serve_flags())
    std::cout << "  " << f.flag << " <value>   (" << f.env << ")\n      " << f.help << "\n";
  std::cout << "  SOCSIM_LLM_API_KEY   bearer key sent to the LLM endpoint (environment only)\n";
}
}  // namespace

int serve_command(const std::vector<std::string>& args) {
  for (const auto& a : args)
    if (a == "--help" || a == "-h") {
      print_serve_help();
      return 0;
    }
  auto config = load_config(args, current_environment());
  if (!config) {
    std::cerr << "socsim serve: " << config.error().detail << "\n";
    return 2;
  }

  // Block the shutdown signals in every thread; one thread waits for them with sigwait.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  auto store = store::Store::open(config->db);
  if (!store) {
    std::cerr << "socsim serve: " << store.error().message() << "\n";
    return 1;
  }
  auto services = Services::create(*config, **store);
  if (!services) {
    std::cerr << "socsim serve: " << services.error().message() << "\n";
    return 2;
  }
  // Daemons sharing a PostgreSQL database pass their catalogue events to one another.
  std::unique_ptr<PgEventRelay> relay;
  if ((*store)->dialect() == store::Dialect::kPostgres) {
    relay = std::make_unique<PgEventRelay>((*store)->target(), (*services)->events);
    std::string why;
    if (!relay->start(why)) {
      std::cerr << "socsim serve: cannot listen for other daemons' events: " << why << "\n";
      return 1;
    }
  }
  ApiServer api(**services);
  auto http_port = api.bind();
  if (!http_port) {
    std::cerr << "socsim serve: " << http_port.error().detail << "\n";
    return 1;
  }
  WsServer ws({config->host, config->ws_port}, **services, *http_port);
  auto ws_port = ws.bind();
  if (!ws_port) {
    std::cerr << "socsim serve: " << ws_port.error().detail << "\n";
    return 1;
  }
  ws.start();

  std::atomic<bool> running{true};
  std::thread waiter([&] {
    int sig = 0;
    sigwait(&signals, &sig);
    if (!running.exchange(false)) return;
    log_line({{"level", "info"}, {"event", "shutdown"}, {"signal", sig == SIGINT ? "SIGINT" : "SIGTERM"}});
    api.stop();
  });

  log_line({{"level", "info"},
            {"event", "listening"},
            {"version", build::kVersion},
            {"http", "http://" + config->host + ":" + std::to_string(*http_port)},
            {"websocket", "ws://" + config->host + ":" + std::to_string(*ws_port) + "/ws"},
            {"db", (*store)->path()},  // a URL without its password
            {"schema_version", (*store)->schema_version()},
            {"migrations_applied", (*store)->migration_report().applied},
            {"writes_require_key", !config->api_keys.empty()},
            {"llm", config->llm.configured() ? Json(config->llm.base_url) : Json(nullptr)}});
  api.run();  // returns after stop(), once in-flight requests have finished
  if (running.exchange(false)) ::kill(::getpid(), SIGTERM);  // run() ended on its own: wake the waiter
  waiter.join();
  ws.stop();
  if (relay) relay->stop();
  (*services)->shutdown();
  (*store)->close();
  log_line({{"level", "info"}, {"event", "stopped"}});
  return 0;
}

SOCSIM_COMMAND("serve", "  serve                 run the REST + WebSocket daemon (socsim serve --help)\n",
               serve_command);

}  // namespace socsim::server
