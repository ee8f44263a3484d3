// The surface area a point stands for, where it lies on a surface: V^(2/3) in 3D; in r-z the
// ring 2 pi r a of side a = sqrt(V / (2 pi r)), V the ring's volume. The impact metrics' contact
// and bonded areas sum it, and the debonding law spreads a bond's area over the grid by it.
#pragma once

#include <cmath>
#include <numbers>

#include "bodies/points.hpp"

namespace coldspray::bodies {

inline double point_area(const Points& P, std::size_t p, bool axisymmetric) {
  const double V = P.volume0[p] * P.J[p];
  if (!axisymmetric) return std::cbrt(V * V);
  const double r = P.position[0][p];
  return 2.0 * std::numbers::pi * r * std::sqrt(V / (2.0 * std::numbers::pi * r));
}

}  // namespace coldspray::bodies
