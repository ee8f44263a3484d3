// Mie-Gruneisen equation of state on a linear Us-up Hugoniot (thesis §3.5.2, eqs 3.42-3.43;
// validation-data.md §4), with E the internal energy per unit REFERENCE volume, as in
// eqs 3.39-3.41. With mu = rho/rho0 - 1 = 1/J - 1, p = A(J) + B E:
//   compression (mu > 0): A = rho0 c0^2 mu [1 + (1 - Gamma0/2) mu] / [1 - (s - 1) mu]^2
//   tension (mu <= 0):    A = rho0 c0^2 mu
//   B = Gamma0 (rho Gamma = rho0 Gamma0 constant, so Gamma rho e = Gamma0 E).
// A is the Hugoniot pressure minus Gamma0 times the Rankine-Hugoniot energy, so A + Gamma0 E
// gives back the Hugoniot exactly on it.
#pragma once

#include "materials/material.hpp"

namespace coldspray::materials::eos {

inline double reference_pressure(const MieGruneisen& g, const Material& m, double J) {
  const double mu = (1.0 - J) / J;  // = 1/J - 1 without cancellation near J = 1
  const double k = m.density * g.c0 * g.c0;
  if (mu <= 0.0) return k * mu;
  const double den = 1.0 - (g.s - 1.0) * mu;
  return k * mu * (1.0 + (1.0 - 0.5 * g.gamma0) * mu) / (den * den);
}

inline double energy_coefficient(const MieGruneisen& g) { return g.gamma0; }

// Isentropic rho dp/drho: with dE = -p dJ along an isentrope and J = rho0/rho,
// K_t = (1 + mu) dA/dmu + Gamma0 J p.
inline double tangent_bulk_modulus(const MieGruneisen& g, const Material& m, double J,
                                   double energy) {
  const double mu = (1.0 - J) / J;  // = 1/J - 1 without cancellation near J = 1
  const double k = m.density * g.c0 * g.c0;
  double dA_dmu = k;
  if (mu > 0.0) {
    const double b = 1.0 - 0.5 * g.gamma0;
    const double den = 1.0 - (g.s - 1.0) * mu;
    dA_dmu = k * ((1.0 + 2.0 * b * mu) / (den * den) +
                  2.0 * (g.s - 1.0) * mu * (1.0 + b * mu) / (den * den * den));
  }
  const double p = reference_pressure(g, m, J) + g.gamma0 * energy;
  return (1.0 + mu) * dA_dmu + g.gamma0 * J * p;
}

}  // namespace coldspray::materials::eos
