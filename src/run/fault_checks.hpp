// The checks that keep a broken run from ending as ok (docs/reliability.md, "Faults that cannot
// pass as ok"): on a fixed stride of steps, whatever the output settings, a run stops as a fault
// when a temperature or a term of its energy budget is not finite, when its total energy has
// grown, when its absorbing faces have given energy back, or when a body moves faster than the
// run's energy allows.
#pragma once

#include "bodies/bodies.hpp"
#include "metrics/energy.hpp"

namespace coldspray::run {

// Steps between the checks (and always the last step). The energy budget and the bodies'
// momenta are a pass over the points each: every step they would cost some percent of a step,
// every 10th a fraction of a percent, and an instability that the checks catch grows over tens
// of steps (the reproducer of issue 24 doubles its kinetic energy every 2-3 steps), so the run
// stops at most 9 steps after the check could first have seen it. A stride in steps, not in
// simulated time, so that the verdict does not depend on output.history_interval.
inline constexpr long kFaultCheckStride = 10;

// The budget's tolerance: a run whose total energy grows past (1 + this) times its initial total
// stops as a fault, and the same share of the initial total bounds the energy the absorbing faces
// may give back and a body's mean motion beyond the initial total.
inline constexpr double kEnergyGrowthLimit = 0.2;

class FaultChecks {
 public:
  // `initial_total`: the run's total energy at t = 0 (kinetic + internal). `driven`: energy may
  // enter the bodies through the budget's contact entry: an adhesive contact's well (the PD
  // paper's contact models), whose depth the bodies may turn into motion, or a grip that moves a
  // body (pd/grip.hpp).
  explicit FaultChecks(double initial_total, bool driven = false)
      : initial_total_(initial_total), driven_(driven) {}

  double initial_total() const { return initial_total_; }

  // Whether the checks fall due after the step that ended at s.step.
  static bool due(const bodies::Bodies& s, bool last) {
    return last || s.step % kFaultCheckStride == 0;
  }

  // Throws RunFault with the body (where there is one), time, cause and numbers of the first
  // fault found, `e` being the energy budget of `s`. Allocates nothing unless it throws.
  void check(const bodies::Bodies& s, const metrics::EnergyBudget& e) const;

 private:
  double initial_total_;
  bool driven_;
};

}  // namespace coldspray::run
