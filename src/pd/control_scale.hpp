// The scale of the zero-energy-mode control's stiffness at a point (pd/forces.hpp): the ratio of
// the material's tangent modulus to its elastic one, 1 in a step without plastic flow.
//
// The control resists a bond's non-uniform deformation with a fraction G_s of the material's
// elastic stiffness (Silling 2017). Where the material flows, the continuum resists further
// deviatoric deformation along the flow with its tangent modulus, not the elastic one, so an
// elastic penalty resists real flow: in the PD paper's impact the crater came out 9-14 % shallower
// than the MPM's and the particle rebounded 2.5-3.5 times faster, the penalty giving back what it
// stored (docs/validation/pd-vs-mpm.md). Scaling the penalty's stiffness with the tangent modulus
// is the remedy of the tangent-modulus-based penalty for elasto-plastic correspondence models (Eur.
// J. Mech. A/Solids 118 (2026) 106092); applied to the penalty's increments (pd/forces.hpp), it
// does not give back on unloading what the penalty took while the material flowed (the
// incremental penalty of Zhang, Wu, Lourenco and Hu, arXiv 2409.11474, for SPH).
//
// For J2 plasticity the tangent along the flow direction is 2G H / (3G + H) against the elastic
// 2G, H the hardening modulus (Simo and Hughes, Computational Inelasticity, 1998, ch. 3: the
// continuum elastoplastic tangent 2G (1 - 3G / (3G + H)) n (x) n). H is the slope of the flow
// stress against the plastic strain at the point's strain rate, temperature and density after
// the step, from a forward difference. (Not the consistent return's slope, whose rate term
// d sigma_y / d(rate) / dt grows without bound as dt falls: with it the control went back to
// the elastic one as the step shrank, and halving the step changed the coarse impact's rebound
// from 3.5 to 26.8 m/s.)
#pragma once

#include <algorithm>

#include "materials/strength/conditions.hpp"
#include "materials/stress_update.hpp"

namespace coldspray::pd {

// The plastic-strain step of the forward difference: small against any eqps that hardens
// appreciably, large enough that the flow stresses' difference is far above their round-off.
inline constexpr double kHardeningStrainStep = 1e-6;

// The ratio for a point's state after a step, `flowed` if its eqps grew in the step, with the
// material's models (materials/model_dispatch.hpp) at density rho: in [0, 1]; 0 where the flow
// stress does not harden.
template <class Models>
double control_scale(const Models& models, const materials::PointState& state, bool flowed,
                     double rho) {
  if (!flowed) return 1.0;
  const materials::strength::Conditions conditions{state.temperature, rho, state.shear_modulus,
                                                   state.melt_temperature};
  const double sigma = models.flow_stress_at(state.eqps, state.eqps_rate, conditions);
  const double hardened =
      models.flow_stress_at(state.eqps + kHardeningStrainStep, state.eqps_rate, conditions);
  const double H = (hardened - sigma) / kHardeningStrainStep;
  if (!(H > 0.0)) return 0.0;
  return std::min(1.0, H / (3.0 * state.shear_modulus + H));
}

}  // namespace coldspray::pd
