// Planar symmetric Al-Al impact at 500 m/s in uniaxial strain (validation-data.md §3):
// shock speed Us = c0 + s up and plateau pressure rho0 Us up, up = V/2, within 3 %.
#include <gtest/gtest.h>

#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, PlateImpactAluminium500) {
  const double rho0 = 2707.0, c0 = 5386.0, s = 1.339, V = 500.0;
  const double up = V / 2.0, Us = c0 + s * up, p = rho0 * Us * up;  // 5720.75 m/s, 3.871 GPa
  const CaseRun run = run_verification_case("plate-impact-al-500");
  const Table probes = run.probes();
  const auto t = probes.values("time");
  // Gauges 10 and 20 um below the impact face: the shock arrives when the material reaches
  // half the particle velocity.
  const double t10 = crossing_time(t, probes.values("g30.velocity_z"), -up / 2.0);
  const double t20 = crossing_time(t, probes.values("g20.velocity_z"), -up / 2.0);
  ASSERT_GT(t10, 0.0);
  ASSERT_GT(t20, t10);
  const double shock_speed = 10e-6 / (t20 - t10);
  // The plateau behind the shock at the deeper gauge, before the flyer's release arrives.
  const double plateau = mean_over(t, probes.values("g20.pressure"), t20 + 0.3e-9, t20 + 1.8e-9);
  const double velocity = mean_over(t, probes.values("g20.velocity_z"), t20 + 0.3e-9, t20 + 1.8e-9);
  std::printf(
      "plate impact: Us %.1f m/s (reference %.1f), plateau p %.4f GPa (reference %.4f), "
      "up %.1f m/s (reference %.1f)\n",
      shock_speed, Us, plateau * 1e-9, p * 1e-9, -velocity, up);
  EXPECT_NEAR(shock_speed, Us, 0.03 * Us);
  EXPECT_NEAR(plateau, p, 0.03 * p);
  EXPECT_NEAR(-velocity, up, 0.03 * up);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.01);
}

}  // namespace
}  // namespace coldspray::verification
