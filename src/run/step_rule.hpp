// How a run chooses its time step and when it ends: solver.cfl, solver.dt_scale, solver.end_time,
// and the extensions of a run whose verdict is undecided (metrics.verdict_window,
// metrics.verdict_extensions; docs/bonding.md).
#pragma once

#include <algorithm>

#include "bodies/bodies.hpp"
#include "case/case.hpp"

namespace coldspray::run {

// Whichever the solver: its state `s` has a stable_time_step(s, cfl) beside it (found by
// argument-dependent lookup, as mpm::stable_time_step), the CFL bound for its wave speeds.
struct StepRule {
  // From the case and the stable step of the undeformed materials (at cfl 1): solver.dt_scale
  // fixes dt at that fraction of it (the thesis' scaling of the critical step, §5.1.4);
  // otherwise dt follows the CFL bound every step.
  StepRule(const case_file::Case& c, double undeformed_step)
      : end(c.solver.end_time),
        cfl(c.solver.cfl),
        fixed_dt(c.solver.dt_scale ? *c.solver.dt_scale * undeformed_step : 0.0),
        window(c.metrics.verdict_window),
        extensions_left(c.metrics.verdict_extensions) {}
  // The same from a solver's state at t = 0.
  template <class State>
  StepRule(const case_file::Case& c, const State& s) : StepRule(c, stable_time_step(s, 1.0)) {}

  // The next step's dt, the last one shortened to land on the end time.
  template <class State>
  double next_dt(const State& s) const {
    return std::min(fixed_dt > 0.0 ? fixed_dt : stable_time_step(s, cfl), end - s.time);
  }
  bool finished(const bodies::Bodies& s) const { return s.time >= end * (1.0 - 1e-12); }
  // Moves the end one verdict window later, if an extension is left; returns whether it did.
  bool extend() {
    if (extensions_left <= 0) return false;
    --extensions_left;
    end += window;
    return true;
  }

  double end, cfl, fixed_dt, window;
  int extensions_left;
};

}  // namespace coldspray::run
