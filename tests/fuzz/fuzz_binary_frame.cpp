// Fuzz target: a binary simulation frame (decode_frame_binary, schemas/simulation_binary_frame.md).
// A decoded frame must encode to version-1 bytes that decode to the same bytes again, and a
// version-1 frame (24-byte header, 32-byte records) must encode to exactly its input.
#include <cstddef>
#include <cstdint>

#include "server/frame_codec.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace socsim::server;
  const std::string_view bytes = socsim::fuzz::text(data, size);
  auto frame = decode_frame_binary(bytes);
  if (!frame) return 0;
  const std::string encoded = encode_frame_binary(frame->seq, frame->t, frame->agents);
  auto again = decode_frame_binary(encoded);
  SOCSIM_FUZZ_CHECK(again.has_value());
  SOCSIM_FUZZ_CHECK(encode_frame_binary(again->seq, again->t, again->agents) == encoded);
  const bool version1 = size >= kBinaryHeaderBytes && data[4] == kBinaryHeaderBytes && data[5] == 0 &&
                        data[6] == kBinaryAgentBytes && data[7] == 0;
  if (version1) SOCSIM_FUZZ_CHECK(encoded == bytes);
  return 0;
}
