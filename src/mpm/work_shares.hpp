// The stress update's division of work among threads: each thread takes one contiguous range of
// the step's items (batches of points, body after body), and the ranges move after every step so
// that the threads' measured times even out. Contiguous ranges keep each thread on its own part of
// the points and so of the grid, which mattered more than balance under OpenMP's schedules (docs/
// mpm.md, "Determinism and speed"); the feedback adds the balance: points that flow plastically
// cost more flow-stress evaluations, and they gather where the bodies touch. Which thread takes
// an item never changes its result, so the timings steer only the speed.
#pragma once

#include <cstddef>
#include <vector>

namespace coldspray::mpm {

class WorkShares {
 public:
  // Ranges for `shares` workers over `items` items: kept if they already are, else even.
  void prepare(int shares, std::size_t items);
  int shares() const { return static_cast<int>(seconds_.size()); }
  // Share k is items [first(k), first(k + 1)).
  std::size_t first(int k) const { return first_[static_cast<std::size_t>(k)]; }
  // The time share k took this step, in seconds.
  void record(int k, double seconds) { seconds_[static_cast<std::size_t>(k)] = seconds; }
  // Moves the ranges halfway towards equal times, taking each range's cost per item as uniform.
  void rebalance();

 private:
  std::vector<std::size_t> first_;   // shares + 1 boundaries, 0 .. items
  std::vector<double> seconds_;      // per share, the last step's time
  std::vector<std::size_t> target_;  // scratch for rebalance
};

}  // namespace coldspray::mpm
