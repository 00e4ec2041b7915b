#pragma once
// The trajectory log of a scenario: pedestrian states sampled at a fixed interval (10 Hz by
// default), in a documented little-endian byte format (socsim-traj-v1, docs/scenarios.md) whose
// SHA-256 a scenario card records, so a replay proves itself bit for bit. Compressed with zlib.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.hpp"
#include "core/crowd/pedestrian_state.hpp"

namespace socsim::scenario {

struct LoggedAgent {
  std::uint32_t id = 0;
  float x = 0, y = 0, yaw = 0, vx = 0, vy = 0;
  crowd::Activity activity = crowd::Activity::kWalking;
  std::uint16_t role = 0;  // index into TrajectoryLog::roles()
  std::int32_t group_id = -1;
};

inline constexpr std::string_view kTrajectoryFormat = "socsim-traj-v1+zlib";

class TrajectoryLog {
 public:
  TrajectoryLog() = default;

  [[nodiscard]] double frame_interval() const { return interval_; }
  [[nodiscard]] std::size_t frame_count() const { return times_.size(); }
  [[nodiscard]] double frame_time(std::size_t i) const { return times_.at(i); }
  [[nodiscard]] const std::vector<std::string>& roles() const { return roles_; }
  // Agents present in frame i (agents that exited are absent), in id order.
  [[nodiscard]] std::span<const LoggedAgent> frame(std::size_t i) const;
  [[nodiscard]] std::size_t agent_count() const { return agent_count_; }  // distinct ids
  [[nodiscard]] double duration() const { return times_.empty() ? 0.0 : times_.back() - times_.front(); }
  // Hex SHA-256 of encoded().
  [[nodiscard]] const std::string& sha256() const { return sha256_; }

  [[nodiscard]] std::string encoded() const;
  // 8-byte little-endian length of encoded(), then its zlib stream.
  [[nodiscard]] std::string compressed() const;
  // Untrusted input: every length and count is checked; at most `max_raw_bytes` are inflated.
  static Result<TrajectoryLog> from_compressed(std::string_view bytes, std::size_t max_raw_bytes = 1u << 30);
  static Result<TrajectoryLog> from_encoded(std::string_view bytes);

 private:
  friend class TrajectoryRecorder;
  void seal();  // computes agent_count_ and sha256_

  double interval_ = 0.1;
  std::vector<std::string> roles_;
  std::vector<double> times_;
  std::vector<std::size_t> offsets_{0};  // frame i = agents_[offsets_[i], offsets_[i+1])
  std::vector<LoggedAgent> agents_;
  std::size_t agent_count_ = 0;
  std::string sha256_;
};

// Collects frames from a ScenarioRunner's frame callback (call add() every `interval` seconds).
class TrajectoryRecorder {
 public:
  explicit TrajectoryRecorder(double interval = 0.1);
  void add(double time, std::span<const crowd::PedestrianState> states);
  [[nodiscard]] std::size_t frame_count() const { return log_.times_.size(); }
  TrajectoryLog finish() &&;

 private:
  TrajectoryLog log_;
};

}  // namespace socsim::scenario
