// One-dimensional shape functions; the 3D (or r-z) weights are their tensor products.
// linear: the trilinear hat of thesis eq 3.20. gimp: uniform GIMP (Bardenhagen & Kober 2004),
// the hat convolved with the particle's characteristic function of half-width lp, which is
// smooth across cell faces and removes the cell-crossing noise the thesis lists as future work.
#pragma once

#include <cmath>

namespace coldspray::mpm {

// Weights of the nodes base, ..., base + count - 1 along one axis, and their derivatives d/dx.
// Left uninitialised: every evaluate() sets all of them, once per point and phase.
template <int Support>
struct Weights1D {
  int base;
  int count;  // the nodes the point reaches: Support, less the end nodes of zero weight
  double w[Support];
  double dw[Support];
};

// Drops the end nodes where both the weight and its derivative are zero: they add nothing to any
// sum, and a loop over the point's nodes then skips them. A GIMP point reaches the nodes within
// h + lp of it, so along an axis it reaches a third node only when it lies within lp of a face
// of its cell: a lattice point of 4 per cell, or one deformed little, reaches 8 of the 27 nodes
// in 3D (docs/mpm.md, "Shape functions").
template <int Support>
void drop_empty_end_nodes(Weights1D<Support>& out) {
  auto empty = [&](int n) { return out.w[n] == 0.0 && out.dw[n] == 0.0; };
  int first = 0, last = Support - 1;
  while (first < last && empty(first)) ++first;
  while (last > first && empty(last)) --last;
  for (int n = 0; n < Support; ++n) {
    const bool kept = n + first <= last;
    out.w[n] = kept ? out.w[n + first] : 0.0;
    out.dw[n] = kept ? out.dw[n + first] : 0.0;
  }
  out.base += first;
  out.count = last - first + 1;
}

struct LinearShape {
  static constexpr int kSupport = 2;
  // xi = (x - origin)/h; a = lp/h (unused).
  static void evaluate(double xi, double /*a*/, double inv_h, Weights1D<2>& out) {
    const double cell = std::floor(xi);
    const double f = xi - cell;
    out.base = static_cast<int>(cell);
    out.w[0] = 1.0 - f;
    out.w[1] = f;
    out.dw[0] = -inv_h;
    out.dw[1] = inv_h;
    out.count = 2;  // (a hat's derivative is never zero at both ends)
  }
};

struct GimpShape {
  static constexpr int kSupport = 3;
  // The support of a node is |r| < 1 + a (r = xi - node, a = lp/h <= 1/2), so the three nodes
  // around the nearest one cover every node with a non-zero weight. (Forced inline: GCC kept it
  // a call, 3 % of an r-z step.)
  [[gnu::always_inline]] static void evaluate(double xi, double a, double inv_h,
                                              Weights1D<3>& out) {
    out.base = static_cast<int>(std::floor(xi + 0.5)) - 1;
    for (int n = 0; n < 3; ++n) {
      const double r = xi - (out.base + n);
      const double d = std::abs(r);
      const double sign = r < 0.0 ? -1.0 : 1.0;
      if (d < a) {
        out.w[n] = 1.0 - (r * r + a * a) / (2.0 * a);
        out.dw[n] = -r / a * inv_h;
      } else if (d <= 1.0 - a) {
        out.w[n] = 1.0 - d;
        out.dw[n] = -sign * inv_h;
      } else if (d < 1.0 + a) {
        const double t = 1.0 + a - d;
        out.w[n] = t * t / (4.0 * a);
        out.dw[n] = -sign * t / (2.0 * a) * inv_h;
      } else {
        out.w[n] = 0.0;
        out.dw[n] = 0.0;
      }
    }
    drop_empty_end_nodes(out);
  }
};

}  // namespace coldspray::mpm
