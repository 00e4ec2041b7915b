#pragma once
// A ROS 2 CDR serializer: XCDR1 little-endian (encapsulation CDR_LE, 00 01 00 00), each primitive
// aligned to its size (8 at most) counted from the end of the 4-byte encapsulation header, strings
// as uint32 length including the NUL, sequences as uint32 count then elements.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace socsim::interop {

static_assert(std::endian::native == std::endian::little, "CdrWriter copies host bytes as little-endian");

class CdrWriter {
 public:
  CdrWriter() { reset(); }
  // Starts a new message (keeps the buffer's capacity).
  void reset() { buf_.assign({'\x00', '\x01', '\x00', '\x00'}); }

  void u8(std::uint8_t v) { put(v); }
  void u32(std::uint32_t v) { put(v); }
  void i32(std::int32_t v) { put(v); }
  void u64(std::uint64_t v) { put(v); }
  void i64(std::int64_t v) { put(v); }
  void f64(double v) { put(v); }
  void string(std::string_view s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    buf_.append(s);
    buf_.push_back('\0');
  }
  // A sequence's element count; its elements follow.
  void sequence_size(std::size_t n) { u32(static_cast<std::uint32_t>(n)); }

  [[nodiscard]] const std::string& bytes() const { return buf_; }

 private:
  template <class T>
  void put(T v) {
    static_assert(std::is_arithmetic_v<T>);
    const std::size_t at = buf_.size();
    const std::size_t pad = (sizeof(T) - (at - kHeader) % sizeof(T)) % sizeof(T);
    buf_.resize(at + pad + sizeof(T));  // the padding is zeros
    std::memcpy(buf_.data() + at + pad, &v, sizeof(T));
  }

  static constexpr std::size_t kHeader = 4;
  std::string buf_;
};

}  // namespace socsim::interop
