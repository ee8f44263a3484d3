// Boundary conditions: essential conditions at grid nodes (grid faces fixed or roller, the
// axis of symmetry, bodies' fixed faces) and absorbing dashpots on bodies' faces.
#pragma once

#include "mpm/state.hpp"

namespace coldspray::mpm {

// Zeroes the held velocity components (State::constraint) of the nodal momenta, total and
// per body; with force_too also of the nodal forces.
void apply_node_constraints(State& s, bool force_too);

// Lysmer-Kuhlemeyer dashpots (thesis §3.5.5, eqs 3.45-3.46): each absorbing point gets the
// external force -damping (x) v, v the velocity the material at the point moved with over the
// last step (its displacement over that step's dt, the grid's velocity there; at the first step
// the point's own). Not the point's FLIP velocity: that carries increments the grid cannot see
// (Hammerquist and Nairn, CMAME 318 (2017) 724), and damping them through the grid put energy
// in: on the size-similar substrate a 14 um particle rebounding at 500 m/s left the dashpots'
// ledger at -1.0e-7 J by 66 ns (-20 % of the run's energy) and the substrate's plastic work
// 21 % up after the impact, at the axis by the bottom face; with the grid's velocity the ledger
// only grows and the plastic work rises 0.4 % (docs/mpm.md, "Grid and boundaries").
void apply_absorbing_dashpots(State& s);

// After the step: the dashpots' work, -f . dx with dx the point's displacement over the step
// (the grid velocities it moved with), is added to each point's absorbed energy.
void account_absorbed_work(State& s);

}  // namespace coldspray::mpm
