// socsim-bench cosim: a co-simulation of N pedestrians (counter-flow lanes) and R robots on an
// in-process daemon, driven by one client over loopback WebSocket. Lock-step: steps per second
// (each a command out and a full observation back). Real time: the steps the server took per
// second against the asked rate, the client's late ticks, and the observation size.
#include <httplib.h>

#include <cstring>
#include <utility>  // before Boost.Asio: its awaitable.hpp uses std::exchange

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include "tests/bench/bench.hpp"
#include "tests/bench/bench_daemon.hpp"

namespace {
using socsim::bench::Args;
using socsim::bench::emit;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

nlohmann::json step_message(std::uint64_t k, int robots) {
  nlohmann::json list = nlohmann::json::array();
  for (int r = 0; r < robots; ++r) list.push_back({{"cmd", {{"v", 0.6}, {"omega", 0.05}}}});
  return {{"type", "step"}, {"step", k}, {"robots", list}};
}

int run(const Args& a) {
  const int agents = static_cast<int>(a.integer("agents", 500));
  const int robots = static_cast<int>(a.integer("robots", 1));
  const double seconds = a.number("seconds", 10.0);
  const bool realtime = a.str("mode", "lockstep") == "realtime";
  const double rate = a.number("rate", 20.0);
  const bool binary = a.str("encoding", "json") == "binary";
  auto daemon = socsim::bench::InProcessDaemon::start("cosim", [&](socsim::server::ServerConfig& cfg) {
    cfg.max_sim_agents = static_cast<std::size_t>(agents);
    cfg.sim_idle_s = 60;
  });
  if (!daemon) return 1;
  std::cout.setstate(std::ios::failbit);  // silence the request log lines while measuring

  // Robots drive along the crowd's lower edge (within reach of the social forces, not in a lane).
  nlohmann::json list = nlohmann::json::array();
  for (int r = 0; r < robots; ++r)
    list.push_back({{"name", "r" + std::to_string(r)},
                    {"start", {{"x", 5.0 + 10.0 * r}, {"y", -1.2}, {"yaw", 0.0}}},
                    {"goal", {{"x", 59.0}, {"y", -1.2}}}});
  nlohmann::json body{
      {"program", socsim::bench::lanes_program(agents)}, {"seed", 1},          {"robots", list},
      {"mode", realtime ? "realtime" : "lockstep"},      {"time_limit", 3600}, {"stuck_time", 3600}};
  if (realtime) body["rate_hz"] = rate;
  httplib::Client http("127.0.0.1", daemon->port());
  http.set_read_timeout(60, 0);
  auto created = http.Post("/api/v1/cosim", body.dump(), "application/json");
  if (!created || created->status != 201) {
    std::cout.clear();
    std::cerr << "socsim-bench cosim: " << (created ? created->body : "no answer") << "\n";
    return 1;
  }
  const auto session = nlohmann::json::parse(created->body);

  asio::io_context io;
  websocket::stream<tcp::socket> ws(io);
  tcp::resolver resolver(io);
  asio::connect(ws.next_layer(), resolver.resolve("127.0.0.1", std::to_string(daemon->ws_port())));
  ws.set_option(websocket::stream_base::decorator([binary](websocket::request_type& req) {
    req.set(beast::http::field::sec_websocket_protocol,
            binary ? "socsim.cosim.v1.binary" : "socsim.cosim.v1");
  }));
  ws.handshake("127.0.0.1", session["ws_url"].get<std::string>());
  ws.text(true);
  beast::flat_buffer buf;
  ws.read(buf);  // hello
  buf.clear();
  ws.read(buf);  // step 0
  std::uint64_t k = 0, first_step = 0, last_step = 0;
  nlohmann::json report;
  double bytes = 0.0;
  const auto t0 = Clock::now();
  const auto end = t0 + std::chrono::milliseconds(static_cast<int>(seconds * 1000));
  if (realtime) ws.write(asio::buffer(step_message(++k, robots).dump()));
  while (Clock::now() < end) {
    if (!realtime) ws.write(asio::buffer(step_message(++k, robots).dump()));
    buf.clear();
    ws.read(buf);
    bytes += static_cast<double>(buf.size());
    if (ws.got_binary()) {  // a binary observation: the step is the header's u64 at byte 8
      const std::string b = beast::buffers_to_string(buf.data());
      if (b.size() < 32 || b.compare(0, 4, "SCB1") != 0) break;
      std::memcpy(&last_step, b.data() + 8, sizeof last_step);
    } else {
      const auto o = nlohmann::json::parse(beast::buffers_to_string(buf.data()));
      if (o.value("type", "") == "report") report = o;
      if (o.value("type", "") != "observation") break;
      last_step = o["step"].get<std::uint64_t>();
    }
    if (first_step == 0) first_step = last_step;
    if (realtime) ws.write(asio::buffer(step_message(++k, robots).dump()));  // answer every observation
  }
  const double wall = socsim::bench::seconds_since(t0);
  beast::error_code ignored;
  if (report.is_null()) ws.write(asio::buffer(std::string(R"({"type":"stop"})")), ignored);
  while (report.is_null()) {
    buf.clear();
    beast::error_code ec;
    ws.read(buf, ec);
    if (ec) break;
    if (ws.got_binary()) continue;
    auto m = nlohmann::json::parse(beast::buffers_to_string(buf.data()));
    if (m.value("type", "") == "report") {
      report = m;
      break;
    }
  }
  std::cout.clear();
  const double steps = static_cast<double>(last_step - first_step + 1);
  emit({{"bench", "cosim"},
        {"mode", realtime ? "realtime" : "lockstep"},
        {"encoding", binary ? "binary" : "json"},
        {"agents", agents},
        {"robots", robots},
        {"seconds", wall},
        {"steps", steps},
        {"steps_per_s", steps / wall},
        {"rate_hz", realtime ? nlohmann::json(rate) : nlohmann::json(nullptr)},
        {"late_ticks", report.is_object() ? report.value("late_ticks", 0) : -1},
        {"outcome", report.is_object() ? report["metrics"]["robots"][0]["outcome"] : nlohmann::json(nullptr)},
        {"bytes_per_observation", bytes / std::max(1.0, steps)}});
  return 0;
}

SOCSIM_BENCH("cosim",
             "a robot co-simulation over loopback WebSocket [--agents 500] [--robots 1] [--seconds 10] "
             "[--mode lockstep|realtime] [--rate 20] [--encoding json|binary]",
             run);

}  // namespace
