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

template <class Models>
void update_point(const Models& models, const StepKinematics& k, const UpdateOptions& opt,
                  PointState& st) {
  using Eigen::Matrix3d;
  const Matrix3d I = Matrix3d::Identity();
  const Matrix3d& W = k.spin_increment;
  const Matrix3d& d = k.strain_increment;
  const double rho = models.material.density / k.J_new;

  // (1) Jaumann rotation of sigma^n by the spin increment W dt (eq A2).
  const Matrix3d rotated = st.stress + st.stress * W.transpose() + W * st.stress;
  // (2) Pressure and deviator (eq A3); the trace is unchanged by (1), so this is p^n.
  const double p_old = -rotated.trace() / 3.0;
  const Matrix3d s_rotated = rotated + p_old * I;
  // (3) Elastic trial deviator (eqs A1.3, A4), G at T^n.
  const double G = models.shear_modulus_at(st.temperature);
  Matrix3d s = s_rotated + 2.0 * G * (d - d.trace() / 3.0 * I);
  // (4) Trial von Mises stress (eq A5).
  const double trial = von_mises(s);
  // (5) Yield check at the rate floor and the consistent return (eqs A6-A8 with sigma_y solved
  // in the step), started from the last step's rate. Temperature is explicit: T^n throughout
  // the step.
  const strength::Conditions c{st.temperature, rho, G, models.melt_temperature_at(rho)};
  const auto flow_stress = models.flow_stress_in_step(c);
  const double eqps = st.eqps;
  const PlasticIncrement inc =
      consistent_return(trial, 3.0 * G, st.eqps_rate * k.dt,
                        [&](double x) { return flow_stress(eqps + x, x / k.dt); });
  const double flow = inc.flow_stress;
  const double d_eqps = inc.eqps_increment;
  st.eqps_rate = d_eqps / k.dt;
  if (d_eqps > 0.0) {
    s *= flow / trial;  // eq A8
    // (6) Adiabatic heating (eq 3.44) with the step's final flow stress.
    if (!opt.isothermal)
      st.temperature += adiabatic_temperature_rise(models.material.thermal, flow, d_eqps, rho);
  }
  st.eqps += d_eqps;

  // (7) Energy and pressure (eqs 3.39-3.43 divided by V0): trapezoidal work of the deviator at
  // the mid-step, then p^{n+1} solved implicitly with the energy it does.
  const double dJ = k.J_new - st.J;
  const double J_half = 0.5 * (st.J + k.J_new);
  const double deviatoric_work = 0.5 * (s_rotated + s).cwiseProduct(d).sum();
  const double energy_trial = st.energy + J_half * deviatoric_work - 0.5 * dJ * p_old;
  const double B = models.energy_coefficient();
  const double p = (models.reference_pressure(k.J_new) + B * energy_trial) / (1.0 + 0.5 * B * dJ);
  st.energy = energy_trial - 0.5 * dJ * p;

  st.stress = s - p * I;
  st.J = k.J_new;
  st.flow_stress = flow;
  st.shear_modulus = G;
  st.melt_temperature = c.melt_temperature;
  st.pressure = p;
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
