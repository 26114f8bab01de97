// The pool runs every task of a run exactly once, on any thread count, run after run,
// whether its workers were spinning or asleep, and shuts down in either state.
#include "engine/util/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace p3d {
namespace {

void expect_each_task_once(ThreadPool& pool, int tasks, const std::string& what) {
  std::vector<std::atomic<int>> calls(size_t(tasks) + 1);
  pool.run(tasks, [&](int i) { calls[size_t(i)].fetch_add(1); });
  for (int i = 0; i < tasks; ++i) ASSERT_EQ(calls[size_t(i)].load(), 1) << what << ": task " << i << " of " << tasks;
  EXPECT_EQ(calls[size_t(tasks)].load(), 0) << what;
}

TEST(ThreadPool, RunsEveryTaskOncePerRun) {
  for (int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (int round = 0; round < 20; ++round)
      for (int tasks : {0, 1, 2, 7, 64})
        expect_each_task_once(pool, tasks, std::to_string(threads) + " threads, round " + std::to_string(round));
  }
}

// Runs far apart (a game's frames): the workers have gone to sleep between them.
TEST(ThreadPool, RunsAfterItsWorkersSlept) {
  ThreadPool pool(3);
  for (int frame = 0; frame < 4; ++frame) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    expect_each_task_once(pool, 8, "frame " + std::to_string(frame));
  }
}

// A pool destroyed with its workers spinning, asleep, or never used joins them all.
TEST(ThreadPool, ShutsDownWhateverItsWorkersAreDoing) {
  for (int i = 0; i < 12; ++i) {
    ThreadPool pool(2);
    if (i % 3 == 1) expect_each_task_once(pool, 4, "spinning");
    if (i % 3 == 2) {
      expect_each_task_once(pool, 4, "asleep");
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
}

// run_timed adds each task's own time to its entry: a task that sleeps is seen to take
// at least its sleep, run after run, and the others no more than they did.
TEST(ThreadPool, TimesEachTaskIntoItsOwnEntry) {
  ThreadPool pool(2);
  std::vector<double> seconds(3, 0.0);
  const auto task = [](int i) {
    if (i == 1) std::this_thread::sleep_for(std::chrono::milliseconds(3));
  };
  pool.run_timed(3, task, seconds);
  pool.run_timed(3, task, seconds);
  EXPECT_GE(seconds[1], 0.006);
  for (const double s : seconds) EXPECT_GE(s, 0.0);
  EXPECT_LT(seconds[0] + seconds[2], seconds[1]);
}

}  // namespace
}  // namespace p3d
