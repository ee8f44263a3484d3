// The D_bond increments of thesis eqs 4.3-4.5 and 4.16-4.17 against hand calculations, and the
// shear part of a plastic strain increment.
#include "bonding/bond_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::bonding {
namespace {

// The thesis' calibrated energy parameters (§5.1.4, rates per us) and its example strain ones
// (§4.1.4), floor 0.1: the hand calculations below are written with them.
BondLaw thesis_law(case_file::BondingModel model) {
  case_file::Bonding b;
  b.model = model;
  b.critical_energy = 1503.74;       // J/m^2
  b.critical_energy_rate = 2.271e6;  // J/m^2/s
  b.critical_strain = 1.4;
  b.critical_strain_rate = 8.5e8;  // 1/s
  b.floor = 0.1;
  return BondLaw::from_case(b, 0.7e-6);
}

TEST(BondLaw, RateFactorIsOneMinusTheLogarithmAboveTheFloor) {
  EXPECT_NEAR(rate_factor(std::exp(0.5), 0.1), 0.5, 1e-15);
  EXPECT_NEAR(rate_factor(1.0, 0.1), 1.0, 1e-15);
  EXPECT_NEAR(rate_factor(std::exp(-2.0), 0.1), 3.0, 1e-15);
  EXPECT_EQ(rate_factor(std::exp(5.0), 0.1), 0.1);  // 1 - 5 < 0: the floor
}

// dG = 300 MPa * 0.01 * 0.7 um = 2.1 J/m^2. At dt = 1e-11 s the ratio to Gdot_c dt is 92470,
// 1 - ln(92470) = -10.43: floored to 0.1, G_bond = 150.374 J/m^2, dD = 0.0139652. At dt = 1 ms
// the ratio is 9.247e-4, 1 - ln = 7.98604, G_bond = 12008.8 J/m^2, dD = 1.74870e-4.
TEST(BondLaw, EnergyIncrementMatchesEq416WithTheFloor) {
  const BondLaw law = thesis_law(case_file::BondingModel::Energy);
  EXPECT_NEAR(energy_bond_increment(law, 300e6, 0.01, 1e-11), 0.0139652, 1e-7);
  EXPECT_NEAR(energy_bond_increment(law, 300e6, 0.01, 1e-3), 1.748699e-4, 1e-9);
  EXPECT_EQ(energy_bond_increment(law, 300e6, 0.0, 1e-11), 0.0);
}

// d_eps_s = 0.02 over 1e-11 s: rate 2e9 1/s, 2.353 times the critical 8.5e8, 1 - ln = 0.144334,
// eps_bond = 0.202067, dD = 0.0989769. d_eps_s = 0.002 over 1 ns: 1 - ln(0.002353) = 7.05209,
// dD = 2.025742e-4.
TEST(BondLaw, StrainIncrementMatchesEqs43To45) {
  const BondLaw law = thesis_law(case_file::BondingModel::Strain);
  EXPECT_NEAR(strain_bond_increment(law, 0.02, 1e-11), 0.0989769, 1e-6);
  EXPECT_NEAR(strain_bond_increment(law, 0.002, 1e-9), 2.025742e-4, 1e-9);
}

TEST(BondLaw, SimpleShearAlongTheSurfaceIsAllShear) {
  // Deviatoric stress of simple shear in the x-z plane; the surface normal is z.
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  s(0, 2) = s(2, 0) = 100e6;
  EXPECT_NEAR(shear_plastic_strain_increment(0.03, s, Eigen::Vector3d::UnitZ()), 0.03, 1e-15);
  // The same shear seen from a surface whose normal is y carries no shear across it.
  EXPECT_NEAR(shear_plastic_strain_increment(0.03, s, Eigen::Vector3d::UnitY()), 0.0, 1e-15);
}

TEST(BondLaw, CompressionNormalToTheSurfaceHasNoShearPart) {
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  s(0, 0) = s(1, 1) = 100e6;
  s(2, 2) = -200e6;  // the deviator of uniaxial compression along z
  EXPECT_NEAR(shear_plastic_strain_increment(0.05, s, Eigen::Vector3d::UnitZ()), 0.0, 1e-15);
  // On a plane at 45 degrees the same flow shears: t = 3/2 d (s n)/sigma_vm has a tangential
  // part 3/2 * 0.05 * 150e6 / 300e6 = 0.0375, times 2/sqrt(3).
  const Eigen::Vector3d n = Eigen::Vector3d(1.0, 0.0, 1.0).normalized();
  EXPECT_NEAR(shear_plastic_strain_increment(0.05, s, n), 0.0375 * 2.0 / std::sqrt(3.0), 1e-14);
}

TEST(BondLaw, IncrementDispatchesOnTheModel) {
  Eigen::Matrix3d stress = -50e6 * Eigen::Matrix3d::Identity();  // pressure drops out
  stress(0, 2) = stress(2, 0) = 300e6 / std::sqrt(3.0);          // sigma_vm = 300 MPa
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(bond_increment(thesis_law(case_file::BondingModel::Energy), stress, 0.01, n, 1e-11),
              0.0139652, 1e-7);
  EXPECT_NEAR(bond_increment(thesis_law(case_file::BondingModel::Strain), stress, 0.02, n, 1e-11),
              0.0989769, 1e-6);
  EXPECT_EQ(bond_increment(thesis_law(case_file::BondingModel::None), stress, 0.02, n, 1e-11), 0.0);
}

}  // namespace
}  // namespace coldspray::bonding
