// The PD paper's contact model 1 (eqs 15-22): a Lennard-Jones-type potential between two points
// of different bodies at distance r,
//   phi(r) = alpha [(r0/r)^m - 2 beta (r0/r)^n]                                   (eq 15)
// whose force, F = -dphi/dr along the line from the other point, is
//   F(r) = (alpha / r0) [m (r0/r)^(m+1) - 2 n beta (r0/r)^(n+1)]                  (eq 16 for 12, 6)
// repulsive when positive, cut off at R_c (2.75 r0 in the paper), zero at the equilibrium
// distance r_e = r0 (2 n beta / m)^(-1/(m-n)) (eq 17: r0 beta^(-1/6)). Near r_e it is a linear
// spring, dF/dr = -2 n (m - n) beta (r0/r_e)^(n+2) alpha / r0^2 (eq 19: -72 alpha beta^(7/3) /
// r0^2), and setting that equal to the bond constant -c V_i V_j (eq 18) with c = 18 K / (pi
// delta^5) (eq 21) gives alpha (eqs 20, 22): per unit V_i V_j,
//   alpha / (V_i V_j) = c r0^2 / (2 n (m - n) beta (r0/r_e)^(n+2))                (eq 22).
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "pd/laws/contact_pair.hpp"

namespace coldspray::pd {

struct LennardJonesPotential {
  double r0 = 0.0;      // m
  double beta = 0.0;    // -
  double m = 12.0;      // repulsion exponent
  double n = 6.0;       // attraction exponent
  double cutoff = 0.0;  // R_c, m
};

// r_e (eq 17), m.
double equilibrium_distance(const LennardJonesPotential& lj);

// phi(r) / alpha (eq 15), -.
double potential_per_alpha(const LennardJonesPotential& lj, double r);

// F(r) / alpha (eq 16), 1/m: positive pushes the points apart; zero beyond the cut-off.
double force_per_alpha(const LennardJonesPotential& lj, double r);

// alpha per unit V_i V_j from the bulk modulus K (Pa) and the horizon delta (m) (eqs 18-22),
// J/m^6.
double alpha_per_volumes(const LennardJonesPotential& lj, double K, double delta);

// Model 1 as a contact law: the pair's alpha is alpha_per_volumes V_i V_j (eq 22), or alpha
// itself when the case gives it (alpha_per_volumes = 0). It holds a point of another body within
// its cut-off.
struct LennardJones {
  static constexpr std::string_view kName = "lennard-jones";
  static constexpr bool kAdhesive = true;  // whether holds() can be true
  double reach = 0.0;                      // R_c, m
  LennardJonesPotential potential;
  double alpha_per_volumes = 0.0;  // J/m^6
  double alpha = 0.0;              // J

  // r0 and R_c = cutoff r0 in units of the finer spacing; alpha from the softer material's K and
  // the larger horizon unless the case gives it.
  static LennardJones make(const ContactLawInputs& in);

  // Eq 16 over V_i: the force density on i, N/m^3, at separation r = y_i - y_j, 0 < |r| < reach.
  Eigen::Vector3d force(const ContactPair& p, const Eigen::Vector3d& r, double length) const {
    const double alpha_over_V_i =
        alpha_per_volumes != 0.0 ? alpha_per_volumes * p.N.volume[p.j] : alpha / p.N.volume[p.i];
    return alpha_over_V_i * force_per_alpha(potential, length) / length * r;
  }
  bool holds(const ContactPair& p) const {
    return (p.N.position[p.i] - p.N.position[p.j]).head<3>().squaredNorm() < reach * reach;
  }
};

}  // namespace coldspray::pd
