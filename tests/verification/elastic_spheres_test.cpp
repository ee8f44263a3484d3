// Two elastic spheres colliding head-on: momentum conserved to 1e-10 relative and at least 95 %
// of the kinetic energy carried away as rigid-body motion once they separate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, ElasticSpheresConserveMomentum) {
  const CaseRun run = run_verification_case("elastic-spheres");
  const auto& upper = run.summary.bodies.at(0);
  const auto& lower = run.summary.bodies.at(1);
  const double reference = upper.mass * 50.0;  // either sphere's initial momentum
  const double total = upper.mass * upper.velocity[2] + lower.mass * lower.velocity[2];
  const double rebound = 0.5 * (upper.velocity[2] - lower.velocity[2]);
  std::printf(
      "elastic spheres: momentum error %.2e, rebound speed %.2f m/s of 50, rigid-body "
      "kinetic energy recovered %.1f %%\n",
      std::abs(total) / reference, rebound, 100.0 * rebound * rebound / 2500.0);
  EXPECT_LT(std::abs(total) / reference, 1e-10);
  EXPECT_GT(rebound * rebound / 2500.0, 0.95);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.01);
}

}  // namespace
}  // namespace coldspray::verification
