// A quarter model with mirrored ghost points (pd/symmetry.hpp) reproduces the whole model of a
// normal impact: the PD paper's Cu on Cu at 500 m/s, coarse (examples/verification/
// pd-quarter-impact.yaml). The issue asks for 1 %; the mirror images make the quarter the whole
// model's solution restricted to x, y >= 0, so the two agree to round-off (measured 1e-13).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, PeridynamicQuarterModelEqualsTheWholeModel) {
  const CaseRun whole = run_verification_case("pd-quarter-impact");
  const CaseRun quarter =
      run_verification_case("pd-quarter-impact", {{"symmetry.x", "0 um"}, {"symmetry.y", "0 um"}});
  const auto& w = whole.summary.bodies;
  const auto& q = quarter.summary.bodies;
  std::printf(
      "pd quarter vs whole: particle v_z %.10g / %.10g m/s, crater %.6g / %.6g um, "
      "flattening %.8g / %.8g, points %zu / %zu\n",
      q[0].velocity[2], w[0].velocity[2], q[1].impact.crater_depth * 1e6,
      w[1].impact.crater_depth * 1e6, q[0].impact.flattening_ratio, w[0].impact.flattening_ratio,
      quarter.summary.particles, whole.summary.particles);
  EXPECT_GT(w[0].velocity[2], 100.0);  // it rebounds
  EXPECT_NEAR(q[0].velocity[2], w[0].velocity[2], 1e-9 * std::abs(w[0].velocity[2]));
  EXPECT_NEAR(q[1].impact.crater_depth, w[1].impact.crater_depth, 1e-9 * w[1].impact.crater_depth);
  EXPECT_NEAR(q[0].impact.flattening_ratio, w[0].impact.flattening_ratio, 1e-9);
  EXPECT_NEAR(q[0].impact.contact_area, w[0].impact.contact_area, 1e-9 * w[0].impact.contact_area);
  EXPECT_GT(w[0].impact.contact_area, 0.0);
  // A quarter of the points (the ghosts are not points of the run) and of the energy.
  EXPECT_NEAR(4.0 * static_cast<double>(quarter.summary.particles),
              static_cast<double>(whole.summary.particles), 0.02 * whole.summary.particles);
  EXPECT_NEAR(4.0 * quarter.summary.energy.plastic_work, whole.summary.energy.plastic_work,
              1e-9 * whole.summary.energy.plastic_work);
}

}  // namespace
}  // namespace coldspray::verification
