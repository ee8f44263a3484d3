// The nonlocal kinematics of correspondence peridynamics at one point (PD paper eqs 5, 6, 28):
// sums over the point's family of omega<xi> beta V_j times bond quantities, xi = X_j - X_i the
// reference bond, beta its partial-volume factor (pd/families.hpp).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "case/case.hpp"
#include "pd/families.hpp"
#include "pd/neighbours.hpp"
#include "pd/quadratic_fit.hpp"

namespace coldspray::pd {

// omega<xi> (eqs 5-7): 1, or delta / |xi|.
template <case_file::Influence kind>
double influence(double length, double delta) {
  if constexpr (kind == case_file::Influence::Constant)
    return 1.0;
  else
    return delta / length;
}

// (Always inlined, with the bond function f, into the loop that calls it: its sums then stay in
// registers.)
template <case_file::Influence kind, class F>
__attribute__((always_inline)) inline void for_each_bond_with(const Families& fam,
                                                              const Neighbours& N,
                                                              const BondWeights& weights,
                                                              std::size_t i, F&& f) {
  const Eigen::Vector4d X_i = N.reference[i];
  for (std::size_t b = fam.begin[i]; b < fam.begin[i + 1]; ++b) {
    const std::size_t j = fam.neighbour[b];
    const Eigen::Vector3d xi = (N.reference[j] - X_i).head<3>();
    const double length = xi.norm();  // not computed where neither omega nor f reads it
    f(b, j, xi, length,
      influence<kind>(length, weights.delta) * fam.volume_fraction(b) * N.volume[j]);
  }
}

// Calls f(bond, j, xi, |xi|, w) for the bonds of point i, w = omega beta V_j. The choice of
// omega is made once per family, not per bond.
template <class F>
__attribute__((always_inline)) inline void for_each_bond(const Families& fam, const Neighbours& N,
                                                         const BondWeights& weights, std::size_t i,
                                                         F&& f) {
  if (weights.influence == case_file::Influence::Constant)
    for_each_bond_with<case_file::Influence::Constant>(fam, N, weights, i, f);
  else
    for_each_bond_with<case_file::Influence::InverseDistance>(fam, N, weights, i, f);
}

// Eq 6: K = sum omega xi (x) xi V_j.
inline Eigen::Matrix3d shape_tensor(const Families& fam, const Neighbours& N,
                                    const BondWeights& weights, std::size_t i) {
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
  for_each_bond(fam, N, weights, i,
                [&](std::size_t, std::size_t, const Eigen::Vector3d& xi, double, double w) {
                  K.noalias() += w * xi * xi.transpose();
                });
  return K;
}

// The moment matrix of the second-order fit (pd/quadratic_fit.hpp): M = sum omega q (x) q V_j.
inline MomentMatrix moment_matrix(const Families& fam, const Neighbours& N,
                                  const BondWeights& weights, std::size_t i) {
  MomentMatrix M = MomentMatrix::Zero();
  for_each_bond(fam, N, weights, i,
                [&](std::size_t, std::size_t, const Eigen::Vector3d& xi, double, double w) {
                  const Monomials q = monomials(xi, weights.delta);
                  M.noalias() += w * q * q.transpose();
                });
  return M;
}

// A sum over a point's family that does not change (pd/pair_forces.hpp): sum omega xi V_j, the
// factor of A_i in eq 8 (zero on a symmetric family).
struct FamilySums {
  Eigen::Vector3d bond = Eigen::Vector3d::Zero();  // m^4
};

inline FamilySums family_sums(const Families& fam, const Neighbours& N, const BondWeights& weights,
                              std::size_t i) {
  FamilySums sums;
  for_each_bond(fam, N, weights, i,
                [&](std::size_t, std::size_t, const Eigen::Vector3d& xi, double, double w) {
                  sums.bond += w * xi;
                });
  return sums;
}

struct Deformation {
  Eigen::Matrix3d F;     // eq 5
  Eigen::Matrix3d Fdot;  // its rate, the same sum over the velocity state
  // The second-order fit of the velocities (pd/quadratic_fit.hpp), Cdot: v_j - v_i ~ Cdot q(xi),
  // the rate of the positions' fit C, which the zero-energy-mode control integrates
  // (pd/forces.hpp).
  QuadraticMap velocity_fit;
};

// Eq 5, F = [sum omega Y (x) xi V_j] K^-1 with Y = y_j - y_i in the current positions, and
// Fdot = [sum omega (v_j - v_i) (x) xi V_j] K^-1; then L = Fdot F^-1 (eq 28). The same sum
// over the bonds' monomials q gives the velocities' second-order fit Cdot = [sum omega
// (v_j - v_i) (x) q V_j] M^-1; the first three monomials are xi / delta, so the sum of Fdot is
// delta times its first columns. The sums run on padded columns, one register each.
inline Deformation deformation(const Families& fam, const Neighbours& N, const BondWeights& weights,
                               const Eigen::Matrix3d& K_inverse, const MomentMatrix& M_inverse,
                               std::size_t i) {
  const double delta = weights.delta;
  const Eigen::Vector4d y_i = N.position[i], v_i = N.velocity[i];
  QuadraticMap VQ = QuadraticMap::Zero();
  Eigen::Matrix<double, 4, 3> YX = Eigen::Matrix<double, 4, 3>::Zero();
  for_each_bond(fam, N, weights, i,
                [&](std::size_t, std::size_t j, const Eigen::Vector3d& xi, double, double w) {
                  const Eigen::Vector4d wY = w * (N.position[j] - y_i);
                  const Eigen::Vector4d wV = w * (N.velocity[j] - v_i);
                  const Monomials q = monomials(xi, delta);
                  for (int k = 0; k < 9; ++k) VQ.col(k) += q[k] * wV;
                  for (int k = 0; k < 3; ++k) YX.col(k) += xi[k] * wY;
                });
  return {YX.topRows<3>() * K_inverse, delta * VQ.topLeftCorner<3, 3>() * K_inverse,
          VQ.lazyProduct(M_inverse)};
}

}  // namespace coldspray::pd
