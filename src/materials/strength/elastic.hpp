// No plasticity: an infinite flow stress, so the yield check of the stress update never fires
// and the deviator stays elastic, with no separate code path.
#pragma once

#include <limits>

#include "materials/material.hpp"
#include "materials/strength/conditions.hpp"

namespace coldspray::materials::strength {

inline double flow_stress(const Elastic&, double /*eqps*/, double /*rate*/,
                          const Conditions& /*conditions*/) {
  return std::numeric_limits<double>::infinity();
}

}  // namespace coldspray::materials::strength
