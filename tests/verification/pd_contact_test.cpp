// The short-range contact keeps the bodies apart (docs/pd.md, "Contact"): on the quarter Cu on
// Cu impact at 500 m/s (examples/verification/pd-quarter-impact.yaml) refined to 0.5 um, after
// 10 ns no particle point lies under the substrate's surface layer. With a contact distance of
// 0.9 spacings for every pair (the form before LAMMPS's min(0.9 |X_i - X_j|, 1.35 spacings)),
// particle points pass between the substrate's surface points once the crater stretches them:
// the same count is then nonzero (131 of the 1056 particle points at 10 ns; on the PD paper's
// 30 um impact at 500 m/s, 12 % of the particle at D/50 by 110 ns).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"

namespace coldspray::pd {
namespace {

constexpr double kSpacing = 0.5e-6;  // m

State impact_to_10ns(const std::string& contact_distance) {
  const case_file::Case c = case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/pd-quarter-impact.yaml",
      {{"symmetry.x", "0 um"},
       {"symmetry.y", "0 um"},
       {"bodies.particle.spacing", "0.5 um"},
       {"bodies.substrate.spacing", "0.5 um"},
       {"contact.peridynamics.repulsion.distance", contact_distance}});
  State s = build_state(c);
  while (s.time < 10e-9) {
    s.dt = stable_time_step(s, c.solver.cfl);
    step(s);
  }
  return s;
}

// Particle points with a point of the substrate's initial top layer less than a spacing away
// sideways and more than half a spacing above them.
int particle_points_under_the_surface(const State& s) {
  const bodies::Points& P = s.points;
  const bodies::BodyRange& particle = s.bodies[0];
  const bodies::BodyRange& substrate = s.bodies[1];
  double top = -INFINITY;
  for (std::size_t q = substrate.begin; q < substrate.end; ++q) top = std::max(top, P.initial_z[q]);
  std::vector<std::size_t> layer;
  for (std::size_t q = substrate.begin; q < substrate.end; ++q)
    if (P.initial_z[q] > top - 0.75 * kSpacing) layer.push_back(q);
  int under = 0;
  for (std::size_t p = particle.begin; p < particle.end; ++p)
    for (const std::size_t q : layer)
      if (std::hypot(P.position[0][p] - P.position[0][q], P.position[1][p] - P.position[1][q]) <
              kSpacing &&
          P.position[2][q] - P.position[2][p] > 0.5 * kSpacing) {
        ++under;
        break;
      }
  return under;
}

TEST(Verification, PeridynamicContactKeepsTheParticleOutOfTheSubstrate) {
  const State lammps = impact_to_10ns("1.35");
  const State every_pair_at_0_9 = impact_to_10ns("0.9");
  const int under = particle_points_under_the_surface(lammps);
  const int under_before = particle_points_under_the_surface(every_pair_at_0_9);
  std::printf(
      "pd contact: particle points under the substrate's surface at 10 ns: %d (d = 0.9 h "
      "for every pair: %d) of %zu\n",
      under, under_before, lammps.bodies[0].end - lammps.bodies[0].begin);
  EXPECT_EQ(under, 0);
  EXPECT_GT(under_before, 20);  // the count sees the defect it guards against
}

}  // namespace
}  // namespace coldspray::pd
