// Linear equation of state p = K mu, mu = rho/rho0 - 1 = 1/J - 1, with no energy term.
// In the form p = A + B E of thesis eq 3.42 it is A = K mu, B = 0.
#pragma once

#include "materials/material.hpp"

namespace coldspray::materials::eos {

inline double reference_pressure(const Linear&, const Material& m, double J) {
  return m.elastic.bulk_modulus * (1.0 - J) / J;  // K (1/J - 1), without cancellation near J = 1
}

inline double energy_coefficient(const Linear&) { return 0.0; }

// rho dp/drho = K rho/rho0 = K/J: exact for this EOS (K itself only at J = 1).
inline double tangent_bulk_modulus(const Linear&, const Material& m, double J, double /*energy*/) {
  return m.elastic.bulk_modulus / J;
}

}  // namespace coldspray::materials::eos
