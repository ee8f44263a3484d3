// The zero-energy-mode control's scale (pd/control_scale.hpp) against hand references: 1 in an
// elastic step; H / (3G + H) for J2 plasticity with linear hardening, the ratio of the
// elastoplastic tangent along the flow to the elastic modulus; for Johnson-Cook the same ratio
// with H = d sigma_y / d eqps = B n eqps^(n-1) (1 + C ln(rate)) at room temperature; and, unlike
// the step's algorithmic tangent, a ratio that does not depend on the time step.
#include <gtest/gtest.h>

#include <cmath>

#include "../materials/reference_materials.hpp"
#include "materials/model_dispatch.hpp"
#include "pd/control_scale.hpp"

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

double scale_of(const materials::Material& m, const PointState& st, bool flowed) {
  return materials::visit_models(
      m, [&](const auto& models) { return control_scale(models, st, flowed, m.density / st.J); });
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

}  // namespace
}  // namespace coldspray::pd
