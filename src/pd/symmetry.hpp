// Symmetry planes in peridynamics (the case's `symmetry`): the modelled part of each body keeps
// its families whole across a plane through ghost points, the mirror images of the real points
// within a horizon (plus half a spacing) of the plane, and of the corner where two planes meet.
// A ghost's position, velocity, A, velocity fit Cdot, flow direction N, softening and slip fit
// are its source's, reflected: y' = R y + 2 (plane) on the flipped axes, v' = R v, A' = R A R,
// N' = R N R and Cdot' = R Cdot Q (pd/quadratic_fit.hpp) with R = diag(+-1, +-1, 1). So a quarter
// model costs a quarter, and the points near a plane see the same neighbours as in the whole body.
#pragma once

#include "pd/state.hpp"

namespace coldspray::pd {

// Appends the ghosts of every real point within reach of the planes to s.ghosts and
// s.neighbours (reference positions, volumes, bodies); s.neighbours holds the real points.
void add_ghosts(State& s);

// The ghosts' positions and velocities from their sources' (after the points moved).
void refresh_ghost_motion(State& s);

// The ghosts' A, Cdot, flow direction and softening from their sources' (after the stress
// update).
void refresh_ghost_tensors(State& s);

// The ghosts' slip fits (pd/control_along_flow.hpp) from their sources' (within the force loop).
void refresh_ghost_slip_fits(State& s);

// Copies the real points' positions and velocities into s.neighbours, then the ghosts'.
void refresh_neighbours(State& s);

}  // namespace coldspray::pd
