// The force density at a point (PD paper eq 14): its bonds' (eqs 7-8), the zero-energy-mode
// control's (Silling 2017) and the contacts' (pd/contact.hpp), from the state's current
// positions, deformation gradients F and A = P K^-1.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "pd/state.hpp"

namespace coldspray::pd {

struct ForceDensity {
  Eigen::Vector3d bonds, control, contact;  // N/m^3
  Eigen::Vector3d total() const { return bonds + control + contact; }
};

// Eq 8 at point i: sum over its family of T[x_i]<xi> - T[x_j]<-xi> = omega (A_i + A_j) xi V_j;
// the control: G_s c / |xi| omega (z_i + z_j) V_j with z = Y - C q(xi) seen from either end
// (C each end's second-order fit, pd/quadratic_fit.hpp), zero under any deformation up to
// quadratic order, at surfaces too; the contacts: sum over the points of other bodies nearby.
// The plain per-point path: the step visits each pair once instead (pd/pair_forces.hpp), and the
// tests hold the two together.
ForceDensity force_density(const State& s, std::size_t i);

// The short-range repulsion on i from j (pd/contact.hpp), N/m^3: zero beyond the contact
// distance.
Eigen::Vector3d contact_force(const State& s, std::size_t i, std::size_t j);

// The sum of the repulsions on i from the points of other bodies in its contact list, N/m^3.
Eigen::Vector3d contact_density(const State& s, std::size_t i);

}  // namespace coldspray::pd
