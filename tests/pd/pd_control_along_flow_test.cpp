// The zero-energy-mode control along the flow (pd/control_along_flow.hpp) against hand
// references. The softening a: 0 in an elastic step; 3G / (3G + H) for J2 plasticity with linear
// hardening, 1 less the ratio of the elastoplastic tangent along the flow to the elastic modulus;
// for Johnson-Cook the same with H = d sigma_y / d eqps = B n eqps^(n-1) (1 + C ln(rate)) at room
// temperature; and, unlike the step's algorithmic tangent, a value that does not depend on the
// time step. The softened part of an increment dz of a bond's z: in simple shear along a bond's
// normal, all of a dz along the shear direction (alpha = 1) where it loads the penalty, none
// where it unloads it; nothing of a dz whose strain is orthogonal to N; a penalty I - a alpha
// m (x) m that stays symmetric positive; and a penalty that never gives back more than it stored.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "../materials/reference_materials.hpp"
#include "materials/model_dispatch.hpp"
#include "pd/control_along_flow.hpp"
#include "pd/state.hpp"

namespace coldspray::pd {
namespace {

using materials::PointState;
using materials::StepKinematics;

// Isothermal uniaxial-strain compression to a strain of -steps * increment, in steps of
// `increment` over dt each; returns the state.
PointState compress(const materials::Material& m, double dt, double increment, int steps) {
  PointState st = materials::initial_state(m, 298.0);
  for (int step = 0; step < steps; ++step) {
    StepKinematics k;
    k.strain_increment(0, 0) = -increment;
    k.dt = dt;
    k.J_new = st.J * std::exp(-increment);
    materials::update_stress(m, k, {.isothermal = true}, st);
  }
  return st;
}

// The ratio of the tangent along the flow to the elastic modulus, 1 - a.
double scale_of(const materials::Material& m, const PointState& st, bool flowed) {
  return 1.0 - materials::visit_models(m, [&](const auto& models) {
           return flow_softening(models, st, flowed, m.density / st.J);
         });
}

TEST(PeridynamicControlScale, IsOneInAnElasticStep) {
  const materials::Material m = materials::testing::linear_hardening();
  EXPECT_EQ(scale_of(m, materials::initial_state(m, 298.0), false), 1.0);
}

TEST(PeridynamicControlScale, IsTheTangentRatioForLinearHardening) {
  const materials::Material m = materials::testing::linear_hardening();
  const double G = 46e9, H = 100e6;
  for (int steps : {44, 200}) {  // yield at 0.43 %: the first step that flows, and far beyond
    const PointState st = compress(m, 1e-8, 1e-4, steps);
    ASSERT_GT(st.eqps, 0.0);
    // The forward difference of a linear flow stress: exact but for round-off.
    EXPECT_NEAR(scale_of(m, st, true), H / (3.0 * G + H), 1e-9 * H / (3.0 * G)) << steps;
  }
}

TEST(PeridynamicControlScale, IsTheTangentRatioForJohnsonCookAndDoesNotDependOnTheStep) {
  const materials::Material m = materials::testing::cu_jc();
  const double B = 292e6, n = 0.31, C = 0.025, G = 46e9;
  // The same path, to a strain of 3 % at 1e7 1/s, in steps of 1e-11 s and of 2.5e-12 s.
  const PointState coarse = compress(m, 1e-11, 1e-4, 300);
  const PointState fine = compress(m, 2.5e-12, 2.5e-5, 1200);
  for (const PointState& st : {coarse, fine}) {
    const double H = B * n * std::pow(st.eqps, n - 1.0) * (1.0 + C * std::log(st.eqps_rate));
    EXPECT_NEAR(scale_of(m, st, true), H / (3.0 * G + H), 1e-4 * H / (3.0 * G));
  }
  const double r_coarse = scale_of(m, coarse, true), r_fine = scale_of(m, fine, true);
  EXPECT_GT(coarse.eqps, 0.01);
  EXPECT_NEAR(r_fine, r_coarse, 1e-3 * r_coarse);
}

Eigen::Vector4d padded(const Eigen::Vector3d& v) { return {v[0], v[1], v[2], 0.0}; }

PaddedTensor padded(const Eigen::Matrix3d& M) {
  PaddedTensor P = PaddedTensor::Zero();
  P.topRows<3>() = M;
  return P;
}

// Simple shear in the x-y plane: sigma_xy = tau, N = (e_x e_y + e_y e_x) / sqrt(2).
Eigen::Matrix3d shear_stress() {
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  sigma(0, 1) = sigma(1, 0) = 80e6;
  sigma.diagonal().setConstant(-1e9);  // a pressure changes nothing
  return sigma;
}

TEST(PeridynamicControlAlongFlow, TheFlowDirectionIsTheUnitDeviator) {
  const Eigen::Matrix3d N = flow_direction(shear_stress());
  EXPECT_NEAR(N(0, 1), 1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(N.norm(), 1.0, 1e-15);
  EXPECT_NEAR(N.trace(), 0.0, 1e-15);
  EXPECT_EQ(flow_direction(-2e9 * Eigen::Matrix3d::Identity()).norm(), 0.0);
}

TEST(PeridynamicControlAlongFlow, SoftensAllOfAShearAcrossTheBondWhereItLoads) {
  // A bond along x (either sign, any length) and dz along y: sym(dz (x) e) lies along N,
  // alpha = 1, all of dz softened where it loads the penalty (e along dz, or e = 0), none where
  // it unloads it.
  const PaddedTensor N = padded(flow_direction(shear_stress()));
  for (double length : {1e-6, -3e-6}) {
    const Eigen::Vector4d Y = padded(Eigen::Vector3d(length, 0.0, 0.0));
    const Eigen::Vector4d dz = padded(Eigen::Vector3d(0.0, 2e-9, 0.0));
    for (const Eigen::Vector4d& e : {Eigen::Vector4d(3.0 * dz), Eigen::Vector4d::Zero().eval()})
      EXPECT_LT((softened_part(N, 0.7, Y, dz, e) - 0.7 * dz).norm(), 1e-15 * dz.norm()) << length;
    EXPECT_EQ(softened_part(N, 0.7, Y, dz, -dz).norm(), 0.0);
    // Stretching the bond along itself: sym(e_x (x) e_x) : N = 0, nothing softened.
    const Eigen::Vector4d stretch = padded(Eigen::Vector3d(2e-9, 0.0, 0.0));
    EXPECT_EQ(softened_part(N, 0.7, Y, stretch, stretch).norm(), 0.0);
    EXPECT_EQ(softened_part(N, 0.0, Y, dz, dz).norm(), 0.0);
  }
}

// The penalty's energy 1/2 |e|^2 (times its stiffness) changes by e . (dz - softened part) when
// the pair's z changes by dz: never more than the work e . dz done on it, for any flow
// direction, bond, increment and state, because e . softened part >= 0.
TEST(PeridynamicControlAlongFlow, ThePenaltyNeverGivesBackWhatItDidNotStore) {
  Eigen::Matrix3d general;
  general << 3.0, 1.0, -0.4, 1.0, -1.0, 0.7, -0.4, 0.7, 0.5;
  const PaddedTensor N = padded(flow_direction(general));
  int softened = 0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector4d Y =
        padded(Eigen::Vector3d(std::sin(1.1 * k), std::cos(2.3 * k), std::sin(0.7 * k + 1.0)));
    const Eigen::Vector4d dz =
        padded(Eigen::Vector3d(std::cos(0.3 * k), std::sin(1.9 * k), std::cos(2.9 * k + 0.5)));
    const Eigen::Vector4d e =
        padded(Eigen::Vector3d(std::sin(0.5 * k + 2.0), std::cos(1.3 * k), std::sin(3.1 * k)));
    const Eigen::Vector4d part = softened_part(N, 0.9, Y, dz, e);
    EXPECT_GE(e.dot(part), 0.0) << k;
    softened += part.norm() > 0.0;
  }
  EXPECT_GT(softened, 50);  // both branches are exercised
  EXPECT_LT(softened, 150);
}

TEST(PeridynamicControlAlongFlow, TheSoftenedPenaltyStaysSymmetricPositive) {
  // For a = 1 and bonds in many directions under a uniaxial and a general deviator, the matrix
  // z -> z - softened_part(z) has eigenvalues in [0, 1] and is symmetric.
  Eigen::Matrix3d general;
  general << 3.0, 1.0, -0.4, 1.0, -1.0, 0.7, -0.4, 0.7, 0.5;
  for (const Eigen::Matrix3d& sigma :
       {Eigen::Matrix3d(Eigen::Vector3d(2.0, -1.0, -1.0).asDiagonal()), general}) {
    const PaddedTensor N = padded(flow_direction(sigma));
    for (int k = 0; k < 50; ++k) {
      const Eigen::Vector4d Y =
          padded(Eigen::Vector3d(std::sin(1.1 * k), std::cos(2.3 * k), std::sin(0.7 * k + 1.0)));
      Eigen::Matrix3d P;
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector4d e = padded(Eigen::Vector3d(Eigen::Vector3d::Unit(c)));
        P.col(c) = (e - softened_part(N, 1.0, Y, e, Eigen::Vector4d::Zero())).head<3>();
      }
      EXPECT_LT((P - P.transpose()).norm(), 1e-14);
      const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(P).eigenvalues();
      EXPECT_GT(eig.minCoeff(), -1e-14) << k;
      EXPECT_LT(eig.maxCoeff(), 1.0 + 1e-14) << k;
    }
  }
}

}  // namespace
}  // namespace coldspray::pd
