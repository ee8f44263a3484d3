// The force density at a point (PD paper eq 14): its bonds' (eqs 7-8), the rate of the
// zero-energy-mode control's (Silling 2017) and the contacts' (pd/contact.hpp), from the state's
// current positions and velocities, A = P K^-1, the velocities' second-order fits Cdot and the
// control scales r (pd/control_scale.hpp).
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "pd/state.hpp"

namespace coldspray::pd {

struct ForceDensity {
  Eigen::Vector3d bonds;         // N/m^3
  Eigen::Vector3d control_rate;  // N/m^3/s
  Eigen::Vector3d contact;       // N/m^3
};

// Eq 8 at point i: sum over its family of T[x_i]<xi> - T[x_j]<-xi> = omega (A_i + A_j) xi V_j.
// The control, Silling's penalty G_s c / |xi| omega (z_i + z_j) V_j on the non-uniform parts
// z = Y - C q(xi) of the bond seen from either end (C each end's second-order fit of the
// positions, pd/quadratic_fit.hpp), is zero under any deformation up to quadratic order, at
// surfaces too. Its rate is given here, with each end's stiffness scaled by its r:
// G_s c / |xi| omega (r_i zdot_i + r_j zdot_j) V_j, zdot = (v_j - v_i) - Cdot q(xi); the step
// accumulates it (pd/stepper.cpp), so that with r = 1 the force is Silling's to round-off (z is
// linear in the positions, which move by dt v each step), and where r < 1 the penalty takes the
// flow's increments with the tangent stiffness and gives back nothing it did not take.
// The contacts: sum over the points of other bodies nearby.
ForceDensity force_density(const State& s, std::size_t i);

// The short-range repulsion on i from j (pd/contact.hpp), N/m^3: zero beyond the contact
// distance.
Eigen::Vector3d contact_force(const State& s, std::size_t i, std::size_t j);

}  // namespace coldspray::pd
