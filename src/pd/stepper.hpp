// One explicit step of correspondence peridynamics (PD paper eqs 5-8, 28-31), velocity Verlet.
#pragma once

#include "pd/state.hpp"

namespace coldspray::pd {

// cfl h / max((c + |v|) / min(1, lambda / 0.7)), h the smallest body spacing and lambda a point's
// compressed stretch (pd/time_step.hpp): a fixed fraction of the measured bound of the explicit
// scheme on the lattice as deformed (docs/pd.md, "Time step").
double stable_time_step(const State& s, double cfl);

// Advances the state by s.dt. Throws RunFault (body, point, time, cause) when a point's state
// stops being finite or its deformation gradient inverts; the state is then that of the failed
// step.
void step(State& s);

}  // namespace coldspray::pd
