// Moving one point's material state between the structure-of-arrays storage and the
// materials::PointState the constitutive kernels work on.
#pragma once

#include "bodies/points.hpp"
#include "materials/stress_update.hpp"

namespace coldspray::bodies {

// Points' stress arrays and SymmetricTensor name the components in the same order.
static_assert(materials::SymmetricTensor::index(0, 0) == kXX &&
              materials::SymmetricTensor::index(1, 1) == kYY &&
              materials::SymmetricTensor::index(2, 2) == kZZ &&
              materials::SymmetricTensor::index(0, 1) == kXY &&
              materials::SymmetricTensor::index(1, 2) == kYZ &&
              materials::SymmetricTensor::index(0, 2) == kXZ);

// Point p's Cauchy stress, Pa.
inline materials::SymmetricTensor stress_at(const Points& P, std::size_t p) {
  materials::SymmetricTensor sigma;
  for (int c = 0; c < 6; ++c) sigma.c[c] = P.stress[c][p];
  return sigma;
}

// The state the next update needs. Its diagnostics melt_temperature and pressure stay unset:
// the update only writes them.
inline materials::PointState load_point_state(const Points& P, std::size_t p) {
  materials::PointState s;
  s.stress = stress_at(P, p);
  s.eqps = P.eqps[p];
  s.eqps_rate = P.eqps_rate[p];
  s.return_slope = P.return_slope[p];
  s.temperature = P.temperature[p];
  s.energy = P.energy[p];
  s.J = P.J[p];
  s.flow_stress = P.flow_stress[p];
  s.shear_modulus = P.shear_modulus[p];
  return s;
}

inline void store_point_state(const materials::PointState& s, Points& P, std::size_t p) {
  for (int c = 0; c < 6; ++c) P.stress[c][p] = s.stress.c[c];
  P.eqps[p] = s.eqps;
  P.eqps_rate[p] = s.eqps_rate;
  P.return_slope[p] = s.return_slope;
  P.temperature[p] = s.temperature;
  P.energy[p] = s.energy;
  P.J[p] = s.J;
  P.flow_stress[p] = s.flow_stress;
  P.shear_modulus[p] = s.shear_modulus;
}

}  // namespace coldspray::bodies
