// Symmetric 3x3 tensors (stresses, strain increments) by their six independent components, in
// the order xx, yy, zz, xy, yz, xz of mpm::Points' stress arrays, and skew ones (spin
// increments) by their three. The constitutive update (stress_update_kernel.hpp) keeps its
// state and works in this form: no 3x3 products, half the memory of a matrix, and every
// operation small enough to inline.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace coldspray::materials {

struct SymmetricTensor {
  double c[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

  // Component (i, j) of the full matrix; (i, j) and (j, i) are the same component.
  static constexpr int index(int i, int j) {
    constexpr int kIndex[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
    return kIndex[i][j];
  }
  double operator()(int i, int j) const { return c[index(i, j)]; }
  double& operator()(int i, int j) { return c[index(i, j)]; }
  bool operator==(const SymmetricTensor&) const = default;

  // The upper triangle of a (symmetric) matrix.
  static SymmetricTensor of(const Eigen::Matrix3d& a) {
    return {{a(0, 0), a(1, 1), a(2, 2), a(0, 1), a(1, 2), a(0, 2)}};
  }
  // The full matrix.
  Eigen::Matrix3d matrix() const {
    Eigen::Matrix3d a;
    a << c[0], c[3], c[5],  //
        c[3], c[1], c[4],   //
        c[5], c[4], c[2];
    return a;
  }

  double trace() const { return c[0] + c[1] + c[2]; }
  // a : b = sum_ij a_ij b_ij, the off-diagonal components counted twice.
  double contract(const SymmetricTensor& b) const {
    return c[0] * b.c[0] + c[1] * b.c[1] + c[2] * b.c[2] +
           2.0 * (c[3] * b.c[3] + c[4] * b.c[4] + c[5] * b.c[5]);
  }
  // Eq A5 for a deviator: sqrt(3/2 s:s).
  double von_mises() const { return std::sqrt(1.5 * contract(*this)); }

  // This tensor plus t times the identity.
  SymmetricTensor plus_identity(double t) const {
    return {{c[0] + t, c[1] + t, c[2] + t, c[3], c[4], c[5]}};
  }
  // This tensor plus f times b.
  SymmetricTensor plus_scaled(double f, const SymmetricTensor& b) const {
    SymmetricTensor r;
    for (int n = 0; n < 6; ++n) r.c[n] = c[n] + f * b.c[n];
    return r;
  }
  SymmetricTensor& operator*=(double f) {
    for (double& v : c) v *= f;
    return *this;
  }
};

// The deviator a - tr(a)/3 I.
inline SymmetricTensor deviator(const SymmetricTensor& a) {
  return a.plus_identity(-a.trace() / 3.0);
}

// The pressure -tr(sigma)/3 of a stress, compression positive. After an update it is the EOS
// pressure p^{n+1} to round-off: the update returns sigma = s - p I with s traceless (eq A3).
inline double mean_pressure(const SymmetricTensor& sigma) { return -sigma.trace() / 3.0; }

// The von Mises stress sqrt(3/2 s:s) of a stress (eq A5 on its deviator s).
inline double von_mises_stress(const SymmetricTensor& sigma) { return deviator(sigma).von_mises(); }
inline double von_mises_stress(const Eigen::Matrix3d& sigma) {
  return von_mises_stress(SymmetricTensor::of(sigma));
}

// A skew 3x3 tensor (spin increments) by the upper triangle of its matrix, W_xy, W_yz, W_xz;
// W_ji = -W_ij.
struct SkewTensor {
  double c[3] = {0.0, 0.0, 0.0};

  bool operator==(const SkewTensor&) const = default;
  // The upper triangle of a skew matrix.
  static SkewTensor of(const Eigen::Matrix3d& w) { return {{w(0, 1), w(1, 2), w(0, 2)}}; }
};

// sigma + sigma W^T + W sigma = sigma + W sigma + (W sigma)^T for a skew spin increment W: the
// Jaumann rotation of eq A2, written out for the upper triangle.
inline SymmetricTensor jaumann_rotated(const SymmetricTensor& sigma, const SkewTensor& W) {
  const auto& [w01, w12, w02] = W.c;
  const auto& [xx, yy, zz, xy, yz, xz] = sigma.c;
  return {{xx + 2.0 * (w01 * xy + w02 * xz),  //
           yy + 2.0 * (w12 * yz - w01 * xy),  //
           zz - 2.0 * (w02 * xz + w12 * yz),  //
           xy + w01 * (yy - xx) + w02 * yz + w12 * xz, yz + w12 * (zz - yy) - w01 * xz - w02 * xy,
           xz + w02 * (zz - xx) + w01 * yz - w12 * xy}};
}

}  // namespace coldspray::materials
