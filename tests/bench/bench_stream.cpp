// socsim-bench stream: one live program session of N agents on an in-process daemon, V WebSocket
// viewers over loopback; frames per second each viewer receives (min, p50), bytes per second,
// frames lost, and whether the simulation kept real time.
#include <httplib.h>

#include <atomic>
#include <filesystem>
#include <mutex>
#include <thread>
#include <utility>  // before Boost.Asio: its awaitable.hpp uses std::exchange

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include "server/simulation_sessions.hpp"
#include "tests/bench/bench.hpp"
#include "tests/bench/bench_daemon.hpp"

namespace {
using socsim::bench::Args;
using socsim::bench::emit;
using socsim::bench::percentile;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

struct ViewerResult {
  std::size_t frames = 0;
  std::size_t bytes = 0;
  std::uint32_t first_seq = 0;
  std::uint32_t last_seq = 0;
  bool failed = false;
  std::string error;
};

// The seq of a frame without parsing the whole message (JSON: "seq":N; binary: bytes 8..11).
std::optional<std::uint32_t> frame_seq(const beast::flat_buffer& buf, bool binary) {
  const auto data = buf.data();
  const char* p = static_cast<const char*>(data.data());
  const std::size_t n = data.size();
  if (binary) {
    if (n < socsim::server::kBinaryHeaderBytes) return std::nullopt;
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
      v |= static_cast<std::uint32_t>(static_cast<unsigned char>(p[8 + i])) << (8 * i);
    return v;
  }
  const std::string_view head(p, std::min<std::size_t>(n, 64));
  if (head.rfind(R"({"type":"frame","seq":)", 0) != 0) return std::nullopt;
  std::uint32_t v = 0;
  for (std::size_t i = 22; i < head.size() && head[i] >= '0' && head[i] <= '9'; ++i)
    v = v * 10 + static_cast<std::uint32_t>(head[i] - '0');
  return v;
}

void watch(int port, const std::string& path, bool binary, Clock::time_point from, Clock::time_point to,
           ViewerResult& out) {
  try {
    asio::io_context io;
    websocket::stream<tcp::socket> ws(io);
    tcp::resolver resolver(io);
    asio::connect(ws.next_layer(), resolver.resolve("127.0.0.1", std::to_string(port)));
    ws.set_option(websocket::stream_base::decorator([binary](websocket::request_type& req) {
      req.set(beast::http::field::sec_websocket_protocol, binary ? "socsim.binary.v1" : "socsim.json.v1");
    }));
    ws.handshake("127.0.0.1", path);
    beast::flat_buffer buf;
    for (;;) {
      buf.clear();
      ws.read(buf);
      const auto now = Clock::now();
      const bool frame = ws.got_binary() == binary;
      if (!frame) {
        const std::string text = beast::buffers_to_string(buf.data());
        if (text.find(R"("type":"end")") != std::string::npos) break;
        if (!binary && text.rfind(R"({"type":"frame")", 0) != 0) continue;
        if (binary) continue;
      }
      if (now < from) continue;
      if (now >= to) continue;  // keep reading until the session ends, so the server never waits
      auto seq = frame_seq(buf, binary);
      if (!seq) continue;
      if (out.frames == 0) out.first_seq = *seq;
      out.last_seq = *seq;
      ++out.frames;
      out.bytes += buf.size();
    }
  } catch (const std::exception& e) {
    if (Clock::now() < to) {
      out.failed = true;
      out.error = e.what();
    }
  }
}

int run_stream(const Args& a) {
  const int viewers = static_cast<int>(a.integer("viewers", 20));
  const int agents = static_cast<int>(a.integer("agents", 2000));
  const double seconds = a.number("seconds", 10.0);
  const double warmup = a.number("warmup", 1.0);
  const double speed = a.number("speed", 1.0);
  const bool binary = a.has("binary");
  auto daemon = socsim::bench::InProcessDaemon::start("stream", [&](socsim::server::ServerConfig& cfg) {
    cfg.max_viewers = static_cast<std::size_t>(viewers) + 1;
    cfg.max_sim_agents = static_cast<std::size_t>(agents);
  });
  if (!daemon) return 1;
  const int port = daemon->port();
  const int ws_port = daemon->ws_port();
  std::cout.setstate(std::ios::failbit);  // silence the request log lines while measuring

  httplib::Client http("127.0.0.1", port);
  http.set_read_timeout(60, 0);
  const auto t_create = Clock::now();
  auto created = http.Post(
      "/api/v1/simulations",
      nlohmann::json{{"program", socsim::bench::lanes_program(agents)}, {"seed", 1}, {"speed", speed}}.dump(),
      "application/json");
  const double create_s = socsim::bench::seconds_since(t_create);
  if (!created || created->status != 201) {
    std::cout.clear();
    std::cerr << "socsim-bench stream: creating the session failed: "
              << (created ? created->body : "no answer") << "\n";
    return 1;
  }
  const auto session = nlohmann::json::parse(created->body);
  const std::string id = session["id"];
  const std::string path = session["ws_url"];

  const auto from = Clock::now() + std::chrono::milliseconds(static_cast<int>(warmup * 1000));
  const auto to = from + std::chrono::milliseconds(static_cast<int>(seconds * 1000));
  std::vector<ViewerResult> results(static_cast<std::size_t>(viewers));
  std::vector<std::thread> threads;
  for (int v = 0; v < viewers; ++v)
    threads.emplace_back(
        [&, v] { watch(ws_port, path, binary, from, to, results[static_cast<std::size_t>(v)]); });

  std::this_thread::sleep_until(from);
  auto before = http.Get(("/api/v1/simulations/" + id).c_str());
  std::this_thread::sleep_until(to);
  auto after = http.Get(("/api/v1/simulations/" + id).c_str());
  http.Post(("/api/v1/simulations/" + id + "/control").c_str(), R"({"action":"stop"})", "application/json");
  for (auto& t : threads) t.join();
  std::cout.clear();

  const auto s0 = nlohmann::json::parse(before->body);
  const auto s1 = nlohmann::json::parse(after->body);
  std::vector<double> fps;
  double bytes = 0;
  std::size_t lost = 0, failed = 0, frames = 0;
  for (const auto& r : results) {
    if (r.failed) {
      ++failed;
      std::cerr << "viewer failed: " << r.error << "\n";
      continue;
    }
    fps.push_back(static_cast<double>(r.frames) / seconds);
    bytes += static_cast<double>(r.bytes);
    frames += r.frames;
    if (r.frames > 0) lost += (r.last_seq - r.first_seq + 1) - r.frames;
  }
  const double sent = s1["frames_sent"].get<double>() - s0["frames_sent"].get<double>();
  emit({{"bench", "stream"},
        {"format", binary ? "binary" : "json"},
        {"viewers", viewers},
        {"agents", s1["agents"]},
        {"seconds", seconds},
        {"speed", speed},
        {"create_s", create_s},
        {"frame_hz", s1["frame_hz"]},
        {"session_frames_per_s", sent / seconds},
        {"sim_time_per_wall_s", (s1["t"].get<double>() - s0["t"].get<double>()) / seconds},
        {"viewer_fps_min", fps.empty() ? 0.0 : *std::min_element(fps.begin(), fps.end())},
        {"viewer_fps_p50", fps.empty() ? 0.0 : percentile(fps, 50)},
        {"bytes_per_frame", frames == 0 ? 0.0 : bytes / static_cast<double>(frames)},
        {"mbytes_per_s_total", bytes / seconds / 1e6},
        {"frames_lost_by_viewers", lost},
        {"frames_dropped_by_server", s1["frames_dropped"]},
        {"viewers_failed", failed}});
  return failed == 0 ? 0 : 1;
}

SOCSIM_BENCH(
    "stream",
    "live simulation streaming over WebSocket [--viewers 20] [--agents 2000] [--seconds 10] [--binary] "
    "[--speed 1] [--warmup 1]",
    run_stream);

}  // namespace
