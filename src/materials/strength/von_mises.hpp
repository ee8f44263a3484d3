// J2 plasticity with linear isotropic hardening: sigma_y = Y + H eqps, independent of rate and
// temperature (the Wilkins-Guinan Taylor-bar material, validation-data.md §3).
#pragma once

#include "materials/material.hpp"
#include "materials/strength/conditions.hpp"

namespace coldspray::materials::strength {

inline double flow_stress(const VonMises& v, double eqps, double /*rate*/,
                          const Conditions& /*conditions*/) {
  return v.yield_stress + v.hardening_modulus * eqps;
}

}  // namespace coldspray::materials::strength
