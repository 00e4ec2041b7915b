#include "server/frame_sources.hpp"

#include <algorithm>

namespace socsim::server {

namespace {

std::int32_t clamp_group(std::int64_t g) {
  return static_cast<std::int32_t>(std::clamp<std::int64_t>(g, -1, std::numeric_limits<std::int32_t>::max()));
}

class RunnerSource final : public FrameSource {
 public:
  RunnerSource(std::shared_ptr<const world::World> world, std::unique_ptr<crowd::ScenarioRunner> runner,
               double duration)
      : world_(std::move(world)), runner_(std::move(runner)), duration_(duration) {
    roles_ = runner_->sim().roles().names();
    for (std::size_t i = 0; i < roles_.size(); ++i)
      role_index_.emplace(roles_[i], static_cast<std::uint8_t>(std::min<std::size_t>(i, 255)));
  }
  [[nodiscard]] double time() const override { return runner_->time(); }
  [[nodiscard]] double interval() const override { return runner_->sim().config().dt; }
  [[nodiscard]] double start_time() const override { return 0.0; }
  [[nodiscard]] double end_time() const override { return duration_; }
  [[nodiscard]] std::vector<std::string> roles() const override { return roles_; }
  [[nodiscard]] std::size_t agent_count() const override { return runner_->agents().size(); }
  bool advance() override {
    runner_->step();
    return true;
  }
  void snapshot(std::vector<FrameAgent>& out, TargetTable& targets) override {
    const std::vector<crowd::PedestrianState> states = runner_->states();
    out.clear();
    out.reserve(states.size());
    for (const crowd::PedestrianState& s : states) {
      if (s.activity == crowd::Activity::kExited) continue;  // gone: absent from the frame
      FrameAgent a;
      a.id = s.id.value();
      a.x = static_cast<float>(s.pose.x);
      a.y = static_cast<float>(s.pose.y);
      a.yaw = static_cast<float>(s.pose.yaw);
      a.vx = static_cast<float>(s.twist.vx);
      a.vy = static_cast<float>(s.twist.vy);
      a.group_id = clamp_group(s.group_id);
      a.state = static_cast<std::uint8_t>(s.activity);
      auto r = role_index_.find(s.role);
      a.role = r == role_index_.end() ? 255 : r->second;
      a.target = targets.of(s.intent.target);
      out.push_back(a);
    }
  }

 private:
  std::shared_ptr<const world::World> world_;  // the runner refers to it
  std::unique_ptr<crowd::ScenarioRunner> runner_;
  double duration_;
  std::vector<std::string> roles_;
  std::unordered_map<std::string, std::uint8_t> role_index_;
};

class RecordingSource final : public FrameSource {
 public:
  explicit RecordingSource(scenario::TrajectoryLog log) : log_(std::move(log)) {}
  [[nodiscard]] double time() const override { return log_.frame_time(frame_); }
  [[nodiscard]] double interval() const override { return log_.frame_interval(); }
  [[nodiscard]] double start_time() const override { return log_.frame_time(0); }
  [[nodiscard]] double end_time() const override { return log_.frame_time(log_.frame_count() - 1); }
  [[nodiscard]] std::vector<std::string> roles() const override { return log_.roles(); }
  [[nodiscard]] bool seekable() const override { return true; }
  [[nodiscard]] std::size_t agent_count() const override { return log_.agent_count(); }
  bool advance() override {
    if (frame_ + 1 >= log_.frame_count()) return false;
    ++frame_;
    return true;
  }
  // The last frame at or before t.
  void seek(double t) override {
    std::size_t lo = 0, hi = log_.frame_count() - 1;
    while (lo < hi) {
      const std::size_t mid = (lo + hi + 1) / 2;
      if (log_.frame_time(mid) <= t + 1e-9)
        lo = mid;
      else
        hi = mid - 1;
    }
    frame_ = lo;
  }
  void snapshot(std::vector<FrameAgent>& out, TargetTable&) override {
    const auto agents = log_.frame(frame_);
    out.clear();
    out.reserve(agents.size());
    for (const scenario::LoggedAgent& l : agents) {
      FrameAgent a;
      a.id = l.id;
      a.x = l.x;
      a.y = l.y;
      a.yaw = l.yaw;
      a.vx = l.vx;
      a.vy = l.vy;
      a.group_id = l.group_id;
      a.state = static_cast<std::uint8_t>(l.activity);
      a.role = static_cast<std::uint8_t>(std::min<std::uint16_t>(l.role, 255));
      out.push_back(a);
    }
  }

 private:
  scenario::TrajectoryLog log_;
  std::size_t frame_ = 0;
};

}  // namespace

std::size_t program_agent_count(const crowd::Program& p) {
  std::size_t n = p.robot ? 1 : 0;
  for (const auto& a : p.agents) n += a.count;
  for (const auto& g : p.ambient_groups) n += g.size;
  return n;
}

std::unique_ptr<FrameSource> runner_source(std::shared_ptr<const world::World> world,
                                           std::unique_ptr<crowd::ScenarioRunner> runner, double duration) {
  return std::make_unique<RunnerSource>(std::move(world), std::move(runner), duration);
}

std::unique_ptr<FrameSource> recording_source(scenario::TrajectoryLog log) {
  return std::make_unique<RecordingSource>(std::move(log));
}

}  // namespace socsim::server
