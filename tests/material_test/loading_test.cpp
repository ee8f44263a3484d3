// The material-test driver's kinematics against small-strain elasticity.
#include "material_test/loading.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace coldspray::material_test {
namespace {

materials::Material elastic_material() {
  materials::Material m;
  m.name = "elastic";
  m.density = 2700.0;
  m.elastic = {.shear_modulus = 26e9, .bulk_modulus = 66.4e9};
  m.strength = materials::strength::Elastic{};
  m.shear_modulus = materials::shear_modulus::Constant{};
  m.melt = materials::melt::Constant{.temperature = 933.0};
  m.eos = materials::eos::Linear{};
  m.thermal = {.specific_heat = 896.0, .taylor_quinney = 0.9};
  return m;
}

std::vector<Sample> run(const materials::Material& m, Mode mode, double final_strain,
                        int steps = 100) {
  Loading l;
  l.mode = mode;
  l.strain_rate = 1e3;
  l.final_strain = final_strain;
  l.steps = steps;
  std::vector<Sample> out;
  drive(m, l, [&](const Sample& s) { out.push_back(s); });
  return out;
}

constexpr double kG = 26e9, kK = 66.4e9;

TEST(MaterialTestDriver, UniaxialStrainFollowsTheConstrainedModulus) {
  // Small compression: axial stress -(K + 4G/3) eps, so von Mises 2G|eps| and pressure K|eps|.
  const double eps = -1e-5;
  const auto samples = run(elastic_material(), Mode::UniaxialStrain, eps);
  ASSERT_EQ(samples.size(), 101u);
  const Sample& last = samples.back();
  EXPECT_NEAR(last.von_mises, 2.0 * kG * std::abs(eps), 1e-4 * 2.0 * kG * std::abs(eps));
  EXPECT_NEAR(last.pressure, kK * std::abs(eps), 1e-4 * kK * std::abs(eps));
  EXPECT_NEAR(last.density, 2700.0 * std::exp(-eps), 1e-9);
  EXPECT_DOUBLE_EQ(last.eqps, 0.0);
}

TEST(MaterialTestDriver, UniaxialStressFollowsYoungsModulus) {
  // sigma_xx = E eps with E = 9KG/(3K + G); lateral stresses vanish, so p = -sigma_xx/3 and
  // von Mises = |sigma_xx|.
  const double eps = -1e-5;
  const double E = 9.0 * kK * kG / (3.0 * kK + kG);
  const auto samples = run(elastic_material(), Mode::UniaxialStress, eps);
  const Sample& last = samples.back();
  EXPECT_NEAR(last.von_mises, E * std::abs(eps), 1e-4 * E * std::abs(eps));
  EXPECT_NEAR(last.pressure, E * std::abs(eps) / 3.0, 1e-4 * E * std::abs(eps));
}

TEST(MaterialTestDriver, SimpleShearFollowsTheShearModulus) {
  // tau = G gamma and von Mises = sqrt(3) tau for small gamma; no volume change.
  const double gamma = 1e-5;
  const auto samples = run(elastic_material(), Mode::SimpleShear, gamma);
  const Sample& last = samples.back();
  EXPECT_NEAR(last.strain, gamma, 1e-15);
  EXPECT_NEAR(last.von_mises, std::sqrt(3.0) * kG * gamma, 1e-4 * kG * gamma);
  EXPECT_NEAR(last.pressure, 0.0, 1e-6 * kG * gamma);
  EXPECT_DOUBLE_EQ(last.density, 2700.0);
}

TEST(MaterialTestDriver, RejectsNonPositiveRateAndZeroStrain) {
  Loading l;
  l.strain_rate = 0.0;
  EXPECT_THROW(drive(elastic_material(), l, [](const Sample&) {}), InputError);
  l.strain_rate = 1.0;
  l.final_strain = 0.0;
  EXPECT_THROW(drive(elastic_material(), l, [](const Sample&) {}), InputError);
}

}  // namespace
}  // namespace coldspray::material_test
