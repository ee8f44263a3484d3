// Building the MPM state from a validated case: the grid, the seeded points with their initial
// material state, node constraints, absorbing faces and the contact rule.
#pragma once

#include "case/case.hpp"
#include "mpm/state.hpp"

namespace coldspray::mpm {

// Throws InputError (naming the key) for what only the seeded geometry reveals: bodies that
// overlap at t = 0, a body outside a grid given by grid.min/max, a body with no points.
State build_state(const case_file::Case& c);

// The margin added around the bodies when grid.min/max are not given: half the bodies' extent
// along each axis (at least 4 cells), so that rebounding and jetted material stays on the grid
// through a typical impact. A point that still leaves the domain leaves the run
// (mpm/departures.hpp).
inline constexpr double kGridMarginFraction = 0.5;
inline constexpr int kGridMarginMinCells = 4;

}  // namespace coldspray::mpm
