// wave_speed: sqrt((K_t + 4G/3)/rho) with K_t the EOS's isentropic tangent bulk modulus.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/stress_update.hpp"
#include "reference_materials.hpp"

namespace coldspray::materials {
namespace {

using namespace testing::al_eos;

double al_p(double J, double E) {
  const double mu = 1.0 / J - 1.0;
  const double A = mu <= 0.0 ? kRho0 * kC0 * kC0 * mu
                             : kRho0 * kC0 * kC0 * mu * (1.0 + (1.0 - kGamma0 / 2.0) * mu) /
                                   std::pow(1.0 - 0.339 * mu, 2);
  return A + kGamma0 * E;
}

// At the reference state K_t = rho0 c0^2: c = sqrt(c0^2 + 4 mu(298)/(3 rho0)).
TEST(MaterialsWaveSpeed, MieGruneisenAtReferenceState) {
  const Material m = testing::al_ptw();
  const double G = 28.8e9 - 3.44e9 / (std::exp(215.0 / 298.0) - 1.0);
  const double c = std::sqrt(kC0 * kC0 + 4.0 * G / (3.0 * kRho0));
  EXPECT_NEAR(wave_speed(m, initial_state(m, 298.0)), c, 1e-12 * c);
}

// Compressed and heated (J = 0.9, E = 2e8 J/m^3): K_t = rho dp/drho along the isentrope
// dE = -p dJ, by a central difference here (O(h^2) even with E stepped to first order).
TEST(MaterialsWaveSpeed, MieGruneisenTangentMatchesIsentropeDifference) {
  const Material m = testing::al_elastic();
  PointState st = initial_state(m, 298.0);
  st.J = 0.9;
  st.energy = 2e8;
  const double p = al_p(st.J, st.energy), h = 1e-5;
  const double dp_dJ =
      (al_p(st.J + h, st.energy - p * h) - al_p(st.J - h, st.energy + p * h)) / (2.0 * h);
  const double K_t = -st.J * dp_dJ;
  const double c = std::sqrt((K_t + 4.0 / 3.0 * 26e9) * st.J / kRho0);
  EXPECT_NEAR(wave_speed(m, st), c, 1e-8 * c);
  EXPECT_GT(c, wave_speed(m, initial_state(m, 298.0)));
}

// Linear EOS: K_t = rho dp/drho = K/J exactly; c = sqrt((K/J + 4G/3) J/rho0).
TEST(MaterialsWaveSpeed, LinearEos) {
  const Material m = testing::linear_hardening();
  PointState st = initial_state(m, 298.0);
  const double K = 129e9, G = 46e9, rho0 = 8930.0;
  EXPECT_NEAR(wave_speed(m, st), std::sqrt((K + 4.0 * G / 3.0) / rho0), 1e-9);
  st.J = 0.9;
  const double c = std::sqrt((K / 0.9 + 4.0 * G / 3.0) * 0.9 / rho0);
  EXPECT_NEAR(wave_speed(m, st), c, 1e-12 * c);
}

// Deep tension (J = 2): the Gruneisen term drives K_t negative; it is floored at 0 and the wave
// speed is the shear-wave bound sqrt(4G/(3 rho)).
TEST(MaterialsWaveSpeed, DeepTensionStaysReal) {
  const Material m = testing::al_elastic();
  PointState st = initial_state(m, 298.0);
  st.J = 2.0;
  const double c = std::sqrt(4.0 / 3.0 * 26e9 * 2.0 / kRho0);
  EXPECT_NEAR(wave_speed(m, st), c, 1e-12 * c);
}

}  // namespace
}  // namespace coldspray::materials
