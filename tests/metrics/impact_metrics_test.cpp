// The impact measures counted by hand on a few points: PBCP (eq 5.1), v_rest's 60 m/s filter
// (thesis §5.2.2), ABP, cor, jetting and areas; and the nodal D_bond of eqs 4.6-4.7.
#include "metrics/impact_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "mpm/contact.hpp"

namespace coldspray::metrics {
namespace {

// Six equal points of one 3D body that came down at 800 m/s, set by hand.
bodies::Bodies six_points() {
  bodies::Bodies s;
  s.geometry = case_file::Geometry::ThreeD;
  bodies::Points& P = s.points;
  P.resize(6);
  bodies::BodyRange body;
  body.name = "particle";
  body.begin = 0;
  body.end = 6;
  body.spacing = 1e-6;
  body.initial_velocity = {0.0, 0.0, -800.0};
  body.initial_diameter = 4e-6;
  s.bodies.push_back(body);
  // The body its points bond to, with no points of its own here.
  bodies::BodyRange other;
  other.name = "substrate";
  other.begin = 6;
  other.end = 6;
  other.spacing = 1e-6;
  s.bodies.push_back(other);
  const double x[6] = {-1e-6, 1e-6, 0.0, 0.0, 3e-6, -1.5e-6};
  const double vz[6] = {1.0, 2.0, 0.5, 0.5, 10.0, 0.0};
  const double vx[6] = {0.0, 0.0, 0.0, 0.0, 500.0, 0.0};  // point 4 jets outward
  const double bond[6] = {1.5, 0.4, 0.0, 1.0, 2.0, 0.0};
  const std::uint8_t touched[6] = {1, 1, 1, 1, 1, 0};
  // Points 0 and 4 keep a bond to body 1; point 3 has D_bond = 1 but met no node that bonded.
  const std::uint16_t bonded_to[6] = {2, 0, 0, 0, 2, 0};
  for (std::size_t p = 0; p < 6; ++p) {
    P.mass[p] = 1e-15;
    P.volume0[p] = 1e-18;
    P.J[p] = 1.0;
    P.position[0][p] = x[p];
    P.velocity[0][p] = vx[p];
    P.velocity[2][p] = vz[p];
    P.bond[p] = bond[p];
    P.touched[p] = touched[p];
    P.bonded_to[p] = bonded_to[p];
    P.surface[p] = 1;
  }
  return s;
}

TEST(ImpactMetrics, CountsByHand) {
  const bodies::Bodies s = six_points();
  const ImpactMeasures m = impact_measures(s, 0, SplatExtent::Measured);
  // D_bond > 0 at points 0, 1, 3, 4; >= 1 at 0, 3, 4: 3 of 4.
  EXPECT_NEAR(m.pbcp, 75.0, 1e-12);
  // ABP over the five touched points: (1.5 + 0.4 + 0 + 1 + 2) / 5.
  EXPECT_NEAR(m.abp, 0.98, 1e-12);
  // v_rest leaves out point 4 (|v| = 500.1 m/s): (1 + 2 + 0.5 + 0.5 + 0) / 5.
  EXPECT_NEAR(m.v_rest, 0.8, 1e-12);
  // cor: mean v_z = 14 / 6 against 800 m/s downward, moving away.
  EXPECT_NEAR(m.cor, 14.0 / 6.0 / 800.0, 1e-15);
  // Point 4 is fast and moves away from the axis through the centroid (x = 1.5e-6 / 6).
  EXPECT_NEAR(m.jetted_fraction, 1.0 / 6.0, 1e-15);
  // Five touched points of area (1e-18)^(2/3) = 1e-12 m^2; two keep a bond.
  EXPECT_NEAR(m.contact_area, 5e-12, 1e-24);
  EXPECT_NEAR(m.bonded_area, 2e-12, 1e-24);
  EXPECT_NEAR(m.bonded_area_with[1], 2e-12, 1e-24);  // both to the substrate
  EXPECT_EQ(m.bonded_area_with[0], 0.0);
  EXPECT_TRUE(m.moving);
  // What the verdict follows, from its own pass: the five slow points' mass and z momentum, and
  // the bonded area.
  const RestAndBond r = rest_and_bond(s, 0);
  EXPECT_NEAR(r.rest_mass, 5e-15, 1e-27);
  EXPECT_NEAR(r.rest_momentum_z, 4e-15, 1e-27);
  EXPECT_NEAR(r.bonded_area, 2e-12, 1e-24);
}

// Three bodies bonded by hand, as in the thesis' two-particle impacts (Table 5.5): a top
// particle bonded to the bottom one, the bottom one to both, the substrate to the bottom one.
// Points of equal mass 1e-15 kg and area 1e-12 m^2.
bodies::Bodies three_bodies() {
  bodies::Bodies s;
  s.geometry = case_file::Geometry::ThreeD;
  bodies::Points& P = s.points;
  P.resize(10);
  const char* names[3] = {"top", "bottom", "substrate"};
  const std::size_t begin[4] = {0, 3, 7, 10};
  for (std::size_t b = 0; b < 3; ++b) {
    bodies::BodyRange body;
    body.name = names[b];
    body.begin = begin[b];
    body.end = begin[b + 1];
    body.spacing = 1e-6;
    body.initial_velocity = {0.0, 0.0, b < 2 ? -810.0 : 0.0};
    body.initial_diameter = 14e-6;
    s.bodies.push_back(body);
  }
  // D_bond and the body each point keeps a bond to (1 + its index; 0: none).
  const double bond[10] = {1.2, 0.5, 0.0, 2.0, 1.0, 0.3, 0.0, 1.1, 0.2, 0.0};
  const std::uint16_t bonded_to[10] = {2, 0, 0, 1, 3, 0, 0, 2, 0, 0};
  for (std::size_t p = 0; p < 10; ++p) {
    P.mass[p] = 1e-15;
    P.volume0[p] = 1e-18;
    P.J[p] = 1.0;
    P.position[2][p] = static_cast<double>(p) * 1e-6;
    P.bond[p] = bond[p];
    P.touched[p] = bond[p] > 0.0;
    P.bonded_to[p] = bonded_to[p];
    P.surface[p] = 1;
  }
  return s;
}

TEST(ImpactMetrics, BondedAreaByPartnerAndTheSystemsPbcp) {
  bodies::Bodies s = three_bodies();
  std::vector<ImpactMeasures> m;
  for (std::size_t b = 0; b < 3; ++b) m.push_back(impact_measures(s, b, SplatExtent::Measured));
  // Points of volume 1e-18 m^3 stand for (1e-18)^(2/3) = 1e-12 m^2.
  const double expected[3][3] = {{0.0, 1e-12, 0.0}, {1e-12, 0.0, 1e-12}, {0.0, 1e-12, 0.0}};
  for (std::size_t b = 0; b < 3; ++b) {
    ASSERT_EQ(m[b].bonded_area_with.size(), 3u);
    for (std::size_t o = 0; o < 3; ++o)
      EXPECT_NEAR(m[b].bonded_area_with[o], expected[b][o], 1e-24) << b << " with " << o;
  }
  // Eq 5.1 per body: 1 of 2, 2 of 3 and 1 of 2 contacted points bonded; over the system 4 of 7.
  EXPECT_NEAR(m[0].pbcp, 50.0, 1e-12);
  EXPECT_NEAR(m[1].pbcp, 200.0 / 3.0, 1e-12);
  EXPECT_NEAR(m[2].pbcp, 50.0, 1e-12);
  EXPECT_NEAR(system_pbcp(m), 400.0 / 7.0, 1e-12);
  // A body cut at a symmetry plane counts twice its points: the substrate's 1 of 2 become 2 of 4,
  // so the system has 5 of 9.
  s.bodies[2].mirror_plane[0] = 0.0;
  m[2] = impact_measures(s, 2, SplatExtent::Measured);
  EXPECT_NEAR(m[2].bonded_area_with[1], 2e-12, 1e-24);
  EXPECT_NEAR(system_pbcp(m), 500.0 / 9.0, 1e-12);
  EXPECT_EQ(system_pbcp({}), 0.0);
}

// Points that left the grid (mpm/departures.hpp) count as jetted; the rest of the measures are
// of the points on the grid.
TEST(ImpactMetrics, PointsThatLeftTheGridCountAsJetted) {
  bodies::Bodies s = six_points();
  s.bodies[0].departed.points = 2;
  s.bodies[0].departed.mass = 2e-15;
  const ImpactMeasures m = impact_measures(s, 0, SplatExtent::Measured);
  // Point 4 and the two departed points, of 6 + 2 points of 1e-15 kg.
  EXPECT_NEAR(m.jetted_fraction, 3.0 / 8.0, 1e-15);
  EXPECT_NEAR(m.v_rest, 0.8, 1e-12);
  EXPECT_NEAR(m.cor, 14.0 / 6.0 / 800.0, 1e-15);
  EXPECT_NEAR(m.pbcp, 75.0, 1e-12);
}

// A rebound is not a jet: the same points moving up at 100 m/s more, two of them spreading
// outward at 1 m/s, have only point 4 jetting (relative to the body's mean z velocity).
TEST(ImpactMetrics, AReboundIsNotAJet) {
  bodies::Bodies s = six_points();
  for (std::size_t p = 0; p < 6; ++p) s.points.velocity[2][p] += 100.0;
  s.points.velocity[0][0] = -1.0;  // x = -1 um, left of the axis at x = 0.25 um: outward
  s.points.velocity[0][1] = 1.0;   // x = 1 um: outward
  const ImpactMeasures m = impact_measures(s, 0, SplatExtent::Measured);
  EXPECT_NEAR(m.jetted_fraction, 1.0 / 6.0, 1e-15);
}

TEST(ImpactMetrics, ABodyAtRestHasNoRestitution) {
  bodies::Bodies s = six_points();
  s.bodies[0].initial_velocity = {0.0, 0.0, 0.0};
  const ImpactMeasures m = impact_measures(s, 0, SplatExtent::Measured);
  EXPECT_TRUE(std::isnan(m.cor));
  EXPECT_FALSE(m.moving);
}

// A quarter model (cut at x = 0 and y = 0): the axis is the planes' intersection, not the
// quarter's centroid, and areas count four times.
TEST(ImpactMetrics, AQuarterModelMeasuresTheWholeBody) {
  bodies::Bodies s = six_points();
  s.bodies[0].mirror_plane = {0.0, 0.0};
  const ImpactMeasures m = impact_measures(s, 0, SplatExtent::Measured);
  EXPECT_NEAR(m.contact_area, 4 * 5e-12, 1e-24);
  EXPECT_NEAR(m.bonded_area, 4 * 2e-12, 1e-24);
  // Non-jetted points reach |x| = 1.5 um from the axis x = 0: (2 * 1.5 + 1) / 4 um. About the
  // centroid (x = 0.25 um) it would be (2 * 1.75 + 1) / 4.
  EXPECT_NEAR(m.flattening_ratio, 1.0, 1e-12);
  EXPECT_NEAR(m.jetted_fraction, 1.0 / 6.0, 1e-15);
  // r-z: the ring already is the whole body.
  s.geometry = case_file::Geometry::Axisymmetric;
  s.bodies[0].mirror_plane = {0.0, std::nullopt};
  for (std::size_t p = 0; p < 6; ++p) s.points.position[0][p] = std::abs(s.points.position[0][p]);
  EXPECT_NEAR(impact_measures(s, 0, SplatExtent::Measured).flattening_ratio, 1.0, 1e-12);
}

// A drop the body shed far out (point 5, at rest, moved from x = -1.5 um to -10 um, 9 um from
// the nearest point: beyond the 3 um link, bodies/splat_piece.hpp) is not part of the splat: the
// non-jetted splat points reach |x| = 1 um from the quarter model's axis, (2 * 1 + 1) / 4 um,
// where the drop would give (2 * 10 + 1) / 4. Skipped, the extent is not measured.
TEST(ImpactMetrics, TheFlatteningRatioLeavesOutShedDrops) {
  bodies::Bodies s = six_points();
  s.bodies[0].mirror_plane = {0.0, 0.0};
  s.points.position[0][5] = -10e-6;
  EXPECT_NEAR(impact_measures(s, 0, SplatExtent::Measured).flattening_ratio, 0.75, 1e-12);
  EXPECT_TRUE(std::isnan(impact_measures(s, 0, SplatExtent::Skipped).flattening_ratio));
}

// Eq 4.6 per body: sum D N / n_sp; eq 4.7: the mean of the two bodies.
TEST(NodalBond, AveragesEachBodyThenThePair) {
  mpm::ContactNodes c;
  const std::int32_t slot = c.add(7);
  const int a = c.entry(slot, 0), b = c.entry(slot, 1);
  c.bond_sum[mpm::ContactNodes::flat(slot, a)] = 1.2;  // e.g. 2.0 * 0.6
  c.surface_count[mpm::ContactNodes::flat(slot, a)] = 2;
  c.bond_sum[mpm::ContactNodes::flat(slot, b)] = 0.9;
  c.surface_count[mpm::ContactNodes::flat(slot, b)] = 3;
  EXPECT_NEAR(mpm::nodal_bond(c, slot, a, b, case_file::NodalAverage::Count), 0.5 * (0.6 + 0.3),
              1e-15);
  EXPECT_FALSE(mpm::bond_forms(mpm::nodal_bond(c, slot, a, b, case_file::NodalAverage::Count)));
  c.bond_sum[mpm::ContactNodes::flat(slot, a)] = 3.4;  // 1.7 and 0.3: the mean is 1
  EXPECT_TRUE(mpm::bond_forms(mpm::nodal_bond(c, slot, a, b, case_file::NodalAverage::Count)));
  // A body with no surface point at the node contributes 0.
  c.surface_count[mpm::ContactNodes::flat(slot, b)] = 0;
  EXPECT_NEAR(mpm::nodal_bond(c, slot, a, b, case_file::NodalAverage::Count), 0.85, 1e-15);
}

// Weight-normalised: sum D N / sum N, the partition-of-unity mean. Two points of body a with
// N = 0.6 and 0.2 and D = 1.5 and 0.5: (0.9 + 0.1) / 0.8 = 1.25 (by count: 1.0 / 2 = 0.5); one of
// body b with N = 0.25 and D = 0.4: 0.1 / 0.25 = 0.4 (by count 0.1). The pair: 0.825 against 0.3.
TEST(NodalBond, WeightNormalisedAverageDividesBySumOfWeights) {
  mpm::ContactNodes c;
  const std::int32_t slot = c.add(3);
  const int a = c.entry(slot, 0), b = c.entry(slot, 1);
  const std::size_t fa = mpm::ContactNodes::flat(slot, a), fb = mpm::ContactNodes::flat(slot, b);
  c.bond_sum[fa] = 1.5 * 0.6 + 0.5 * 0.2;
  c.surface_count[fa] = 2;
  c.surface_weight[fa] = 0.8;
  c.bond_sum[fb] = 0.4 * 0.25;
  c.surface_count[fb] = 1;
  c.surface_weight[fb] = 0.25;
  EXPECT_NEAR(mpm::nodal_bond(c, slot, a, b, case_file::NodalAverage::Weight), 0.825, 1e-15);
  EXPECT_NEAR(mpm::nodal_bond(c, slot, a, b, case_file::NodalAverage::Count), 0.3, 1e-15);
}

// A kept bond holds at a node only where bonded points of both bodies reach it.
TEST(KeptBond, HoldsWhereBondedPointsOfBothSidesMeet) {
  using mpm::ContactNodes;
  EXPECT_FALSE(mpm::bond_holds(0));
  EXPECT_FALSE(mpm::bond_holds(ContactNodes::kLowerSide));
  EXPECT_FALSE(mpm::bond_holds(ContactNodes::kHigherSide));
  EXPECT_TRUE(mpm::bond_holds(ContactNodes::kLowerSide | ContactNodes::kHigherSide));
}

}  // namespace
}  // namespace coldspray::metrics
