#include "core/crowd/worker_pool.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace socsim::crowd {

namespace {

void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// A step calls parallel_for several times in a row (neighbour forces, separation passes, the
// update) with serial work between them: up to a few hundred microseconds for 10,000 agents
// (rebuilding the cell index). Waking a sleeping thread costs tens of microseconds, more on a
// virtual machine, so both sides first wait actively for the state they wait for, up to
// kSpinTime, and only then sleep on the condition variable: for kPauseTime spinning with pause,
// then yielding the processor between looks, so threads of other simulations (or anything else)
// that have work run first. Timed rather than counted: a pause takes 3 ns on some processors and
// 30–40 ns on others; 2,048 pauses (62 µs here) let the worker fall asleep before most steps'
// first parallel loop. (No speed-up of the whole step survived alternated runs on the noisy test
// machine: docs/PERFORMANCE.md, "Session 18".)
constexpr auto kPauseTime = std::chrono::microseconds(300);
constexpr auto kSpinTime = std::chrono::microseconds(1000);

// Waits actively until ready() or kSpinTime has passed (the caller then checks again, and sleeps).
template <class Ready>
void spin_until(Ready ready) {
  const auto start = std::chrono::steady_clock::now();
  bool yielding = false;
  for (unsigned k = 1;; ++k) {
    if (ready()) return;
    if (yielding) {
      std::this_thread::yield();
    } else {
      relax();
    }
    if (yielding || k % 64 == 0) {
      const auto waited = std::chrono::steady_clock::now() - start;
      if (waited > kSpinTime) return;
      yielding = waited > kPauseTime;
    }
  }
}

thread_local unsigned t_thread_index = 0;  // set once by each worker

}  // namespace

WorkerPool::WorkerPool(unsigned threads) : parts_(std::max(threads, 1u)) {
  const unsigned extra = threads > 1 ? threads - 1 : 0;
  workers_.reserve(extra);
  for (unsigned i = 0; i < extra; ++i)
    workers_.emplace_back([this, i] {
      t_thread_index = i + 1;
      worker_loop();
    });
}

unsigned WorkerPool::current_thread() {
  return t_thread_index;
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  start_cv_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::drain(unsigned self) {
  const auto n = static_cast<unsigned>(parts_.size());
  for (unsigned k = 0; k < n; ++k) {
    Part& part = parts_[(self + k) % n];
    for (;;) {
      const std::size_t begin = part.next.fetch_add(chunk_, std::memory_order_relaxed);
      if (begin >= part.end) break;
      const std::size_t end = std::min(part.end, begin + chunk_);
      try {
        (*fn_)(begin, end);
      } catch (...) {
        std::lock_guard lock(mutex_);
        if (!error_) error_ = std::current_exception();
      }
    }
  }
}

void WorkerPool::worker_loop() {
  std::size_t seen = 0;
  for (;;) {
    spin_until([&] {
      return generation_.load(std::memory_order_acquire) != seen || stop_.load(std::memory_order_acquire);
    });
    {
      std::unique_lock lock(mutex_);
      start_cv_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    drain(t_thread_index);
    if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      std::lock_guard lock(mutex_);  // the caller checks busy_ under the mutex before it sleeps
      done_cv_.notify_one();
    }
  }
}

void WorkerPool::parallel_for(std::size_t count, std::size_t chunk, const RangeFn& fn) {
  if (count == 0) return;
  chunk = std::max<std::size_t>(chunk, 1);
  if (workers_.empty() || count <= chunk) {
    fn(0, count);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    fn_ = &fn;
    chunk_ = chunk;
    // Equal parts (the same split for every loop over the same count, whatever its chunk).
    const auto n = parts_.size();
    for (std::size_t p = 0; p < n; ++p) {
      parts_[p].next.store(count * p / n, std::memory_order_relaxed);
      parts_[p].end = count * (p + 1) / n;
    }
    error_ = nullptr;
    busy_ = static_cast<unsigned>(workers_.size());
    ++generation_;
  }
  start_cv_.notify_all();
  drain(0);
  spin_until([&] { return busy_.load(std::memory_order_acquire) == 0; });
  std::exception_ptr error;
  {
    std::unique_lock lock(mutex_);
    done_cv_.wait(lock, [&] { return busy_ == 0; });
    fn_ = nullptr;
    error = error_;
    error_ = nullptr;
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace socsim::crowd
