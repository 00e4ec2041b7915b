#include "server/config.hpp"

#include <charconv>
#include <set>

#include "server/http_server.hpp"

extern char** environ;

namespace socsim::server {
namespace {

// "a, b,c" → {"a", "b", "c"}
std::vector<std::string> split_list(const std::string& value) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= value.size()) {
    std::size_t comma = value.find(',', start);
    if (comma == std::string::npos) comma = value.size();
    std::string item = value.substr(start, comma - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) out.push_back(std::move(item));
    start = comma + 1;
  }
  return out;
}

template <class T>
bool parse_number(const std::string& s, T& out) {
  const char* end = s.data() + s.size();
  auto [p, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && p == end;
}

Status apply(ServerConfig& c, const std::string& flag, const std::string& value, const std::string& origin) {
  auto bad = [&](const std::string& why) {
    return fail(ErrorCode::kBadRequest, origin + ": " + why, {{"", why, flag, 0, 0}});
  };
  auto port = [&](int& out) -> Status {
    int v = 0;
    if (!parse_number(value, v) || v < 0 || v > 65535) return bad("must be a port number 0–65535");
    out = v;
    return {};
  };
  auto size = [&](std::size_t& out, std::size_t lo) -> Status {
    std::size_t v = 0;
    if (!parse_number(value, v) || v < lo) return bad("must be an integer ≥ " + std::to_string(lo));
    out = v;
    return {};
  };
  auto real = [&](double& out) -> Status {
    try {
      std::size_t used = 0;
      const double v = std::stod(value, &used);
      if (used != value.size() || v < 0) return bad("must be a non-negative number");
      out = v;
    } catch (const std::exception&) {
      return bad("must be a non-negative number");
    }
    return {};
  };
  if (flag == "--host")
    c.host = value;
  else if (flag == "--port")
    return port(c.port);
  else if (flag == "--ws-port")
    return port(c.ws_port);
  else if (flag == "--public-host")
    c.public_host = value;
  else if (flag == "--db")
    c.db = value;
  else if (flag == "--web-root")
    c.web_root = value;
  else if (flag == "--threads") {
    std::size_t t = 0;
    if (auto s = size(t, 1); !s) return s;
    c.threads = static_cast<int>(std::min<std::size_t>(t, 256));
  } else if (flag == "--max-body")
    return size(c.max_body_bytes, 1024);
  else if (flag == "--max-prompt")
    return size(c.max_prompt_bytes, 1);
  else if (flag == "--max-page-size")
    return size(c.max_page_size, 1);
  else if (flag == "--rate-limit")
    return real(c.rate_limit_rps);
  else if (flag == "--rate-burst")
    return real(c.rate_limit_burst);
  else if (flag == "--api-keys") {
    auto keys = parse_api_keys(value);
    if (!keys) return bad(keys.error().detail);
    c.api_keys = std::move(*keys);
  } else if (flag == "--allowed-origins")
    c.allowed_origins = split_list(value);
  else if (flag == "--allowed-hosts")
    c.allowed_hosts = split_list(value);
  else if (flag == "--trusted-proxies")
    c.trusted_proxies = split_list(value);
  else if (flag == "--max-connections-per-client")
    return size(c.max_connections_per_client, 1);
  else if (flag == "--read-timeout") {
    std::size_t t = 0;
    if (auto s = size(t, 1); !s) return s;
    c.read_timeout_s = static_cast<int>(std::min<std::size_t>(t, 3600));
  } else if (flag == "--llm-url")
    c.llm.base_url = value;
  else if (flag == "--llm-model")
    c.llm.model = value;
  else if (flag == "--job-workers") {
    std::size_t w = 0;
    if (auto s = size(w, 1); !s) return s;
    c.job_workers = static_cast<int>(std::min<std::size_t>(w, 64));
  } else if (flag == "--max-scenario-agents")
    return size(c.max_scenario_agents, 1);
  else if (flag == "--max-scenario-seconds") {
    if (auto s = real(c.max_scenario_seconds); !s) return s;
    if (c.max_scenario_seconds < 1.0 || c.max_scenario_seconds > 86400.0)
      return bad("must be between 1 and 86400");
  } else if (flag == "--max-simulations")
    return size(c.max_simulations, 1);
  else if (flag == "--max-viewers")
    return size(c.max_viewers, 1);
  else if (flag == "--max-sim-agents")
    return size(c.max_sim_agents, 1);
  else if (flag == "--min-sim-speed")
    return real(c.min_sim_speed);
  else if (flag == "--max-sim-speed")
    return real(c.max_sim_speed);
  else if (flag == "--stream-hz")
    return real(c.stream_hz);
  else if (flag == "--sim-idle")
    return real(c.sim_idle_s);
  else if (flag == "--max-sim-duration")
    return real(c.max_sim_duration_s);
  else if (flag == "--viewer-queue")
    return size(c.viewer_queue, 1);
  else if (flag == "--max-jobs-per-client")
    return size(c.max_jobs_per_client, 1);
  else if (flag == "--worker-id") {
    if (value.empty() || value.size() > 100) return bad("must be 1-100 characters");
    c.worker_id = value;
  } else if (flag == "--job-lease") {
    if (auto s = real(c.job_lease_s); !s) return s;
    if (c.job_lease_s < 1 || c.job_lease_s > 3600) return bad("must be between 1 and 3600 seconds");
  } else if (flag == "--llm-deadline") {
    double s = 0;
    if (auto st = real(s); !st) return st;
    if (s < 1 || s > 86400) return bad("must be between 1 and 86400 seconds");
    c.llm.deadline_ms = static_cast<int>(s * 1000);
    c.llm.attempt_timeout_ms = std::min(c.llm.attempt_timeout_ms, c.llm.deadline_ms);
  } else
    return fail(ErrorCode::kBadRequest, "unknown option " + flag + " (see socsim serve --help)");
  return {};
}

}  // namespace

