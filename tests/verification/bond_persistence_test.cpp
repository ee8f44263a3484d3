// Bonds kept on the points (issue 22): once a bond forms between the particle and the substrate,
// the bonded interface holds without a debonding law, in r-z and in 3D. The small bonding impact
// (examples/verification/bonding-impact.yaml) with an adhesion energy that bonds part of the
// interface: at every step after the first bond, (a) no point loses its bond, (b) the bond force
// acts at some node (the bond kept on the points, not only where eq 4.7's nodal average happens to
// reach 1), and (c) every bonded particle point still has a bonded substrate point within two
// cells: the interface has not opened anywhere it bonded. The cases use the thesis' count average
// of eq 4.6, whose nodal value falls back below 1 on some steps after a bond formed, so that they
// exercise the kept bond (with Gdot_c fixed at 2.8207e5 J/m^2/us, so that the shipped calibration
// does not move them); with the weight average (the default) the nodal value is steadier and
// stays >= 1 somewhere on every step of these runs (measured at G_c 150-200 J/m^2 in r-z and
// 200 J/m^2 in 3D).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

struct Interface {
  std::size_t bonded_points = 0;  // points of either body keeping a bond
  std::size_t forming = 0;        // node pairs where eq 4.7's nodal D_bond is >= 1 this step
  std::size_t acting = 0;         // node pairs where the bond force acts this step
  double widest_gap = 0.0;        // max over bonded particle points of the nearest bonded
                                  // substrate point's distance, m
};

Interface measure(const State& s) {
  Interface m;
  const ContactNodes& c = s.contact;
  for (std::size_t slot = 0; slot < c.size(); ++slot) {
    const auto sl = static_cast<std::int32_t>(slot);
    for (int e1 = 0; e1 < c.body_count(sl); ++e1)
      for (int e2 = e1 + 1; e2 < c.body_count(sl); ++e2) {
        const std::size_t k = ContactNodes::pair(sl, e1, e2);
        if (c.pair_master[k] < 0) continue;
        m.forming += c.pair_bond_forms[k];
        m.acting += c.pair_bond_forms[k] || bond_holds(c.pair_bonded_sides[k]);
      }
  }
  const Points& P = s.points;
  std::vector<std::size_t> substrate;
  for (std::size_t p = 0; p < P.size(); ++p) {
    m.bonded_points += P.bonded_to[p] != 0;
    if (P.bonded_to[p] != 0 && P.body[p] == 1) substrate.push_back(p);
  }
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.bonded_to[p] == 0 || P.body[p] != 0) continue;
    double nearest = INFINITY;
    for (const std::size_t q : substrate) {
      double d2 = 0.0;
      for (int d = 0; d < 3; ++d) d2 += std::pow(P.position[d][p] - P.position[d][q], 2);
      nearest = std::min(nearest, std::sqrt(d2));
    }
    m.widest_gap = std::max(m.widest_gap, nearest);
  }
  return m;
}

void expect_bonds_persist(const std::vector<case_file::Override>& overrides, int steps) {
  const case_file::Case c = case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/bonding-impact.yaml", overrides);
  State s = build_state(c);
  const double h = s.layout.h;
  std::size_t bonded_before = 0, flickers = 0, first_bond = 0;
  double widest = 0.0;
  for (int k = 1; k <= steps; ++k) {
    s.dt = stable_time_step(s, c.solver.cfl);
    step(s);
    const Interface m = measure(s);
    if (k % 250 == 0)
      std::printf("t %6.2f ns: bonded points %zu, forming %zu, acting %zu, gap %.3f um\n",
                  s.time * 1e9, m.bonded_points, m.forming, m.acting, m.widest_gap * 1e6);
    ASSERT_GE(m.bonded_points, bonded_before) << "a point lost its bond at step " << k;
    if (bonded_before > 0) {
      ASSERT_GT(m.acting, 0u) << "the bond force stopped acting at step " << k;
      flickers += m.forming == 0;
      widest = std::max(widest, m.widest_gap);
    } else if (m.bonded_points > 0) {
      first_bond = static_cast<std::size_t>(k);
    }
    bonded_before = m.bonded_points;
  }
  std::printf(
      "first bond at step %zu; steps after it with no node at nodal D >= 1: %zu; widest "
      "gap %.3f um (cell %.3f um)\n",
      first_bond, flickers, widest * 1e6, h * 1e6);
  ASSERT_GT(bonded_before, 0u) << "nothing bonded: the test needs a bond";
  EXPECT_LT(widest, 2.0 * h);
  // The case exercises what the kept bond is for: on these steps eq 4.7 alone, recomputed from
  // the points at the node, would have applied no bond force anywhere.
  EXPECT_GT(flickers, 0u);
}

TEST(BondPersistence, AxisymmetricInterfaceHolds) {
  expect_bonds_persist({{"bonding.critical_energy", "100 J/m^2"},
                        {"bonding.critical_energy_rate", "2.8207e5 J/m^2/us"},
                        {"bonding.nodal_average", "count"}},
                       1500);
}

TEST(BondPersistence, ThreeDimensionalInterfaceHolds) {
  expect_bonds_persist({{"solver.geometry", "3d"},
                        {"grid.cell_size", "1 um"},
                        {"grid.min", "[0 um, 0 um, -6 um]"},
                        {"grid.max", "[9 um, 9 um, 9 um]"},
                        {"grid.faces", "{xmin: roller, ymin: roller}"},
                        {"bodies.particle.spacing", "0.25 um"},
                        {"bodies.substrate.spacing", "0.25 um"},
                        {"bonding.critical_energy", "50 J/m^2"},
                        {"bonding.critical_energy_rate", "2.8207e5 J/m^2/us"},
                        {"bonding.nodal_average", "count"}},
                       1000);
}

}  // namespace
}  // namespace coldspray::mpm
