// Linear EOS p = K (rho/rho0 - 1), no energy term; the energy is still accumulated by the
// trapezoidal rule of eqs 3.39-3.41 for bookkeeping.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "materials/stress_update.hpp"
#include "reference_materials.hpp"

namespace coldspray::materials {
namespace {

// Compression J 1 -> 0.95 in 500 steps: p = K (1/J - 1) exactly at every step, and E tends to
// the closed-form work -int_1^J K (1/j - 1) dj = K (J - 1 - ln J) at second order.
TEST(MaterialsLinearEos, PressureAndEnergyBookkeeping) {
  const Material m = testing::linear_hardening();
  const double K = 129.0e9;
  PointState st = initial_state(m, 298.0);
  const int steps = 500;
  for (int n = 1; n <= steps; ++n) {
    StepKinematics k;
    k.J_new = 1.0 - 0.05 * n / steps;
    k.strain_increment =
        SymmetricTensor::of(std::log(k.J_new / st.J) / 3.0 * Eigen::Matrix3d::Identity());
    k.dt = 1e-9;
    const PointState before = st;
    update_stress(m, k, {}, st);
    // 1/J - 1 loses digits to cancellation near J = 1: its absolute error is a few ulp of 1/J.
    const double p = K * (1.0 / k.J_new - 1.0);
    ASSERT_NEAR(st.pressure, p, 4e-16 * K / k.J_new) << n;
    ASSERT_NEAR(st.energy - before.energy,
                -0.5 * (before.pressure + st.pressure) * (k.J_new - before.J), 1e-6)
        << n;
  }
  const double closed = K * (0.95 - 1.0 - std::log(0.95));
  EXPECT_NEAR(st.energy, closed, 1e-6 * closed);
  EXPECT_GT(st.energy, 0.0);
}

}  // namespace
}  // namespace coldspray::materials