const std::vector<FlagSpec>& serve_flags() {
  static const std::vector<FlagSpec> flags = {
      {"--host", "SOCSIM_HOST", "address to listen on (default 127.0.0.1; 0.0.0.0 for all)"},
      {"--port", "SOCSIM_PORT", "HTTP port (default 8080)"},
      {"--ws-port", "SOCSIM_WS_PORT", "WebSocket port (default 8081)"},
      {"--public-host", "SOCSIM_PUBLIC_HOST",
       "host name clients use to reach this server (for URLs in /info)"},
      {"--db", "SOCSIM_DB", "SQLite file (default ./var/socsim.db) or postgresql:// URL"},
      {"--web-root", "SOCSIM_WEB_ROOT", "static viewer files served at / (default ./web)"},
      {"--threads", "SOCSIM_THREADS", "HTTP worker threads (default 8)"},
      {"--max-body", "SOCSIM_MAX_BODY", "largest request body in bytes (default 2097152)"},
      {"--max-prompt", "SOCSIM_MAX_PROMPT", "longest prompt in bytes (default 4000)"},
      {"--max-page-size", "SOCSIM_MAX_PAGE_SIZE", "largest page_size for lists (default 100)"},
      {"--rate-limit", "SOCSIM_RATE_LIMIT", "requests per second per client, 0 = off (default 50)"},
      {"--rate-burst", "SOCSIM_RATE_BURST", "burst size of the per-client rate limit (default 100)"},
      {"--api-keys", "SOCSIM_API_KEYS", "name:secret[,name:secret…]; when set, writes need a Bearer key"},
      {"--job-workers", "SOCSIM_JOB_WORKERS", "threads running generation jobs (default 2)"},
      {"--worker-id", "SOCSIM_WORKER_ID",
       "this process's name among the workers sharing one database's job queue (default host-pid-random)"},
      {"--job-lease", "SOCSIM_JOB_LEASE",
       "seconds a job stays its worker's without a heartbeat; then another worker takes it (default 30)"},
      {"--max-scenario-agents", "SOCSIM_MAX_SCENARIO_AGENTS",
       "people in one generated scenario (default 2000)"},
      {"--max-scenario-seconds", "SOCSIM_MAX_SCENARIO_SECONDS",
       "simulated seconds of one generated scenario (default 600)"},
      {"--max-simulations", "SOCSIM_MAX_SIMULATIONS", "live simulations running at once (default 4)"},
      {"--max-viewers", "SOCSIM_MAX_VIEWERS", "WebSocket viewers per live simulation (default 32)"},
      {"--max-sim-agents", "SOCSIM_MAX_SIM_AGENTS", "agents in one live simulation (default 10000)"},
      {"--min-sim-speed", "SOCSIM_MIN_SIM_SPEED", "slowest speed factor of a live simulation (default 0.1)"},
      {"--max-sim-speed", "SOCSIM_MAX_SIM_SPEED", "fastest speed factor of a live simulation (default 16)"},
      {"--stream-hz", "SOCSIM_STREAM_HZ", "most frames per second streamed to a viewer, 1-120 (default 20)"},
      {"--sim-idle", "SOCSIM_SIM_IDLE",
       "seconds a live simulation runs without viewers before it ends (default 30)"},
      {"--max-sim-duration", "SOCSIM_MAX_SIM_DURATION",
       "longest simulated time of a live program, seconds (default 3600)"},
      {"--viewer-queue", "SOCSIM_VIEWER_QUEUE",
       "frames queued per slow viewer before the oldest is dropped (default 8)"},
      {"--allowed-origins", "SOCSIM_ALLOWED_ORIGINS",
       "origins (scheme://host[:port], comma-separated, * = any) allowed to write and open WebSockets "
       "besides this server's own pages (default: none)"},
      {"--allowed-hosts", "SOCSIM_ALLOWED_HOSTS",
       "Host names served besides localhost, --host and --public-host (default: any when bound to 0.0.0.0)"},
      {"--trusted-proxies", "SOCSIM_TRUSTED_PROXIES",
       "proxy addresses or CIDRs whose X-Forwarded-For names the client (default: none)"},
      {"--max-connections-per-client", "SOCSIM_MAX_CONNECTIONS_PER_CLIENT",
       "open connections per client address, REST and WebSocket each (default 64)"},
      {"--read-timeout", "SOCSIM_READ_TIMEOUT",
       "seconds for a request header to arrive; bodies get more by size (default 10)"},
      {"--llm-url", "SOCSIM_LLM_URL",
       "OpenAI-compatible endpoint base URL, e.g. http://localhost:11434 (optional)"},
      {"--llm-model", "SOCSIM_LLM_MODEL", "model name for the LLM generator"},
      {"--llm-deadline", "SOCSIM_LLM_DEADLINE_S",
       "seconds one LLM call may take, retries included (default 60; SOCSIM_LLM_DEADLINE_MS also works)"},
      {"--max-jobs-per-client", "SOCSIM_MAX_JOBS_PER_CLIENT",
       "generation jobs one key (or address, without keys) may have queued or running (default 8)"},
  };
  return flags;
}

