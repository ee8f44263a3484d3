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
#include "materials/symmetric_tensor.hpp"

namespace coldspray::materials {

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

// rho^{n+1} = rho0 / J^{n+1} (eq 3.36).
template <class Models>
double step_density(const Models& models, const StepKinematics& k) {
  return models.material.density / k.J_new;
}

// Steps (1)-(4) of a point's update, up to the trial stress: what the return needs, and what
// completes the step after it.
struct ElasticTrial {
  SymmetricTensor s_rotated;        // deviator of sigma^n after the Jaumann rotation
  SymmetricTensor s;                // elastic trial deviator (eq A4)
  double p_old = 0.0;               // p^n
  double trial = 0.0;               // von Mises stress of s (eq A5)
  double three_G = 0.0;             // 3G, G at T^n
  strength::Conditions conditions;  // T^n, rho^{n+1}, G, Tm(rho^{n+1}): fixed in the step
};

// G at T^n is the state's (kept by every update); Tm at rho^{n+1} is the caller's, so that a
// batch of points can evaluate the melt model together (stress_update_lanes.hpp).
template <class Models>
ElasticTrial elastic_trial(const Models& models, const StepKinematics& k, const PointState& st,
                           double melt_temperature) {
  ElasticTrial t;
  // (1) Jaumann rotation of sigma^n by the spin increment W dt (eq A2).
  const SymmetricTensor rotated = jaumann_rotated(st.stress, k.spin_increment);
  // (2) Pressure and deviator (eq A3); the trace is unchanged by (1), so this is p^n.
  t.p_old = -rotated.trace() / 3.0;
  t.s_rotated = rotated.plus_identity(t.p_old);
  // (3) Elastic trial deviator (eqs A1.3, A4), G at T^n.
  const double G = st.shear_modulus;
  t.s = t.s_rotated.plus_scaled(2.0 * G, deviator(k.strain_increment));
  // (4) Trial von Mises stress (eq A5).
  t.trial = t.s.von_mises();
  t.three_G = 3.0 * G;
  // Temperature is explicit: T^n throughout the step.
  t.conditions = {st.temperature, step_density(models, k), G, melt_temperature};
  return t;
}

// The return's starting point: the last step's increment, advanced along the last step's slope.
inline double warm_start(const StepKinematics& k, const ElasticTrial& t, const PointState& st) {
  return predicted_increment(t.trial, t.three_G, st.eqps_rate * k.dt, st.flow_stress,
                             st.return_slope);
}

// (5) The yield check at the rate floor and the consistent return (eqs A6-A8 with sigma_y solved
// in the step), started from the last step's increment and slope.
template <class Models>
PlasticIncrement plastic_increment(const Models& models, const StepKinematics& k,
                                   const ElasticTrial& t, const PointState& st) {
  const auto flow_stress = models.flow_stress_in_step(t.conditions);
  const double eqps = st.eqps;
  return consistent_return(t.trial, t.three_G, warm_start(k, t, st), st.return_slope,
                           [&](double x) { return flow_stress(eqps + x, x / k.dt); });
}

// Steps (5)-(7) from the return's increment: the returned deviator, heating, energy and pressure.
// The shear modulus is left at G(T^n); the caller brings it to the new temperature.
template <class Models>
void complete_update(const Models& models, const StepKinematics& k, const UpdateOptions& opt,
                     ElasticTrial& t, const PlasticIncrement& inc, PointState& st) {
  const double rho = t.conditions.density;
  SymmetricTensor& s = t.s;
  const double flow = inc.flow_stress;
  const double d_eqps = inc.eqps_increment;
  st.eqps_rate = d_eqps / k.dt;
  st.return_slope = inc.residual_slope;
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
  const SymmetricTensor& d = k.strain_increment;
  const double deviatoric_work = 0.5 * (t.s_rotated.contract(d) + s.contract(d));
  const double energy_trial = st.energy + J_half * deviatoric_work - 0.5 * dJ * t.p_old;
  const double B = models.energy_coefficient();
  const double p = (models.reference_pressure(k.J_new) + B * energy_trial) / (1.0 + 0.5 * B * dJ);
  st.energy = energy_trial - 0.5 * dJ * p;

  st.stress = s.plus_identity(-p);
  st.J = k.J_new;
  st.flow_stress = flow;
  st.melt_temperature = t.conditions.melt_temperature;
  st.pressure = p;
}

template <class Models>
void update_point(const Models& models, const StepKinematics& k, const UpdateOptions& opt,
                  PointState& st) {
  ElasticTrial t =
      elastic_trial(models, k, st, models.melt_temperature_at(step_density(models, k)));
  const PlasticIncrement inc = plastic_increment(models, k, t, st);
  complete_update(models, k, opt, t, inc, st);
  // G at T^{n+1}, for the wave speed and the next step.
  if (st.temperature != t.conditions.temperature)
    st.shear_modulus = models.shear_modulus_at(st.temperature);
}

// The longitudinal (P-wave) modulus K_t + 4G/3 at the point's state.
template <class Models>
double longitudinal_modulus(const Models& models, const PointState& st) {
  // K_t floored at zero: in deep tension the Gruneisen term can make it negative, and the
  // time-step bound then rests on the shear wave alone.
  const double K = std::max(models.tangent_bulk_modulus(st.J, st.energy), 0.0);
  return K + 4.0 / 3.0 * st.shear_modulus;
}

// sqrt(M / rho), rho = rho0 / J: plain arithmetic, so that a loop over points vectorises it.
inline double wave_speed_of(double longitudinal_modulus, double rho0, double J) {
  return std::sqrt(longitudinal_modulus / (rho0 / J));
}

template <class Models>
double point_wave_speed(const Models& models, const PointState& st) {
  return wave_speed_of(longitudinal_modulus(models, st), models.material.density, st.J);
}

}  // namespace coldspray::materials
