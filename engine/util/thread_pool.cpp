#include "engine/util/thread_pool.h"

#include <chrono>

namespace p3d {

namespace {

constexpr auto kSpin = std::chrono::microseconds(50);

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

ThreadPool::ThreadPool(int threads) {
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void ThreadPool::take_tasks() {
  for (int i; (i = next_.fetch_add(1)) < tasks_;) (*task_)(i);
}

void ThreadPool::run(int tasks, const std::function<void(int)>& task) {
  if (workers_.empty() || tasks <= 1) {
    for (int i = 0; i < tasks; ++i) task(i);
    return;
  }
  task_ = &task;
  tasks_ = tasks;
  next_ = 0;
  busy_ = int(workers_.size());
  {
    std::lock_guard lock(mutex_);  // a worker about to sleep sees the new generation or is woken
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  take_tasks();
  for (int spins = 0; busy_.load(std::memory_order_acquire) != 0; ++spins)
    spins < 4096 ? relax() : std::this_thread::yield();
}

void ThreadPool::run_timed(int tasks, const std::function<void(int)>& task, std::span<double> seconds) {
  run(tasks, [&](int i) {
    const auto start = std::chrono::steady_clock::now();
    task(i);
    seconds[size_t(i)] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
}

// Spins for a moment, then sleeps, until the generation moves past `seen`.
bool ThreadPool::wait_for_run(uint64_t seen) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int spins = 0; generation_.load(std::memory_order_acquire) == seen && !stop_; ++spins) {
    relax();
    if (spins % 64 == 63 && std::chrono::steady_clock::now() > until) {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_.load() != seen; });
    }
  }
  return !stop_;
}

void ThreadPool::work() {
  uint64_t seen = 0;
  while (wait_for_run(seen)) {
    seen = generation_.load(std::memory_order_acquire);
    take_tasks();
    busy_.fetch_sub(1, std::memory_order_release);
  }
}

}  // namespace p3d
