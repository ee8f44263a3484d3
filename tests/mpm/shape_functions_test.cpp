// The 1D shape functions: partition of unity, linear reproduction, derivatives against finite
// differences, and uGIMP's closed form (Bardenhagen & Kober 2004) at hand-picked points.
#include "mpm/shape_functions.hpp"

#include <gtest/gtest.h>

namespace coldspray::mpm {
namespace {

template <class Shape>
void check_consistency(double a) {
  constexpr int S = Shape::kSupport;
  const double h = 0.7, inv_h = 1.0 / h;
  for (double xi = 3.0; xi < 5.0; xi += 0.01237) {
    Weights1D<S> w;
    Shape::evaluate(xi, a, inv_h, w);
    double sum = 0.0, first_moment = 0.0, dsum = 0.0, dmoment = 0.0;
    for (int n = 0; n < S; ++n) {
      sum += w.w[n];
      first_moment += w.w[n] * (w.base + n);
      dsum += w.dw[n];
      dmoment += w.dw[n] * (w.base + n) * h;
      EXPECT_GE(w.w[n], 0.0);
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << xi;          // partition of unity
    EXPECT_NEAR(first_moment, xi, 1e-13) << xi;  // reproduces x
    EXPECT_NEAR(dsum, 0.0, 1e-12) << xi;         // gradient of 1
    EXPECT_NEAR(dmoment, 1.0, 1e-12) << xi;      // gradient of x
    // Derivative against a central difference of the same node's weight.
    const double e = 1e-7;
    for (int n = 0; n < S; ++n) {
      Weights1D<S> lo, hi;
      Shape::evaluate(xi - e, a, inv_h, lo);
      Shape::evaluate(xi + e, a, inv_h, hi);
      if (lo.base != w.base || hi.base != w.base) continue;
      EXPECT_NEAR(w.dw[n], (hi.w[n] - lo.w[n]) / (2.0 * e * h), 1e-6 * inv_h) << xi << " " << n;
    }
  }
}

TEST(ShapeFunctions, LinearIsConsistent) { check_consistency<LinearShape>(0.0); }
TEST(ShapeFunctions, GimpIsConsistent) {
  for (double a : {0.125, 0.25, 0.5}) check_consistency<GimpShape>(a);
}

TEST(ShapeFunctions, GimpMatchesTheClosedForm) {
  // lp = h/4 (a = 1/4). A point at xi = 2.1: distances 1.1, 0.1, -0.9 to nodes 1, 2, 3.
  // |r| = 1.1 in (1 - a, 1 + a): (1 + a - |r|)^2 / (4a) = 0.15^2 = 0.0225;
  // |r| = 0.1 < a: 1 - (r^2 + a^2)/(2a) = 1 - (0.01 + 0.0625)/0.5 = 0.855;
  // |r| = 0.9 in (1 - a, 1 + a): (0.35)^2 = 0.1225. Sum 1.
  Weights1D<3> w;
  GimpShape::evaluate(2.1, 0.25, 1.0, w);
  EXPECT_EQ(w.base, 1);
  EXPECT_NEAR(w.w[0], 0.0225, 1e-15);
  EXPECT_NEAR(w.w[1], 0.855, 1e-15);
  EXPECT_NEAR(w.w[2], 0.1225, 1e-15);
}

}  // namespace
}  // namespace coldspray::mpm
