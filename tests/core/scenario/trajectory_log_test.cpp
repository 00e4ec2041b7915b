// Trajectory logs: recording skips exited agents and sorts by id, the byte format round-trips
// through zlib and the store bit for bit, and corrupt or hostile input is refused, never trusted.
#include "core/scenario/trajectory_log.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>

#include "core/scenario/trajectory_store.hpp"

namespace socsim::scenario {
namespace {

crowd::PedestrianState state(std::uint32_t id, double x, double y, const std::string& role,
                             crowd::Activity a = crowd::Activity::kWalking) {
  crowd::PedestrianState s;
  s.id = crowd::AgentId(id);
  s.pose = {x, y, 0.5};
  s.twist = {1.0, -0.25, 0.0};
  s.role = role;
  s.activity = a;
  s.group_id = id % 2 ? 7 : -1;
  return s;
}

TrajectoryLog sample_log() {
  TrajectoryRecorder rec(0.1);
  for (int f = 0; f < 5; ++f) {
    std::vector<crowd::PedestrianState> states = {
        state(2, 1.0 + f, 2.0, "nurse"), state(0, 0.5, f * 0.1, "visitor"),
        state(1, 3, 3, "visitor", f >= 3 ? crowd::Activity::kExited : crowd::Activity::kQueuing)};
    rec.add(f * 0.1, states);
  }
  return std::move(rec).finish();
}

TEST(TrajectoryLog, RecordsPresentAgentsInIdOrder) {
  const auto log = sample_log();
  ASSERT_EQ(log.frame_count(), 5u);
  EXPECT_EQ(log.agent_count(), 3u);
  EXPECT_EQ(log.roles(), (std::vector<std::string>{"nurse", "visitor"}));
  auto f0 = log.frame(0);
  ASSERT_EQ(f0.size(), 3u);
  EXPECT_EQ(f0[0].id, 0u);
  EXPECT_EQ(f0[2].id, 2u);
  EXPECT_EQ(log.roles()[f0[2].role], "nurse");
  EXPECT_EQ(f0[1].activity, crowd::Activity::kQueuing);
  EXPECT_EQ(f0[1].group_id, 7);
  EXPECT_EQ(log.frame(4).size(), 2u) << "agent 1 exited at frame 3";
  EXPECT_FLOAT_EQ(log.frame(4)[1].x, 5.0f);
  EXPECT_DOUBLE_EQ(log.frame_time(4), 0.4);
  EXPECT_TRUE(log.frame(9).empty());
}

TEST(TrajectoryLog, CompressedRoundTripIsBitIdentical) {
  const auto log = sample_log();
  EXPECT_EQ(log.sha256().size(), 64u);
  auto back = TrajectoryLog::from_compressed(log.compressed());
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(back->encoded(), log.encoded());
  EXPECT_EQ(back->sha256(), log.sha256());
  EXPECT_EQ(back->agent_count(), 3u);
}

TEST(TrajectoryLog, DifferentTrajectoriesHashDifferently) {
  TrajectoryRecorder a, b;
  std::vector<crowd::PedestrianState> sa = {state(0, 1.0, 1.0, "adult")};
  std::vector<crowd::PedestrianState> sb = {state(0, 1.0, 1.0001, "adult")};
  a.add(0, sa);
  b.add(0, sb);
  EXPECT_NE(std::move(a).finish().sha256(), std::move(b).finish().sha256());
}

TEST(TrajectoryLog, RefusesCorruptInput) {
  const auto log = sample_log();
  const std::string raw = log.encoded();
  EXPECT_FALSE(TrajectoryLog::from_encoded(raw.substr(0, raw.size() - 1)));  // truncated
  EXPECT_FALSE(TrajectoryLog::from_encoded(raw + "x"));                      // trailing
  std::string bad_magic = raw;
  bad_magic[0] = 'X';
  EXPECT_FALSE(TrajectoryLog::from_encoded(bad_magic));
  auto packed = log.compressed();
  packed[packed.size() / 2] ^= 0x5a;
  EXPECT_FALSE(TrajectoryLog::from_compressed(packed));
  // A length prefix that promises a huge inflation is refused before allocating.
  std::string bomb = log.compressed();
  const std::uint64_t huge = std::uint64_t{1} << 40;
  std::memcpy(bomb.data(), &huge, 8);
  auto r = TrajectoryLog::from_compressed(bomb);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().detail.find("exceeds the limit"), std::string::npos);
  EXPECT_FALSE(TrajectoryLog::from_compressed("abc"));
}

TEST(TrajectoryStore, SavesOnceAndLoadsByHash) {
  const auto dir = std::filesystem::temp_directory_path() / ("socsim_traj_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  auto store = store::Store::open((dir / "s.db").string());
  ASSERT_TRUE(store) << store.error().message();
  const auto log = sample_log();
  ASSERT_TRUE(save_trajectory_log(**store, log));
  ASSERT_TRUE(save_trajectory_log(**store, log)) << "saving the same log twice is idempotent";
  auto back = load_trajectory_log(**store, log.sha256());
  ASSERT_TRUE(back) << back.error().message();
  EXPECT_EQ(back->encoded(), log.encoded());
  auto missing = load_trajectory_log(**store, std::string(64, '0'));
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().code, ErrorCode::kNotFound);
  (*store)->close();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace socsim::scenario
