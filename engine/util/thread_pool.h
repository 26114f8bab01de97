// A persistent pool of worker threads for work split into independent tasks (a
// frame's column strips): run(n, task) calls task(0..n-1) on the workers and the
// calling thread and returns when every call has returned. Tasks are handed out in
// order but finish in any order, so a task writes only its own results.
//
// Waking a sleeping thread costs tens of microseconds, a large part of a frame: a
// worker that has just finished spins briefly for the next run before it sleeps, and
// the caller spins for the workers to finish (their tasks are as short as its own).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace p3d {

class ThreadPool {
 public:
  // threads counts the caller: 1 runs everything on the calling thread.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return int(workers_.size()) + 1; }
  void run(int tasks, const std::function<void(int)>& task);
  // As run, adding each task's time in seconds to seconds[i]: a clock read to share
  // work out between threads, which never reaches what the tasks compute.
  void run_timed(int tasks, const std::function<void(int)>& task, std::span<double> seconds);

 private:
  void work();
  void take_tasks();
  bool wait_for_run(uint64_t seen);  // false: stop

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  const std::function<void(int)>* task_ = nullptr;
  int tasks_ = 0;
  std::atomic<int> next_{0};
  std::atomic<int> busy_{0};                 // workers still in the current run
  std::atomic<uint64_t> generation_{0};      // bumped by each run: a worker's signal to start
  std::atomic<bool> stop_{false};
};

}  // namespace p3d
