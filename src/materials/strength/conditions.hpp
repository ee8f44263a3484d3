// What a flow stress depends on besides the plastic strain and its rate. Within one stress
// update these are fixed (temperature at the start of the step, density at its end), so the
// consistent return (radial_return.hpp) varies only the strain and the rate.
#pragma once

namespace coldspray::materials::strength {

struct Conditions {
  double temperature = 0.0;       // K
  double density = 0.0;           // kg/m^3
  double shear_modulus = 0.0;     // Pa, from the material's shear-modulus model
  double melt_temperature = 0.0;  // K, from the material's melt model
};

}  // namespace coldspray::materials::strength
