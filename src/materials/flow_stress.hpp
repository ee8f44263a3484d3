// A material's flow stress, shear modulus and melt temperature at a given state, composing its
// strength, shear-modulus and melt models. For output, checks and tests; the stress update uses
// the same kernels through model_dispatch.hpp.
#pragma once

#include "materials/material.hpp"

namespace coldspray::materials {

// Flow stress in Pa at plastic strain eqps, plastic strain rate eqps_rate (1/s), temperature (K)
// and density (kg/m^3). +infinity for elastic strength (it never yields); 0 at or above melt.
double flow_stress(const Material& m, double eqps, double eqps_rate, double temperature,
                   double density);

// Shear modulus in Pa. Named _at because `shear_modulus` is the sub-model namespace. No current
// shear model depends on density; the argument keeps call sites stable for one that will.
double shear_modulus_at(const Material& m, double temperature, double density);

// Melting temperature in K at the given density.
double melt_temperature(const Material& m, double density);

}  // namespace coldspray::materials
