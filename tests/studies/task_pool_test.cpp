// The studies' task pool: every task runs once, also those submitted by running tasks (a bond
// family's branches), on no more threads at once than jobs; run() returns when all are done.
#include "studies/task_pool.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace coldspray::studies {
namespace {

TEST(TaskPool, RunsSubmittedTasksAndTheirChildrenOnce) {
  TaskPool pool(3, 1);
  std::vector<std::atomic<int>> runs(40);
  std::atomic<int> running{0}, most{0};
  // Tasks 0-9 each submit 3 more (10 + 3k, ...), some after a pause, so that workers find the
  // queue empty while a task is still running and must wait for what it submits.
  auto task = [&](auto& self, int k) -> void {
    const int now = ++running;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    ++runs[k];
    if (k < 10) {
      std::this_thread::sleep_for(std::chrono::milliseconds(k % 3 == 0 ? 20 : 1));
      for (int c = 0; c < 3; ++c) pool.submit([&self, k, c] { self(self, 10 + 3 * k + c); });
    }
    --running;
  };
  for (int k = 0; k < 10; ++k) pool.submit([&task, k] { task(task, k); });
  pool.run();
  for (int k = 0; k < 40; ++k) EXPECT_EQ(runs[k].load(), 1) << k;
  EXPECT_LE(most.load(), 3);
  EXPECT_EQ(pool.queued(), 0u);
}

TEST(TaskPool, AnEmptyPoolReturns) {
  TaskPool pool(2, 1);
  pool.run();
  EXPECT_EQ(pool.queued(), 0u);
}

}  // namespace
}  // namespace coldspray::studies
