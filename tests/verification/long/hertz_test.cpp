// Hertz impact of an elastic sphere on an elastic half-space: the peak contact force within
// 10 % of F_max = (4/3) E* sqrt(R) delta_max^(3/2); the contact time is printed against
// t_c = 2.868 (m^2/(R E*^2 v))^(1/5) (validation-data.md §3). Run at 200 m/s with 0.25 um
// cells so that the indentation (1.64 um) spans several cells.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "verification_support.hpp"

namespace coldspray::verification {
namespace {

TEST(LongVerification, HertzSphereOnHalfSpace) {
  const double R = 10e-6, v = 200.0, rho = 2700.0, K = 66.4e9, G = 26e9;
  const double E = 9.0 * K * G / (3.0 * K + G), nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
  const double E_star = E / (2.0 * (1.0 - nu * nu));
  const double m = rho * 4.0 / 3.0 * std::numbers::pi * R * R * R;
  const double delta = std::pow(15.0 * m * v * v / (16.0 * E_star * std::sqrt(R)), 0.4);
  const double F_max = 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(delta, 1.5);
  const double t_c = 2.868 * std::pow(m * m / (R * E_star * E_star * v), 0.2);

  const CaseRun run =
      run_verification_case("hertz", {{"bodies.sphere.velocity", "[0, 0, -200 m/s]"},
                                      {"grid.cell_size", "0.25 um"},
                                      {"bodies.sphere.spacing", "0.125 um"},
                                      {"bodies.half-space.spacing", "0.125 um"},
                                      {"solver.end_time", "35 ns"}});
  // The force on the sphere from its momentum history (the only force on it is contact).
  const Table h = run.history();
  const auto t = h.values("time"), vz = h.values("sphere.vz");
  double peak = 0.0;
  std::vector<double> force;
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    force.push_back(m * (vz[i + 1] - vz[i - 1]) / (t[i + 1] - t[i - 1]));
    peak = std::max(peak, force.back());
  }
  double first = -1.0, last = -1.0;
  for (std::size_t i = 0; i < force.size(); ++i)
    if (force[i] > 0.02 * peak) {
      if (first < 0.0) first = t[i + 1];
      last = t[i + 1];
    }
  std::printf(
      "hertz: peak force %.1f mN (Hertz %.1f), contact time above 2 %% of the peak "
      "%.2f ns (Hertz %.2f), %.0f s on %d threads\n",
      peak * 1e3, F_max * 1e3, (last - first) * 1e9, t_c * 1e9, run.summary.wall_seconds,
      run.summary.threads);
  EXPECT_NEAR(peak, F_max, 0.10 * F_max);
}

}  // namespace
}  // namespace coldspray::verification
