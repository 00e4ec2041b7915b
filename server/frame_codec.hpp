#pragma once
// The binary simulation frame (schemas/simulation_binary_frame.md): encoder and the decoder of
// untrusted bytes. Pure code with no transport, so the fuzz target (tests/fuzz) compiles it alone.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"

namespace socsim::server {

// One agent of a frame, at wire precision.
struct FrameAgent {
  std::uint32_t id = 0;
  float x = 0, y = 0, yaw = 0, vx = 0, vy = 0;
  std::int32_t group_id = -1;
  std::uint8_t state = 0;    // crowd::Activity
  std::uint8_t role = 0;     // index into the session's roles
  std::uint16_t target = 0;  // index into the session's targets; 0 = none
  friend bool operator==(const FrameAgent&, const FrameAgent&) = default;
};

inline constexpr std::size_t kBinaryHeaderBytes = 24;
inline constexpr std::size_t kBinaryAgentBytes = 32;

std::string encode_frame_binary(std::uint32_t seq, double t, std::span<const FrameAgent> agents);

struct BinaryFrame {
  std::uint32_t seq = 0;
  double t = 0;
  std::vector<FrameAgent> agents;
};
// Untrusted bytes: magic, sizes and count are checked.
Result<BinaryFrame> decode_frame_binary(std::string_view bytes);

}  // namespace socsim::server
