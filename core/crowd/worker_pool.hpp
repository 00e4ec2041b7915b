#pragma once
// A small persistent pool of compute threads for stepping the crowd: parallel_for hands out
// index chunks to the calling thread plus (threads - 1) workers and returns when all are done.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace socsim::crowd {

class WorkerPool {
 public:
  using RangeFn = std::function<void(std::size_t begin, std::size_t end)>;

  // `threads` counts the caller: 1 means no extra thread is started.
  explicit WorkerPool(unsigned threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  [[nodiscard]] unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }
  // Inside fn: which of this pool's threads runs it, 0 .. threads() − 1 (0: the caller's).
  [[nodiscard]] static unsigned current_thread();

  // Calls fn on disjoint ranges covering [0, count), each at most `chunk` long (one call for all
  // of it when the pool has one thread or count <= chunk). Which thread runs which range varies;
  // callers must make each index's work independent of the others.
  // An exception thrown by fn is rethrown here after all ranges finished.
  void parallel_for(std::size_t count, std::size_t chunk, const RangeFn& fn);

 private:
  void worker_loop();
  void drain(unsigned self);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_cv_;
  std::condition_variable done_cv_;
  // Written under mutex_, read by spinning threads without it.
  std::atomic<std::size_t> generation_{0};
  std::atomic<unsigned> busy_{0};
  std::atomic<bool> stop_{false};

  const RangeFn* fn_ = nullptr;
  std::size_t chunk_ = 1;
  // Thread t takes chunks from its own part of [0, count) first (part t of threads(), so the same
  // thread runs the same indices in consecutive loops over the same agents, and their data stays
  // in its core's cache), then from the other parts (so no thread waits while chunks are left).
  struct alignas(64) Part {
    std::atomic<std::size_t> next{0};
    std::size_t end = 0;
  };
  std::vector<Part> parts_;
  std::exception_ptr error_;
};

}  // namespace socsim::crowd
