// The 3D Taylor bar at the axisymmetric case's resolution (0.4 mm cells, 0.2 mm spacing).
#include <gtest/gtest.h>

#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(LongVerification, TaylorBar3dFine) {
  const CaseRun run = run_verification_case(
      "taylor-bar-3d", {{"grid.cell_size", "0.4 mm"}, {"bodies.bar.spacing", "0.2 mm"}});
  const auto& bar = run.summary.bodies.at(0);
  const double length = bar.extent_max[2] + 0.1e-3, foot = bar.extent_max[0] + 0.1e-3;
  std::printf("taylor-bar-3d fine: length %.3f mm, foot radius %.3f mm, %.1f s on %d threads\n",
              length * 1e3, foot * 1e3, run.summary.wall_seconds, run.summary.threads);
  EXPECT_NEAR(length, 21.45e-3, 0.03 * 21.45e-3);
  EXPECT_NEAR(foot, 7.15e-3, 0.03 * 7.15e-3);
}

}  // namespace
}  // namespace coldspray::verification
