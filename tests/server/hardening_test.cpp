// The daemon as an attacker or a careless client meets it (issue 14): refused requests never have
// their bodies parsed as requests, slow and idle connections do not stall anyone, per-address
// caps, cross-site writes, Host checks, trusted proxies and consistent problems.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <thread>

#include "server/access_policy.hpp"
#include "server/http_server.hpp"
#include "server/ws_server.hpp"
#include "tests/server/raw_socket.hpp"
#include "tests/server/test_server.hpp"

namespace socsim::server {
namespace {
using namespace std::chrono_literals;
using testing::count_responses;
using testing::RawSocket;

server::ServerConfig open_config() {
  server::ServerConfig c;
  c.rate_limit_rps = 0;
  return c;
}

std::string post_bytes(const std::string& path, const std::string& content_type, const std::string& body,
                       const std::string& extra = "") {
  std::string r = "POST " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n";
  if (!content_type.empty()) r += "Content-Type: " + content_type + "\r\n";
  return r + extra + "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

const std::string kSmuggled = "GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";

// One response, then the connection is closed: the body was not taken for a second request.
void expect_refused_alone(int port, const std::string& request, const std::string& status) {
  RawSocket s(port);
  ASSERT_TRUE(s.connected());
  ASSERT_TRUE(s.send(request));
  const std::string reply = s.read_all(3000ms);
  EXPECT_EQ(count_responses(reply), 1) << reply;
  EXPECT_EQ(reply.rfind("HTTP/1.1 " + status, 0), 0u) << reply;
  EXPECT_NE(reply.find("application/problem+json"), std::string::npos) << reply;
  EXPECT_TRUE(s.closed_by_peer()) << "a refused request's connection is closed";
}

TEST(Smuggling, BodyOfARequestRefusedBeforeReadingIsNeverParsed) {
  {
    testing::TestServer server(open_config());
    expect_refused_alone(server.port(), post_bytes("/api/v1/cards", "text/plain", kSmuggled), "415");
  }
  {
    server::ServerConfig c = open_config();
    c.api_keys = {{"alice", "alice-secret-0123456789"}};
    testing::TestServer server(c);
    expect_refused_alone(server.port(), post_bytes("/api/v1/cards", "application/json", kSmuggled), "401");
  }
  {
    server::ServerConfig c;
    c.rate_limit_rps = 0.001;
    c.rate_limit_burst = 1;
    testing::TestServer server(c);  // its start-up probe took the one token
    expect_refused_alone(server.port(), post_bytes("/api/v1/cards", "application/json", kSmuggled), "429");
  }
  {
    server::ServerConfig c = open_config();
    c.max_body_bytes = 1024;
    testing::TestServer server(c);
    const std::string big(4096, ' ');
    expect_refused_alone(server.port(), post_bytes("/api/v1/cards", "application/json", big + kSmuggled),
                         "413");
  }
}

TEST(Smuggling, AcceptedRequestsKeepTheConnectionAlive) {
  testing::TestServer server(open_config());
  RawSocket s(server.port());
  ASSERT_TRUE(s.send(kSmuggled + kSmuggled));  // two pipelined requests
  const std::string reply = s.read_all(1500ms);
  EXPECT_EQ(count_responses(reply), 2) << reply;
  EXPECT_FALSE(s.closed_by_peer());
}

TEST(SlowClients, AHeaderMustArriveWithinItsDeadlineHoweverOftenBytesCome) {
  server::ServerConfig c = open_config();
  c.read_timeout_s = 1;
  testing::TestServer server(c);
  RawSocket s(server.port());
  const std::string request =
      "GET /api/v1/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Pad: " + std::string(100, 'a');
  const auto start = std::chrono::steady_clock::now();
  bool closed = false;
  for (char ch : request) {  // one byte every 50 ms: each read is quick, the whole header is not
    if (!s.send(std::string(1, ch)) || s.peer_closed_within(50ms)) {
      closed = true;
      break;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(closed) << "the connection is cut once the header deadline passes";
  EXPECT_LT(seconds, 2.5);
}

// 200 slow and 500 idle connections (spread over loopback addresses, 50 each) while /health is
// asked 200 times: every answer comes quickly.
TEST(SlowClients, HealthStaysFastWhileSlowAndIdleConnectionsAreOpen) {
  server::ServerConfig c = open_config();
  c.read_timeout_s = 60;
  testing::TestServer server(c);
  std::vector<RawSocket> idle, slow;
  auto from = [](std::size_t i) { return "127.0.0." + std::to_string(10 + i / 50); };
  for (std::size_t i = 0; i < 500; ++i) idle.emplace_back(server.port(), from(i));
  for (std::size_t i = 0; i < 200; ++i) slow.emplace_back(server.port(), from(500 + i));
  for (auto& s : slow) s.send("GET /api/v1/health HTTP/1.1\r\nHo");
  std::atomic<bool> done{false};
  std::thread dribble([&] {
    while (!done) {
      for (auto& s : slow) s.send("o");
      std::this_thread::sleep_for(200ms);
    }
  });
  std::vector<double> ms;
  auto client = server.client();
  for (int i = 0; i < 200; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    auto r = client.Get("/api/v1/health");
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    ASSERT_TRUE(r && r->status == 200);
  }
  done = true;
  dribble.join();
  std::sort(ms.begin(), ms.end());
  const double p99 = ms[ms.size() * 99 / 100];
  std::printf("health p50 %.2f ms, p99 %.2f ms with 500 idle + 200 slow connections\n", ms[ms.size() / 2],
              p99);
  EXPECT_LT(p99, 100.0);
  std::size_t still_open = 0;
  for (auto& s : idle) still_open += s.peer_closed_within(0ms) ? 0 : 1;
  EXPECT_EQ(still_open, idle.size()) << "the idle connections were held open, not dropped";
}

TEST(Connections, APerAddressCapRefusesTheExcessOnly) {
  server::ServerConfig c = open_config();
  c.max_connections_per_client = 4;
  testing::TestServer server(c);
  std::vector<RawSocket> held;
  for (int i = 0; i < 4; ++i) held.emplace_back(server.port(), "127.0.0.5");
  std::this_thread::sleep_for(200ms);
  RawSocket extra(server.port(), "127.0.0.5");
  const std::string refusal = extra.read_all(2000ms);
  EXPECT_EQ(refusal.rfind("HTTP/1.1 503", 0), 0u) << refusal;
  EXPECT_TRUE(extra.closed_by_peer());
  RawSocket other(server.port(), "127.0.0.6");
  other.send(kSmuggled);
  EXPECT_EQ(other.read_all(1000ms).rfind("HTTP/1.1 200", 0), 0u) << "another address is served";
}

TEST(CrossSite, OnlyJsonMediaTypesAreTakenForWrites) {
  testing::TestServer server(open_config());
  auto c = server.client();
  const std::string card = R"({"title":"x"})";
  for (const char* type : {"text/plain; a=+json", "text/plain", "application/x-www-form-urlencoded",
                           "multipart/form-data; boundary=x", "application/json; charset=latin1",
                           "application/jsonp", "application/+json"}) {
    auto r = c.Post("/api/v1/cards", card, type);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 415) << type;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  }
  // No Content-Type at all with a body.
  RawSocket s(server.port());
  s.send(post_bytes("/api/v1/cards", "", card));
  EXPECT_EQ(s.read_all(2000ms).rfind("HTTP/1.1 415", 0), 0u);
  EXPECT_FALSE(check_media_type("application/json; charset=UTF-8"));
  EXPECT_FALSE(check_media_type("Application/Problem+JSON"));
}

TEST(CrossSite, HostAndOriginAreChecked) {
  testing::TestServer server(open_config());
  auto c = server.client();
  const httplib::Headers evil_origin = {{"Origin", "http://evil.example"}};
  auto r = c.Post("/api/v1/cards", evil_origin, R"({"title":"x"})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403) << r->body;
  const std::string self = "http://127.0.0.1:" + std::to_string(server.port());
  r = c.Post("/api/v1/cards", {{"Origin", self}}, R"({})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_NE(r->status, 403) << "the server's own pages may write";
  r = c.Get("/api/v1/health", {{"Host", "attacker.example"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400) << "DNS rebinding: an unknown Host is refused";
  EXPECT_TRUE(c.Get("/api/v1/health", {{"Host", "localhost:1234"}})->status == 200);
}

TEST(CrossSite, ListedOriginsGetCors) {
  server::ServerConfig cfg = open_config();
  cfg.allowed_origins = {"https://lab.example.org"};
  testing::TestServer server(cfg);
  auto c = server.client();
  auto pre = c.Options("/api/v1/cards",
                       {{"Origin", "https://lab.example.org"}, {"Access-Control-Request-Method", "POST"}});
  ASSERT_TRUE(pre);
  EXPECT_EQ(pre->status, 204);
  EXPECT_EQ(pre->get_header_value("Access-Control-Allow-Origin"), "https://lab.example.org");
  auto other = c.Options("/api/v1/cards", {{"Origin", "https://evil.example"}});
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 403);
}

TEST(CrossSite, WebSocketRefusesForeignOrigins) {
  testing::TestServer http(open_config());
  WsServer ws({"127.0.0.1", 0}, http.services(), http.port());
  const int port = ws.bind().value();
  ws.start();
  auto handshake = [&](const std::string& origin) {
    RawSocket s(port);
    s.send("GET /ws/catalogue HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
           "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n"
           "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nOrigin: " +
           origin + "\r\n\r\n");
    return s.read_all(1000ms);
  };
  EXPECT_EQ(handshake("http://evil.example").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(handshake("http://127.0.0.1:" + std::to_string(http.port())).rfind("HTTP/1.1 101", 0), 0u)
      << "pages of the daemon's own HTTP port may open sockets";
  ws.stop();
}

TEST(WebSocketLimits, IdleConnectionsDoNotLockOutViewers) {
  EventHub hub;
  WsOptions o{"127.0.0.1", 0, 4096, 16};
  o.handshake_timeout = 700ms;
  o.max_clients_per_address = 32;
  WsServer ws(o, hub);
  const int port = ws.bind().value();
  ws.start();
  std::vector<RawSocket> idle;
  for (int i = 0; i < 300; ++i) idle.emplace_back(port, "127.0.0.7");  // never send a byte
  std::this_thread::sleep_for(100ms);
  EXPECT_GE(ws.stats().refused, 260u) << "one address holds at most 32 sockets";
  RawSocket viewer(port, "127.0.0.8");
  viewer.send(
      "GET /ws/catalogue HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
      "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n");
  EXPECT_EQ(viewer.read_all(500ms).rfind("HTTP/1.1 101", 0), 0u) << "a viewer gets in";
  std::this_thread::sleep_for(1000ms);
  EXPECT_LE(ws.stats().sessions, 1u) << "sockets that never handshake are closed at the deadline";
  ws.stop();
}

TEST(Proxies, TrustedProxiesNameTheClient) {
  auto proxies = TrustedProxies::parse({"127.0.0.1", "10.0.0.0/8", "::1"}).value();
  EXPECT_EQ(proxies.client("127.0.0.1", "203.0.113.7"), "203.0.113.7");
  EXPECT_EQ(proxies.client("127.0.0.1", "198.51.100.1, 203.0.113.7, 10.1.2.3"), "203.0.113.7")
      << "the rightmost address that is not a proxy";
  EXPECT_EQ(proxies.client("192.0.2.9", "203.0.113.7"), "192.0.2.9")
      << "an untrusted peer's header is ignored";
  EXPECT_EQ(proxies.client("127.0.0.1", "not-an-address"), "127.0.0.1");
  EXPECT_FALSE(TrustedProxies::parse({"10.0.0.0/33"}));
  EXPECT_FALSE(TrustedProxies::parse({"proxy.local"}));

  // Behind a trusted proxy each client has its own rate-limit bucket.
  server::ServerConfig c;
  c.rate_limit_rps = 0.001;
  c.rate_limit_burst = 3;
  c.trusted_proxies = {"127.0.0.1"};
  testing::TestServer server(c);
  auto client = server.client();
  int ok_a = 0, ok_b = 0;
  for (int i = 0; i < 5; ++i) {
    ok_a += client.Get("/api/v1/health", {{"X-Forwarded-For", "203.0.113.1"}})->status == 200;
    ok_b += client.Get("/api/v1/health", {{"X-Forwarded-For", "203.0.113.2"}})->status == 200;
  }
  EXPECT_EQ(ok_a, 3);
  EXPECT_EQ(ok_b, 3);
}

TEST(Problems, RefusalsCarryTheirReasonAndBearerIsCaseInsensitive) {
  server::ServerConfig c = open_config();
  c.api_keys = {{"alice", "alice-secret-0123456789"}};
  testing::TestServer server(c);
  auto client = server.client();
  auto r = client.Post("/api/v1/cards", R"({})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 401);
  const Json problem = Json::parse(r->body);
  ASSERT_FALSE(problem["errors"].empty()) << r->body;
  EXPECT_EQ(problem["errors"][0]["parameter"], "Authorization");
  r = client.Post("/api/v1/cards", {{"Authorization", "bearer alice-secret-0123456789"}}, R"({})",
                  "application/json");
  ASSERT_TRUE(r);
  EXPECT_NE(r->status, 401) << "the scheme is case-insensitive (RFC 7235)";
  r = client.Post("/api/v1/cards", {{"Authorization", "Bearer alice-secret-0123456789"}}, R"({})",
                  "text/plain");
  ASSERT_TRUE(r);
  EXPECT_FALSE(Json::parse(r->body)["errors"].empty()) << "415 names the header";
}

TEST(Routing, WrongMethodIs405WithAllow) {
  testing::TestServer server(open_config());
  auto r = server.client().Delete("/api/v1/health");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 405);
  EXPECT_EQ(r->get_header_value("Allow"), "GET");
  auto head = server.client().Head("/api/v1/health");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->status, 200);
  EXPECT_TRUE(head->body.empty());
  auto traversal = server.client().Get("/../../etc/passwd");
  ASSERT_TRUE(traversal);
  EXPECT_EQ(traversal->status, 404);
}

}  // namespace
}  // namespace socsim::server
