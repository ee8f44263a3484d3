// Mechanical Threshold Stress shear modulus (thesis eq 2.6; Varshni, Phys. Rev. B 2 (1970)
// 3952, as used by Preston, Tonks & Wallace 2003): mu(T) = mu0 - D / (exp(T0/T) - 1).
#pragma once

#include <algorithm>
#include <cmath>

#include "materials/material.hpp"

namespace coldspray::materials::shear_modulus {

// Floor on mu as a fraction of mu0. Eq 2.6 falls linearly at high T and crosses zero (Al near
// 1800 K); a positive G keeps the return bracket trial/(3G), PTW's xi_dot and the wave speed
// finite. It is reached only above the melt temperature, where the flow stress is zero anyway.
inline constexpr double kMtsMinShearFraction = 0.01;

inline double modulus(const Mts& m, const Elastic&, double temperature) {
  return std::max(m.mu0 - m.D / std::expm1(m.T0 / temperature), kMtsMinShearFraction * m.mu0);
}

}  // namespace coldspray::materials::shear_modulus
