// The length that sets peridynamics' time step (docs/pd.md, "Time step"). The discretisation is
// total Lagrangian: bonds keep their reference vectors xi, so a signal that runs at c through the
// current configuration runs at c / lambda through the reference one, lambda the stretch along its
// path, and crosses a reference spacing h in lambda h / c. The critical step of an explicit
// total-Lagrangian discretisation is therefore set by the current length, not the initial one
// (Belytschko, Liu, Moran and Elkhodary, Nonlinear Finite Elements for Continua and Structures,
// 2nd ed., Wiley 2014, ch. 6). A point counts with the smallest principal stretch of its F
// (eq 5); a stretched one (lambda > 1) counts at h, since the control's and the contact's
// stiffnesses, fixed in the reference configuration, do not soften with it.
//
// The bound itself, measured on the Cu impacts (docs/pd.md, "Time step"): about 2.6 h / c on the
// undeformed lattice and about 3.7 lambda h / c once compressed (the family spreads the stiff
// direction over its horizon). The two meet at lambda = 0.7, so the step scales with
// min(1, lambda / 0.7): the same fraction cfl / 2.6 of the bound at every stretch.
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace coldspray::pd {

// Where the measured compressed bound, 3.7 lambda h / c, falls below the undeformed one, 2.6 h / c.
inline constexpr double kStiffeningStretch = 0.7;

// Subcycling (pd/stepper.hpp): a body takes at most this many steps per step of the largest.
inline constexpr int kMaxSubsteps = 8;

// A point crushed below this stretch stops the run (exit 3, with the point): the step, which
// follows it, would fall a hundredfold and the run stall, where det F <= 0 is a fault already.
inline constexpr double kCrushedStretch = 0.01;

// Below this distance |C - I| (Frobenius) a point is counted at Weyl's lower bound instead of its
// exact stretch: at most 2.5 % short of it, and without the eigen-solve that took 8 % of a D/25
// impact step (most points of an impact are nearly undeformed; measured A/B, 2 threads).
inline constexpr double kNearlyUndeformed = 0.05;

// min(1, lambda_min), lambda_min^2 the smallest eigenvalue of C = F^T F; near C = I a lower bound
// of it: every eigenvalue of C = I + E lies within |E|_2 <= |E|_F of 1 (Weyl's inequality).
inline double compressed_stretch(const Eigen::Matrix3d& F) {
  const Eigen::Matrix3d C = F.transpose() * F;
  const double distance = (C - Eigen::Matrix3d::Identity()).norm();
  if (distance < kNearlyUndeformed) return std::sqrt(1.0 - distance);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(C, Eigen::EigenvaluesOnly);
  return std::min(1.0, std::sqrt(std::max(0.0, eigen.eigenvalues()[0])));
}

// The factor on h / c that a point of compressed stretch lambda allows the step: min(1, lambda /
// 0.7), so that a step of cfl h / c on the undeformed lattice keeps its margin when compressed.
inline double step_length_factor(double compressed_stretch) {
  return std::min(1.0, compressed_stretch / kStiffeningStretch);
}

}  // namespace coldspray::pd
