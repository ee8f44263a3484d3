// The shear modulus and the melting temperature of four points at once, for update_lanes
// (stress_update_lanes.hpp): the formulas of shear_modulus/mts.hpp (thesis eq 2.6) and melt/scg.hpp
// (eq 2.9) lane by lane, with libmvec's expm1, exp and log (core/simd.hpp). Constant models
// broadcast their value. A lane differs from the scalar form only by the vector functions'
// rounding (a few ulp).
#pragma once

#include "core/simd.hpp"

#if COLDSPRAY_HAVE_SIMD

#include "materials/material.hpp"
#include "materials/shear_modulus/mts.hpp"

namespace coldspray::materials {

namespace shear_modulus {

COLDSPRAY_SIMD_TARGET inline simd::Doubles modulus_lanes(const Constant&, const Elastic& elastic,
                                                         simd::Doubles) {
  return simd::broadcast(elastic.shear_modulus);
}

COLDSPRAY_SIMD_TARGET inline simd::Doubles modulus_lanes(const Mts& m, const Elastic&,
                                                         simd::Doubles temperature) {
  return simd::max(m.mu0 - m.D / simd::expm1(m.T0 / temperature),
                   simd::broadcast(kMtsMinShearFraction * m.mu0));
}

}  // namespace shear_modulus

namespace melt {

COLDSPRAY_SIMD_TARGET inline simd::Doubles temperature_lanes(const Constant& c, simd::Doubles) {
  return simd::broadcast(c.temperature);
}

COLDSPRAY_SIMD_TARGET inline simd::Doubles temperature_lanes(const Scg& s, simd::Doubles eta) {
  return s.Tm0 * simd::exp(2.0 * s.a * (1.0 - 1.0 / eta) +
                           2.0 * (s.gamma0 - s.a - 1.0 / 3.0) * simd::log(eta));
}

}  // namespace melt

// G at four temperatures and Tm at four densities, with a ModelSet's models.
template <class Models>
COLDSPRAY_SIMD_TARGET simd::Doubles shear_modulus_lanes(const Models& models,
                                                        simd::Doubles temperature) {
  return shear_modulus::modulus_lanes(models.shear_model, models.material.elastic, temperature);
}

template <class Models>
COLDSPRAY_SIMD_TARGET simd::Doubles melt_temperature_lanes(const Models& models,
                                                           simd::Doubles density) {
  return melt::temperature_lanes(models.melt_model, density / models.material.density);
}

}  // namespace coldspray::materials

#endif
