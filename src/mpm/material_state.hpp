// Moving one point's material state between the structure-of-arrays storage and the
// materials::PointState the constitutive kernels work on.
#pragma once

#include "materials/stress_update.hpp"
#include "mpm/points.hpp"

namespace coldspray::mpm {

inline materials::PointState load_point_state(const Points& P, std::size_t p) {
  materials::PointState s;
  s.stress << P.stress[kXX][p], P.stress[kXY][p], P.stress[kXZ][p],  //
      P.stress[kXY][p], P.stress[kYY][p], P.stress[kYZ][p],          //
      P.stress[kXZ][p], P.stress[kYZ][p], P.stress[kZZ][p];
  s.eqps = P.eqps[p];
  s.eqps_rate = P.eqps_rate[p];
  s.return_slope = P.return_slope[p];
  s.temperature = P.temperature[p];
  s.energy = P.energy[p];
  s.J = P.J[p];
  s.flow_stress = P.flow_stress[p];
  s.shear_modulus = P.shear_modulus[p];
  s.melt_temperature = P.melt_temperature[p];
  s.pressure = P.pressure[p];
  return s;
}

// The stress is symmetric; its upper triangle is stored.
inline void store_point_state(const materials::PointState& s, Points& P, std::size_t p) {
  P.stress[kXX][p] = s.stress(0, 0);
  P.stress[kYY][p] = s.stress(1, 1);
  P.stress[kZZ][p] = s.stress(2, 2);
  P.stress[kXY][p] = s.stress(0, 1);
  P.stress[kYZ][p] = s.stress(1, 2);
  P.stress[kXZ][p] = s.stress(0, 2);
  P.eqps[p] = s.eqps;
  P.eqps_rate[p] = s.eqps_rate;
  P.return_slope[p] = s.return_slope;
  P.temperature[p] = s.temperature;
  P.energy[p] = s.energy;
  P.J[p] = s.J;
  P.flow_stress[p] = s.flow_stress;
  P.shear_modulus[p] = s.shear_modulus;
  P.melt_temperature[p] = s.melt_temperature;
  P.pressure[p] = s.pressure;
}

}  // namespace coldspray::mpm
