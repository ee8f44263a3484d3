// The second-order fit of a field over a family, the reference against which the
// zero-energy-mode control (pd/forces.hpp) measures a bond's non-uniform deformation: the
// weighted least-squares map C with u_j - u_i ~ C q(xi) over the family, q the bond's monomials
// up to second order, u the positions (C) or the velocities (its rate Cdot, which the control
// integrates). This is the peridynamic differential operator of order two (Madenci, Barut and
// Futch, CMAME 304 (2016) 408): C = [sum omega (u_j - u_i) (x) q V_j] M^-1 with the moment
// matrix M = sum omega q (x) q V_j. Its first three columns are the gradient (times delta), the
// other six the curvature; on a symmetric family the first three equal eq 5's F (or its rate).
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace coldspray::pd {

// q(xi) with s = xi / delta (the scaling keeps M well conditioned): s1, s2, s3, s1^2 / 2,
// s2^2 / 2, s3^2 / 2, s1 s2, s1 s3, s2 s3.
using Monomials = Eigen::Matrix<double, 9, 1>;
using MomentMatrix = Eigen::Matrix<double, 9, 9>;
// C: u_j - u_i ~ C q(xi), in the field's unit. Stored with a fourth row, always zero, so that each
// column is one four-double (AVX) register in the bond loops, which read C of every neighbour
// (pd/deformation.hpp, pd/forces.cpp).
using QuadraticMap = Eigen::Matrix<double, 4, 9>;

inline Monomials monomials(const Eigen::Vector3d& xi, double delta) {
  const Eigen::Vector3d s = xi * (1.0 / delta);  // one division per family, not three per bond
  Monomials q;
  q << s[0], s[1], s[2], 0.5 * s[0] * s[0], 0.5 * s[1] * s[1], 0.5 * s[2] * s[2], s[0] * s[1],
      s[0] * s[2], s[1] * s[2];
  return q;
}

// q(-xi) from q(xi): the linear monomials change sign, the quadratic ones do not.
inline Monomials reversed(const Monomials& q) {
  Monomials r = q;
  r.head<3>() = -q.head<3>();
  return r;
}

// The fit of a field mirrored across the planes of `flips` (bit 0: x, bit 1: y): with
// R = diag(+-1, +-1, 1), y'(X) = R y(R X), so C' = R C Q with q(R xi) = Q q(xi).
inline QuadraticMap mirrored(const QuadraticMap& C, std::uint8_t flips) {
  const double rx = (flips & 1) ? -1.0 : 1.0, ry = (flips & 2) ? -1.0 : 1.0;
  Monomials Q;
  Q << rx, ry, 1.0, 1.0, 1.0, 1.0, rx * ry, rx, ry;
  const Eigen::Vector4d R(rx, ry, 1.0, 1.0);
  return R.asDiagonal() * C * Q.asDiagonal();
}

}  // namespace coldspray::pd
