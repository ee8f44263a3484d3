// The PD paper's contact model 1 (pd/laws/lennard_jones.hpp) against its equations 15-22, by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pd/laws/lennard_jones.hpp"

namespace coldspray::pd {
namespace {

constexpr double kR0 = 1.32e-6;  // m: 1.1 spacings of 1.2 um
const LennardJonesPotential kPaper{kR0, 0.005, 12.0, 6.0, 2.75 * kR0};

TEST(LennardJones, EquilibriumDistanceIsEq17) {
  // r_e = r0 beta^(-1/6): 2.4183 r0 at beta = 0.005.
  EXPECT_NEAR(equilibrium_distance(kPaper), kR0 * std::pow(0.005, -1.0 / 6.0), 1e-18);
  EXPECT_NEAR(equilibrium_distance(kPaper) / kR0, 2.4183, 1e-4);
  EXPECT_NEAR(force_per_alpha(kPaper, equilibrium_distance(kPaper)), 0.0, 1e-6 / kR0);
}

TEST(LennardJones, ForceIsEq16AndMinusTheSlopeOfEq15) {
  for (const double r : {1.0 * kR0, 1.7 * kR0, 2.2 * kR0, 2.6 * kR0}) {
    const double x = kR0 / r;
    const double eq16 = 12.0 / kR0 * (std::pow(x, 13) - 0.005 * std::pow(x, 7));
    EXPECT_NEAR(force_per_alpha(kPaper, r), eq16, 1e-12 * std::abs(eq16)) << r / kR0;
    const double h = 1e-6 * r;
    const double slope =
        (potential_per_alpha(kPaper, r + h) - potential_per_alpha(kPaper, r - h)) / (2.0 * h);
    EXPECT_NEAR(force_per_alpha(kPaper, r), -slope, 1e-6 * std::abs(eq16)) << r / kR0;
  }
  // Repulsive inside r_e, attractive beyond it, nothing past the cut-off R_c = 2.75 r0.
  EXPECT_GT(force_per_alpha(kPaper, 2.0 * kR0), 0.0);
  EXPECT_LT(force_per_alpha(kPaper, 2.6 * kR0), 0.0);
  EXPECT_EQ(force_per_alpha(kPaper, 2.75 * kR0), 0.0);
}

TEST(LennardJones, AlphaIsEq22AndGivesTheBondStiffnessAtEquilibrium) {
  const double K = 129e9, delta = 3.6e-6;
  const double c = 18.0 * K / (std::numbers::pi * std::pow(delta, 5));  // eq 21
  // Eq 22: alpha = 18 k r0^2 dV dV / (72 beta^(7/3) pi delta^5), per unit dV dV.
  const double eq22 = 18.0 * K * kR0 * kR0 /
                      (72.0 * std::pow(0.005, 7.0 / 3.0) * std::numbers::pi * std::pow(delta, 5));
  EXPECT_NEAR(alpha_per_volumes(kPaper, K, delta), eq22, 1e-12 * eq22);
  // Eq 19: alpha dF/dr at r_e = -c (eq 18, per unit dV dV).
  const double r_e = equilibrium_distance(kPaper), h = 1e-7 * r_e;
  const double slope =
      (force_per_alpha(kPaper, r_e + h) - force_per_alpha(kPaper, r_e - h)) / (2 * h);
  EXPECT_NEAR(alpha_per_volumes(kPaper, K, delta) * slope, -c, 1e-5 * c);
}

TEST(LennardJones, OtherExponentsKeepTheirEquilibriumAndStiffness) {
  // m = 9, n = 3: r_e = r0 (6 beta / 9)^(-1/6), and the same bond stiffness at r_e.
  const LennardJonesPotential lj{kR0, 0.02, 9.0, 3.0, 10.0 * kR0};
  const double r_e = equilibrium_distance(lj);
  EXPECT_NEAR(r_e, kR0 * std::pow(6.0 * 0.02 / 9.0, -1.0 / 6.0), 1e-18);
  EXPECT_NEAR(force_per_alpha(lj, r_e), 0.0, 1e-9 / kR0);
  const double K = 129e9, delta = 3.6e-6, c = 18.0 * K / (std::numbers::pi * std::pow(delta, 5));
  const double h = 1e-7 * r_e;
  const double slope = (force_per_alpha(lj, r_e + h) - force_per_alpha(lj, r_e - h)) / (2 * h);
  EXPECT_NEAR(alpha_per_volumes(lj, K, delta) * slope, -c, 1e-5 * c);
}

// The work of adhesion per unit area of two flat, aligned simple-cubic half-lattices of spacing
// h at r0 = 1.1 h, alpha from eq 22 with Cu's K = 129 GPa and delta = 3 h: W = -min over the gap
// of the pairs' energy phi(r) - phi(R_c) per area. Reference: tools/lj_adhesion_work.py (numpy,
// its own sums and minimiser) gives 57.3 and 176.2 J/m^2 at beta 0.003 and 0.0035 for h = 1.2
// um (docs/validation/pd-adhesion.md). Everything scales with h and alpha with K h^3, so W is
// proportional to h: half the spacing, half the work.
double aligned_work_of_adhesion(double beta, double h) {
  const double K = 129e9;
  const LennardJonesPotential lj{1.1 * h, beta, 12.0, 6.0, 2.75 * 1.1 * h};
  const double alpha = alpha_per_volumes(lj, K, 3.0 * h) * std::pow(h, 6);
  const int n = static_cast<int>(std::ceil(lj.cutoff / h)) + 1;
  auto energy = [&](double gap) {
    double sum = 0.0;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = 0; k <= 2 * n; ++k) {  // k = k_a + k_b: k + 1 pairs of layers
          const double r = std::sqrt((i * i + j * j) * h * h + std::pow(gap + k * h, 2));
          if (r < lj.cutoff)
            sum += (k + 1) * (potential_per_alpha(lj, r) - potential_per_alpha(lj, lj.cutoff));
        }
    return alpha * sum / (h * h);
  };
  // A scan, then golden sections about its lowest point.
  const double first = 0.3 * h, step = (lj.cutoff - first) / 400;
  double best = first;
  for (int k = 1; k <= 400; ++k)
    if (energy(first + k * step) < energy(best)) best = first + k * step;
  double a = best - step, b = best + step;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 60; ++k) {
    const double c = b - golden * (b - a), d = a + golden * (b - a);
    (energy(c) < energy(d) ? b : a) = energy(c) < energy(d) ? d : c;
  }
  return -std::min(0.0, energy(0.5 * (a + b)));
}

TEST(LennardJones, WorkOfAdhesionPerAreaGrowsWithTheSpacing) {
  EXPECT_NEAR(aligned_work_of_adhesion(0.003, 1.2e-6), 57.3, 0.002 * 57.3);
  EXPECT_NEAR(aligned_work_of_adhesion(0.0035, 1.2e-6), 176.2, 0.002 * 176.2);
  EXPECT_NEAR(aligned_work_of_adhesion(0.0035, 0.6e-6),
              0.5 * aligned_work_of_adhesion(0.0035, 1.2e-6), 1e-9 * 175.3);
}

}  // namespace
}  // namespace coldspray::pd
