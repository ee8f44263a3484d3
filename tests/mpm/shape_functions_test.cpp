// The 1D shape functions: partition of unity, linear reproduction, derivatives against finite
// differences, and uGIMP's closed form (Bardenhagen & Kober 2004) at hand-picked points; the
// nodes a point reaches against that closed form; and a 3D stencil's nodes.
#include "mpm/shape_functions.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "bodies/points.hpp"
#include "mpm/stencil.hpp"

namespace coldspray::mpm {
namespace {

// The weight of `node` (zero where the point does not reach it).
template <int S>
double weight_at(const Weights1D<S>& w, int node) {
  const int n = node - w.base;
  return n >= 0 && n < w.count ? w.w[n] : 0.0;
}

// uGIMP's weight of a node at distance r (in cells) from a point of half-width a, written out
// from Bardenhagen & Kober (2004) eq 20 independently of shape_functions.hpp: the reference the
// evaluated weights are checked against.
double gimp_reference(double r, double a) {
  const double d = std::abs(r);
  if (d < a) return 1.0 - (r * r + a * a) / (2.0 * a);
  if (d <= 1.0 - a) return 1.0 - d;
  if (d < 1.0 + a) return (1.0 + a - d) * (1.0 + a - d) / (4.0 * a);
  return 0.0;
}

template <class Shape>
void check_consistency(double a) {
  constexpr int S = Shape::kSupport;
  const double h = 0.7, inv_h = 1.0 / h;
  for (double xi = 3.0; xi < 5.0; xi += 0.01237) {
    Weights1D<S> w;
    Shape::evaluate(xi, a, inv_h, w);
    double sum = 0.0, first_moment = 0.0, dsum = 0.0, dmoment = 0.0;
    for (int n = 0; n < w.count; ++n) {
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
    for (int n = 0; n < w.count; ++n) {
      Weights1D<S> lo, hi;
      Shape::evaluate(xi - e, a, inv_h, lo);
      Shape::evaluate(xi + e, a, inv_h, hi);
      if (lo.base != w.base || hi.base != w.base) continue;  // (across a kink)
      const int node = w.base + n;
      EXPECT_NEAR(w.dw[n], (weight_at(hi, node) - weight_at(lo, node)) / (2.0 * e * h),
                  1e-6 * inv_h)
          << xi << " " << n;
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

TEST(ShapeFunctions, GimpReachesEveryNodeOfNonZeroWeightAndNoOther) {
  for (double a : {0.125, 0.25, 0.5})
    for (double xi = 3.0; xi < 5.0; xi += 0.003137) {
      Weights1D<3> w;
      GimpShape::evaluate(xi, a, 1.0, w);
      const int nearest = static_cast<int>(std::floor(xi + 0.5));
      for (int node = nearest - 2; node <= nearest + 2; ++node) {
        const double reference = gimp_reference(xi - node, a);
        EXPECT_NEAR(weight_at(w, node), reference, 1e-15) << xi << " " << node;
        const bool reached = node >= w.base && node < w.base + w.count;
        EXPECT_EQ(reached, reference > 0.0) << xi << " " << node;
      }
    }
}

TEST(ShapeFunctions, AGimpPointOfFourPerCellReachesTwoNodesAlongAnAxis) {
  // a = 1/8 (4 points per cell). At xi = 32.375 the nodes are 31 (|r| = 1.375 >= 1 + a, no
  // weight), 32 (0.375: 1 - 0.375 = 0.625) and 33 (0.625: 0.375): two nodes.
  Weights1D<3> w;
  GimpShape::evaluate(32.375, 0.125, 1.0, w);
  EXPECT_EQ(w.base, 32);
  EXPECT_EQ(w.count, 2);
  EXPECT_DOUBLE_EQ(w.w[0], 0.625);
  EXPECT_DOUBLE_EQ(w.w[1], 0.375);
  // Within lp of the cell face at node 32 (xi = 32.0625) it reaches node 31 too:
  // (1 + a - |r|)^2 / (4a) = (1.125 - 1.0625)^2 / 0.5 = 0.0078125.
  GimpShape::evaluate(32.0625, 0.125, 1.0, w);
  EXPECT_EQ(w.base, 31);
  EXPECT_EQ(w.count, 3);
  EXPECT_DOUBLE_EQ(w.w[0], 0.0078125);
}

TEST(ShapeFunctions, AGimpStencilVisitsOnlyTheNodesItReaches) {
  // One point of a 4-per-cell lattice in a cell of 0.5 m (positions and half-width exact in
  // binary): 2 x 2 x 2 nodes, whose weights sum to 1 and gradients to 0.
  GridLayout g;
  g.h = 0.5;
  g.nodes = {10, 10, 10};
  bodies::Points P;
  P.resize(1);
  const double x[3] = {1.0 + 0.1875, 2.0 + 0.3125, 1.5 + 0.0625};  // 3/8, 5/8, 1/8 of a cell
  for (int d = 0; d < 3; ++d) {
    P.position[d][0] = x[d];
    P.half_width[d][0] = 0.0625;  // h/8
  }
  Stencil<GimpShape, false> st;
  st.evaluate(g, P, 0);
  int nodes = 0;
  double sum = 0.0, grad[3] = {0.0, 0.0, 0.0};
  st.for_each(g, [&](std::size_t, double w, double gx, double gy, double gz) {
    ++nodes;
    sum += w;
    grad[0] += gx;
    grad[1] += gy;
    grad[2] += gz;
  });
  EXPECT_EQ(nodes, 8);
  EXPECT_NEAR(sum, 1.0, 1e-15);
  for (double gd : grad) EXPECT_NEAR(gd, 0.0, 1e-14);
  // Moved within lp of a face along x (1/16 of a cell past node 2), it reaches a third layer.
  P.position[0][0] = 1.0 + 0.03125;
  st.evaluate(g, P, 0);
  nodes = 0;
  st.for_each(g, [&](std::size_t, double, double, double, double) { ++nodes; });
  EXPECT_EQ(nodes, 12);
}

}  // namespace
}  // namespace coldspray::mpm
