// The per-point constitutive kernels behind stress_update.hpp, as templates over the concrete
// models of a ModelSet (model_dispatch.hpp), for solvers that loop over arrays of points.
// update_point follows thesis Appendix A step by step; see docs/materials.md. It needs dt > 0,
// J_new > 0 and, for a material that yields, C_p > 0 (checked where materials are loaded).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "materials/heating.hpp"
#include "materials/radial_return.hpp"
#include "materials/strength/conditions.hpp"
#include "materials/stress_update.hpp"

namespace coldspray::materials {

// Eq A5 for a deviator s: sqrt(3/2 s:s).
inline double von_mises(const Eigen::Matrix3d& s) { return std::sqrt(1.5 * s.squaredNorm()); }

template <class Models>
PointState initial_point(const Models& models, double temperature) {
  const double rho0 = models.material.density;
  PointState st;
  st.temperature = temperature;
  st.shear_modulus = models.shear_modulus_at(temperature);
  st.melt_temperature = models.melt_temperature_at(rho0);
  st.flow_stress =
      models.flow_stress_at(0.0, 0.0, {temperature, rho0, st.shear_modulus, st.melt_temperature});
  st.pressure = models.reference_pressure(1.0);
  return st;
}

// Steps (1)-(4) of a point's update, up to the trial stress: what the return needs, and what
// completes the step after it.
struct ElasticTrial {
  Eigen::Matrix3d s_rotated;        // deviator of sigma^n after the Jaumann rotation
  Eigen::Matrix3d s;                // elastic trial deviator (eq A4)
  double p_old = 0.0;               // p^n
  double trial = 0.0;               // von Mises stress of s (eq A5)
  double three_G = 0.0;             // 3G, G at T^n
  strength::Conditions conditions;  // T^n, rho^{n+1}, G, Tm(rho^{n+1}): fixed in the step
};

template <class Models>
ElasticTrial elastic_trial(const Models& models, const StepKinematics& k, const PointState& st) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d& W = k.spin_increment;
  const Eigen::Matrix3d& d = k.strain_increment;
  const double rho = models.material.density / k.J_new;
  ElasticTrial t;
  // (1) Jaumann rotation of sigma^n by the spin increment W dt (eq A2).
  const Eigen::Matrix3d rotated = st.stress + st.stress * W.transpose() + W * st.stress;
  // (2) Pressure and deviator (eq A3); the trace is unchanged by (1), so this is p^n.
  t.p_old = -rotated.trace() / 3.0;
  t.s_rotated = rotated + t.p_old * I;
  // (3) Elastic trial deviator (eqs A1.3, A4), G at T^n.
  const double G = models.shear_modulus_at(st.temperature);
  t.s = t.s_rotated + 2.0 * G * (d - d.trace() / 3.0 * I);
  // (4) Trial von Mises stress (eq A5).
  t.trial = von_mises(t.s);
  t.three_G = 3.0 * G;
  // Temperature is explicit: T^n throughout the step.
  t.conditions = {st.temperature, rho, G, models.melt_temperature_at(rho)};
  return t;
}

// (5) The yield check at the rate floor and the consistent return (eqs A6-A8 with sigma_y solved
// in the step), started from the last step's rate.
template <class Models>
PlasticIncrement plastic_increment(const Models& models, const StepKinematics& k,
                                   const ElasticTrial& t, const PointState& st) {
  const auto flow_stress = models.flow_stress_in_step(t.conditions);
  const double eqps = st.eqps;
  return consistent_return(t.trial, t.three_G, st.eqps_rate * k.dt,
                           [&](double x) { return flow_stress(eqps + x, x / k.dt); });
}

// Steps (5)-(7) from the return's increment: the returned deviator, heating, energy and pressure.
template <class Models>
void complete_update(const Models& models, const StepKinematics& k, const UpdateOptions& opt,
                     ElasticTrial& t, const PlasticIncrement& inc, PointState& st) {
  const Eigen::Matrix3d& d = k.strain_increment;
  const double rho = t.conditions.density;
  Eigen::Matrix3d& s = t.s;
  const double flow = inc.flow_stress;
  const double d_eqps = inc.eqps_increment;
  st.eqps_rate = d_eqps / k.dt;
  if (d_eqps > 0.0) {
    s *= flow / t.trial;  // eq A8
    // (6) Adiabatic heating (eq 3.44) with the step's final flow stress.
    if (!opt.isothermal)
      st.temperature += adiabatic_temperature_rise(models.material.thermal, flow, d_eqps, rho);
  }
  st.eqps += d_eqps;

  // (7) Energy and pressure (eqs 3.39-3.43 divided by V0): trapezoidal work of the deviator at
  // the mid-step, then p^{n+1} solved implicitly with the energy it does.
  const double dJ = k.J_new - st.J;
  const double J_half = 0.5 * (st.J + k.J_new);
  const double deviatoric_work = 0.5 * (t.s_rotated + s).cwiseProduct(d).sum();
  const double energy_trial = st.energy + J_half * deviatoric_work - 0.5 * dJ * t.p_old;
  const double B = models.energy_coefficient();
  const double p = (models.reference_pressure(k.J_new) + B * energy_trial) / (1.0 + 0.5 * B * dJ);
  st.energy = energy_trial - 0.5 * dJ * p;

  st.stress = s - p * Eigen::Matrix3d::Identity();
  st.J = k.J_new;
  st.flow_stress = flow;
  st.shear_modulus = t.conditions.shear_modulus;
  st.melt_temperature = t.conditions.melt_temperature;
  st.pressure = p;
}

template <class Models>
void update_point(const Models& models, const StepKinematics& k, const UpdateOptions& opt,
                  PointState& st) {
  ElasticTrial t = elastic_trial(models, k, st);
  const PlasticIncrement inc = plastic_increment(models, k, t, st);
  complete_update(models, k, opt, t, inc, st);
}

template <class Models>
double point_wave_speed(const Models& models, const PointState& st) {
  const double rho = models.material.density / st.J;
  const double G = models.shear_modulus_at(st.temperature);
  // K_t floored at zero: in deep tension the Gruneisen term can make it negative, and the
  // time-step bound then rests on the shear wave alone.
  const double K = std::max(models.tangent_bulk_modulus(st.J, st.energy), 0.0);
  return std::sqrt((K + 4.0 / 3.0 * G) / rho);
}

}  // namespace coldspray::materials
