// Building the peridynamics state from a validated case: the bodies seeded as for every solver
// (bodies/seed_bodies.hpp), their families and shape tensors, held points and contact laws.
#pragma once

#include "case/case.hpp"
#include "pd/state.hpp"

namespace coldspray::pd {

// Throws InputError (naming the key) for what only the seeded points reveal: overlapping bodies,
// a body with no points, or a point whose family cannot span three dimensions (a singular shape
// tensor: the spacing leaves a body too thin for one full family); Interrupted at SIGINT or
// SIGTERM, read while it seeds and builds the families and shape tensors (core/interrupt.hpp).
State build_state(const case_file::Case& c);

}  // namespace coldspray::pd
