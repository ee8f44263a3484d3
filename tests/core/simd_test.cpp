// The four-lane math of core/simd.hpp against the scalar libm, over the ranges PTW's return
// feeds it (log of rates and atomic rates, erf of the thermal term, exp of the power laws,
// expm1/log1p of the hardening law, including expm1's -1 limit). libmvec documents 4 ulp.
#include "core/simd.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#if COLDSPRAY_HAVE_SIMD

namespace coldspray::simd {
namespace {

// The largest difference between f4 and f over xs, in units of the scalar result's ulp.
COLDSPRAY_SIMD_TARGET double max_ulp(Doubles (*f4)(Doubles), double (*f)(double),
                                     const std::vector<double>& xs) {
  double worst = 0.0;
  for (std::size_t i = 0; i + kLanes <= xs.size(); i += kLanes) {
    const Doubles x = {xs[i], xs[i + 1], xs[i + 2], xs[i + 3]};
    const Doubles y = f4(x);
    for (int l = 0; l < kLanes; ++l) {
      const double ref = f(xs[i + l]);
      const double ulp =
          std::nextafter(std::abs(ref), std::numeric_limits<double>::infinity()) - std::abs(ref);
      worst = std::max(worst, std::abs(y[l] - ref) / ulp);
    }
  }
  return worst;
}

std::vector<double> span(double lo, double hi, int n) {
  std::vector<double> xs;
  for (int i = 0; i < n; ++i) xs.push_back(lo + (hi - lo) * i / (n - 1));
  return xs;
}

COLDSPRAY_SIMD_TARGET double log_ulp(const std::vector<double>& xs) {
  return max_ulp(&simd::log, std::log, xs);
}
COLDSPRAY_SIMD_TARGET double exp_ulp(const std::vector<double>& xs) {
  return max_ulp(&simd::exp, std::exp, xs);
}
COLDSPRAY_SIMD_TARGET double expm1_ulp(const std::vector<double>& xs) {
  return max_ulp(&simd::expm1, std::expm1, xs);
}
COLDSPRAY_SIMD_TARGET double log1p_ulp(const std::vector<double>& xs) {
  return max_ulp(&simd::log1p, std::log1p, xs);
}
COLDSPRAY_SIMD_TARGET double erf_ulp(const std::vector<double>& xs) {
  return max_ulp(&simd::erf, std::erf, xs);
}

TEST(CoreSimd, VectorMathAgreesWithLibmToFourUlp) {
  if (!available()) GTEST_SKIP() << "no AVX2 on this processor";
  std::vector<double> rates;  // 1e-6 .. 1e12 1/s, and (gamma xi_dot)^6 ~ 1e50
  for (double e = -6.0; e <= 50.0; e += 0.0137) rates.push_back(std::pow(10.0, e));
  EXPECT_LE(log_ulp(rates), 4.0);
  EXPECT_LE(exp_ulp(span(-60.0, 5.0, 4001)), 4.0);
  EXPECT_LE(expm1_ulp(span(-800.0, 1.0, 4001)), 4.0);
  EXPECT_LE(expm1_ulp(span(-1e-3, 1e-3, 4001)), 4.0);
  EXPECT_LE(log1p_ulp(span(-0.99, 50.0, 4001)), 4.0);
  EXPECT_LE(log1p_ulp(span(0.0, 1e-8, 4001)), 4.0);
  EXPECT_LE(erf_ulp(span(-8.0, 8.0, 4001)), 4.0);
}

COLDSPRAY_SIMD_TARGET bool selections_are_lane_wise() {
  const Doubles a = {1.0, -2.0, 3.0, -4.0}, b = {0.5, 0.5, 5.0, -5.0};
  const Doubles hi = max(a, b), lo = min(a, b), mag = abs(a);
  return hi[0] == 1.0 && hi[1] == 0.5 && hi[2] == 5.0 && hi[3] == -4.0 && lo[0] == 0.5 &&
         lo[1] == -2.0 && lo[2] == 3.0 && lo[3] == -5.0 && mag[1] == 2.0 && mag[3] == 4.0 &&
         any(a > 2.5) && !any(a > 3.5);
}

TEST(CoreSimd, SelectionsAreLaneWise) {
  if (!available()) GTEST_SKIP() << "no AVX2 on this processor";
  EXPECT_TRUE(selections_are_lane_wise());
}

}  // namespace
}  // namespace coldspray::simd

#endif
