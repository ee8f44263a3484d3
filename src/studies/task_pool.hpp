// Tasks run on a few threads of this process, as the studies' cases are. A task may submit more
// (a bond family hands its branches on, run/bond_family.hpp); run() returns once none is queued
// or running. Tasks start in the order they were submitted.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>

namespace coldspray::studies {

class TaskPool {
 public:
  // `jobs` threads (run()'s caller among them), each set to `threads_per_job` OpenMP threads
  // (0: the cores shared among the jobs).
  TaskPool(int jobs, int threads_per_job);

  // Before run(), or from a running task (on any thread). Tasks must not throw.
  void submit(std::function<void()> task);
  // Tasks waiting for a thread.
  std::size_t queued() const;
  int jobs() const { return jobs_; }
  // Runs the tasks, and those they submit, until none is left.
  void run();

 private:
  void work();

  int jobs_, threads_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> queue_;
  int running_ = 0;
};

}  // namespace coldspray::studies
