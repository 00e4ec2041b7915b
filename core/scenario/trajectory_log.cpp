#include "core/scenario/trajectory_log.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "core/common/sha256.hpp"

namespace socsim::scenario {

static_assert(std::endian::native == std::endian::little,
              "the log byte format is written little-endian as is");

namespace {

constexpr std::string_view kMagic = "SOCTRAJ1";
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kMaxRoles = 65535;
constexpr std::size_t kMaxRoleBytes = 256;

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// Reads the fields of one value type from a frame's column.
class LogReader {
 public:
  explicit LogReader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  bool get(T& value) {
    if (bytes_.size() - pos_ < sizeof(T)) return false;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return true;
  }
  bool get_text(std::size_t n, std::string& text) {
    if (bytes_.size() - pos_ < n) return false;
    text.assign(bytes_.data() + pos_, n);
    pos_ += n;
    return true;
  }
  [[nodiscard]] std::size_t remaining() const { return bytes_.size() - pos_; }
  [[nodiscard]] std::size_t position() const { return pos_; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

Error corrupt(std::string detail, std::size_t at) {
  return Error(ErrorCode::kValidation, "trajectory log is not socsim-traj-v1: " + detail,
               {FieldError{"", detail + " at byte " + std::to_string(at)}});
}

float narrow(double v) {
  if (!std::isfinite(v)) return 0.0f;
  return static_cast<float>(v);
}

}  // namespace

std::span<const LoggedAgent> TrajectoryLog::frame(std::size_t i) const {
  if (i >= times_.size()) return {};
  return std::span<const LoggedAgent>(agents_.data() + offsets_[i], offsets_[i + 1] - offsets_[i]);
}

// Layout (all little-endian): "SOCTRAJ1", u32 version, f64 interval, u32 role count, roles as
// (u16 length, UTF-8 bytes), u32 frame count; per frame: f64 time, u32 n, then columns of n
// values each: u32 id, f32 x, f32 y, f32 yaw, f32 vx, f32 vy, u8 state, u16 role, i32 group.
std::string TrajectoryLog::encoded() const {
  std::string out;
  out.reserve(64 + agents_.size() * 31 + times_.size() * 12);
  out.append(kMagic);
  put(out, kVersion);
  put(out, interval_);
  put(out, static_cast<std::uint32_t>(roles_.size()));
  for (const auto& r : roles_) {
    put(out, static_cast<std::uint16_t>(r.size()));
    out.append(r);
  }
  put(out, static_cast<std::uint32_t>(times_.size()));
  for (std::size_t f = 0; f < times_.size(); ++f) {
    const auto agents = frame(f);
    put(out, times_[f]);
    put(out, static_cast<std::uint32_t>(agents.size()));
    for (const auto& a : agents) put(out, a.id);
    for (const auto& a : agents) put(out, a.x);
    for (const auto& a : agents) put(out, a.y);
    for (const auto& a : agents) put(out, a.yaw);
    for (const auto& a : agents) put(out, a.vx);
    for (const auto& a : agents) put(out, a.vy);
    for (const auto& a : agents) put(out, static_cast<std::uint8_t>(a.activity));
    for (const auto& a : agents) put(out, a.role);
    for (const auto& a : agents) put(out, a.group_id);
  }
  return out;
}

std::string TrajectoryLog::compressed() const {
  const std::string raw = encoded();
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string out;
  put(out, static_cast<std::uint64_t>(raw.size()));
  out.resize(8 + size);
  const int rc = compress2(reinterpret_cast<Bytef*>(out.data() + 8), &size,
                           reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()), 6);
  if (rc != Z_OK) throw std::runtime_error("zlib compress2 failed: " + std::to_string(rc));
  out.resize(8 + size);
  return out;
}

Result<TrajectoryLog> TrajectoryLog::from_compressed(std::string_view bytes, std::size_t max_raw_bytes) {
  std::uint64_t raw_size = 0;
  if (bytes.size() < 8) return tl::unexpected(corrupt("missing length prefix", 0));
  std::memcpy(&raw_size, bytes.data(), 8);
  if (raw_size > max_raw_bytes)
    return tl::unexpected(corrupt("declared size " + std::to_string(raw_size) + " exceeds the limit of " +
                                      std::to_string(max_raw_bytes) + " bytes",
                                  0));
  std::string raw(static_cast<std::size_t>(raw_size), '\0');
  uLongf out_size = static_cast<uLongf>(raw_size);
  const int rc =
      uncompress(reinterpret_cast<Bytef*>(raw.data()), &out_size,
                 reinterpret_cast<const Bytef*>(bytes.data() + 8), static_cast<uLong>(bytes.size() - 8));
  if (rc != Z_OK || out_size != raw_size)
    return tl::unexpected(
        corrupt("zlib stream does not inflate to the declared size (zlib " + std::to_string(rc) + ")", 8));
  return from_encoded(raw);
}

Result<TrajectoryLog> TrajectoryLog::from_encoded(std::string_view bytes) {
  LogReader r(bytes);
  std::string magic;
  if (!r.get_text(kMagic.size(), magic) || magic != kMagic) return tl::unexpected(corrupt("bad magic", 0));
  std::uint32_t version = 0;
  if (!r.get(version) || version != kVersion)
    return tl::unexpected(corrupt("unsupported version " + std::to_string(version), 8));
  TrajectoryLog log;
  if (!r.get(log.interval_) || !std::isfinite(log.interval_) || log.interval_ <= 0)
    return tl::unexpected(corrupt("frame interval must be a positive number", r.position()));
  std::uint32_t roles = 0;
  if (!r.get(roles) || roles > kMaxRoles) return tl::unexpected(corrupt("bad role count", r.position()));
  for (std::uint32_t i = 0; i < roles; ++i) {
    std::uint16_t n = 0;
    std::string role;
    if (!r.get(n) || n > kMaxRoleBytes || !r.get_text(n, role))
      return tl::unexpected(corrupt("bad role name", r.position()));
    log.roles_.push_back(std::move(role));
  }
  std::uint32_t frames = 0;
  if (!r.get(frames)) return tl::unexpected(corrupt("missing frame count", r.position()));
  // Each frame takes at least 12 bytes: a count larger than the rest of the input is a lie.
  if (frames > r.remaining() / 12)
    return tl::unexpected(corrupt("frame count exceeds the data", r.position()));
  log.times_.reserve(frames);
  log.offsets_.reserve(frames + 1u);
  constexpr std::size_t kBytesPerAgent = 4 + 5 * 4 + 1 + 2 + 4;
  const auto activities = crowd::activity_names().size();
  for (std::uint32_t f = 0; f < frames; ++f) {
    double t = 0;
    std::uint32_t n = 0;
    if (!r.get(t) || !std::isfinite(t) || (f > 0 && t < log.times_.back()))
      return tl::unexpected(corrupt("frame " + std::to_string(f) + " has a bad time", r.position()));
    if (!r.get(n) || n > r.remaining() / kBytesPerAgent)
      return tl::unexpected(
          corrupt("frame " + std::to_string(f) + " agent count exceeds the data", r.position()));
    const std::size_t base = log.agents_.size();
    log.agents_.resize(base + n);
    auto column = [&](auto member, auto check) -> bool {
      for (std::uint32_t k = 0; k < n; ++k) {
        auto& value = log.agents_[base + k].*member;
        if (!r.get(value) || !check(value)) return false;
      }
      return true;
    };
    auto any = [](auto) { return true; };
    auto finite = [](float v) { return std::isfinite(v); };
    bool ok = column(&LoggedAgent::id, any) && column(&LoggedAgent::x, finite) &&
              column(&LoggedAgent::y, finite) && column(&LoggedAgent::yaw, finite) &&
              column(&LoggedAgent::vx, finite) && column(&LoggedAgent::vy, finite);
    if (ok) {
      for (std::uint32_t k = 0; k < n && ok; ++k) {
        std::uint8_t a = 0;
        ok = r.get(a) && a < activities;
        log.agents_[base + k].activity = static_cast<crowd::Activity>(a);
      }
    }
    ok = ok && column(&LoggedAgent::role, [&](std::uint16_t v) { return v < log.roles_.size(); }) &&
         column(&LoggedAgent::group_id, any);
    if (!ok)
      return tl::unexpected(corrupt("frame " + std::to_string(f) + " has a bad agent column", r.position()));
    for (std::uint32_t k = 1; k < n; ++k)
      if (log.agents_[base + k].id <= log.agents_[base + k - 1].id)
        return tl::unexpected(
            corrupt("frame " + std::to_string(f) + " ids are not increasing", r.position()));
    log.times_.push_back(t);
    log.offsets_.push_back(log.agents_.size());
  }
  if (r.remaining() != 0) return tl::unexpected(corrupt("trailing bytes", r.position()));
  log.seal();
  return log;
}

void TrajectoryLog::seal() {
  std::set<std::uint32_t> ids;
  for (const auto& a : agents_) ids.insert(a.id);
  agent_count_ = ids.size();
  sha256_ = sha256_hex(encoded());
}

TrajectoryRecorder::TrajectoryRecorder(double interval) {
  if (!(interval > 0) || !std::isfinite(interval))
    throw std::invalid_argument("trajectory frame interval must be > 0");
  log_.interval_ = interval;
}

void TrajectoryRecorder::add(double time, std::span<const crowd::PedestrianState> states) {
  const std::size_t base = log_.agents_.size();
  for (const auto& s : states) {
    if (s.activity == crowd::Activity::kExited) continue;
    auto it = std::find(log_.roles_.begin(), log_.roles_.end(), s.role);
    if (it == log_.roles_.end()) {
      if (log_.roles_.size() >= kMaxRoles)
        throw std::length_error("more than 65535 roles in one trajectory log");
      log_.roles_.push_back(s.role.substr(0, kMaxRoleBytes));
      it = log_.roles_.end() - 1;
    }
    LoggedAgent a;
    a.id = s.id.value();
    a.x = narrow(s.pose.x);
    a.y = narrow(s.pose.y);
    a.yaw = narrow(s.pose.yaw);
    a.vx = narrow(s.twist.vx);
    a.vy = narrow(s.twist.vy);
    a.activity = s.activity;
    a.role = static_cast<std::uint16_t>(it - log_.roles_.begin());
    a.group_id = static_cast<std::int32_t>(std::clamp<std::int64_t>(
        s.group_id, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()));
    log_.agents_.push_back(a);
  }
  std::sort(log_.agents_.begin() + static_cast<std::ptrdiff_t>(base), log_.agents_.end(),
            [](const LoggedAgent& l, const LoggedAgent& r) { return l.id < r.id; });
  log_.times_.push_back(time);
  log_.offsets_.push_back(log_.agents_.size());
}

TrajectoryLog TrajectoryRecorder::finish() && {
  log_.seal();
  return std::move(log_);
}

}  // namespace socsim::scenario
