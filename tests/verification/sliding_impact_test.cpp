// The same frictionless Al-on-Al impact in r-z and in 3D (examples/verification/sliding-impact-*):
// with both bodies plastic, how the plastic work splits between particle and substrate depends on
// the interface slipping freely, so it checks the r-z contact normal against the 3D one. At 10 ns
// (1.0/0.25 um) each body's plastic energy density agrees within 5 %; with the ring-mass normal of
// the r-z model before issue 22 the particle's was 19 % low and the substrate's 19 % high.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, SlidingImpactAgreesBetweenRzAnd3d) {
  const CaseRun rz = run_verification_case("sliding-impact-axisymmetric");
  const CaseRun full = run_verification_case("sliding-impact-3d");
  for (std::size_t b = 0; b < 2; ++b) {
    const double a = rz.summary.bodies.at(b).impact.plastic_energy_density;
    const double c = full.summary.bodies.at(b).impact.plastic_energy_density;
    std::printf("body %zu: plastic energy density r-z %.1f, 3D %.1f MJ/m^3 (%+.1f %%)\n", b,
                a * 1e-6, c * 1e-6, 100.0 * (a / c - 1.0));
    EXPECT_NEAR(a / c, 1.0, 0.05) << "body " << b;
  }
  // The particle's speed, which the contact force decides, and also the absorbing faces 10 um
  // below and 15 um out, whose reflections are back from 3 ns: within 2 % (measured 1.89 % with
  // the dashpots on the grid's velocity, 0.16 % with them on the points' FLIP velocity before
  // issue 52, 1.24 % with free faces; each model's own dashpot change moved it 2.7 % in r-z
  // and 0.6 % in 3D, so the bound is the boundary treatment's, not the contact's).
  const double vz_rz = rz.summary.bodies.at(0).velocity[2];
  const double vz_3d = full.summary.bodies.at(0).velocity[2];
  EXPECT_NEAR(vz_rz / vz_3d, 1.0, 0.02);
}

}  // namespace
}  // namespace coldspray::verification
