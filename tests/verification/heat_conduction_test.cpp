// Heat conduction (solver.heat_conduction, mpm/heat_conduction.hpp) against the analytic solution
// of two semi-infinite bodies in contact (examples/verification/heat-conduction.yaml): bars at
// 400 K and 300 K meeting at z = L, T = 350 K + 50 K erf((L - z) / (2 sqrt(alpha t))), in 3D and
// in r-z (the bars as solid cylinders about the axis, where the ring volumes must leave the axial
// solution unchanged); and the heat the points hold, sum m C_p T, conserved to round-off. The
// points start on the solution at t0 = 1 ns (1.3 um wide across the interface, five cells), not on
// the step of t = 0: the grid resolves temperature to about a cell, and a step inside a cell would
// stay there (docs/mpm.md, heat conduction).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

constexpr double kInterface = 10e-6, kDiffusivity = 1e-3;  // m, m^2/s (the example's)

double heat_held(const State& s) {
  double sum = 0.0;
  for (std::size_t p = 0; p < s.points.size(); ++p)
    sum += s.points.mass[p] * s.bodies[s.points.body[p]].material.thermal.specific_heat *
           s.points.temperature[p];
  return sum;
}

void expect_erf_profile(const std::vector<case_file::Override>& overrides) {
  const case_file::Case c = case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/heat-conduction.yaml", overrides);
  State s = build_state(c);
  const double t0 = 1e-9;
  auto exact = [&](double z, double t) {
    return 350.0 + 50.0 * std::erf((kInterface - z) / (2.0 * std::sqrt(kDiffusivity * t)));
  };
  for (std::size_t p = 0; p < s.points.size(); ++p)
    s.points.temperature[p] = exact(s.points.position[2][p], t0);
  const double heat0 = heat_held(s);
  while (s.time < c.solver.end_time * (1.0 - 1e-12)) {
    s.dt = std::min(stable_time_step(s, c.solver.cfl), c.solver.end_time - s.time);
    step(s);
  }
  double worst = 0.0, interface = 0.0;
  std::size_t at_interface = 0;
  for (std::size_t p = 0; p < s.points.size(); ++p) {
    const double z = s.points.position[2][p];
    worst = std::max(worst, std::abs(s.points.temperature[p] - exact(z, t0 + s.time)));
    if (std::abs(z - kInterface) < 0.07e-6) {
      interface += s.points.temperature[p];
      ++at_interface;
    }
  }
  const double heat_error = std::abs(heat_held(s) - heat0) / heat0;
  std::printf(
      "t0 + %.3f ns: worst |T - erf| %.3f K of 100 K, mean T beside the interface %.3f K, "
      "heat held error %.2e\n",
      s.time * 1e9, worst, interface / at_interface, heat_error);
  EXPECT_LT(worst, 0.3);  // 0.3 % of the step (measured 0.08 K in 3D and in r-z)
  EXPECT_NEAR(interface / at_interface, 350.0, 0.05);
  EXPECT_LT(heat_error, 1e-12);
}

TEST(HeatConduction, ThreeDimensionalBarsFollowTheErfSolution) { expect_erf_profile({}); }

TEST(HeatConduction, AxisymmetricCylindersFollowTheErfSolution) {
  expect_erf_profile({{"solver.geometry", "axisymmetric"},
                      {"bodies.hot.shape",
                       "{type: cylinder, base_center: [0, 0, 0], radius: 1 um, height: 10 um}"},
                      {"bodies.cold.shape",
                       "{type: cylinder, base_center: [0, 0, 10 um], radius: 1 um, height: 10 um}"},
                      {"grid.max", "[1.5 um, 0.5 um, 21 um]"},
                      {"grid.faces", "{}"}});
}

}  // namespace
}  // namespace coldspray::mpm
