#include "server/frame_codec.hpp"

#include <bit>
#include <cstring>

namespace socsim::server {

namespace {

void le_u16(std::string& out, std::uint16_t v) {
  out += static_cast<char>(v & 0xffu);
  out += static_cast<char>((v >> 8) & 0xffu);
}
void le_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xffu);
}
void le_u64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out += static_cast<char>((v >> (8 * i)) & 0xffu);
}
void le_f32(std::string& out, float v) {
  le_u32(out, std::bit_cast<std::uint32_t>(v));
}

std::uint64_t read_le(std::string_view b, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i)
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]))
         << (8 * i);
  return v;
}

constexpr char kMagic[4] = {'S', 'S', 'F', '1'};

}  // namespace

std::string encode_frame_binary(std::uint32_t seq, double t, std::span<const FrameAgent> agents) {
  std::string out;
  out.reserve(kBinaryHeaderBytes + agents.size() * kBinaryAgentBytes);
  out.append(kMagic, 4);
  le_u16(out, static_cast<std::uint16_t>(kBinaryHeaderBytes));
  le_u16(out, static_cast<std::uint16_t>(kBinaryAgentBytes));
  le_u32(out, seq);
  le_u64(out, std::bit_cast<std::uint64_t>(t));
  le_u32(out, static_cast<std::uint32_t>(agents.size()));
  for (const FrameAgent& a : agents) {
    le_u32(out, a.id);
    le_f32(out, a.x);
    le_f32(out, a.y);
    le_f32(out, a.yaw);
    le_f32(out, a.vx);
    le_f32(out, a.vy);
    le_u32(out, static_cast<std::uint32_t>(a.group_id));
    out += static_cast<char>(a.state);
    out += static_cast<char>(a.role);
    le_u16(out, a.target);
  }
  return out;
}

Result<BinaryFrame> decode_frame_binary(std::string_view b) {
  if (b.size() < kBinaryHeaderBytes || std::memcmp(b.data(), kMagic, 4) != 0)
    return fail(ErrorCode::kBadRequest, "not a socsim binary frame (no SSF1 header)");
  const std::size_t header = read_le(b, 4, 2);
  const std::size_t record = read_le(b, 6, 2);
  if (header < kBinaryHeaderBytes || record < kBinaryAgentBytes)
    return fail(ErrorCode::kBadRequest, "binary frame header or record size is smaller than version 1's");
  BinaryFrame f;
  f.seq = static_cast<std::uint32_t>(read_le(b, 8, 4));
  f.t = std::bit_cast<double>(read_le(b, 12, 8));
  const std::size_t count = read_le(b, 20, 4);
  if (b.size() < header || (b.size() - header) / record != count || (b.size() - header) % record != 0)
    return fail(ErrorCode::kBadRequest, "binary frame of " + std::to_string(b.size()) +
                                            " bytes does not hold " + std::to_string(count) + " agents");
  f.agents.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = header + i * record;
    FrameAgent& a = f.agents[i];
    a.id = static_cast<std::uint32_t>(read_le(b, at, 4));
    a.x = std::bit_cast<float>(static_cast<std::uint32_t>(read_le(b, at + 4, 4)));
    a.y = std::bit_cast<float>(static_cast<std::uint32_t>(read_le(b, at + 8, 4)));
    a.yaw = std::bit_cast<float>(static_cast<std::uint32_t>(read_le(b, at + 12, 4)));
    a.vx = std::bit_cast<float>(static_cast<std::uint32_t>(read_le(b, at + 16, 4)));
    a.vy = std::bit_cast<float>(static_cast<std::uint32_t>(read_le(b, at + 20, 4)));
    a.group_id = static_cast<std::int32_t>(static_cast<std::uint32_t>(read_le(b, at + 24, 4)));
    a.state = static_cast<std::uint8_t>(read_le(b, at + 28, 1));
    a.role = static_cast<std::uint8_t>(read_le(b, at + 29, 1));
    a.target = static_cast<std::uint16_t>(read_le(b, at + 30, 2));
  }
  return f;
}

}  // namespace socsim::server
