// One explicit MUSL step of the material point method (thesis §3.4, steps 1-12).
#pragma once

#include "mpm/state.hpp"

namespace coldspray::mpm {

// The stable time step for the state's current wave speeds: cfl h / max(c + |v|) (or, with
// solver.dt_scale, that fraction of h / c of the undeformed materials).
double stable_time_step(const State& s, double cfl);

// Advances the state by s.dt. Throws RunFault (naming body, point, time and cause) when a point
// leaves the grid or its state stops being finite; the state is then that of the failed step.
void step(State& s);

}  // namespace coldspray::mpm
