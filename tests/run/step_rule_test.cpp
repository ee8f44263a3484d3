// The time step rules (run/step_rule.hpp): solver.cfl follows the signal speed every step;
// solver.dt_scale holds the given fraction of the undeformed critical step, which at dt_scale =
// cfl is the CFL rule's first step (examples/al-14um-810-3d-fast.yaml, docs/validation/
// coarsening.md).
#include "run/step_rule.hpp"

#include <gtest/gtest.h>

namespace coldspray::run {
namespace {

// A solver state whose CFL bound is cfl h / (c + |v|), found by argument-dependent lookup as
// mpm::stable_time_step is.
struct SignalState : bodies::Bodies {
  double h = 0.7e-6;       // m
  double max_speed = 0.0;  // max c + |v|, m/s
};
double stable_time_step(const SignalState& s, double cfl) { return cfl * s.h / s.max_speed; }

TEST(StepRule, DtScaleHoldsTheFirstStepWhereTheCflRuleFollowsTheSignalSpeed) {
  case_file::Case c;
  c.solver.end_time = 80e-9;
  c.solver.cfl = 0.3;
  SignalState s;
  s.max_speed = 7282.0;  // the 3D fast case at t = 0: c = 6 472 m/s, v = 810 m/s
  const StepRule cfl_rule(c, s);
  c.solver.dt_scale = 0.3;
  const StepRule fixed_rule(c, s);
  const double first = 0.3 * 0.7e-6 / 7282.0;  // 28.84 ps
  EXPECT_DOUBLE_EQ(cfl_rule.next_dt(s), first);
  EXPECT_DOUBLE_EQ(fixed_rule.next_dt(s), first);
  // Later a crushed point's c + |v| reaches 9 330 m/s: the CFL step shrinks, the fixed one stays.
  s.time = 75e-9;
  s.max_speed = 9330.0;
  EXPECT_DOUBLE_EQ(cfl_rule.next_dt(s), 0.3 * 0.7e-6 / 9330.0);
  EXPECT_DOUBLE_EQ(fixed_rule.next_dt(s), first);
  // The last step of either lands on the end time.
  s.time = 80e-9 - 1e-12;
  EXPECT_NEAR(fixed_rule.next_dt(s), 1e-12, 1e-22);  // (80 ns carries 1.3e-23 s of rounding)
}

}  // namespace
}  // namespace coldspray::run
