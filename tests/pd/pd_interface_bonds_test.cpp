// The PD paper's contact model 2 (pd/laws/interface_bonds.hpp) against its equations 23-25 by hand,
// and the bulk-fracture test it is fitted to (pd/laws/bulk_fracture.hpp) against the continuum
// limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pd/laws/bulk_fracture.hpp"
#include "pd/laws/interface_bonds.hpp"

namespace coldspray::pd {
namespace {

const InterfaceBondLaw kLaw{0.002, 300.0};  // s_y, m

TEST(InterfaceBonds, CriticalStretchIsEq23) {
  // Cu: G_c = 2 x 1.825 J/m^2, K = 129 GPa, delta = 3 x 1.2 um:
  // s_c = sqrt(5 x 3.65 / (9 x 129e9 x 3.6e-6)) = 2.0896e-3.
  const double K = 129e9, delta = 3.6e-6;
  const double s_c = critical_stretch(3.65, K, delta);
  EXPECT_NEAR(s_c, 2.0896e-3, 1e-7);
  const double c = 18.0 * K / (std::numbers::pi * std::pow(delta, 4));
  EXPECT_NEAR(std::numbers::pi * c * s_c * s_c * std::pow(delta, 5) / 10.0, 3.65, 1e-12);
}

TEST(InterfaceBonds, ForceIsEq25InCompressionAndEq24InTension) {
  EXPECT_DOUBLE_EQ(force_per_micromodulus(kLaw, -0.01, kUnbonded), 0.01);  // eq 25, c |s|
  EXPECT_DOUBLE_EQ(force_per_micromodulus(kLaw, -0.01, 0.005), 0.01);
  EXPECT_DOUBLE_EQ(force_per_micromodulus(kLaw, 0.001, 0.001), -0.001);  // linear: c s
  EXPECT_DOUBLE_EQ(force_per_micromodulus(kLaw, 0.002, 0.002), -0.002);  // the peak, c s_y
  // Eq 24: c s_y exp(-m (s - s_y)) = 0.002 exp(-0.9) = 8.1314e-4 at s = 0.005.
  EXPECT_NEAR(force_per_micromodulus(kLaw, 0.005, 0.005), -8.1314e-4, 1e-8);
  // Pulled back to half its largest stretch: along the secant, half that force.
  EXPECT_NEAR(force_per_micromodulus(kLaw, 0.0025, 0.005), -4.0657e-4, 1e-8);
  // Pulled back before it yielded: elastic.
  EXPECT_DOUBLE_EQ(force_per_micromodulus(kLaw, 0.0005, 0.0015), -0.0005);
  // A pair that has not bonded does not pull.
  EXPECT_EQ(force_per_micromodulus(kLaw, 0.001, kUnbonded), 0.0);
}

TEST(InterfaceBonds, BreaksWhereItsForceHasDecayedToOnePercent) {
  // s_y + ln(100) / m = 0.002 + 4.60517 / 300.
  EXPECT_NEAR(kLaw.break_stretch(), 0.0173506, 1e-7);
  EXPECT_NEAR(envelope_per_micromodulus(kLaw, kLaw.break_stretch() - 1e-12), kBreakFraction * 0.002,
              1e-12);
  EXPECT_EQ(envelope_per_micromodulus(kLaw, kLaw.break_stretch()), 0.0);
}

TEST(InterfaceBonds, FormUnderCompressionRememberTheirLargestStretchBreakAndReform) {
  double largest = kUnbonded;
  largest = next_largest_stretch(kLaw, 0.001, largest);  // approaching, not yet touching
  EXPECT_EQ(largest, kUnbonded);
  largest = next_largest_stretch(kLaw, -0.001, largest);  // compressed: bonded
  EXPECT_EQ(largest, 0.0);
  largest = next_largest_stretch(kLaw, 0.004, largest);
  EXPECT_EQ(largest, 0.004);
  largest = next_largest_stretch(kLaw, 0.001, largest);  // unloading keeps the damage
  EXPECT_EQ(largest, 0.004);
  largest = next_largest_stretch(kLaw, -0.002, largest);  // compressed again: still damaged
  EXPECT_EQ(largest, 0.004);
  largest = next_largest_stretch(kLaw, 0.02, largest);  // past the break stretch
  EXPECT_EQ(largest, kUnbonded);
  largest = next_largest_stretch(kLaw, 0.001, largest);  // broken pairs do not pull
  EXPECT_EQ(largest, kUnbonded);
  largest = next_largest_stretch(kLaw, -1e-4, largest);  // touching again: a new bond
  EXPECT_EQ(largest, 0.0);
  EXPECT_DOUBLE_EQ(force_per_micromodulus(kLaw, 0.001, 0.001), -0.001);
}

TEST(InterfaceBonds, WorkToBreakIsTheIntegralOfTheLaw) {
  // The envelope integrated numerically (midpoints) against c (s_y^2 / 2 + 0.99 s_y / m).
  const int n = 200000;
  const double ds = kLaw.break_stretch() / n;
  double work = 0.0;
  for (int k = 0; k < n; ++k) work += envelope_per_micromodulus(kLaw, (k + 0.5) * ds) * ds;
  EXPECT_NEAR(work, interface_work(kLaw), 1e-9 * interface_work(kLaw));
  EXPECT_NEAR(interface_work(kLaw), 0.5 * 0.002 * 0.002 + 0.99 * 0.002 / 300.0, 1e-15);
}

TEST(BulkFracture, RisesWithSlopeOnePeaksAtTheCriticalStretchAndBreaksCompletely) {
  const ForceStretchCurve curve = bulk_fracture_curve(3.0, 1000);
  for (std::size_t n = 0; n < 990; n += 90)
    EXPECT_NEAR(curve.force[n], curve.stretch[n], 1e-6) << curve.stretch[n];
  const InterfaceBondLaw fit = fit_interface_law(curve);
  EXPECT_NEAR(fit.yield_stretch, 1.0, 2e-3);  // the steepest bonds break first, at s_c
  EXPECT_EQ(curve.force.back(), 0.0);
  // The flattest bond crossing a plane, (2, 2, 1) / 3, breaks at 9 s_c.
  EXPECT_NEAR(curve.stretch.back(), 9.0, 2e-3);
}

TEST(BulkFracture, WorkTendsToTheContinuumLimit) {
  // In the continuum a bond at direction cosine mu stretches e mu^2 and breaks at e = s_c /
  // mu^2, so the traction per equivalent bond is c e for e < s_c and c s_c (s_c / e)^(3/2)
  // beyond; a lattice of horizon N spacings has no bond flatter than mu = 1 / N, so its curve
  // ends near e = N^2 s_c: work = c s_c^2 (1/2 + 2 (1 - 1 / N)). The lattice's error (1.7 % at
  // N = 10, 0.74 % at 20) falls as the horizon spans more spacings.
  auto error = [](double N) {
    const double continuum = 0.5 + 2.0 * (1.0 - 1.0 / N);
    return std::abs(work_of_fracture(bulk_fracture_curve(N, 50)) / continuum - 1.0);
  };
  const double at_10 = error(10.0), at_20 = error(20.0);
  EXPECT_LT(at_10, 0.02);
  EXPECT_LT(at_20, 0.01);
  EXPECT_LT(at_20, at_10);
}

TEST(BulkFracture, TheFitKeepsThePeakAndTheWork) {
  const ForceStretchCurve curve = bulk_fracture_curve(3.0, 1000);
  const InterfaceBondLaw fit = fit_interface_law(curve);
  EXPECT_NEAR(interface_work(fit), work_of_fracture(curve), 1e-12);
  EXPECT_NEAR(envelope_per_micromodulus(fit, fit.yield_stretch),
              *std::max_element(curve.force.begin(), curve.force.end()), 2e-3);
}

}  // namespace
}  // namespace coldspray::pd
