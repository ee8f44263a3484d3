// The force density at a point (PD paper eq 14): its bonds' (eqs 7-8), the rate of the
// zero-energy-mode control's (Silling 2017) and the contacts' (pd/contact.hpp), from the state's
// current positions and velocities, A = P K^-1, the velocities' second-order fits Cdot and, for
// the control along the flow, each point's flow direction and softening.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>

#include "pd/state.hpp"

namespace coldspray::pd {

struct ForceDensity {
  Eigen::Vector3d bonds;         // N/m^3
  Eigen::Vector3d control_rate;  // N/m^3/s
  Eigen::Vector3d contact;       // N/m^3
};

// Eq 8 at point i: sum over its family of T[x_i]<xi> - T[x_j]<-xi> = omega (A_i + A_j) xi V_j.
// The control, Silling's penalty G_s c / l omega (z_i + z_j) V_j on the non-uniform parts
// z = Y - C q(xi) of the bond seen from either end (C each end's second-order fit of the
// positions, pd/quadratic_fit.hpp), is zero under any deformation up to quadratic order, at
// surfaces too; weighed by c / l (pd/control_length.hpp), not Silling's c / |xi|, it derives from
// a stored energy. Its rate is given here, G_s c / l omega (P_i zdot_i + P_j zdot_j) V_j with
// zdot = (v_j - v_i) - Cdot q(xi) and P = I less the part each end's flow softens (identity for
// the elastic control and where the point did not flow; pd/control_along_flow.hpp). The step
// accumulates it (pd/stepper.cpp): with P = I the sum is Silling's penalty on the current
// positions to round-off (z is linear in the positions, which move by dt v each step); where
// P < I the penalty takes the flow's increments with the softened stiffness and gives back
// nothing it did not take. The contacts: sum over the points of other bodies nearby.
// The plain per-point path: the step visits each pair once instead (pd/pair_forces.hpp), and the
// tests hold the two together.
ForceDensity force_density(const State& s, std::size_t i);

// The penalty displacement e of the pair (i, j) seen from i (pd/control_along_flow.hpp), m: the
// pair is stored at its lower index, and found in j's family where j < i (j is then real), with
// the sign of i's side. `bond` is j's place in i's family.
Eigen::Vector4d control_displacement(const State& s, std::size_t i, std::size_t j,
                                     std::size_t bond);

// The contact force density on i from the `candidate`-th point of its contact list, by the law
// between their bodies (pd/laws/registry.hpp), N/m^3: zero beyond the law's reach.
Eigen::Vector3d contact_force(const State& s, std::size_t i, std::size_t candidate);

// 1 + the body whose point holds i through an adhesive contact law, 0 if none (bodies::Points::
// bonded_to): with model 1, a point of another body within its cut-off; with model 2, an interface
// bond that has formed and not broken. The repulsion holds nothing.
std::uint16_t adhesive_partner(const State& s, std::size_t i);

// The sum of the contact forces on i from the points of other bodies in its contact list, N/m^3.
Eigen::Vector3d contact_density(const State& s, std::size_t i);

}  // namespace coldspray::pd
