// The JSON frame (schemas/simulation_frame.schema.json), written by hand: one frame goes to every
// viewer, so it is encoded once per frame and as cheaply as the binary one.
#include <charconv>
#include <cmath>

#include "core/crowd/pedestrian_state.hpp"
#include "server/simulation_sessions.hpp"

namespace socsim::server {

namespace {

void put_float(std::string& out, float v) {
  if (!std::isfinite(v)) v = 0.0f;  // JSON has no NaN; the engine keeps states finite anyway
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

void put_double(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0.0;
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

template <class Int>
void put_int(std::string& out, Int v) {
  char buf[24];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, ec == std::errc() ? end : buf);
}

const std::vector<std::string>& quoted_states() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> q;
    for (std::string_view n : crowd::activity_names()) q.push_back(Json(std::string(n)).dump());
    return q;
  }();
  return names;
}

}  // namespace

std::string encode_frame_json(std::uint32_t seq, double t, std::span<const FrameAgent> agents,
                              const std::vector<std::string>& roles,
                              const std::vector<std::string>& targets) {
  std::vector<std::string> quoted_roles;
  quoted_roles.reserve(roles.size());
  for (const auto& r : roles)
    quoted_roles.push_back(Json(r).dump(-1, ' ', false, Json::error_handler_t::replace));
  std::vector<std::string> quoted_targets;
  quoted_targets.reserve(targets.size());
  for (const auto& s : targets)
    quoted_targets.push_back(s.empty() ? "null"
                                       : Json(s).dump(-1, ' ', false, Json::error_handler_t::replace));
  const auto& states = quoted_states();

  std::string out;
  out.reserve(64 + agents.size() * 150);
  out += R"({"type":"frame","seq":)";
  put_int(out, seq);
  out += R"(,"t":)";
  put_double(out, t);
  out += R"(,"agents":[)";
  bool first = true;
  for (const FrameAgent& a : agents) {
    if (!first) out += ',';
    first = false;
    out += R"({"id":)";
    put_int(out, a.id);
    out += R"(,"x":)";
    put_float(out, a.x);
    out += R"(,"y":)";
    put_float(out, a.y);
    out += R"(,"yaw":)";
    put_float(out, a.yaw);
    out += R"(,"vx":)";
    put_float(out, a.vx);
    out += R"(,"vy":)";
    put_float(out, a.vy);
    out += R"(,"state":)";
    out += a.state < states.size() ? states[a.state] : std::string("null");
    out += R"(,"role":)";
    out += a.role < quoted_roles.size() ? quoted_roles[a.role] : std::string("null");
    out += R"(,"group_id":)";
    put_int(out, a.group_id);
    out += R"(,"target":)";
    out += a.target < quoted_targets.size() ? quoted_targets[a.target] : std::string("null");
    out += '}';
  }
  out += "]}";
  return out;
}

}  // namespace socsim::server
