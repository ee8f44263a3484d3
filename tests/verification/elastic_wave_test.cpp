// Elastic wave in a bar in uniaxial strain: the front speed within 2 % of
// sqrt((K + 4G/3)/rho), and the energy of this elastic problem conserved within 1 %; in
// peridynamics within 3 %, the error falling with the spacing (docs/pd.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

const double kLongitudinal = std::sqrt((66.4e9 + 4.0 / 3.0 * 26e9) / 2700.0);  // 6118.2 m/s

// The front stops the bar (10 m/s down): it passes a gauge when the velocity is half way; the
// gauges z10 and z30 are 20 um apart.
double front_speed(const CaseRun& run) {
  const Table probes = run.probes();
  const auto t = probes.values("time");
  const double t10 = crossing_time(t, probes.values("z10.velocity_z"), -5.0);
  const double t30 = crossing_time(t, probes.values("z30.velocity_z"), -5.0);
  EXPECT_GT(t10, 0.0);
  EXPECT_GT(t30, t10);
  return 20e-6 / (t30 - t10);
}

TEST(Verification, ElasticWaveFrontSpeed) {
  const double c = kLongitudinal;
  const CaseRun run = run_verification_case("elastic-wave");
  const double front = front_speed(run);
  std::printf("elastic wave: front speed %.1f m/s (reference %.1f), energy error %.2e\n", front, c,
              run.summary.energy_relative_error());
  EXPECT_NEAR(front, c, 0.02 * c);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.01);
}

TEST(Verification, PeridynamicElasticWaveFrontSpeed) {
  const double fine = front_speed(run_verification_case("pd-elastic-wave"));
  // At 0.5 um the lattice points nearest the gauges lie at 0.75 um across and 10.25, 30.25 um up.
  const double coarse = front_speed(run_verification_case(
      "pd-elastic-wave", {{"bodies.bar.spacing", "0.5 um"},
                          {"output.probes",
                           "[{name: z10, position: [0.75 um, 0.75 um, 10.25 um], fields: "
                           "[velocity_z]}, {name: z30, position: [0.75 um, 0.75 um, 30.25 um], "
                           "fields: [velocity_z]}]"}}));
  const double fine_error = fine / kLongitudinal - 1.0, coarse_error = coarse / kLongitudinal - 1.0;
  std::printf(
      "pd elastic wave: front %.1f m/s at 0.25 um (%+.2f %%), %.1f m/s at 0.5 um "
      "(%+.2f %%)\n",
      fine, 100.0 * fine_error, coarse, 100.0 * coarse_error);
  EXPECT_LT(std::abs(fine_error), 0.03);
  EXPECT_LT(std::abs(fine_error), std::abs(coarse_error));
}

}  // namespace
}  // namespace coldspray::verification
