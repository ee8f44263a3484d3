// Output times at a fixed interval of simulated time: an output is due once per interval crossed
// (at every step, with interval 0). Times within 1e-9 of an interval count as on it.
#pragma once

#include <string>

namespace coldspray::run {

class Schedule {
 public:
  explicit Schedule(double interval) : interval_(interval) {}
  bool due(double t) const { return interval_ <= 0.0 || t + 1e-9 * interval_ >= next_; }
  // The output at t is done: the next is due at the first interval past t.
  void done(double t) {
    if (interval_ <= 0.0) return;
    while (next_ <= t + 1e-9 * interval_) next_ += interval_;
  }
  // Its progress in a checkpoint (checkpoint/archive.hpp).
  template <class Archive>
  void fields(Archive& a, const std::string& name) {
    a(name, next_);
  }

 private:
  double interval_;
  double next_ = 0.0;
};

}  // namespace coldspray::run
