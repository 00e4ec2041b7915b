// The WebSocket endpoint with a real Beast client: hello frame, catalogue events, refusal of
// unknown paths, and a client that never reads does not block publishers.
#include "server/ws_server.hpp"

#include <gtest/gtest.h>

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include "core/common/json_io.hpp"

namespace socsim::server {
namespace {
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = boost::asio::ip::tcp;

struct Client {
  boost::asio::io_context io;
  websocket::stream<tcp::socket> ws{io};
  explicit Client(int port, const std::string& path = "/ws/catalogue") {
    tcp::resolver resolver(io);
    boost::asio::connect(ws.next_layer(), resolver.resolve("127.0.0.1", std::to_string(port)));
    ws.handshake("127.0.0.1", path);
  }
  Json read() {
    beast::flat_buffer buf;
    ws.read(buf);
    return Json::parse(beast::buffers_to_string(buf.data()));
  }
};

TEST(WebSocket, StreamsCatalogueEvents) {
  EventHub hub;
  WsServer ws({"127.0.0.1", 0, 8, 16}, hub);
  const int port = ws.bind().value();
  ws.start();
  Client client(port);
  Json hello = client.read();
  EXPECT_EQ(hello["type"], "hello");
  EXPECT_EQ(hello["topic"], "cards");
  hub.publish("cards", {{"type", "card.created"}, {"card", {{"id", "crd_x"}}}});
  Json ev = client.read();
  EXPECT_EQ(ev["type"], "card.created");
  EXPECT_EQ(ev["card"]["id"], "crd_x");
  ws.stop();
}

TEST(WebSocket, UnknownPathIsRefused) {
  EventHub hub;
  WsServer ws({"127.0.0.1", 0, 8, 16}, hub);
  const int port = ws.bind().value();
  ws.start();
  EXPECT_THROW(Client(port, "/ws/nowhere"), beast::system_error);
  ws.stop();
}

TEST(WebSocket, ASlowClientDoesNotBlockPublishing) {
  EventHub hub;
  WsServer ws({"127.0.0.1", 0, 8, 4}, hub);
  const int port = ws.bind().value();
  ws.start();
  Client idle(port);  // never reads after the handshake
  (void)idle.read();  // hello: the session is open
  // 64 MB published at a client that reads nothing: with a blocking publisher this loop would
  // never end once the socket buffers are full; here the session drops its oldest frames.
  const std::string big(32 * 1024, 'x');
  for (int i = 0; i < 2000; ++i) hub.publish("cards", {{"type", "card.created"}, {"pad", big}});
  WsStats st;
  for (int i = 0; i < 500; ++i) {
    st = ws.stats();
    if (st.frames_dropped > 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(st.sessions, 1u);
  EXPECT_GT(st.frames_dropped, 0u) << "a slow client's frames are dropped, not buffered without bound";
  EXPECT_LE(st.frames_queued, 4u);
  ws.stop();
}

}  // namespace
}  // namespace socsim::server
