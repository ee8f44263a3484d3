// The constitutive update of one material point over one time step (thesis Appendix A):
// Jaumann rotation, deviatoric elastic trial, J2 radial return with a rate- and
// temperature-dependent flow stress solved consistently in the step, adiabatic heating,
// then the equation of state with the energy coupling of eqs 3.39-3.43.
// Both solvers and `coldspray material-test` call this, so what the tests check is what runs.
#pragma once

#include <Eigen/Core>

#include "materials/material.hpp"
#include "materials/symmetric_tensor.hpp"

namespace coldspray::materials {

// Everything the update needs to remember about a point between steps.
struct PointState {
  SymmetricTensor stress;  // Cauchy stress, Pa, tension positive
  double eqps = 0.0;       // equivalent plastic strain
  double eqps_rate = 0.0;  // its rate over the last step, 1/s
  // -df/dx of the last step's return near its root, Pa (radial_return.hpp): with eqps_rate, the
  // next return's starting point. 0: none yet.
  double return_slope = 0.0;
  double temperature = 298.0;  // K
  double energy = 0.0;         // internal energy per reference volume E, J/m^3 (eqs 3.39-3.41)
  double J = 1.0;              // V/V0 = rho0/rho
  // G at `temperature`, Pa: set by initial_state and brought to the new temperature by every
  // update, whose elastic trial and wave speed use it (so the shear-modulus model is evaluated
  // once per step). A state must therefore come from initial_state or an earlier update.
  double shear_modulus = 0.0;
  // Diagnostics of the last update, kept for output.
  double flow_stress = 0.0;       // Pa
  double melt_temperature = 0.0;  // K
  double pressure = 0.0;          // Pa, compression positive
};

struct UpdateOptions {
  bool isothermal = false;  // skip adiabatic heating (eq 3.44)
};

// The kinematics of the step, supplied by the solver: strain increment D*dt (symmetric),
// spin increment W*dt (skew), the step dt, and J at the end of the step.
struct StepKinematics {
  SymmetricTensor strain_increment;
  SkewTensor spin_increment;
  double dt = 0.0;
  double J_new = 1.0;

  // D dt and W dt of a velocity gradient L held over dt: its symmetric and skew parts (eq 3.34).
  void set_velocity_gradient(const Eigen::Matrix3d& L, double step) {
    strain_increment = SymmetricTensor::of(0.5 * (L + L.transpose()) * step);
    spin_increment = SkewTensor::of(0.5 * (L - L.transpose()) * step);
    dt = step;
  }
};

// Initial state of a stress-free point at temperature T: fills the diagnostics consistently.
PointState initial_state(const Material& m, double temperature);

// Advances `state` by one step. Pure function of its inputs; no allocation.
void update_stress(const Material& m, const StepKinematics& k, const UpdateOptions& opt,
                   PointState& state);

// Longitudinal elastic wave speed sqrt((K_t + 4G/3)/rho) at the point's state, with K_t the
// tangent bulk modulus of the EOS: the solvers' time-step bound.
double wave_speed(const Material& m, const PointState& state);

}  // namespace coldspray::materials
