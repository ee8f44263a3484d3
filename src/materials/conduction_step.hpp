// The time-step bound of explicit heat conduction (solver.heat_conduction): the solver's and the
// case check's, from one formula.
#pragma once

namespace coldspray::materials {

// Explicit conduction (forward Euler in time) is stable for alpha dt / h^2 <= 1 / (2 n) on a
// lattice of n dimensions; half of that, since a point's stencil spans more than two cells.
inline double conduction_step_limit(double h, bool axisymmetric, double diffusivity) {
  const double dimensions = axisymmetric ? 2.0 : 3.0;
  return 0.5 * h * h / (2.0 * dimensions * diffusivity);
}

}  // namespace coldspray::materials
