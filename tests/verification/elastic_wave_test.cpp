// Elastic wave in a bar in uniaxial strain: the front speed within 2 % of
// sqrt((K + 4G/3)/rho), and the energy of this elastic problem conserved within 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, ElasticWaveFrontSpeed) {
  const double K = 66.4e9, G = 26e9, rho = 2700.0;
  const double c = std::sqrt((K + 4.0 / 3.0 * G) / rho);  // 6118.2 m/s
  const CaseRun run = run_verification_case("elastic-wave");
  const Table probes = run.probes();
  const auto t = probes.values("time");
  // The front stops the bar (10 m/s down): it passes a gauge when the velocity is half way.
  const double t10 = crossing_time(t, probes.values("z10.velocity_z"), -5.0);
  const double t30 = crossing_time(t, probes.values("z30.velocity_z"), -5.0);
  ASSERT_GT(t10, 0.0);
  ASSERT_GT(t30, t10);
  const double front = 20e-6 / (t30 - t10);
  std::printf("elastic wave: front speed %.1f m/s (reference %.1f), energy error %.2e\n", front, c,
              run.summary.energy_relative_error());
  EXPECT_NEAR(front, c, 0.02 * c);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.01);
}

}  // namespace
}  // namespace coldspray::verification
