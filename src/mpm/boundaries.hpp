// Boundary conditions: essential conditions at grid nodes (grid faces fixed or roller, the
// axis of symmetry, bodies' fixed faces) and absorbing dashpots on bodies' faces.
#pragma once

#include "mpm/state.hpp"

namespace coldspray::mpm {

// Zeroes the held velocity components (State::constraint) of the nodal momenta, total and
// per body; with force_too also of the nodal forces.
void apply_node_constraints(State& s, bool force_too);

// Lysmer-Kuhlemeyer dashpots (thesis §3.5.5, eqs 3.45-3.46): each absorbing point gets the
// external force -damping (x) v from its velocity at the start of the step.
void apply_absorbing_dashpots(State& s);

// After the step: the dashpots' work, -f . dx with dx the point's displacement over the step
// (the grid velocities it moved with), is added to each point's absorbed energy.
void account_absorbed_work(State& s);

}  // namespace coldspray::mpm
