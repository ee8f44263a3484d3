// The zero-energy-mode control's stiffness along the flow (peridynamics.control_stiffness: flow;
// pd/forces.hpp). The control resists the non-uniform part z of each bond's deformation with a
// fraction G_s of the material's elastic stiffness (Silling 2017). Where the material flows, a
// J2 material resists further deviatoric strain along the flow direction N = s / |s| with its
// tangent modulus 2G H / (3G + H), not the elastic 2G, and every other strain as before (the
// continuum elastoplastic tangent C - 2G 3G / (3G + H) N (x) N; Simo and Hughes, Computational
// Inelasticity, 1998, ch. 3). An elastic penalty on a shear band narrower than the horizon
// resists the flow itself and gives back, on unloading, energy the material dissipated: in the
// PD paper's impact the crater came out 9-14 % shallower than the MPM's and the particle
// rebounded 3.5-5 times faster (docs/validation/pd-vs-mpm.md). One scalar scale for the whole
// penalty was tried and withdrawn: it removes the control of every mode where the material
// flows (docs/pd.md). Here only the part of z whose strain lies along N is softened:
//
//   a bond's z strains the material by sym(z (x) e) / |Y|, e = Y / |Y| its current direction;
//   the strain's component along N is z . N e / |Y|, largest for z along m = N e / |N e|, and
//   the unit strain of z = m lies along N by the share alpha = (m . N e)^2 / |sym(m (x) e)|^2 =
//   2 |N e|^2 / (1 + (m . e)^2), in [0, 1] (Cauchy-Schwarz, |N| = 1). The softened part of an
//   increment dz is a alpha m (m . dz), a = 1 - H / (3G + H) = 3G / (3G + H) where the point
//   flowed in the step (0 elsewhere): 2 a |u|^2 (u . dz) / (|u|^2 |Y|^2 + (u . Y)^2) u with
//   u = N Y, no square root.
//
// Like the stress it stands beside, the penalty is elastic-plastic, not hypoelastic: each pair of
// neighbours keeps its penalty's displacement e (the accumulated z_i + z_j less the softened
// parts), and an increment is softened only where it loads, (u . dz) (u . e) >= 0, so that the
// penalty never gives back what it did not store. (Softening every increment, whatever its
// sign, was tried: the answer did not depend on the step, but a stiffness that falls while the
// spring is loaded releases energy it never stored, and the coarse impact's control did 1.9e-8 J
// of work on the bodies, 12 % of the impact energy. Softening only the loading increments of a
// force summed per point, without e, ratchets and was unstable.) Then e . (softened part) >= 0,
// and the penalty's energy never grows by more than the work done on it.
#pragma once

#include <Eigen/Core>
#include <algorithm>

#include "materials/strength/conditions.hpp"
#include "materials/stress_update.hpp"

namespace coldspray::pd {

// The plastic-strain step of the forward difference for H: small against any eqps that hardens
// appreciably, large enough that the flow stresses' difference is far above their round-off.
inline constexpr double kHardeningStrainStep = 1e-6;

// a = 3G / (3G + H) for a point's state after a step, `flowed` if its eqps grew in the step, with
// the material's models (materials/model_dispatch.hpp) at density rho; 0 if it did not flow, 1
// where the flow stress does not harden. H is the slope of the flow stress against the plastic
// strain at the point's strain rate, temperature and density, from a forward difference: not the
// consistent return's slope, whose rate term d sigma_y / d(rate) / dt grows without bound as dt
// falls (with it the coarse impact's rebound went from 3.5 to 26.8 m/s when the step halved).
template <class Models>
double flow_softening(const Models& models, const materials::PointState& state, bool flowed,
                      double rho) {
  if (!flowed) return 0.0;
  const materials::strength::Conditions conditions{state.temperature, rho, state.shear_modulus,
                                                   state.melt_temperature};
  const double sigma = models.flow_stress_at(state.eqps, state.eqps_rate, conditions);
  const double hardened =
      models.flow_stress_at(state.eqps + kHardeningStrainStep, state.eqps_rate, conditions);
  const double H = std::max(0.0, (hardened - sigma) / kHardeningStrainStep);
  const double three_G = 3.0 * state.shear_modulus;
  return three_G / (three_G + H);
}

// The unit deviatoric direction N = s / |s| of a Cauchy stress, zero if it has no deviator.
inline Eigen::Matrix3d flow_direction(const Eigen::Matrix3d& sigma) {
  Eigen::Matrix3d s = sigma;
  s.diagonal().array() -= sigma.trace() / 3.0;
  const double norm = s.norm();
  return norm > 0.0 ? Eigen::Matrix3d(s / norm) : Eigen::Matrix3d::Zero();
}

// The part a alpha m (m . dz) of an increment dz (or rate) of a bond's non-uniform deformation
// that the flow softens, seen from an end with flow direction N (padded, pd/state.hpp) and
// softening a, for the bond Y = y_j - y_i in the current positions (either sign, with dz and e in
// the same sign) whose penalty displacement is e: zero where a = 0 or where dz unloads e along u.
template <class Padded>
Eigen::Vector4d softened_part(const Padded& N, double a, const Eigen::Vector4d& Y,
                              const Eigen::Vector4d& dz, const Eigen::Vector4d& e) {
  if (a == 0.0) return Eigen::Vector4d::Zero();
  const Eigen::Vector4d u = Y[0] * N.col(0) + Y[1] * N.col(1) + Y[2] * N.col(2);
  const double uu = u.squaredNorm(), uY = u.dot(Y), along = u.dot(dz);
  const double denominator = uu * Y.squaredNorm() + uY * uY;
  if (denominator == 0.0 || along * u.dot(e) < 0.0) return Eigen::Vector4d::Zero();
  return (2.0 * a * along * uu / denominator) * u;
}

}  // namespace coldspray::pd
