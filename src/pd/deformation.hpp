// The nonlocal kinematics of correspondence peridynamics at one point (PD paper eqs 5, 6, 28):
// sums over the point's family of omega<xi> beta V_j times bond quantities, xi = X_j - X_i the
// reference bond, beta its partial-volume factor (pd/families.hpp).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "case/case.hpp"
#include "core/double4.hpp"
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
// delta times its first columns.
//
// The sums are kept by rows, four doubles to a register: row d of the first gains Y_d w s
// (s = xi / delta), row d of the second V_d w q, q's first eight monomials (pd/quadratic_fit.hpp)
// in two registers; the ninth monomial's column of all three rows takes one more. Ten
// registers, every lane used, and q built with permutes; tested against the exact gradients of
// a homogeneous deformation and against the fit of a quadratic field (pd_kinematics_test).
inline Deformation deformation(const Families& fam, const Neighbours& N, const BondWeights& weights,
                               const Eigen::Matrix3d& K_inverse, const MomentMatrix& M_inverse,
                               std::size_t i) {
  const double delta = weights.delta, per_delta = 1.0 / delta;
  const Double4 X_i = as_lanes(N.reference[i]), y_i = as_lanes(N.position[i]),
                v_i = as_lanes(N.velocity[i]);
  const Double4 zero = {0.0, 0.0, 0.0, 0.0};
  Double4 ys[3] = {zero, zero, zero}, vq_low[3] = {zero, zero, zero},
          vq_high[3] = {zero, zero, zero}, vq_last = zero;
  for_each_bond(fam, N, weights, i,
                [&](std::size_t, std::size_t j, const Eigen::Vector3d&, double, double w) {
                  const Double4 s = (as_lanes(N.reference[j]) - X_i) * per_delta;  // s0 s1 s2 0
                  const Double4 Y = as_lanes(N.position[j]) - y_i;
                  const Double4 V = as_lanes(N.velocity[j]) - v_i;
                  const Double4 ws = w * s;
                  // w (s0, s1, s2, s0^2 / 2) and w (s1^2 / 2, s2^2 / 2, s0 s1, s0 s2); s's
                  // fourth lane, 0, makes the first factor's (1, 1, 1, s0 / 2).
                  const Double4 wq_low =
                      __builtin_shuffle(ws, Lanes4{0, 1, 2, 0}) *
                      (__builtin_shuffle(s, Lanes4{3, 3, 3, 0}) * Double4{0.0, 0.0, 0.0, 0.5} +
                       Double4{1.0, 1.0, 1.0, 0.0});
                  const Double4 wq_high = __builtin_shuffle(ws, Lanes4{1, 2, 0, 0}) *
                                          __builtin_shuffle(s, Lanes4{1, 2, 1, 2}) *
                                          Double4{0.5, 0.5, 1.0, 1.0};
                  ys[0] += lane<0>(Y) * ws;
                  ys[1] += lane<1>(Y) * ws;
                  ys[2] += lane<2>(Y) * ws;
                  const Double4 V0 = lane<0>(V), V1 = lane<1>(V), V2 = lane<2>(V);
                  vq_low[0] += V0 * wq_low;
                  vq_low[1] += V1 * wq_low;
                  vq_low[2] += V2 * wq_low;
                  vq_high[0] += V0 * wq_high;
                  vq_high[1] += V1 * wq_high;
                  vq_high[2] += V2 * wq_high;
                  vq_last += (ws[1] * s[2]) * V;
                });
  Eigen::Matrix3d YX;
  QuadraticMap VQ;
  for (int d = 0; d < 3; ++d) {
    YX.row(d) << delta * ys[d][0], delta * ys[d][1], delta * ys[d][2];
    VQ.row(d) << vq_low[d][0], vq_low[d][1], vq_low[d][2], vq_low[d][3], vq_high[d][0],
        vq_high[d][1], vq_high[d][2], vq_high[d][3], vq_last[d];
  }
  VQ.row(3).setZero();
  return {YX * K_inverse, delta * VQ.topLeftCorner<3, 3>() * K_inverse, VQ.lazyProduct(M_inverse)};
}

}  // namespace coldspray::pd
