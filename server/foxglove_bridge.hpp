#pragma once
// The Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1, docs/interop.md) for one
// client of a live simulation: what the client is told on connecting (serverInfo, advertise), its
// subscribe/unsubscribe requests, and the session's messages (hello, frames, end) turned into the
// protocol's binary Time and Message Data records for the channels it subscribed to:
//   1 /people        socsim_people_msgs/msg/People, ros2msg schema, CDR (as the MCAP export)
//   2 /people/json   the same people as socsim pedestrian states, JSON
//   3 /scene/world   foxglove.SceneUpdate, JSON: walls, zones and doors, sent on subscribing
//   4 /scene/people  foxglove.SceneUpdate, JSON: a cylinder per person per frame
// No sockets or threads here: the WebSocket server feeds it and writes what it returns.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/crowd/pedestrian_state.hpp"
#include "core/interop/cdr_writer.hpp"
#include "core/interop/foxglove_scene.hpp"
#include "core/world/world.hpp"
#include "server/simulation_sessions.hpp"

namespace socsim::server {

inline constexpr std::string_view kFoxgloveProtocol = "foxglove.websocket.v1";
inline constexpr std::string_view kFoxglovePath = "/foxglove/";

enum class FoxgloveChannel : std::uint32_t {
  kPeople = 1,
  kPeopleJson = 2,
  kSceneWorld = 3,
  kScenePeople = 4
};

class FoxgloveBridge {
 public:
  // `world` may be null (a session without a world: no /scene/world channel).
  FoxgloveBridge(std::string session_id, std::shared_ptr<const world::World> world,
                 std::string frame_id = "map");

  // serverInfo and advertise, the first two messages of a connection.
  std::vector<WirePtr> open() const;
  // A text message from the client: subscribe / unsubscribe. Anything else, or a bad request, is
  // answered with a status message (level 2) and changes nothing.
  std::vector<WirePtr> on_client_text(std::string_view text);
  // A message of the simulation session (its hello, frames, targets, status, end).
  std::vector<WirePtr> on_session(const WireMessage& message);

  [[nodiscard]] std::size_t subscriptions() const { return subscriptions_.size(); }

 private:
  std::vector<WirePtr> on_frame(std::string_view bytes);
  [[nodiscard]] WirePtr status(int level, const std::string& message) const;
  [[nodiscard]] WirePtr data(std::uint32_t subscription, std::uint64_t ns, std::string_view payload) const;
  void set_roles(const std::vector<std::string>& roles);

  std::string session_id_;
  std::shared_ptr<const world::World> world_;
  std::string frame_id_;
  std::map<std::uint32_t, FoxgloveChannel> subscriptions_;  // client's subscription id → channel
  std::vector<std::string> roles_;                          // the session's role table (from hello)
  std::vector<crowd::Proxemics> proxemics_;                 // per role
  std::unique_ptr<interop::PeopleSceneEncoder> scene_;
  std::uint64_t last_ns_ = 0;  // the latest frame's time
  interop::CdrWriter cdr_;
  std::vector<crowd::PedestrianState> people_;
  std::vector<std::uint16_t> people_roles_;
};

}  // namespace socsim::server
