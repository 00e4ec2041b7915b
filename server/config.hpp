#pragma once
// Daemon configuration: built-in defaults, overridden by SOCSIM_* environment variables,
// overridden by command-line flags. Every flag has an environment variable.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/llm/llm_config.hpp"

namespace socsim::server {

struct ApiKey {
  std::string name;    // becomes the author of cards written with this key
  std::string secret;  // never logged
};

struct ServerConfig {
  std::string host = "127.0.0.1";
  int port = 8080;
  int ws_port = 8081;
  std::string public_host;  // host name put in URLs given to clients (default: host, or localhost)
  std::string db = "./var/socsim.db";
  std::string web_root = "./web";
  int threads = 8;
  std::size_t max_body_bytes = 2u << 20;
  std::size_t max_prompt_bytes = 4000;
  std::size_t max_page_size = 100;
  std::size_t default_page_size = 20;
  double rate_limit_rps = 50.0;  // per client; 0 disables
  double rate_limit_burst = 100.0;
  int read_timeout_s = 10;   // a request's header (idle wait included); its body gets more by size
  int write_timeout_s = 10;  // a whole response
  std::size_t max_connections_per_client = 64;  // per address, REST and WebSocket each
  // Cross-site protection. Origins allowed to write (and to open WebSockets) besides the
  // server's own ("*" = any); Host names served besides loopback names, --host and --public-host
  // (empty and bound to all addresses: any; "*" = any).
  std::vector<std::string> allowed_origins;
  std::vector<std::string> allowed_hosts;
  std::vector<std::string> trusted_proxies;  // addresses or CIDRs whose X-Forwarded-For is believed
  std::vector<ApiKey> api_keys;              // empty: writes are open (local use)
  int job_workers = 2;
  std::size_t max_jobs_per_client = 8;  // queued + running per key (or address, without keys)
  // The shared job queue (issue 21): this process's name among the workers on one database (empty:
  // host-pid-random) and how long a claimed job stays its own without a heartbeat.
  std::string worker_id;
  double job_lease_s = 30.0;
  // Text to scenario (/api/v1/scenarios): bounds on what one request may ask for.
  std::size_t max_scenario_agents = 2000;  // people in one scenario (spotlight + ambient)
  double max_scenario_seconds = 600.0;     // simulated seconds logged into a card
  // Live simulations (/api/v1/simulations, /ws/simulations/{id}).
  std::size_t max_simulations = 4;     // running at once
  std::size_t max_viewers = 32;        // per simulation
  std::size_t max_sim_agents = 10000;  // per simulation
  double min_sim_speed = 0.1;
  double max_sim_speed = 16.0;
  double stream_hz = 20.0;             // most frames per second sent to a viewer
  double sim_idle_s = 30.0;            // a simulation without viewers this long ends
  double max_sim_duration_s = 3600.0;  // simulated seconds of a program session
  std::size_t viewer_queue = 8;        // frames queued per viewer before the oldest is dropped
  llm::LlmConfig llm;  // SOCSIM_LLM_* (see core/llm/llm_config.hpp); --llm-url/--llm-model override
};

struct FlagSpec {
  std::string flag;  // "--port"
  std::string env;   // "SOCSIM_PORT"
  std::string help;
};

// The flags `socsim serve` understands, for --help and docs.
const std::vector<FlagSpec>& serve_flags();

// Reads environment then argv (argv[0] is the first flag, not the program name).
Result<ServerConfig> load_config(const std::vector<std::string>& args,
                                 const std::map<std::string, std::string>& env);

// "alice:s3cret,bob:hunter2" → keys; names must be unique, secrets at least 16 characters.
Result<std::vector<ApiKey>> parse_api_keys(const std::string& spec);

std::map<std::string, std::string> current_environment();

}  // namespace socsim::server