Result<std::vector<ApiKey>> parse_api_keys(const std::string& spec) {
  std::vector<ApiKey> keys;
  std::set<std::string> names;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = spec.find(',', start);
    const std::string item =
        spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    start = comma == std::string::npos ? spec.size() + 1 : comma + 1;
    if (item.empty()) continue;
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos || colon == 0)
      return fail(ErrorCode::kBadRequest, "each API key must be written name:secret");
    ApiKey k{item.substr(0, colon), item.substr(colon + 1)};
    if (k.secret.size() < 16)
      return fail(ErrorCode::kBadRequest, "the secret of key '" + k.name + "' is shorter than 16 characters");
    if (!names.insert(k.name).second)
      return fail(ErrorCode::kBadRequest, "key name '" + k.name + "' is used twice");
    keys.push_back(std::move(k));
  }
  return keys;
}

std::map<std::string, std::string> current_environment() {
  std::map<std::string, std::string> env;
  for (char** e = environ; e && *e; ++e) {
    std::string kv = *e;
    if (auto eq = kv.find('='); eq != std::string::npos && kv.rfind("SOCSIM_", 0) == 0)
      env[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  return env;
}

Result<ServerConfig> load_config(const std::vector<std::string>& args,
                                 const std::map<std::string, std::string>& env) {
  ServerConfig c;
  auto llm = llm::LlmConfig::from_environment([&env](const char* name) -> const char* {
    auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
  if (!llm) return tl::unexpected(llm.error());
  c.llm = std::move(*llm);
  for (const FlagSpec& f : serve_flags()) {
    if (f.env == "SOCSIM_LLM_URL" || f.env == "SOCSIM_LLM_MODEL") continue;  // read by LlmConfig
    if (auto it = env.find(f.env); it != env.end() && !it->second.empty())
      if (auto s = apply(c, f.flag, it->second, f.env); !s) return tl::unexpected(s.error());
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string flag = args[i], value;
    if (auto eq = flag.find('='); eq != std::string::npos) {
      value = flag.substr(eq + 1);
      flag = flag.substr(0, eq);
    } else {
      if (i + 1 >= args.size()) return fail(ErrorCode::kBadRequest, flag + " needs a value");
      value = args[++i];
    }
    if (auto s = apply(c, flag, value, flag); !s) return tl::unexpected(s.error());
  }
  if (c.default_page_size > c.max_page_size) c.default_page_size = c.max_page_size;
  if (c.min_sim_speed <= 0 || c.min_sim_speed > c.max_sim_speed)
    return fail(ErrorCode::kBadRequest, "--min-sim-speed must be above 0 and at most --max-sim-speed",
                {{"", "bad speed range", "--min-sim-speed", 0, 0}});
  if (c.stream_hz < 1 || c.stream_hz > 120)
    return fail(ErrorCode::kBadRequest, "--stream-hz must be between 1 and 120",
                {{"", "out of range", "--stream-hz", 0, 0}});
  if (c.max_sim_duration_s <= 0)
    return fail(ErrorCode::kBadRequest, "--max-sim-duration must be above 0",
                {{"", "out of range", "--max-sim-duration", 0, 0}});
  if (auto s = c.llm.validate(); !s) return tl::unexpected(s.error());
  for (const std::string& o : c.allowed_origins)
    if (o != "*" && o.find("://") == std::string::npos)
      return fail(ErrorCode::kBadRequest, "allowed origin '" + o + "' must be scheme://host[:port] or *",
                  {{"", "not an origin", "--allowed-origins", 0, 0}});
  if (auto proxies = TrustedProxies::parse(c.trusted_proxies); !proxies)
    return tl::unexpected(proxies.error());
  return c;
}

}  // namespace socsim::server
