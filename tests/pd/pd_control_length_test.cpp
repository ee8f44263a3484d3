// The control length l (pd/control_length.hpp): a full family's sum of omega beta / l equals its
// sum of omega beta / |xi|. In the continuum limit (horizon >> spacing) the sums are integrals
// over a ball: l = int r^2 omega dr / int r omega dr, 2 delta / 3 for omega = 1 and delta / 2
// for omega = delta / r (approached as h / delta); at the default horizon factor 3 the lattice
// gives 0.709 delta (docs/pd.md, "Zero-energy modes").
#include <gtest/gtest.h>

#include <cmath>

#include "pd/control_length.hpp"

namespace coldspray::pd {
namespace {

TEST(PeridynamicControlLength, TendsToTheContinuumValueAsTheHorizonGrows) {
  const double h = 1.0;
  EXPECT_NEAR(control_length(case_file::Influence::Constant, 24.0, h) / 24.0, 2.0 / 3.0, 5e-3);
  // With omega = delta / r the sums weigh the bonds near the origin most, where the lattice is
  // coarsest against the ball: the error falls as h / delta (1.5 % at delta = 24 h).
  const auto error = [&](double delta) {
    return std::abs(control_length(case_file::Influence::InverseDistance, delta, h) / delta - 0.5);
  };
  EXPECT_LT(error(48.0), 0.6 * error(24.0));
  EXPECT_LT(error(48.0), 1e-2);
}

TEST(PeridynamicControlLength, AtTheDefaultHorizon) {
  EXPECT_NEAR(control_length(case_file::Influence::Constant, 3.0, 1.0) / 3.0, 0.709, 5e-4);
  EXPECT_NEAR(control_length(case_file::Influence::InverseDistance, 3.0, 1.0) / 3.0, 0.629, 5e-4);
}

}  // namespace
}  // namespace coldspray::pd
