// The energy budget of a run: kinetic + internal + viscous + absorbed + contact + departed
// must stay equal to the initial total (kinetic + internal at t = 0). Kinetic, internal and
// plastic work are of the points on the grid; the works done (viscous, absorbed, contact) count
// the points that have left it too, and `departed` is what those carried off (mpm/departures.hpp).
#pragma once

#include "bodies/bodies.hpp"

namespace coldspray::metrics {

struct EnergyBudget {
  double kinetic = 0.0;       // sum 1/2 m v^2, J
  double internal = 0.0;      // sum E V0 (eqs 3.39-3.41), J
  double plastic_work = 0.0;  // sum sigma_y d eqps V, J (part of internal)
  double viscous = 0.0;       // work of the artificial bulk viscosity, J
  double absorbed = 0.0;      // work done on the absorbing dashpots, J
  double contact = 0.0;       // kinetic energy the contact corrections took from the points, J
  double departed = 0.0;      // kinetic + internal energy of the points that left the grid, J

  double elastic() const { return internal - plastic_work; }
  double total() const { return kinetic + internal + viscous + absorbed + contact + departed; }
};

// Sums over points in index order, then over the bodies' departed ledgers, so the result does not
// depend on the thread count.
EnergyBudget energy_budget(const bodies::Bodies& s);

}  // namespace coldspray::metrics
