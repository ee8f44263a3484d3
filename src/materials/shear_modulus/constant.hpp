// Temperature-independent shear modulus: the material's elastic G.
#pragma once

#include "materials/material.hpp"

namespace coldspray::materials::shear_modulus {

inline double modulus(const Constant&, const Elastic& elastic, double /*temperature*/) {
  return elastic.shear_modulus;
}

}  // namespace coldspray::materials::shear_modulus
