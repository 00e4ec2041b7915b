// The Foxglove bridge without sockets: what a client is told, its subscribe/unsubscribe requests
// (good and bad), and the binary records of the protocol (opcode, little-endian subscription id and
// nanosecond time, payload) made from a session's binary frames. The wire itself is tested by
// tests/e2e/foxglove.test.mjs with Foxglove's own client.
#include "server/foxglove_bridge.hpp"

#include <gtest/gtest.h>

#include "core/interop/people_msgs.hpp"
#include "core/world/world_yaml.hpp"
#include "server/frame_codec.hpp"

namespace socsim::server {
namespace {

std::uint64_t le(const std::string& bytes, std::size_t at, int n) {
  std::uint64_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes.at(at + i));
  return v;
}

Json text_of(const WirePtr& m) {
  EXPECT_FALSE(m->binary);
  return Json::parse(m->bytes);
}

WireMessage hello(const std::vector<std::string>& roles) {
  WireMessage m;
  m.bytes = Json{{"type", "hello"}, {"roles", roles}}.dump();
  return m;
}

WireMessage frame(double t, std::size_t agents) {
  std::vector<FrameAgent> list(agents);
  for (std::size_t i = 0; i < agents; ++i) {
    list[i].id = static_cast<std::uint32_t>(i + 1);
    list[i].x = static_cast<float>(i);
    list[i].role = static_cast<std::uint8_t>(i % 2);
  }
  WireMessage m;
  m.binary = true;
  m.frame = true;
  m.bytes = encode_frame_binary(1, t, list);
  return m;
}

TEST(FoxgloveBridge, AdvertisesItsChannelsAndTheWorldOnlyWhenThereIsOne) {
  FoxgloveBridge without("sim_a", nullptr);
  auto open = without.open();
  ASSERT_EQ(open.size(), 2u);
  const Json info = text_of(open[0]);
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["sessionId"], "sim_a");
  EXPECT_EQ(info["capabilities"], Json::array({"time"}));
  const Json advertise = text_of(open[1]);
  ASSERT_EQ(advertise["op"], "advertise");
  std::vector<std::string> topics;
  for (const Json& c : advertise["channels"]) topics.push_back(c["topic"]);
  EXPECT_EQ(topics, (std::vector<std::string>{"/people", "/people/json", "/scene/people"}));
  EXPECT_EQ(advertise["channels"][0]["schema"], interop::people_msg_definition());
  EXPECT_FALSE(open[0]->droppable);  // never lost to back-pressure

  auto world = world::world_from_yaml(R"(name: box
zones:
  - name: hall
    type: hall
    polygon: [[0, 0], [10, 0], [10, 6], [0, 6]]
)");
  ASSERT_TRUE(world) << world.error().message();
  FoxgloveBridge with("sim_b", std::make_shared<const world::World>(std::move(*world)));
  EXPECT_EQ(text_of(with.open()[1])["channels"].size(), 4u);
  auto sub = with.on_client_text(R"({"op":"subscribe","subscriptions":[{"id":7,"channelId":3}]})");
  ASSERT_EQ(sub.size(), 1u);  // the world at once
  ASSERT_TRUE(sub[0]->binary);
  EXPECT_EQ(sub[0]->bytes[0], '\x01');
  EXPECT_EQ(le(sub[0]->bytes, 1, 4), 7u);
  const Json scene = Json::parse(sub[0]->bytes.substr(13));
  EXPECT_EQ(scene["entities"][1]["id"], "zones");
}

TEST(FoxgloveBridge, FramesBecomeTimeAndDataRecordsForEachSubscription) {
  FoxgloveBridge b("sim", nullptr);
  EXPECT_TRUE(b.on_session(hello({"adult", "staff"})).empty());
  EXPECT_TRUE(b.on_session(frame(0.5, 3)).empty());  // nobody subscribed yet: nothing is encoded
  EXPECT_TRUE(b.on_client_text(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1},)"
                               R"({"id":2,"channelId":2},{"id":3,"channelId":4}]})")
                  .empty());
  EXPECT_EQ(b.subscriptions(), 3u);
  auto out = b.on_session(frame(1.25, 3));
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0]->bytes.size(), 9u);
  EXPECT_EQ(out[0]->bytes[0], '\x02');
  EXPECT_EQ(le(out[0]->bytes, 1, 8), 1'250'000'000u);
  for (std::size_t i = 1; i < out.size(); ++i) {
    EXPECT_TRUE(out[i]->binary && out[i]->frame);
    EXPECT_EQ(le(out[i]->bytes, 1, 4), i);  // subscriptions in id order
    EXPECT_EQ(le(out[i]->bytes, 5, 8), 1'250'000'000u);
  }
  const Json people = Json::parse(out[2]->bytes.substr(13));
  ASSERT_EQ(people["people"].size(), 3u);
  EXPECT_EQ(people["people"][1]["role"], "staff");
  EXPECT_EQ(people["stamp"]["sec"], 1);
  EXPECT_EQ(people["stamp"]["nsec"], 250'000'000);

  EXPECT_TRUE(b.on_client_text(R"({"op":"unsubscribe","subscriptionIds":[2,3]})").empty());
  EXPECT_EQ(b.on_session(frame(1.3, 3)).size(), 2u);  // time + /people
}

TEST(FoxgloveBridge, BadRequestsAreAnsweredWithAStatusAndChangeNothing) {
  FoxgloveBridge b("sim", nullptr);
  ASSERT_TRUE(b.on_client_text(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})").empty());
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"not json", "a JSON object"},
      {R"([1,2])", "a JSON object"},
      {R"({"op":7})", "a JSON object"},
      {R"({"op":"subscribe"})", "needs an array"},
      {R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":1}]})", "unsigned 32-bit"},
      {R"({"op":"subscribe","subscriptions":[{"id":2,"channelId":3}]})", "no channel 3"},
      {R"({"op":"subscribe","subscriptions":[{"id":2,"channelId":99}]})", "no channel 99"},
      {R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":2}]})", "already in use"},
      {R"({"op":"subscribe","subscriptions":[{"id":5,"channelId":1}]})", "already subscribed"},
      {R"({"op":"unsubscribe","subscriptionIds":[42]})", "no subscription 42"},
      {R"({"op":"unsubscribe"})", "needs an array"},
      {R"({"op":"setParameters","parameters":[]})", "unsupported operation 'setParameters'"},
  };
  for (const auto& [request, message] : cases) {
    auto out = b.on_client_text(request);
    ASSERT_EQ(out.size(), 1u) << request;
    const Json status = text_of(out[0]);
    EXPECT_EQ(status["op"], "status") << request;
    EXPECT_NE(status["message"].get<std::string>().find(message), std::string::npos)
        << request << " → " << status.dump();
  }
  EXPECT_EQ(b.subscriptions(), 1u);
  WireMessage garbage;
  garbage.binary = true;
  garbage.bytes = "SSF1 but not a frame";
  auto out = b.on_session(garbage);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(text_of(out[0])["level"], 2);
  WireMessage end;
  end.bytes = R"({"type":"end","reason":"duration"})";
  out = b.on_session(end);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0]->last);
  EXPECT_NE(text_of(out[0])["message"].get<std::string>().find("duration"), std::string::npos);
}

}  // namespace
}  // namespace socsim::server
