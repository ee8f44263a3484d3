// A fragment thrown off the grid (examples/verification/fragment-leaves.yaml): the run goes on to
// its end, the summary and the history count what left, and the probes follow their points
// though the points before them left.
#include <gtest/gtest.h>

#include <cmath>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(Verification, AFragmentLeavesTheGridAndTheRunGoesOn) {
  const CaseRun run = run_verification_case("fragment-leaves");
  EXPECT_EQ(run.summary.status, "ok");
  // The same case on a grid wide enough that nothing leaves.
  const CaseRun wide =
      run_verification_case("fragment-leaves", {{"grid.max", "[10 um, 7 um, 3 um]"}});

  // By hand: the leading layer, 4 points of 2700 kg/m^3 x (0.5 um)^3, crosses x = 4 um at
  // 1.25 ns (1.25 um at 1000 m/s).
  const double m = 2700.0 * 0.125e-18;
  const metrics::BodyMetrics& fragment = run.summary.bodies[0];
  EXPECT_EQ(fragment.departed.points, 4u);
  EXPECT_NEAR(fragment.departed.mass, 4.0 * m, 1e-15 * m);
  EXPECT_NEAR(fragment.departed.kinetic, 4.0 * 0.5 * m * 1000.0 * 1000.0, 1e-9 * m * 1e6);
  EXPECT_NEAR(fragment.mass, 12.0 * m, 1e-15 * m);
  EXPECT_NEAR(run.summary.energy.departed, fragment.departed.kinetic, 1e-12 * m * 1e6);
  // Its energy error is the wide run's (the block's dashpots'): the removal adds none.
  EXPECT_NEAR(run.summary.energy_relative_error(), wide.summary.energy_relative_error(), 1e-13);
  const Table history = run.history();
  const std::vector<double> t = history.values("time"),
                            departed = history.values("fragment.departed_mass");
  for (std::size_t i = 0; i < t.size(); ++i)
    EXPECT_NEAR(departed[i], t[i] < 1.25e-9 ? 0.0 : 4.0 * m, 1e-15 * m) << "t = " << t[i];

  const Table probes = run.probes(), wide_probes = wide.probes();
  ASSERT_EQ(probes.rows.size(), wide_probes.rows.size());
  const std::vector<double> time = probes.values("time"), lead = probes.values("lead.velocity_x"),
                            trail = probes.values("trail.velocity_x"),
                            corner = probes.values("corner.velocity_z"),
                            wide_corner = wide_probes.values("corner.velocity_z");
  for (std::size_t i = 0; i < time.size(); ++i) {
    // The leading layer crosses x = 4 um at 1.25 ns (1.25 um at 1000 m/s).
    if (time[i] < 1.2e-9) {
      EXPECT_NEAR(lead[i], 1000.0, 1e-6) << "t = " << time[i];
    } else if (time[i] > 1.3e-9) {
      EXPECT_TRUE(std::isnan(lead[i])) << "t = " << time[i];
    }
    EXPECT_NEAR(trail[i], 1000.0, 1e-6) << "t = " << time[i];
    // The block's corner, whose index moved by 4 when the leading layer left, is the same point.
    EXPECT_EQ(corner[i], wide_corner[i]) << "t = " << time[i];
  }
  // (The dashpots under it have changed its velocity, from -20 m/s.)
  EXPECT_EQ(corner.front(), -20.0);
  EXPECT_GT(std::abs(corner.back() - corner.front()), 1.0);
}

}  // namespace
}  // namespace coldspray::verification
