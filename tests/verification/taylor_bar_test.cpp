// Taylor bar, Wilkins-Guinan copper at 227 m/s on a rigid frictionless wall: final length and
// foot radius within 3 % of 21.45 mm and 7.15 mm (validation-data.md §3), axisymmetric and a
// coarse 3D quarter bar; the energy budget of this plastic impact closes within 2 %.
#include <gtest/gtest.h>

#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

// The material's edge: the outermost point plus half the initial point spacing.
void check_taylor_bar(const std::string& name, double spacing) {
  const CaseRun run = run_verification_case(name);
  const auto& bar = run.summary.bodies.at(0);
  const double length = bar.extent_max[2] + 0.5 * spacing;
  const double foot = bar.extent_max[0] + 0.5 * spacing;
  std::printf(
      "%s: length %.3f mm (reference 21.45), foot radius %.3f mm (reference 7.15), "
      "energy error %.2e\n",
      name.c_str(), length * 1e3, foot * 1e3, run.summary.energy_relative_error());
  EXPECT_NEAR(length, 21.45e-3, 0.03 * 21.45e-3);
  EXPECT_NEAR(foot, 7.15e-3, 0.03 * 7.15e-3);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.02);
}

TEST(Verification, TaylorBarAxisymmetric) { check_taylor_bar("taylor-bar-axisymmetric", 0.2e-3); }

TEST(Verification, TaylorBar3dCoarse) { check_taylor_bar("taylor-bar-3d", 0.4e-3); }

}  // namespace
}  // namespace coldspray::verification
