#include "server/foxglove_bridge.hpp"

#include <algorithm>

#include "core/common/json_io.hpp"
#include "core/crowd/role_parameters.hpp"
#include "core/interop/people_msgs.hpp"
#include "server/frame_codec.hpp"

namespace socsim::server {
namespace {

constexpr std::uint8_t kMessageDataOp = 0x01;
constexpr std::uint8_t kTimeOp = 0x02;

void put_le(std::string& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}

WirePtr text_message(const Json& j, bool droppable = true) {
  auto m = std::make_shared<WireMessage>();
  m->bytes = j.dump(-1, ' ', false, Json::error_handler_t::replace);
  m->droppable = droppable;
  return m;
}

Json channel(FoxgloveChannel id, const char* topic, const char* encoding, const std::string& schema_name,
             const std::string& schema, const char* schema_encoding) {
  return {{"id", static_cast<std::uint32_t>(id)},
          {"topic", topic},
          {"encoding", encoding},
          {"schemaName", schema_name},
          {"schema", schema},
          {"schemaEncoding", schema_encoding}};
}

const Json& people_json_schema() {
  static const Json schema = {
      {"$schema", "https://json-schema.org/draft/2020-12/schema"},
      {"title", "socsim.People"},
      {"description", "socsim's unified pedestrian states (docs/interop.md), one message per frame"},
      {"type", "object"},
      {"properties",
       {{"stamp",
         {{"type", "object"},
          {"properties", {{"sec", {{"type", "integer"}}}, {"nsec", {{"type", "integer"}}}}},
          {"required", {"sec", "nsec"}}}},
        {"frame_id", {{"type", "string"}}},
        {"people", {{"type", "array"}, {"items", {{"type", "object"}}}}}}},
      {"required", {"stamp", "frame_id", "people"}}};
  return schema;
}

std::optional<std::uint32_t> id_of(const Json& j) {
  if (!j.is_number_integer() && !j.is_number_unsigned()) return std::nullopt;
  const auto v = j.get<std::int64_t>();
  if (v < 0 || v > static_cast<std::int64_t>(UINT32_MAX)) return std::nullopt;
  return static_cast<std::uint32_t>(v);
}

}  // namespace

FoxgloveBridge::FoxgloveBridge(std::string session_id, std::shared_ptr<const world::World> world,
                               std::string frame_id)
    : session_id_(std::move(session_id)), world_(std::move(world)), frame_id_(std::move(frame_id)) {
  set_roles({});
}

void FoxgloveBridge::set_roles(const std::vector<std::string>& roles) {
  roles_ = roles.empty() ? std::vector<std::string>{"adult"} : roles;
  const crowd::RoleTable table = crowd::RoleTable::defaults();
  proxemics_.clear();
  std::vector<double> diameters;
  std::vector<std::string> colors;
  for (std::size_t i = 0; i < roles_.size(); ++i) {
    // Roles a program added or changed stream with the nearest default parameters (adult).
    const auto index = table.index_of(roles_[i]);
    const crowd::RoleParameters role = index ? table.at(*index) : crowd::RoleParameters{};
    proxemics_.push_back(role.proxemics);
    diameters.push_back(2 * role.radius);
    colors.push_back(interop::role_color(i));
  }
  scene_ = std::make_unique<interop::PeopleSceneEncoder>(frame_id_, std::move(diameters), std::move(colors));
}

std::vector<WirePtr> FoxgloveBridge::open() const {
  const Json info = {{"op", "serverInfo"},
                     {"name", "socsim"},
                     {"capabilities", {"time"}},
                     {"metadata", {{"simulation", session_id_}, {"frame_id", frame_id_}}},
                     {"sessionId", session_id_}};
  const std::string scene_schema = interop::scene_update_json_schema().dump();
  Json channels = Json::array();
  channels.push_back(channel(FoxgloveChannel::kPeople, "/people", "cdr", std::string(interop::kPeopleMsgType),
                             interop::people_msg_definition(), "ros2msg"));
  channels.push_back(channel(FoxgloveChannel::kPeopleJson, "/people/json", "json", "socsim.People",
                             people_json_schema().dump(), "jsonschema"));
  if (world_)
    channels.push_back(channel(FoxgloveChannel::kSceneWorld, "/scene/world", "json", "foxglove.SceneUpdate",
                               scene_schema, "jsonschema"));
  channels.push_back(channel(FoxgloveChannel::kScenePeople, "/scene/people", "json", "foxglove.SceneUpdate",
                             scene_schema, "jsonschema"));
  return {text_message(info, false), text_message({{"op", "advertise"}, {"channels", channels}}, false)};
}

WirePtr FoxgloveBridge::status(int level, const std::string& message) const {
  return text_message({{"op", "status"}, {"level", level}, {"message", message}});
}

WirePtr FoxgloveBridge::data(std::uint32_t subscription, std::uint64_t ns, std::string_view payload) const {
  auto m = std::make_shared<WireMessage>();
  m->bytes.reserve(13 + payload.size());
  m->bytes.push_back(static_cast<char>(kMessageDataOp));
  put_le(m->bytes, subscription, 4);
  put_le(m->bytes, ns, 8);
  m->bytes.append(payload);
  m->binary = true;
  m->frame = true;  // a slow client loses old data, as a viewer loses old frames
  return m;
}

std::vector<WirePtr> FoxgloveBridge::on_client_text(std::string_view text) {
  auto parsed = parse_json_untrusted(text);
  if (!parsed || !parsed->is_object() || !parsed->contains("op") || !(*parsed)["op"].is_string())
    return {status(2, "expected a JSON object with a string \"op\" (subscribe or unsubscribe)")};
  const Json& j = *parsed;
  const std::string op = j["op"];
  std::vector<WirePtr> out;
  if (op == "subscribe") {
    if (!j.contains("subscriptions") || !j["subscriptions"].is_array())
      return {status(2, "subscribe needs an array \"subscriptions\" of {id, channelId}")};
    for (const Json& s : j["subscriptions"]) {
      const auto id = s.is_object() && s.contains("id") ? id_of(s["id"]) : std::nullopt;
      const auto ch = s.is_object() && s.contains("channelId") ? id_of(s["channelId"]) : std::nullopt;
      if (!id || !ch) {
        out.push_back(status(2, "each subscription needs an id and a channelId, unsigned 32-bit integers"));
        continue;
      }
      const bool known = *ch >= 1 && *ch <= 4 && (*ch != 3 || world_);
      if (!known) {
        out.push_back(status(2, "no channel " + std::to_string(*ch) + " (see the advertise message)"));
        continue;
      }
      if (subscriptions_.count(*id) != 0) {
        out.push_back(status(2, "subscription id " + std::to_string(*id) + " is already in use"));
        continue;
      }
      const auto channel_id = static_cast<FoxgloveChannel>(*ch);
      const bool twice = std::any_of(subscriptions_.begin(), subscriptions_.end(),
                                     [channel_id](const auto& kv) { return kv.second == channel_id; });
      if (twice) {
        out.push_back(status(2, "channel " + std::to_string(*ch) + " is already subscribed"));
        continue;
      }
      subscriptions_.emplace(*id, channel_id);
      if (channel_id == FoxgloveChannel::kSceneWorld)
        out.push_back(data(*id, last_ns_, interop::world_scene_update(*world_, last_ns_, frame_id_)));
    }
    return out;
  }
  if (op == "unsubscribe") {
    if (!j.contains("subscriptionIds") || !j["subscriptionIds"].is_array())
      return {status(2, "unsubscribe needs an array \"subscriptionIds\"")};
    for (const Json& s : j["subscriptionIds"]) {
      const auto id = id_of(s);
      if (!id || subscriptions_.erase(*id) == 0)
        out.push_back(status(1, "no subscription " + s.dump() + " to end"));
    }
    return out;
  }
  return {status(2, "unsupported operation '" + op.substr(0, 64) +
                        "': this server offers subscribe and unsubscribe (capabilities: time)")};
}

std::vector<WirePtr> FoxgloveBridge::on_session(const WireMessage& message) {
  if (message.binary) return on_frame(message.bytes);
  auto j = parse_json_untrusted(message.bytes);
  if (!j || !j->is_object()) return {};
  const std::string type = j->value("type", "");
  if (type == "hello" && j->contains("roles") && (*j)["roles"].is_array()) {
    std::vector<std::string> roles;
    for (const Json& r : (*j)["roles"]) roles.push_back(r.is_string() ? r.get<std::string>() : "adult");
    set_roles(roles);
  } else if (type == "end") {
    auto m =
        std::make_shared<WireMessage>(*status(0, "the simulation ended (" + j->value("reason", "") + ")"));
    m->droppable = false;
    m->last = true;
    return {m};
  }
  return {};
}

std::vector<WirePtr> FoxgloveBridge::on_frame(std::string_view bytes) {
  auto frame = decode_frame_binary(bytes);
  if (!frame) return {status(2, "an undecodable frame was skipped: " + frame.error().message())};
  const std::uint64_t ns = interop::to_nanoseconds(frame->t);
  last_ns_ = ns;
  if (subscriptions_.empty()) return {};

  const auto states = crowd::activity_names().size();
  people_.resize(frame->agents.size());
  people_roles_.resize(frame->agents.size());
  for (std::size_t i = 0; i < frame->agents.size(); ++i) {
    const FrameAgent& a = frame->agents[i];
    const std::uint16_t role = a.role < roles_.size() ? a.role : 0;
    crowd::PedestrianState& p = people_[i];
    p.id = crowd::AgentId(a.id);
    p.pose = {a.x, a.y, a.yaw};
    p.twist = {a.vx, a.vy, 0.0};
    p.activity = a.state < states ? static_cast<crowd::Activity>(a.state) : crowd::Activity::kWalking;
    p.role = roles_[role];
    p.group_id = a.group_id;
    p.proxemics = proxemics_[role];
    people_roles_[i] = role;
  }

  std::vector<WirePtr> out;
  auto time = std::make_shared<WireMessage>();
  time->bytes.push_back(static_cast<char>(kTimeOp));
  put_le(time->bytes, ns, 8);
  time->binary = true;
  time->frame = true;
  out.push_back(std::move(time));
  for (const auto& [id, channel] : subscriptions_) {
    switch (channel) {
      case FoxgloveChannel::kPeople:
        interop::encode_people_cdr(cdr_, frame->t, frame_id_, people_);
        out.push_back(data(id, ns, cdr_.bytes()));
        break;
      case FoxgloveChannel::kPeopleJson: {
        Json people = Json::array();
        for (const auto& p : people_) people.push_back(crowd::to_json(p));
        const Json msg = {{"stamp", {{"sec", ns / 1'000'000'000u}, {"nsec", ns % 1'000'000'000u}}},
                          {"frame_id", frame_id_},
                          {"people", std::move(people)}};
        out.push_back(data(id, ns, msg.dump(-1, ' ', false, Json::error_handler_t::replace)));
        break;
      }
      case FoxgloveChannel::kScenePeople:
        out.push_back(data(id, ns, scene_->encode(ns, people_, people_roles_)));
        break;
      case FoxgloveChannel::kSceneWorld:
        break;  // sent once, on subscribing
    }
  }
  return out;
}

}  // namespace socsim::server
