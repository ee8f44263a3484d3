// One explicit MUSL step of the material point method (thesis §3.4, steps 1-12).
#pragma once

#include "mpm/state.hpp"

namespace coldspray::mpm {

// The stable time step for the state's current wave speeds: cfl h / max(c + |v|) (or, with
// solver.dt_scale, that fraction of h / c of the undeformed materials).
double stable_time_step(const State& s, double cfl);

// Advances the state by s.dt; the points that moved out of the grid leave it at the end of the
// step (mpm/departures.hpp). Throws RunFault (naming body, point, time and cause) when a point's
// state stops being finite, a point crosses the axis in r-z or a body's bulk leaves the grid; the
// state is then that of the failed step.
// Which pairs of bodies may bond this step (ContactRule::may_bond): those whose impact has
// penetrated the bond law's critical share so far (bodies/penetration.hpp, docs/bonding.md
// "Activation"), none while the run carries bond shadows. The penetration only grows, so an
// activated pair stays so. The step calls it first.
void activate_bonding(State& s);

void step(State& s);

// step() in two halves, split where the contact step decides which nodes are bonded, so that a
// run can be copied there (run/bond_family.hpp): step_to_contact is steps 1-4 up to the contact
// correction, step_from_contact the rest (and the fault check).
void step_to_contact(State& s);
void step_from_contact(State& s);

}  // namespace coldspray::mpm
