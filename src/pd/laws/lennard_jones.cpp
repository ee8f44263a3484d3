#include "pd/laws/lennard_jones.hpp"

#include <cmath>
#include <numbers>

namespace coldspray::pd {

double equilibrium_distance(const LennardJonesPotential& lj) {
  return lj.r0 * std::pow(2.0 * lj.n * lj.beta / lj.m, -1.0 / (lj.m - lj.n));
}

double potential_per_alpha(const LennardJonesPotential& lj, double r) {
  const double x = lj.r0 / r;
  return std::pow(x, lj.m) - 2.0 * lj.beta * std::pow(x, lj.n);
}

double force_per_alpha(const LennardJonesPotential& lj, double r) {
  if (r >= lj.cutoff) return 0.0;
  const double x = lj.r0 / r;
  return (lj.m * std::pow(x, lj.m + 1.0) - 2.0 * lj.n * lj.beta * std::pow(x, lj.n + 1.0)) / lj.r0;
}

double alpha_per_volumes(const LennardJonesPotential& lj, double K, double delta) {
  const double c = 18.0 * K / (std::numbers::pi * std::pow(delta, 5));  // eq 21, N/m^7
  const double x_e = lj.r0 / equilibrium_distance(lj);
  return c * lj.r0 * lj.r0 / (2.0 * lj.n * (lj.m - lj.n) * lj.beta * std::pow(x_e, lj.n + 2.0));
}

LennardJones LennardJones::make(const ContactLawInputs& in) {
  const case_file::PeridynamicsContact& contact = in.c.contact.peridynamics;
  LennardJones law;
  law.potential = {contact.r0 * in.spacing, contact.beta, contact.repulsion_exponent,
                   contact.attraction_exponent, contact.cutoff * contact.r0 * in.spacing};
  law.reach = law.potential.cutoff;
  if (contact.alpha)
    law.alpha = *contact.alpha;
  else
    law.alpha_per_volumes = pd::alpha_per_volumes(law.potential, in.bulk_modulus, in.horizon);
  return law;
}

}  // namespace coldspray::pd
