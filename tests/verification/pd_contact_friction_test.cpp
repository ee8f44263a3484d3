// The short-range contact has no tangential law, but between two lattices of the same spacing it
// acts as friction (docs/pd.md, "Contact"): an elastic bar landing on a block while sliding at
// 100 m/s along a lattice axis (examples/verification/pd-sliding-bars.yaml) takes a tangential
// contact impulse of 0.078 times the normal one (measured; 0.17 along the diagonal), the same at
// half the size, because each pair force leans along the line between two points and the
// points of two equal lattices catch on each other's rows. With the bar's spacing 0.7 of the
// block's the rows do not line up and the ratio is 0.002; without sliding it is zero.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

// Tangential over normal contact impulse on the bar (uniform history interval, so sums).
double friction_ratio(const std::vector<std::pair<std::string, std::string>>& sets) {
  const Table h = run_verification_case("pd-sliding-bars", sets).history();
  const std::vector<double> fx = h.values("upper.contact_fx");
  const std::vector<double> fz = h.values("upper.contact_fz");
  double tangential = 0.0, normal = 0.0;
  for (std::size_t k = 0; k < fz.size(); ++k) {
    tangential += fx[k];
    normal += fz[k];
  }
  EXPECT_GT(normal, 0.0);
  std::printf("tangential / normal contact impulse %.4f\n", tangential / normal);
  return tangential / normal;
}

TEST(Verification, PeridynamicContactBetweenEqualLatticesActsAsFriction) {
  const double mu = friction_ratio({});
  EXPECT_LT(mu, -0.04);  // against the sliding
  EXPECT_GT(mu, -0.12);
}

TEST(Verification, PeridynamicContactBetweenUnequalLatticesSlidesFreely) {
  EXPECT_LT(std::abs(friction_ratio({{"bodies.upper.spacing", "0.7 um"}})), 0.01);
}

TEST(Verification, PeridynamicContactWithoutSlidingHasNoTangentialForce) {
  EXPECT_LT(std::abs(friction_ratio({{"bodies.upper.velocity", "[0 m/s, 0 m/s, -40 m/s]"}})),
            1e-12);
}

}  // namespace
}  // namespace coldspray::verification
