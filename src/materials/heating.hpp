// Adiabatic heating by plastic work (thesis eq 3.44): dT = chi sigma_y d_eqps / (rho C_p), with
// chi the Taylor-Quinney fraction of plastic work turned into heat.
#pragma once

#include "materials/material.hpp"

namespace coldspray::materials {

inline double adiabatic_temperature_rise(const Thermal& t, double flow_stress, double d_eqps,
                                         double density) {
  return t.taylor_quinney * flow_stress * d_eqps / (density * t.specific_heat);
}

}  // namespace coldspray::materials
