// SymmetricTensor against the full-matrix formulas it replaces in the stress update, and the
// Jaumann rotation of a uniaxial stress and the von Mises stress by hand.
#include "materials/symmetric_tensor.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::materials {
namespace {

using Eigen::Matrix3d;

Matrix3d symmetric_sample() {
  Matrix3d a;
  a << 3.0, -1.25, 0.5,   //
      -1.25, -2.0, 0.75,  //
      0.5, 0.75, 4.5;
  return a;
}

Matrix3d skew_sample() {
  Matrix3d w;
  w << 0.0, 0.3, -0.2,  //
      -0.3, 0.0, 0.1,   //
      0.2, -0.1, 0.0;
  return w;
}

TEST(MaterialsSymmetricTensor, RoundTripsTheUpperTriangle) {
  const Matrix3d a = symmetric_sample();
  const SymmetricTensor s = SymmetricTensor::of(a);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(s(i, j), a(i, j)) << i << j;
  EXPECT_EQ(s.matrix(), a);
  EXPECT_EQ(s.plus_identity(2.0).matrix(), a + 2.0 * Matrix3d::Identity());
  EXPECT_EQ(s.trace(), 5.5);
  // Writing (i, j) writes (j, i).
  SymmetricTensor t = s;
  t(2, 0) = 9.0;
  EXPECT_EQ(t(0, 2), 9.0);
  EXPECT_EQ(t.c[SymmetricTensor::index(0, 2)], 9.0);
}

TEST(MaterialsSymmetricTensor, SkewTensorKeepsTheUpperTriangle) {
  const SkewTensor w = SkewTensor::of(skew_sample());
  EXPECT_EQ(w.c[0], skew_sample()(0, 1));
  EXPECT_EQ(w.c[1], skew_sample()(1, 2));
  EXPECT_EQ(w.c[2], skew_sample()(0, 2));
}

TEST(MaterialsSymmetricTensor, ContractionAndVonMisesMatchTheFullMatrices) {
  const Matrix3d a = symmetric_sample();
  const Matrix3d b_symmetric = Matrix3d::Identity() + skew_sample() * skew_sample();
  const SymmetricTensor sa = SymmetricTensor::of(a), sb = SymmetricTensor::of(b_symmetric);
  EXPECT_NEAR(sa.contract(sb), a.cwiseProduct(b_symmetric).sum(), 1e-14);
  const Matrix3d dev = a - a.trace() / 3.0 * Matrix3d::Identity();
  EXPECT_NEAR(deviator(sa).trace(), 0.0, 1e-14);
  EXPECT_NEAR(deviator(sa).von_mises(), std::sqrt(1.5 * dev.squaredNorm()), 1e-14);
  // A uniaxial stress of 7: its von Mises stress is 7.
  SymmetricTensor uniaxial;
  uniaxial.c[0] = 7.0;
  EXPECT_NEAR(deviator(uniaxial).von_mises(), 7.0, 1e-14);
}

TEST(MaterialsSymmetricTensor, JaumannRotationMatchesTheMatrixForm) {
  const Matrix3d sigma = symmetric_sample(), W = skew_sample();
  const Matrix3d full = sigma + sigma * W.transpose() + W * sigma;  // eq A2
  const SymmetricTensor r = jaumann_rotated(SymmetricTensor::of(sigma), SkewTensor::of(W));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(r(i, j), full(i, j), 1e-14) << i << j;
}

// sigma_xx = 1 spun by w about z (W_xy = w, W_yx = -w): the rotation adds sigma_xy = -w and
// leaves the diagonal as it was (to first order).
TEST(MaterialsSymmetricTensor, JaumannRotationOfUniaxialStressByHand) {
  Matrix3d W = Matrix3d::Zero();
  const double w = 1e-3;
  W(0, 1) = w;
  W(1, 0) = -w;
  SymmetricTensor uniaxial;
  uniaxial.c[0] = 1.0;
  const SymmetricTensor r = jaumann_rotated(uniaxial, SkewTensor::of(W));
  EXPECT_EQ(r(0, 0), 1.0);
  EXPECT_EQ(r(0, 1), -w);
  EXPECT_EQ(r(1, 1), 0.0);
  EXPECT_EQ(r(0, 2), 0.0);
  EXPECT_EQ(r(1, 2), 0.0);
  EXPECT_EQ(r(2, 2), 0.0);
}

// The von Mises stress by hand: uniaxial sigma gives |sigma|, pure shear tau gives sqrt(3) tau,
// and a pressure adds nothing.
TEST(MaterialsSymmetricTensor, VonMisesStressByHand) {
  EXPECT_NEAR(von_mises_stress(SymmetricTensor{{-250e6, 0.0, 0.0, 0.0, 0.0, 0.0}}), 250e6, 1e-6);
  const double tau = 80e6, p = 1.3e9;
  EXPECT_NEAR(von_mises_stress(SymmetricTensor{{0.0, 0.0, 0.0, 0.0, tau, 0.0}}),
              std::sqrt(3.0) * tau, 1e-6);
  Matrix3d sheared = -p * Matrix3d::Identity();
  sheared(0, 2) = sheared(2, 0) = tau;
  EXPECT_NEAR(von_mises_stress(sheared), std::sqrt(3.0) * tau, 1e-6);
}

}  // namespace
}  // namespace coldspray::materials
