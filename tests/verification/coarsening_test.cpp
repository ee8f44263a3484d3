// Coarsened seeding against the uniform lattice (docs/mpm.md, "Coarsened seeding"): the Hertz
// impact of examples/verification/hertz.yaml (an elastic 10 um sphere at 50 m/s on a half-space,
// r-z, 0.5 um cells, 0.25 um spacing) with the half-space's points merged into 0.5 um ones away
// from the contact gives the uniform run's contact force history and rebound: the fast path
// against its plain reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

struct Contact {
  double peak = 0.0;      // N, on the sphere
  double duration = 0.0;  // s, with the force above 2 % of its peak
  double rebound = 0.0;   // m/s, the sphere's final z velocity
  std::size_t points = 0;
};

Contact hertz_contact(const std::vector<std::pair<std::string, std::string>>& sets) {
  const CaseRun run = run_verification_case("hertz", sets);
  const double R = 10e-6, m = 2700.0 * 4.0 / 3.0 * std::numbers::pi * R * R * R;
  const Table h = run.history();
  const auto t = h.values("time"), vz = h.values("sphere.vz");
  Contact c;
  std::vector<double> force;
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    force.push_back(m * (vz[i + 1] - vz[i - 1]) / (t[i + 1] - t[i - 1]));
    c.peak = std::max(c.peak, force.back());
  }
  double first = -1.0, last = -1.0;
  for (std::size_t i = 0; i < force.size(); ++i)
    if (force[i] > 0.02 * c.peak) {
      if (first < 0.0) first = t[i + 1];
      last = t[i + 1];
    }
  c.duration = last - first;
  c.rebound = vz.back();
  c.points = run.summary.particles;
  return c;
}

TEST(Verification, ACoarsenedHalfSpaceGivesTheUniformHertzImpact) {
  const Contact uniform = hertz_contact({});
  const Contact coarse = hertz_contact(
      {{"bodies.half-space.coarsening",
        "{levels: 1, fine: {type: cylinder, base_center: [0, 0, -3 um], radius: 4 um, "
        "height: 3 um}}"}});
  std::printf(
      "hertz, uniform / coarsened half-space: %zu / %zu points; peak %.3f / %.3f mN; above 2 %% "
      "of it %.3f / %.3f ns; rebound %.3f / %.3f m/s\n",
      uniform.points, coarse.points, uniform.peak * 1e3, coarse.peak * 1e3, uniform.duration * 1e9,
      coarse.duration * 1e9, uniform.rebound, coarse.rebound);
  EXPECT_LT(coarse.points, uniform.points * 6 / 10);
  // A tenth of the Hertz test's 10 % tolerance against the analytic solution
  // (tests/verification/long/hertz_test.cpp): the coarse points far from the contact must not
  // change what the contact sees.
  EXPECT_NEAR(coarse.peak, uniform.peak, 0.01 * uniform.peak);
  EXPECT_NEAR(coarse.duration, uniform.duration, 0.01 * uniform.duration);
  EXPECT_NEAR(coarse.rebound, uniform.rebound, 0.01 * uniform.rebound);
}

}  // namespace
}  // namespace coldspray::verification
