// Building the MPM state from a validated case: the grid, the seeded points with their initial
// material state, node constraints, absorbing faces and the contact rule.
#pragma once

#include "case/case.hpp"
#include "case/grid_domain.hpp"
#include "mpm/state.hpp"

namespace coldspray::mpm {

// Throws InputError (naming the key) for what only the seeded geometry reveals: bodies that
// overlap at t = 0, a body outside a grid given by grid.min/max, a body with no points;
// Interrupted at SIGINT or SIGTERM, read while it seeds the bodies (core/interrupt.hpp).
State build_state(const case_file::Case& c);

// The margin around the bodies when grid.min/max are not given (case/grid_domain.hpp).
using case_file::kGridMarginFraction;
using case_file::kGridMarginMinCells;

}  // namespace coldspray::mpm
