// Johnson-Cook flow stress (thesis eq 2.3; Johnson & Cook, 7th Int. Symp. Ballistics, 1983):
//   sigma_y = (A + B eqps^n) (1 + C ln rate*) (1 - T*^m).
#pragma once

#include <algorithm>
#include <cmath>

#include "materials/material.hpp"
#include "materials/strength/conditions.hpp"

namespace coldspray::materials::strength {

inline double flow_stress(const JohnsonCook& jc, double eqps, double rate, const Conditions& c) {
  const double T = c.temperature;
  const double T_ref = jc.reference_temperature;
  if (T >= c.melt_temperature) return 0.0;
  // T* clamped to [0, 1]: no hardening below T_ref (the fit's range), none left at melt.
  const double T_star = T <= T_ref ? 0.0 : (T - T_ref) / (c.melt_temperature - T_ref);
  // rate* >= 1: below the reference rate the log term would soften the material (and diverge
  // at rest), outside the range the parameters were fitted on.
  const double rate_star = std::max(rate / jc.reference_strain_rate, 1.0);
  return (jc.A + jc.B * std::pow(eqps, jc.n)) * (1.0 + jc.C * std::log(rate_star)) *
         (1.0 - std::pow(T_star, jc.m));
}

}  // namespace coldspray::materials::strength
