// Points that leave the grid leave the run (mpm/departures.hpp): what they carried goes into
// their bodies' ledgers, so the energy budget and the momentum are the same before and after a
// removal, and the points left keep their state and order. The fragment case
// (examples/verification/fragment-leaves.yaml) counts the points that left by hand, and a body
// whose bulk leaves stops the run.
#include "mpm/departures.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "core/error.hpp"
#include "metrics/energy.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"
#include "run/step_rule.hpp"

namespace coldspray::mpm {
namespace {

case_file::Case load(const std::string& example, std::vector<case_file::Override> overrides) {
  return case_file::load_case(std::string(COLDSPRAY_SOURCE_DIR) + "/examples/" + example,
                              overrides);
}

// Runs the case to its end time with its own step rule.
State run_case_steps(const case_file::Case& c) {
  State s = build_state(c);
  const run::StepRule rule(c, s);
  while (!rule.finished(s)) {
    s.dt = rule.next_dt(s);
    step(s);
  }
  return s;
}

// Total momentum of the points on the grid and of those that left, kg m/s.
std::array<double, 3> momentum(const State& s) {
  std::array<double, 3> total{};
  for (std::size_t p = 0; p < s.points.size(); ++p)
    for (int d = 0; d < 3; ++d) total[d] += s.points.mass[p] * s.points.velocity[d][p];
  for (const BodyRange& b : s.bodies)
    for (int d = 0; d < 3; ++d) total[d] += b.departed.momentum[d];
  return total;
}

// 60 steps of the r-z impact, coarse: points with stress, plastic, viscous and contact work, and
// absorbing points that have done work.
State impact_under_way() {
  const case_file::Case c = load("al-14um-810.yaml", {{"grid.cell_size", "1.4 um"},
                                                      {"bodies.particle.spacing", "0.35 um"},
                                                      {"bodies.substrate.spacing", "0.35 um"}});
  State s = build_state(c);
  for (int k = 0; k < 60; ++k) {
    s.dt = stable_time_step(s, c.solver.cfl);
    step(s);
  }
  return s;
}

TEST(MpmDepartures, RemovalKeepsTheBudgetTheMomentumAndTheOtherPoints) {
  State s = impact_under_way();
  const Points before = s.points;
  const std::vector<BodyRange> bodies_before = s.bodies;
  const std::vector<AbsorbingPoint> absorbing_before = s.absorbing;
  const metrics::EnergyBudget e0 = metrics::energy_budget(s);
  const std::array<double, 3> p0 = momentum(s);

  // Every fifth point of the particle, and the first and last absorbing points of the substrate,
  // moved past the top of the domain.
  std::vector<std::size_t> gone;
  for (std::size_t p = s.bodies[0].begin; p < s.bodies[0].end; p += 5) gone.push_back(p);
  gone.push_back(s.absorbing.front().point);
  gone.push_back(s.absorbing.back().point);
  const double above = s.layout.extent(2);
  for (const std::size_t p : gone) s.points.position[2][p] = above;
  s.departing = gone.size();

  // What they carry, summed here from the copy.
  std::array<std::size_t, 2> count{};
  std::array<double, 2> mass{}, kinetic{}, internal{}, plastic{}, absorbed{};
  for (const std::size_t p : gone) {
    const int b = before.body[p];
    ++count[b];
    mass[b] += before.mass[p];
    double v2 = 0.0;
    for (int d = 0; d < 3; ++d) v2 += before.velocity[d][p] * before.velocity[d][p];
    kinetic[b] += 0.5 * before.mass[p] * v2;
    internal[b] += before.energy[p] * before.volume0[p];
    plastic[b] += before.plastic_work[p];
  }
  absorbed[1] = absorbing_before.front().absorbed + absorbing_before.back().absorbed;
  ASSERT_GT(plastic[0], 0.0);
  ASSERT_GT(absorbed[1], 0.0);

  remove_departed_points(s);

  EXPECT_EQ(s.departing, 0u);
  for (int b = 0; b < 2; ++b) {
    const Departed& d = s.bodies[b].departed;
    EXPECT_EQ(d.points, count[b]);
    EXPECT_NEAR(d.mass, mass[b], 1e-14 * mass[b]);
    EXPECT_NEAR(d.kinetic, kinetic[b], 1e-14 * kinetic[b]);
    EXPECT_NEAR(d.internal, internal[b], 1e-14 * std::abs(internal[b]));
    EXPECT_NEAR(d.plastic_work, plastic[b], 1e-14 * plastic[b]);
    EXPECT_EQ(d.absorbed, absorbed[b]);
    EXPECT_EQ(s.bodies[b].end - s.bodies[b].begin,
              bodies_before[b].end - bodies_before[b].begin - count[b]);
  }
  EXPECT_EQ(s.bodies[1].begin, s.bodies[0].end);
  EXPECT_EQ(s.points.size(), before.size() - gone.size());

  // The budget closes: every term moved to `departed` or stayed where it was.
  const metrics::EnergyBudget e1 = metrics::energy_budget(s);
  EXPECT_NEAR(e1.total(), e0.total(), 1e-14 * e0.total());
  EXPECT_NEAR(e1.kinetic + kinetic[0] + kinetic[1], e0.kinetic, 1e-14 * e0.kinetic);
  EXPECT_NEAR(e1.departed, kinetic[0] + kinetic[1] + internal[0] + internal[1],
              1e-14 * e1.departed);
  EXPECT_NEAR(e1.viscous, e0.viscous, 1e-14 * e0.viscous);
  EXPECT_NEAR(e1.contact, e0.contact, 1e-14 * e0.contact);
  EXPECT_NEAR(e1.absorbed, e0.absorbed, 1e-14 * e0.absorbed);
  const std::array<double, 3> p1 = momentum(s);
  const double scale = std::abs(p0[2]);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(p1[d], p0[d], 1e-14 * scale) << "axis " << d;

  // The points left are the others, in order, with all they held.
  std::size_t q = 0;
  for (std::size_t p = 0; p < before.size(); ++p) {
    if (std::binary_search(gone.begin(), gone.end(), p)) continue;
    ASSERT_EQ(s.points.id[q], before.id[p]);
    ASSERT_EQ(s.points.body[q], before.body[p]);
    for (int c = 0; c < 6; ++c) ASSERT_EQ(s.points.stress[c][q], before.stress[c][p]);
    ASSERT_EQ(s.points.position[0][q], before.position[0][p]);
    ASSERT_EQ(s.points.contact_work[q], before.contact_work[p]);
    ++q;
  }
  // The absorbing points left are the same points, with the work they did.
  ASSERT_EQ(s.absorbing.size(), absorbing_before.size() - 2);
  for (std::size_t i = 0; i < s.absorbing.size(); ++i) {
    const AbsorbingPoint& was = absorbing_before[i + 1];
    EXPECT_EQ(s.points.id[s.absorbing[i].point], before.id[was.point]);
    EXPECT_EQ(s.absorbing[i].absorbed, was.absorbed);
  }

  // And the run goes on.
  for (int k = 0; k < 5; ++k) {
    s.dt = stable_time_step(s, 0.3);
    step(s);
  }
  EXPECT_EQ(s.points.size(), before.size() - gone.size());
}

TEST(MpmDepartures, AFragmentThrownOffTheGridLeavesTheRunAndTheBlockBesideItIsUnchanged) {
  const State s = run_case_steps(load("verification/fragment-leaves.yaml", {}));
  // The same case on a grid wide enough that nothing leaves.
  const State wide = run_case_steps(
      load("verification/fragment-leaves.yaml", {{"grid.max", "[10 um, 7 um, 3 um]"}}));
  ASSERT_EQ(wide.bodies[0].departed.points, 0u);

  // By hand: the leading layer of 4 points (x = 2.75 um, 1.25 um from the face at 1000 m/s)
  // has left by 1.5 ns, the next (1.75 ns) has not. A point is 2700 kg/m^3 x (0.5 um)^3.
  const double m = 2700.0 * 0.125e-18;
  const Departed& d = s.bodies[0].departed;
  EXPECT_EQ(d.points, 4u);
  EXPECT_NEAR(d.mass, 4.0 * m, 1e-15 * m);
  EXPECT_NEAR(d.momentum[0], 4.0 * m * 1000.0, 1e-9 * m * 1000.0);
  EXPECT_NEAR(d.kinetic, 4.0 * 0.5 * m * 1e6, 1e-9 * m * 1e6);
  EXPECT_LT(std::abs(d.internal), 1e-12 * d.kinetic);
  EXPECT_EQ(s.bodies[1].departed.points, 0u);
  // The points left are the fragment's three trailing layers (ids with x index 0-2; the
  // lattice runs x fastest).
  ASSERT_EQ(s.bodies[0].end - s.bodies[0].begin, 12u);
  for (std::size_t p = s.bodies[0].begin; p < s.bodies[0].end; ++p)
    EXPECT_NE(s.points.id[p] % 4, 3u) << "point " << p;

  // Momentum of the fragment, on and off the grid, is its initial 16 m x 1000 m/s.
  double px = d.momentum[0];
  for (std::size_t p = s.bodies[0].begin; p < s.bodies[0].end; ++p)
    px += s.points.mass[p] * s.points.velocity[0][p];
  EXPECT_NEAR(px, 16.0 * m * 1000.0, 1e-12 * 16.0 * m * 1000.0);
  // The energy budget's error is the wide run's (the block's dashpots): the removal added none.
  const double initial =
      metrics::energy_budget(build_state(load("verification/fragment-leaves.yaml", {}))).total();
  EXPECT_NEAR(metrics::energy_budget(s).total(), metrics::energy_budget(wide).total(),
              1e-14 * initial);

  // The block never shares a node with the fragment and its steps are fixed (solver.dt_scale):
  // its points and dashpots end bit for bit as on the wide grid, though 4 points before them
  // left and every index behind them moved.
  const BodyRange& block = s.bodies[1];
  const BodyRange& block_wide = wide.bodies[1];
  ASSERT_EQ(block.end - block.begin, block_wide.end - block_wide.begin);
  for (std::size_t i = 0; i < block.end - block.begin; ++i) {
    const std::size_t p = block.begin + i, q = block_wide.begin + i;
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(s.points.position[k][p], wide.points.position[k][q]) << "point " << i;
      ASSERT_EQ(s.points.velocity[k][p], wide.points.velocity[k][q]) << "point " << i;
    }
    for (int c = 0; c < 6; ++c) ASSERT_EQ(s.points.stress[c][p], wide.points.stress[c][q]);
  }
  ASSERT_EQ(s.absorbing.size(), wide.absorbing.size());
  ASSERT_GT(s.absorbing.size(), 0u);
  for (std::size_t i = 0; i < s.absorbing.size(); ++i) {
    EXPECT_EQ(s.absorbing[i].point - block.begin, wide.absorbing[i].point - block_wide.begin);
    EXPECT_EQ(s.absorbing[i].absorbed, wide.absorbing[i].absorbed);
  }
}

TEST(MpmDepartures, ABodyWhoseBulkLeavesStopsTheRunNamingIt) {
  // A third layer leaves at 2.25 ns: 12 of the fragment's 16 points, 75 % > 50 %.
  const case_file::Case c =
      load("verification/fragment-leaves.yaml", {{"solver.end_time", "2.5 ns"}});
  try {
    run_case_steps(c);
    FAIL() << "no fault";
  } catch (const RunFault& fault) {
    const std::string what = fault.what();
    EXPECT_NE(what.find("body 'fragment': 75 % of its mass has left the grid"), std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace coldspray::mpm
