// Johnson-Cook flow stress (thesis eq 2.3) for OFHC copper (Johnson & Cook 1983/1985).
#include <gtest/gtest.h>

#include <cmath>

#include "materials/flow_stress.hpp"
#include "reference_materials.hpp"

namespace coldspray::materials {
namespace {

constexpr double kRho = 8930.0;

// eqps 0.2, 1e3 1/s, 500 K:
//   A + B eqps^n          = 90e6 + 292e6 0.2^0.31 = 267.29731150232193e6 Pa
//   1 + C ln(1e3/1)       = 1.1726938819745534
//   T* = (500-298)/(1356-298) = 0.19092627599243856, 1 - T*^1.09 = 0.83550844169175175
//   sigma_y               = 261.89673983504822e6 Pa
TEST(MaterialsJohnsonCook, OfhcCopperMatchesHandCalculation) {
  const double T_star = (500.0 - 298.0) / (1356.0 - 298.0);
  const double hand = (90e6 + 292e6 * std::pow(0.2, 0.31)) * (1.0 + 0.025 * std::log(1e3)) *
                      (1.0 - std::pow(T_star, 1.09));
  EXPECT_NEAR(hand, 261.89673983504822e6, 1e-5);
  EXPECT_NEAR(flow_stress(testing::cu_jc(), 0.2, 1e3, 500.0, kRho), hand, 1e-12 * hand);
}

// Below the reference rate (1 1/s) rate* is held at 1: no rate softening, finite at rest.
TEST(MaterialsJohnsonCook, RateFloorAtReferenceRate) {
  const Material m = testing::cu_jc();
  const double at_reference = flow_stress(m, 0.2, 1.0, 298.0, kRho);
  EXPECT_NEAR(at_reference, 90e6 + 292e6 * std::pow(0.2, 0.31), 1e-6);
  EXPECT_EQ(flow_stress(m, 0.2, 0.01, 298.0, kRho), at_reference);
  EXPECT_EQ(flow_stress(m, 0.2, 0.0, 298.0, kRho), at_reference);
  EXPECT_GT(flow_stress(m, 0.2, 10.0, 298.0, kRho), at_reference);
}

// T* clamped to [0, 1]: no extra strength below T_ref, zero at and above Tm.
TEST(MaterialsJohnsonCook, HomologousTemperatureClamps) {
  const Material m = testing::cu_jc();
  EXPECT_EQ(flow_stress(m, 0.2, 1e3, 200.0, kRho), flow_stress(m, 0.2, 1e3, 298.0, kRho));
  EXPECT_NEAR(flow_stress(m, 0.2, 1e3, 298.0, kRho),
              (90e6 + 292e6 * std::pow(0.2, 0.31)) * (1.0 + 0.025 * std::log(1e3)), 1e-6);
  EXPECT_EQ(flow_stress(m, 0.2, 1e3, 1356.0, kRho), 0.0);
  EXPECT_EQ(flow_stress(m, 0.2, 1e3, 2000.0, kRho), 0.0);
  EXPECT_GT(flow_stress(m, 0.2, 1e3, 1355.0, kRho), 0.0);
}

// At zero plastic strain the hardening term vanishes: sigma_y = A at the reference state.
TEST(MaterialsJohnsonCook, InitialYieldIsA) {
  EXPECT_DOUBLE_EQ(flow_stress(testing::cu_jc(), 0.0, 1.0, 298.0, kRho), 90e6);
}

}  // namespace
}  // namespace coldspray::materials
