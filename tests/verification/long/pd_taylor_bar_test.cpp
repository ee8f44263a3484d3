// Taylor bars in peridynamics, quarter models (docs/pd.md, "Taylor bar").
// - Wilkins-Guinan copper at 227 m/s (examples/verification/pd-wilkins-guinan-bar.yaml), the
//   code-to-code reference the MPM is verified on (21.45 mm long, 7.15 mm foot radius;
//   validation-data.md §3): the length within 3 % at h = 0.4 and 0.2 mm (measured -0.25 % and
//   +0.55 %), and the foot converging to the reference: its error at 0.2 mm less than half its
//   error at 0.4 mm (measured -14.6 % and -5.2 %, a ratio of 2.8).
// - Johnson and Cook's OFHC copper at 190 m/s (examples/verification/pd-taylor-bar.yaml) at
//   h = 0.2 mm: the length within 2 % of the MPM's on the same constants, 17.31 mm (r-z, 0.2 mm
//   cells, 0.1 mm spacing). With these constants the MPM, this PD and an independent
//   finite-element code all end 6.9-7.4 % longer than the experiment's 16.2 mm, so the
//   experiment's length tests the constants, not the solver. The foot diameter within 5 % of
//   the experiment's 13.6 mm (measured 13.72 mm, +0.9 %: PD's foot 5 % short of the converged
//   MPM's 14.47 mm, which these constants put 6.4 % over the experiment; docs/pd.md).
// Both bars' energy budgets close within 2 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

struct Bar {
  double length = 0.0;       // m, the top point's height plus half a spacing
  double foot_radius = 0.0;  // m, the largest x plus half a spacing
};

Bar run_bar(const std::string& name, double spacing) {
  const CaseRun run =
      run_verification_case(name, {{"bodies.bar.spacing", std::to_string(spacing * 1e3) + " mm"}});
  const auto& bar = run.summary.bodies.at(0);
  const Bar b{bar.extent_max[2] + 0.5 * spacing, bar.extent_max[0] + 0.5 * spacing};
  std::printf(
      "%s, h = %.1f mm: length %.3f mm, foot radius %.3f mm, energy error %.2e, %ld steps\n",
      name.c_str(), spacing * 1e3, b.length * 1e3, b.foot_radius * 1e3,
      run.summary.energy_relative_error(), run.summary.steps);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.02);
  return b;
}

TEST(LongVerification, PeridynamicTaylorBarWilkinsGuinanConverges) {
  const Bar coarse = run_bar("pd-wilkins-guinan-bar", 0.4e-3);
  const Bar fine = run_bar("pd-wilkins-guinan-bar", 0.2e-3);
  EXPECT_NEAR(coarse.length, 21.45e-3, 0.03 * 21.45e-3);
  EXPECT_NEAR(fine.length, 21.45e-3, 0.03 * 21.45e-3);
  EXPECT_LT(std::abs(fine.foot_radius - 7.15e-3), 0.5 * std::abs(coarse.foot_radius - 7.15e-3));
}

TEST(LongVerification, PeridynamicTaylorBarJohnsonCook) {
  const Bar bar = run_bar("pd-taylor-bar", 0.2e-3);
  EXPECT_NEAR(bar.length, 17.31e-3, 0.02 * 17.31e-3);
  EXPECT_NEAR(2.0 * bar.foot_radius, 13.6e-3, 0.05 * 13.6e-3);
}

}  // namespace
}  // namespace coldspray::verification
