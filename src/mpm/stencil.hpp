// The nodes a material point talks to and their weights N_Ip and gradients N_Ip,j: tensor
// products of the 1D shape functions. In r-z runs the y axis has a single node layer.
#pragma once

#include <algorithm>
#include <cstddef>

#include "bodies/points.hpp"
#include "mpm/grid.hpp"
#include "mpm/shape_functions.hpp"

namespace coldspray::mpm {

template <class Shape, bool Axisymmetric>
struct Stencil {
  static constexpr int S = Shape::kSupport;
  static constexpr int SY = Axisymmetric ? 1 : S;

  Weights1D<S> wx, wy, wz;

  // The weights at point p: its position and GIMP half-widths.
  void evaluate(const GridLayout& g, const bodies::Points& P, std::size_t p) {
    const double inv_h = 1.0 / g.h;
    // A domain wider than a cell would reach past the 3-node support: capped at h/2.
    auto a = [&](int d) { return std::min(P.half_width[d][p] * inv_h, 0.5); };
    const double x = P.position[0][p], y = P.position[1][p], z = P.position[2][p];
    Shape::evaluate((z - g.origin[2]) * inv_h, a(2), inv_h, wz);
    if constexpr (Axisymmetric) {
      // The point's domain stops at the axis: within lp of r = 0 it shrinks to [0, 2r], so the
      // weights tend to the linear hat, v_r interpolates to 0 at r = 0 and the hoop rate v_r/r
      // stays bounded. (An uncut GIMP domain gives v_r(r -> 0) != 0 and a diverging hoop rate.)
      Shape::evaluate((x - g.origin[0]) * inv_h, std::min(a(0), x * inv_h), inv_h, wx);
      wy.base = 0;
      wy.count = 1;
      for (int n = 0; n < S; ++n) wy.w[n] = wy.dw[n] = 0.0;
      wy.w[0] = 1.0;
    } else {
      Shape::evaluate((x - g.origin[0]) * inv_h, a(0), inv_h, wx);
      Shape::evaluate((y - g.origin[1]) * inv_h, a(1), inv_h, wy);
    }
  }

  // Calls f(node, N, dN/dx, dN/dy, dN/dz) for every node of the support the point reaches, in a
  // fixed order.
  template <class F>
  void for_each(const GridLayout& g, F&& f) const {
    for (int k = 0; k < wz.count; ++k)
      for (int j = 0; j < wy.count; ++j) {
        const double wyz = wy.w[j] * wz.w[k];
        const double dy = wy.dw[j] * wz.w[k];
        const double dz = wy.w[j] * wz.dw[k];
        const std::size_t row = g.index(wx.base, wy.base + j, wz.base + k);
        for (int i = 0; i < wx.count; ++i)
          f(row + i, wx.w[i] * wyz, wx.dw[i] * wyz, wx.w[i] * dy, wx.w[i] * dz);
      }
  }
};

}  // namespace coldspray::mpm
