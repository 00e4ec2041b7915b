#pragma once
// Cooperative cancellation of LLM calls: the job that owns a token cancels it, and the client
// notices between retries, while waiting for a concurrency slot and during a transfer.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>

namespace socsim::llm {

class CancelToken {
 public:
  CancelToken() : state_(std::make_shared<State>()) {}  // copies share one flag

  void cancel() const {
    {
      std::lock_guard<std::mutex> lock(state_->mutex);
      state_->cancelled.store(true);
    }
    state_->cv.notify_all();
  }
  [[nodiscard]] bool cancelled() const { return state_->cancelled.load(); }

  // Sleeps until `until` or until cancelled; false when cancelled.
  bool sleep_until(std::chrono::steady_clock::time_point until) const {
    std::unique_lock<std::mutex> lock(state_->mutex);
    return !state_->cv.wait_until(lock, until, [&] { return state_->cancelled.load(); });
  }

 private:
  struct State {
    std::mutex mutex;
    std::condition_variable cv;
    std::atomic<bool> cancelled{false};
  };
  std::shared_ptr<State> state_;
};

}  // namespace socsim::llm
