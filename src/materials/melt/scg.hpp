// Steinberg-Cochran-Guinan melt temperature (thesis eq 2.9; Steinberg, Cochran & Guinan,
// J. Appl. Phys. 51 (1980) 1498), a modified Lindemann law:
//   Tm = Tm0 exp(2a (1 - 1/eta)) eta^(2 (Gamma0 - a - 1/3)),  eta = rho/rho0.
// The thesis prints the exponent as 2 Gamma0 - a - 1/3; the parentheses of the published form
// were lost in its rendering, and the published form is the one used here (docs/materials.md).
#pragma once

#include <cmath>

#include "materials/material.hpp"

namespace coldspray::materials::melt {

// The power of eta taken as exp(k ln eta) inside the one exp: cheaper than pow.
inline double temperature(const Scg& s, double eta) {
  return s.Tm0 * std::exp(2.0 * s.a * (1.0 - 1.0 / eta) +
                          2.0 * (s.gamma0 - s.a - 1.0 / 3.0) * std::log(eta));
}

}  // namespace coldspray::materials::melt
