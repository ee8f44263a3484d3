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
inline double influence(case_file::Influence kind, double length, double delta) {
  return kind == case_file::Influence::Constant ? 1.0 : delta / length;
}

// Calls f(bond, j, xi, |xi|, w) for the bonds of point i, w = omega beta V_j.
template <class F>
void for_each_bond(const Families& fam, const Neighbours& N, case_file::Influence kind,
                   double delta, std::size_t i, F&& f) {
  const std::array<std::vector<double>, 3>& X = N.reference;
  for (std::size_t b = fam.begin[i]; b < fam.begin[i + 1]; ++b) {
    const std::size_t j = fam.neighbour[b];
    const Eigen::Vector3d xi(X[0][j] - X[0][i], X[1][j] - X[1][i], X[2][j] - X[2][i]);
    const double length = xi.norm();
    f(b, j, xi, length,
      influence(kind, length, delta) * static_cast<double>(fam.volume_fraction[b]) * N.volume[j]);
  }
}

// Eq 6: K = sum omega xi (x) xi V_j.
inline Eigen::Matrix3d shape_tensor(const Families& fam, const Neighbours& N,
                                    case_file::Influence kind, double delta, std::size_t i) {
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
  for_each_bond(fam, N, kind, delta, i,
                [&](std::size_t, std::size_t, const Eigen::Vector3d& xi, double, double w) {
                  K.noalias() += w * xi * xi.transpose();
                });
  return K;
}

// The moment matrix of the second-order fit (pd/quadratic_fit.hpp): M = sum omega q (x) q V_j.
inline MomentMatrix moment_matrix(const Families& fam, const Neighbours& N,
                                  case_file::Influence kind, double delta, std::size_t i) {
  MomentMatrix M = MomentMatrix::Zero();
  for_each_bond(fam, N, kind, delta, i,
                [&](std::size_t, std::size_t, const Eigen::Vector3d& xi, double, double w) {
                  const Monomials q = monomials(xi, delta);
                  M.noalias() += w * q * q.transpose();
                });
  return M;
}

// Sums over a point's family that do not change (pd/forces.hpp): sum omega xi V_j, the factor
// of A_i in eq 8 (zero on a symmetric family), and sum omega q(xi) / |xi| V_j, the factor of C_i
// in the control.
struct FamilySums {
  Eigen::Vector3d bond = Eigen::Vector3d::Zero();  // m^4
  Monomials control = Monomials::Zero();           // m^2
};

inline FamilySums family_sums(const Families& fam, const Neighbours& N, case_file::Influence kind,
                              double delta, std::size_t i) {
  FamilySums sums;
  for_each_bond(fam, N, kind, delta, i,
                [&](std::size_t, std::size_t, const Eigen::Vector3d& xi, double length, double w) {
                  sums.bond += w * xi;
                  sums.control += w / length * monomials(xi, delta);
                });
  return sums;
}

struct Deformation {
  Eigen::Matrix3d F;     // eq 5
  Eigen::Matrix3d Fdot;  // its rate, the same sum over the velocity state
  QuadraticMap fit;      // the second-order fit of the positions (pd/quadratic_fit.hpp)
};

// Eq 5, F = [sum omega Y (x) xi V_j] K^-1 with Y = y_j - y_i in the current positions, and
// Fdot = [sum omega (v_j - v_i) (x) xi V_j] K^-1; then L = Fdot F^-1 (eq 28). The same sum
// over the bonds' monomials q gives the second-order fit C = [sum omega Y (x) q V_j] M^-1; the
// first three monomials are xi / delta, so the sum of eq 5 is delta times its first columns.
inline Deformation deformation(const Families& fam, const Neighbours& N, case_file::Influence kind,
                               double delta, const Eigen::Matrix3d& K_inverse,
                               const MomentMatrix& M_inverse, std::size_t i) {
  const auto& y = N.position;
  const auto& v = N.velocity;
  QuadraticMap YQ = QuadraticMap::Zero();
  Eigen::Matrix3d VX = Eigen::Matrix3d::Zero();
  for_each_bond(fam, N, kind, delta, i,
                [&](std::size_t, std::size_t j, const Eigen::Vector3d& xi, double, double w) {
                  const Eigen::Vector3d Y(y[0][j] - y[0][i], y[1][j] - y[1][i], y[2][j] - y[2][i]);
                  const Eigen::Vector3d V(v[0][j] - v[0][i], v[1][j] - v[1][i], v[2][j] - v[2][i]);
                  YQ.noalias() += (w * Y) * monomials(xi, delta).transpose();
                  VX.noalias() += w * V * xi.transpose();
                });
  return {delta * YQ.leftCols<3>() * K_inverse, VX * K_inverse, YQ.lazyProduct(M_inverse)};
}

}  // namespace coldspray::pd
