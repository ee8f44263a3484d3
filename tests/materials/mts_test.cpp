// MTS shear modulus (thesis eq 2.6) for the al-ptw constants.
#include "materials/shear_modulus/mts.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/flow_stress.hpp"
#include "reference_materials.hpp"

namespace coldspray::materials {
namespace {

// mu(298 K) = 28.8e9 - 3.44e9/(exp(215/298) - 1): exp(0.72147651006711409) = 2.0575...,
// 3.44e9/1.0575... = 3.2530509e9, mu = 25.546949071397262e9 Pa.
TEST(MaterialsMts, AlAtRoomTemperatureMatchesHandCalculation) {
  const double hand = 28.8e9 - 3.44e9 / (std::exp(215.0 / 298.0) - 1.0);
  EXPECT_NEAR(hand, 25.546949071397262e9, 1e-4);
  EXPECT_NEAR(shear_modulus_at(testing::al_ptw(), 298.0, 2700.0), hand, 1e-15 * hand);
}

// mu -> mu0 at 0 K and falls with temperature.
TEST(MaterialsMts, ColdLimitAndSoftening) {
  const Material m = testing::al_ptw();
  EXPECT_NEAR(shear_modulus_at(m, 1.0, 2700.0), 28.8e9, 1e-6);
  EXPECT_GT(shear_modulus_at(m, 298.0, 2700.0), shear_modulus_at(m, 600.0, 2700.0));
}

// Far above melt eq 2.6 would go negative (Al: about 1800 K); the floor keeps 1 % of mu0.
TEST(MaterialsMts, FloorKeepsShearModulusPositive) {
  const Material m = testing::al_ptw();
  const double floor = shear_modulus::kMtsMinShearFraction * 28.8e9;
  EXPECT_EQ(shear_modulus_at(m, 5000.0, 2700.0), floor);
  EXPECT_LT(28.8e9 - 3.44e9 / (std::exp(215.0 / 5000.0) - 1.0), 0.0);
  EXPECT_GT(shear_modulus_at(m, 1500.0, 2700.0), floor);
}

// The constant model returns the elastic G.
TEST(MaterialsMts, ConstantModelIsElasticShearModulus) {
  EXPECT_EQ(shear_modulus_at(testing::cu_jc(), 900.0, 8930.0), 46.0e9);
}

}  // namespace
}  // namespace coldspray::materials
