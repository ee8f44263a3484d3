// When a run writes a checkpoint (run/checkpoints.hpp): every output.checkpoint_interval of
// simulated time and every output.checkpoint_wall_interval of wall-clock time (0 turns either
// off), and always at the end and at a fault; the last output.checkpoint_keep are kept.
#pragma once

#include <string>

#include "case/case.hpp"
#include "run/schedule.hpp"

namespace coldspray::run {

class CheckpointPolicy {
 public:
  explicit CheckpointPolicy(const case_file::Output& o)
      : simulated_(o.checkpoint_interval),
        simulated_interval_(o.checkpoint_interval),
        wall_interval_(o.checkpoint_wall_interval),
        keep_(o.checkpoint_keep) {
    simulated_.done(0.0);  // none at t = 0: the case is that checkpoint
  }
  // Whether one falls due after the step that ended at simulated `time`, `wall` seconds after
  // this process started the run.
  bool due(double time, double wall) const {
    return enabled_ && ((simulated_interval_ > 0.0 && simulated_.due(time)) ||
                        (wall_interval_ > 0.0 && wall - last_wall_ >= wall_interval_));
  }
  void done(double time, double wall) {
    simulated_.done(time);
    last_wall_ = wall;
  }
  int keep() const { return keep_; }
  // Whether the run writes checkpoints at all: run_case's do; a bond family's members, which
  // share their steps (run/bond_family.hpp), do not.
  bool enabled() const { return enabled_; }
  void enable() { enabled_ = true; }

  // Its progress in a checkpoint (checkpoint/archive.hpp). (The wall clock restarts with the
  // process.)
  template <class Archive>
  void fields(Archive& a) {
    simulated_.fields(a, "recorder/checkpoint_due");
  }

 private:
  Schedule simulated_;
  double simulated_interval_, wall_interval_;
  int keep_;
  double last_wall_ = 0.0;
  bool enabled_ = false;
};

}  // namespace coldspray::run
