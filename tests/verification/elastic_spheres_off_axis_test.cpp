// Two elastic spheres colliding off-axis (examples/verification/elastic-spheres-off-axis.yaml)
// with the average-gradient contact normal: frictionless contact acts along the line of centres,
// so the relative velocity's part along the tangent at first contact is kept, and the spheres
// leave at the angle the instantaneous frictionless impact gives for the normal restitution the
// run measures (docs/validation/multi-particle.md, "Contact normals": measured 1.006 of the
// tangential part, 61.9 against 61.7 degrees; max-gradient 1.068 and 65.3 against 63.5).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, OffAxisElasticSpheresKeepTheirTangentialVelocity) {
  const CaseRun run = run_verification_case("elastic-spheres-off-axis");
  const auto& upper = run.summary.bodies.at(0);
  const auto& lower = run.summary.bodies.at(1);
  // Centres 5 um apart across the motion, 10 um apart at contact: the line of centres n and the
  // tangent t in the x-z plane; the relative velocity (0, 0, -100) m/s has n-part -86.6, t-part 50.
  const double s = 0.5, c = std::sqrt(3.0) / 2.0;
  const double vx = upper.velocity[0] - lower.velocity[0];
  const double vz = upper.velocity[2] - lower.velocity[2];
  const double normal = s * vx + c * vz, tangential = c * vx - s * vz;
  const double e = normal / (100.0 * c);
  // The frictionless impact's leaving direction at that restitution, from +z towards +x.
  const double ax = e * 100.0 * c * s + 50.0 * c, az = e * 100.0 * c * c - 50.0 * s;
  const double angle = std::atan2(vx, vz) * 180.0 / std::numbers::pi;
  const double expected = std::atan2(ax, az) * 180.0 / std::numbers::pi;
  const double px = upper.mass * upper.velocity[0] + lower.mass * lower.velocity[0];
  const double pz = upper.mass * upper.velocity[2] + lower.mass * lower.velocity[2];
  const double momentum_error = std::hypot(px, pz) / (upper.mass * 50.0);
  std::printf(
      "restitution %.3f, tangential part kept %.3f, angle %.2f deg (frictionless %.2f), "
      "momentum error %.1e\n",
      e, tangential / 50.0, angle, expected, momentum_error);
  EXPECT_LT(momentum_error, 1e-8);  // y is the symmetry plane's
  EXPECT_NEAR(tangential / 50.0, 1.0, 0.02);
  EXPECT_NEAR(angle, expected, 1.0);
  EXPECT_GT(e, 0.9);
}

}  // namespace
}  // namespace coldspray::verification
