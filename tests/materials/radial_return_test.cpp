// The consistent-return root solve (radial_return.hpp) on flow-stress functions with known
// roots, including ones that would defeat an unguarded Newton or secant iteration.
#include "materials/radial_return.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::materials {
namespace {

constexpr double kTrial = 500e6, kThreeG = 3.0 * 26e9;

// Linear hardening sigma_y = Y + H x: f is linear, regula falsi is exact at once (after the
// yield check and x_max), x = (trial - Y)/(3G + H).
TEST(MaterialsRadialReturn, LinearHardeningIsExactInOneStep) {
  const double Y = 300e6, H = 2e9;
  const PlasticIncrement r =
      consistent_return(kTrial, kThreeG, 0.0, [&](double x) { return Y + H * x; });
  const double x = (kTrial - Y) / (kThreeG + H);
  EXPECT_NEAR(r.eqps_increment, x, 1e-14 * x);
  EXPECT_NEAR(r.flow_stress, Y + H * x, 1e-14 * kTrial);
  EXPECT_LE(r.evaluations, 3);
}

// Zero flow stress (melt): all of the trial deviator is returned, x = trial/(3G), at once
// (after the yield check).
TEST(MaterialsRadialReturn, ZeroFlowStressReturnsToTheOrigin) {
  const PlasticIncrement r = consistent_return(kTrial, kThreeG, 0.0, [](double) { return 0.0; });
  EXPECT_EQ(r.eqps_increment, kTrial / kThreeG);
  EXPECT_EQ(r.flow_stress, 0.0);
  EXPECT_EQ(r.evaluations, 2);
}

// Below the flow stress at rest the point does not yield: x = 0 and sigma_y(0), from the one
// evaluation of the yield check, or three when a guess (a last step that flowed) is tried first:
// the guess and the second secant point, whose secant root lies below x = 0.
TEST(MaterialsRadialReturn, ElasticPointCostsTheYieldCheck) {
  const double Y = 600e6, H = 2e9;
  auto flow = [&](double x) { return Y + H * x; };
  for (const double guess : {0.0, 1e-4}) {
    const PlasticIncrement r = consistent_return(kTrial, kThreeG, guess, flow);
    EXPECT_EQ(r.eqps_increment, 0.0) << guess;
    EXPECT_EQ(r.flow_stress, Y) << guess;
    EXPECT_EQ(r.evaluations, guess > 0.0 ? 3 : 1) << guess;
  }
}

// A strongly rate-sensitive flow stress, sigma_y = Y (x/dt / 1e-3)^0.02, infinitely steep at
// x = 0 (sigma_y(0) = 0). The result must meet the documented tolerance, agree with a plain
// 200-step bisection, and take far fewer evaluations than bisection.
TEST(MaterialsRadialReturn, SteepRateSensitivityConverges) {
  const double Y = 200e6, dt = 1e-9;
  auto flow = [&](double x) { return Y * std::pow(x / dt / 1e-3, 0.02); };
  const PlasticIncrement r = consistent_return(kTrial, kThreeG, 0.0, flow);
  const double x = r.eqps_increment;
  EXPECT_LE(std::abs(kTrial - kThreeG * x - flow(x)), kReturnTolerance * kTrial);
  EXPECT_EQ(r.flow_stress, flow(x));
  double a = 0.0, b = kTrial / kThreeG;
  for (int i = 0; i < 200; ++i) {
    const double c = 0.5 * (a + b);
    (kTrial - kThreeG * c - flow(c) > 0.0 ? a : b) = c;
  }
  EXPECT_NEAR(x, a, 1e-10 * a);
  EXPECT_LT(r.evaluations, 15);
}

// A warm start (the last step's increment) finds the same root in fewer evaluations, from
// either side; a poor guess, far off or outside the bracket, still converges.
TEST(MaterialsRadialReturn, WarmStartFindsTheSameRoot) {
  const double Y = 200e6, dt = 1e-9;
  auto flow = [&](double x) { return Y * std::pow(x / dt / 1e-3, 0.02); };
  const PlasticIncrement cold = consistent_return(kTrial, kThreeG, 0.0, flow);
  const double x = cold.eqps_increment;
  for (const double guess :
       {0.95 * x, 1.05 * x, 1e-9 * x, 0.5 * kTrial / kThreeG, 2.0 * kTrial / kThreeG}) {
    const PlasticIncrement r = consistent_return(kTrial, kThreeG, guess, flow);
    EXPECT_LE(std::abs(kTrial - kThreeG * r.eqps_increment - flow(r.eqps_increment)),
              kReturnTolerance * kTrial)
        << guess;
    EXPECT_NEAR(r.eqps_increment, x, 1e-10 * x) << guess;
    EXPECT_EQ(r.flow_stress, flow(r.eqps_increment)) << guess;
    EXPECT_LT(r.evaluations, 25) << guess;
  }
  EXPECT_LT(consistent_return(kTrial, kThreeG, 1.05 * x, flow).evaluations, cold.evaluations);
}

// A flow stress that jumps across the trial line has no root: the solver must still stop, with
// the bracket collapsed onto the jump, inside its evaluation bound.
TEST(MaterialsRadialReturn, DiscontinuousFlowStressTerminates) {
  const double x_jump = 1e-3;
  auto flow = [&](double x) { return x < x_jump ? 100e6 : 490e6; };
  for (const double guess : {0.0, 0.5 * x_jump, 2.0 * x_jump}) {
    const PlasticIncrement r = consistent_return(kTrial, kThreeG, guess, flow);
    EXPECT_NEAR(r.eqps_increment, x_jump, 1e-14) << guess;
    EXPECT_LT(r.evaluations, kReturnMaxEvaluations) << guess;
  }
}

}  // namespace
}  // namespace coldspray::materials
