#include "pd/interface_bonds.hpp"

#include <algorithm>
#include <cmath>

namespace coldspray::pd {

double InterfaceBondLaw::break_stretch() const {
  return yield_stretch + std::log(1.0 / kBreakFraction) / softening;
}

double critical_stretch(double fracture_energy, double bulk_modulus, double delta) {
  return std::sqrt(5.0 * fracture_energy / (9.0 * bulk_modulus * delta));
}

double next_largest_stretch(const InterfaceBondLaw& law, double stretch, double largest) {
  if (stretch < 0.0) return std::max(largest, 0.0);
  if (largest == kUnbonded) return kUnbonded;
  largest = std::max(largest, stretch);
  return largest >= law.break_stretch() ? kUnbonded : largest;
}

double envelope_per_micromodulus(const InterfaceBondLaw& law, double stretch) {
  if (stretch <= law.yield_stretch) return stretch;
  if (stretch >= law.break_stretch()) return 0.0;
  return law.yield_stretch * std::exp(-law.softening * (stretch - law.yield_stretch));  // eq 24
}

double force_per_micromodulus(const InterfaceBondLaw& law, double stretch, double largest) {
  if (stretch < 0.0) return -stretch;  // eq 25
  if (largest == kUnbonded || stretch == 0.0) return 0.0;
  if (stretch >= largest) return -envelope_per_micromodulus(law, stretch);
  // Unloading: along the secant from the largest stretch's force to the origin.
  return -stretch * envelope_per_micromodulus(law, largest) / largest;
}

}  // namespace coldspray::pd
