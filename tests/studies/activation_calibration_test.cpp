// The calibration of bonding's activation (studies/activation_calibration.hpp) by hand: power
// laws through two points and the critical penetration whose worst size errs least.
#include "studies/activation_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::studies {
namespace {

TEST(ActivationCalibration, APowerLawThroughTwoRuns) {
  // p = 0.44 (v / 810)^0.9 sampled at 793.8 and 826.2 m/s.
  auto p = [](double v) { return 0.44 * std::pow(v / 810.0, 0.9); };
  const PenetrationLaw law = penetration_law(810.0, 793.8, p(793.8), 826.2, p(826.2));
  ASSERT_TRUE(law.usable());
  EXPECT_NEAR(law.at_velocity, 0.44, 1e-14);
  EXPECT_NEAR(law.exponent, 0.9, 1e-12);
  EXPECT_NEAR(predicted_vcrit(law, 810.0, p(800.0)), 800.0, 1e-9);
  EXPECT_FALSE(penetration_law(810.0, 800.0, 0.0, 820.0, 0.44).usable());
  EXPECT_FALSE(penetration_law(810.0, 800.0, 0.45, 820.0, 0.44).usable());  // falling
}

TEST(ActivationCalibration, TheWorstSizesErrorIsLeast) {
  // Two sizes: errors (x - L_i) / b_i cancel at x = (L1/b1 + L2/b2) / (1/b1 + 1/b2).
  const PenetrationLaw a{0.4378, 0.89}, b{0.4505, 0.95};
  const double L1 = std::log(a.at_velocity), L2 = std::log(b.at_velocity);
  const double x = (L1 / a.exponent + L2 / b.exponent) / (1.0 / a.exponent + 1.0 / b.exponent);
  const double delta = minimax_critical_penetration({a, b});
  EXPECT_NEAR(delta, std::exp(x), 1e-12);
  const double e1 = std::log(predicted_vcrit(a, 810.0, delta) / 810.0);
  const double e2 = std::log(predicted_vcrit(b, 770.0, delta) / 770.0);
  EXPECT_NEAR(e1, -e2, 1e-12);
  EXPECT_GT(e1, 0.0);  // the size that reaches less penetration at its velocity needs more speed
  // A third size between them does not move the answer; one outside does.
  EXPECT_NEAR(minimax_critical_penetration({a, b, {0.444, 0.9}}), delta, 1e-12);
  EXPECT_GT(minimax_critical_penetration({a, b, {0.47, 0.9}}), delta);
  // One size: its own penetration.
  EXPECT_NEAR(minimax_critical_penetration({a}), 0.4378, 1e-12);
}

}  // namespace
}  // namespace coldspray::studies
