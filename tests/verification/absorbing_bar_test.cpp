// An elastic pulse reaching an absorbing (Lysmer-Kuhlemeyer) face reflects under 10 % of its
// energy: once the pulse has gone, the energy left in the bodies is what the face sent back.
#include <gtest/gtest.h>

#include <cstdio>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, AbsorbingFaceReflectsLittle) {
  const CaseRun run = run_verification_case("absorbing-bar");
  const auto& e = run.summary.energy;
  const double injected = run.summary.total_energy_initial;  // the striker's kinetic energy
  const double left = e.kinetic + e.elastic();
  std::printf(
      "absorbing face: %.2f %% of the pulse energy absorbed, %.2f %% left in the bodies, "
      "energy error %.2e\n",
      100.0 * e.absorbed / injected, 100.0 * left / injected, run.summary.energy_relative_error());
  EXPECT_LT(left, 0.10 * injected);
  EXPECT_GT(e.absorbed, 0.85 * injected);
  EXPECT_LT(std::abs(run.summary.energy_relative_error()), 0.01);
}

}  // namespace
}  // namespace coldspray::verification
