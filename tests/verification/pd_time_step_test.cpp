// Peridynamics' time step follows the deformed lattice (docs/pd.md, "Time step"): dt = cfl h
// min(1, lambda / 0.7) / (c + |v|), lambda a point's smallest principal stretch. On the PD
// paper's Cu on Cu at 500 m/s, coarse (examples/verification/pd-quarter-impact.yaml):
// - the default, cfl 1.2, gives the impact of cfl 0.3 (rebound and crater within 0.5 %, measured
//   0.06 % and 0.04 %) with the energy budget within 0.5 % (measured 4.3e-3);
// - cfl 1.6 runs to the end with the budget within the 2 % asked of every verification run
//   (measured 0.68 %, rebound 122.5 m/s): with h alone in place of h min(1, lambda / 0.7), cfl 1.5
//   faulted at 12.4 ns, once the particle's south pole was compressed to lambda = 0.35
//   (measured).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, PeridynamicDefaultTimeStepGivesTheFineStepsImpact) {
  const CaseRun coarse = run_verification_case("pd-quarter-impact");
  const CaseRun fine = run_verification_case("pd-quarter-impact", {{"solver.cfl", "0.3"}});
  const auto& c = coarse.summary.bodies;
  const auto& f = fine.summary.bodies;
  std::printf(
      "pd time step: cfl 1.2 / 0.3: steps %ld / %ld, particle v_z %.6g / %.6g m/s, crater "
      "%.6g / %.6g um, energy error %.2e / %.2e\n",
      coarse.summary.steps, fine.summary.steps, c[0].velocity[2], f[0].velocity[2],
      c[1].impact.crater_depth * 1e6, f[1].impact.crater_depth * 1e6,
      coarse.summary.energy_relative_error(), fine.summary.energy_relative_error());
  EXPECT_GT(f[0].velocity[2], 100.0);  // it rebounds
  EXPECT_LT(static_cast<double>(coarse.summary.steps),
            0.5 * static_cast<double>(fine.summary.steps));
  EXPECT_NEAR(c[0].velocity[2], f[0].velocity[2], 5e-3 * f[0].velocity[2]);
  EXPECT_NEAR(c[1].impact.crater_depth, f[1].impact.crater_depth, 5e-3 * f[1].impact.crater_depth);
  EXPECT_LT(std::abs(coarse.summary.energy_relative_error()), 5e-3);
}

TEST(Verification, PeridynamicTimeStepFollowsTheCompression) {
  const CaseRun run = run_verification_case("pd-quarter-impact", {{"solver.cfl", "1.6"}});
  std::printf("pd time step: cfl 1.6: %ld steps, particle v_z %.6g m/s, energy error %.2e\n",
              run.summary.steps, run.summary.bodies[0].velocity[2],
              run.summary.energy_relative_error());
  EXPECT_EQ(run.summary.status, "ok");
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 2e-2);
  EXPECT_GT(run.summary.bodies[0].velocity[2], 100.0);
}

}  // namespace
}  // namespace coldspray::verification
