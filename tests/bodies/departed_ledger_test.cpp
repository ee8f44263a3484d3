// The ledger of the points that left the computation (bodies::Departed), by hand: what the MPM
// books when points leave its grid (mpm/departures.hpp: mass, momentum, kinetic and internal
// energy, the works, the dashpots' absorbed energy), that it adds up over removals, how the
// energy budget (metrics/energy.hpp) counts it, and the bulk that may leave before the run stops.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "elastic_case.hpp"
#include "metrics/energy.hpp"
#include "mpm/departures.hpp"
#include "mpm/setup.hpp"

namespace coldspray::bodies {
namespace {

using testing::box;
using testing::elastic_case;
using testing::kPointMass;

// A block of 4 x 2 x 2 points at rest, absorbing at its bottom: the layer z = 0.25 um, points 0-7
// (the lattice runs x fastest, z slowest).
mpm::State block() {
  return mpm::build_state(
      elastic_case(box("block", "[0, 0, 0]", "[2 um, 1 um, 1 um]", "    absorbing: [bottom]\n")));
}

// Moves the points past the grid's face at x max, as a step that carried them there leaves them.
void carry_off(mpm::State& s, const std::vector<std::size_t>& points) {
  for (const std::size_t p : points) s.points.position[0][p] = s.layout.extent(0) + 1e-6;
  s.departing = points.size();
}

TEST(DepartedLedger, BooksTheMassMomentumEnergiesAndWorksOfThePointsThatLeave) {
  mpm::State s = block();
  ASSERT_EQ(s.points.size(), 16u);
  Points& P = s.points;
  // Point 3 (an absorbing one) and point 12 carry what the ledger must add up.
  const double v[2][3] = {{1000.0, 0.0, 0.0}, {0.0, -200.0, 50.0}};
  const std::size_t a = 3, b = 12;
  for (int d = 0; d < 3; ++d) P.velocity[d][a] = v[0][d], P.velocity[d][b] = v[1][d];
  P.energy[a] = 1e6, P.energy[b] = -2e5;  // J/m^3
  P.plastic_work[a] = 1e-15, P.plastic_work[b] = 2e-15;
  P.viscous_work[a] = 3e-16, P.viscous_work[b] = 4e-16;
  P.contact_work[a] = 5e-17, P.contact_work[b] = 6e-17;
  ASSERT_EQ(s.absorbing.size(), 8u);
  AbsorbingPoint* dashpot = nullptr;
  for (AbsorbingPoint& ap : s.absorbing)
    if (ap.point == a) dashpot = &ap;
  ASSERT_NE(dashpot, nullptr);
  dashpot->absorbed = 7e-14;
  const metrics::EnergyBudget before = metrics::energy_budget(s);

  carry_off(s, {a, b});
  mpm::remove_departed_points(s);

  const Departed& d = s.bodies[0].departed;
  EXPECT_EQ(d.points, 2u);
  EXPECT_NEAR(d.mass, 6.75e-16, 1e-30);
  // m (1000, -200, 50) m/s, m = 3.375e-16 kg.
  EXPECT_NEAR(d.momentum[0], 3.375e-13, 1e-27);
  EXPECT_NEAR(d.momentum[1], -6.75e-14, 1e-27);
  EXPECT_NEAR(d.momentum[2], 1.6875e-14, 1e-27);
  // m/2 (1000^2 + 200^2 + 50^2) m^2/s^2 = 1.75921875e-10 J; (1e6 - 2e5) J/m^3 x (0.5 um)^3 = 1e-13
  // J.
  EXPECT_NEAR(d.kinetic, 1.75921875e-10, 1e-22);
  EXPECT_NEAR(d.internal, 1e-13, 1e-25);
  EXPECT_NEAR(d.plastic_work, 3e-15, 1e-28);
  EXPECT_NEAR(d.viscous_work, 7e-16, 1e-29);
  EXPECT_NEAR(d.contact_work, 1.1e-16, 1e-29);
  EXPECT_EQ(d.absorbed, 7e-14);
  EXPECT_EQ(s.points.size(), 14u);
  EXPECT_EQ(s.absorbing.size(), 7u);

  // The budget: what left is `departed`, its works stay in their terms, and the total is kept.
  const metrics::EnergyBudget after = metrics::energy_budget(s);
  EXPECT_NEAR(after.departed, 1.75921875e-10 + 1e-13, 1e-22);
  EXPECT_NEAR(after.kinetic, 0.0, 1e-30);
  EXPECT_NEAR(after.viscous, before.viscous, 1e-29);
  EXPECT_NEAR(after.viscous, 7e-16, 1e-29);
  EXPECT_NEAR(after.contact, -1.1e-16, 1e-29);
  EXPECT_NEAR(after.absorbed, 7e-14, 1e-27);
  EXPECT_NEAR(after.total(), before.total(), 1e-24);
}

TEST(DepartedLedger, AddsUpOverRemovalsAndAHalfMayLeaveButNoMore) {
  mpm::State s = block();
  for (std::size_t p = 0; p < 16; ++p) s.points.velocity[2][p] = -100.0;
  carry_off(s, {0, 5, 10});
  mpm::remove_departed_points(s);
  carry_off(s, {0, 1, 2, 3, 4});  // 8 of 16: half the block, not more
  mpm::remove_departed_points(s);
  const Departed& d = s.bodies[0].departed;
  EXPECT_EQ(d.points, 8u);
  EXPECT_NEAR(d.mass, 8 * kPointMass, 1e-29);
  EXPECT_NEAR(d.momentum[2], -8 * kPointMass * 100.0, 1e-26);
  EXPECT_NEAR(d.kinetic, 8 * 0.5 * kPointMass * 1e4, 1e-24);
  EXPECT_EQ(s.points.size(), 8u);
  EXPECT_EQ(s.bodies[0].end - s.bodies[0].begin, 8u);

  // Two more: 10 of 16 would have gone. The run stops with the state as the step left it.
  carry_off(s, {0, 1});
  try {
    mpm::remove_departed_points(s);
    FAIL() << "no RunFault";
  } catch (const RunFault& e) {
    EXPECT_NE(std::string(e.what()).find("body 'block': 62.5 % of its mass has left the grid"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(s.bodies[0].departed.points, 8u);
  EXPECT_EQ(s.points.size(), 8u);
}

}  // namespace
}  // namespace coldspray::bodies
