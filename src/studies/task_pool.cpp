#include "studies/task_pool.hpp"

#include <omp.h>

#include <algorithm>
#include <thread>
#include <vector>

namespace coldspray::studies {

TaskPool::TaskPool(int jobs, int threads_per_job)
    : jobs_(std::max(1, jobs)),
      threads_(threads_per_job > 0 ? threads_per_job
                                   : std::max(1, omp_get_max_threads() / std::max(1, jobs))) {}

void TaskPool::submit(std::function<void()> task) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(std::move(task));
  }
  changed_.notify_one();
}

std::size_t TaskPool::queued() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return queue_.size();
}

void TaskPool::work() {
  omp_set_num_threads(threads_);
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    // A running task may still submit: wait for it unless nothing runs.
    changed_.wait(lock, [&] { return !queue_.empty() || running_ == 0; });
    if (queue_.empty()) return;
    std::function<void()> task = std::move(queue_.front());
    queue_.pop_front();
    ++running_;
    lock.unlock();
    task();
    task = nullptr;  // its captures (a branch's state) go now, not at the next task
    lock.lock();
    --running_;
    if (running_ == 0 && queue_.empty()) changed_.notify_all();
  }
}

void TaskPool::run() {
  std::vector<std::thread> pool;
  for (int j = 1; j < jobs_; ++j) pool.emplace_back([this] { work(); });
  work();
  for (auto& t : pool) t.join();
}

}  // namespace coldspray::studies
