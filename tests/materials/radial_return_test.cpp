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
      consistent_return(kTrial, kThreeG, 0.0, 0.0, [&](double x) { return Y + H * x; });
  const double x = (kTrial - Y) / (kThreeG + H);
  EXPECT_NEAR(r.eqps_increment, x, 1e-14 * x);
  EXPECT_NEAR(r.flow_stress, Y + H * x, 1e-14 * kTrial);
  EXPECT_LE(r.evaluations, 3);
}

// Zero flow stress (melt): all of the trial deviator is returned, x = trial/(3G), at once
// (after the yield check).
TEST(MaterialsRadialReturn, ZeroFlowStressReturnsToTheOrigin) {
  const PlasticIncrement r =
      consistent_return(kTrial, kThreeG, 0.0, 0.0, [](double) { return 0.0; });
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
    const PlasticIncrement r = consistent_return(kTrial, kThreeG, guess, 0.0, flow);
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
  const PlasticIncrement r = consistent_return(kTrial, kThreeG, 0.0, 0.0, flow);
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
  const PlasticIncrement cold = consistent_return(kTrial, kThreeG, 0.0, 0.0, flow);
  const double x = cold.eqps_increment;
  for (const double guess :
       {0.95 * x, 1.05 * x, 1e-9 * x, 0.5 * kTrial / kThreeG, 2.0 * kTrial / kThreeG}) {
    const PlasticIncrement r = consistent_return(kTrial, kThreeG, guess, 0.0, flow);
    EXPECT_LE(std::abs(kTrial - kThreeG * r.eqps_increment - flow(r.eqps_increment)),
              kReturnTolerance * kTrial)
        << guess;
    EXPECT_NEAR(r.eqps_increment, x, 1e-10 * x) << guess;
    EXPECT_EQ(r.flow_stress, flow(r.eqps_increment)) << guess;
    EXPECT_LT(r.evaluations, 25) << guess;
  }
  EXPECT_LT(consistent_return(kTrial, kThreeG, 1.05 * x, 0.0, flow).evaluations, cold.evaluations);
}

// With linear hardening, f is a line of slope -(3G + H): the return reports that slope, and from
// it the predictor of the next step lands on the root, which the return then accepts after one
// evaluation (x = (trial - Y)/(3G + H) by hand).
TEST(MaterialsRadialReturn, LinearHardeningSlopeMakesTheNextStartExact) {
  const double Y = 300e6, H = 2e9;
  auto flow = [&](double x) { return Y + H * x; };
  const PlasticIncrement first = consistent_return(kTrial, kThreeG, 0.0, 0.0, flow);
  EXPECT_NEAR(first.residual_slope, kThreeG + H, 1e-6 * (kThreeG + H));

  // The next step: a larger trial stress; the last step ended at x^n on sigma_y^n = Y + H x^n.
  const double trial = 1.2 * kTrial, x = (trial - Y) / (kThreeG + H);
  const double guess = predicted_increment(trial, kThreeG, first.eqps_increment, first.flow_stress,
                                           first.residual_slope);
  EXPECT_NEAR(guess, x, 1e-6 * x);
  const PlasticIncrement next =
      consistent_return(trial, kThreeG, guess, first.residual_slope, flow);
  EXPECT_NEAR(next.eqps_increment, x, 1e-12 * x);
  EXPECT_LE(next.evaluations, 2);
}

// Slopes that cannot serve a Newton step (none, below 3G, non-finite, absurdly large) are
// ignored or survived: every start still reaches the root.
TEST(MaterialsRadialReturn, UnusableSlopesStillConverge) {
  const double Y = 200e6, dt = 1e-9;
  auto flow = [&](double x) { return Y * std::pow(x / dt / 1e-3, 0.02); };
  const double x = consistent_return(kTrial, kThreeG, 0.0, 0.0, flow).eqps_increment;
  for (const double slope : {0.0, -kThreeG, 0.5 * kThreeG, 1e30, 1.0 / 0.0, std::nan("")}) {
    // An unusable slope leaves the last increment as the start; a huge one barely moves it.
    EXPECT_NEAR(predicted_increment(kTrial, kThreeG, 0.9 * x, Y, slope), 0.9 * x, 1e-12 * x)
        << slope;
    for (const double guess : {0.0, 0.9 * x, 1.1 * x, 2.0 * kTrial / kThreeG}) {
      const PlasticIncrement r = consistent_return(kTrial, kThreeG, guess, slope, flow);
      EXPECT_NEAR(r.eqps_increment, x, 1e-10 * x) << slope << " " << guess;
    }
  }
}

// A loading path of steps whose trial stress grows, on a strain- and rate-hardening flow stress:
// starting each return from the predictor and the last slope finds the same roots as starting
// from the last increment alone, in a fifth fewer evaluations.
TEST(MaterialsRadialReturn, LastSlopeSavesEvaluationsAlongALoadingPath) {
  const double dt = 1e-9;
  struct Path {
    double eqps = 0.0, increment = 0.0, flow_stress = 0.0, slope = 0.0;
    int evaluations = 0;
  };
  Path plain, newton;
  for (int step = 0; step < 40; ++step) {
    const double trial = 400e6 * (1.0 + 0.01 * step);
    auto step_of = [&](Path& path, bool use_slope) {
      const double eqps = path.eqps;
      auto flow = [&](double x) {
        return (200e6 + 1e9 * (eqps + x)) * std::pow(1.0 + x / dt / 1e3, 0.02);
      };
      const double guess = use_slope ? predicted_increment(trial, kThreeG, path.increment,
                                                           path.flow_stress, path.slope)
                                     : path.increment;
      const PlasticIncrement r =
          consistent_return(trial, kThreeG, guess, use_slope ? path.slope : 0.0, flow);
      path.eqps += r.eqps_increment;
      path.increment = r.eqps_increment;
      path.flow_stress = r.flow_stress;
      path.slope = r.residual_slope;
      path.evaluations += r.evaluations;
      return r.eqps_increment;
    };
    const double x_plain = step_of(plain, false), x_newton = step_of(newton, true);
    ASSERT_NEAR(x_newton, x_plain, 1e-10 * x_plain) << step;
  }
  // Measured: 163 against 202.
  EXPECT_LT(newton.evaluations, 0.85 * plain.evaluations);
}

// A flow stress that jumps across the trial line has no root: the solver must still stop, with
// the bracket collapsed onto the jump, inside its evaluation bound.
TEST(MaterialsRadialReturn, DiscontinuousFlowStressTerminates) {
  const double x_jump = 1e-3;
  auto flow = [&](double x) { return x < x_jump ? 100e6 : 490e6; };
  for (const double guess : {0.0, 0.5 * x_jump, 2.0 * x_jump}) {
    const PlasticIncrement r = consistent_return(kTrial, kThreeG, guess, 0.0, flow);
    EXPECT_NEAR(r.eqps_increment, x_jump, 1e-14) << guess;
    EXPECT_LT(r.evaluations, kReturnMaxEvaluations) << guess;
  }
}

}  // namespace
}  // namespace coldspray::materials
