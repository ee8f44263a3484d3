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

struct Deformation {
  Eigen::Matrix3d F;     // eq 5
  Eigen::Matrix3d Fdot;  // its rate, the same sum over the velocity state
};

// Eq 5, F = [sum omega Y (x) xi V_j] K^-1 with Y = y_j - y_i in the current positions, and
// Fdot = [sum omega (v_j - v_i) (x) xi V_j] K^-1; then L = Fdot F^-1 (eq 28).
inline Deformation deformation(const Families& fam, const Neighbours& N, case_file::Influence kind,
                               double delta, const Eigen::Matrix3d& K_inverse, std::size_t i) {
  const auto& y = N.position;
  const auto& v = N.velocity;
  Eigen::Matrix3d YX = Eigen::Matrix3d::Zero(), VX = Eigen::Matrix3d::Zero();
  for_each_bond(fam, N, kind, delta, i,
                [&](std::size_t, std::size_t j, const Eigen::Vector3d& xi, double, double w) {
                  const Eigen::Vector3d Y(y[0][j] - y[0][i], y[1][j] - y[1][i], y[2][j] - y[2][i]);
                  const Eigen::Vector3d V(v[0][j] - v[0][i], v[1][j] - v[1][i], v[2][j] - v[2][i]);
                  YX.noalias() += w * Y * xi.transpose();
                  VX.noalias() += w * V * xi.transpose();
                });
  return {YX * K_inverse, VX * K_inverse};
}

}  // namespace coldspray::pd
