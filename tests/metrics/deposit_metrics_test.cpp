// The deposit's measures (metrics/deposit_metrics.hpp) counted by hand: porosity and thickness
// of a known voxel pattern, the voxelisation of a lattice of points, deposition efficiency.
#include "metrics/deposit_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::metrics {
namespace {

constexpr std::uint8_t kS = DepositVoxels::kSubstrate, kD = DepositVoxels::kDeposit;

// Four columns of five voxels of 1 um from z = -1 um, each written bottom to top:
//   column (0,0): S . D D .   envelope from z-index 1 to 3: 1 void of 3
//   column (1,0): S D D . D   envelope 1..4: 1 void of 4
//   column (0,1): S . . . .   no deposit
//   column (1,1): S S . . D   envelope 2..4: 2 voids of 3
DepositVoxels four_columns() {
  DepositVoxels v;
  v.origin = {0.0, 0.0, -1e-6};
  v.edge = 1e-6;
  v.count = {2, 2, 5};
  v.mark.assign(20, 0);
  const std::uint8_t columns[4][5] = {
      {kS, 0, kD, kD, 0}, {kS, kD, kD, 0, kD}, {kS, 0, 0, 0, 0}, {kS, kS, 0, 0, kD}};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 5; ++k) v.mark[v.index(c % 2, c / 2, k)] = columns[c][k];
  return v;
}

TEST(DepositMetrics, PorosityAndThicknessOfAKnownVoxelPattern) {
  const DepositShape shape = deposit_shape(four_columns(), 0.0);
  EXPECT_DOUBLE_EQ(shape.porosity, 4.0 / 10.0);
  // Tops: index 3 -> z = -1 + 4 = 3 um; index 4 -> 4 um (twice); none -> 0.
  EXPECT_NEAR(shape.thickness[0], 3e-6, 1e-18);
  EXPECT_NEAR(shape.thickness[1], 4e-6, 1e-18);
  EXPECT_EQ(shape.thickness[2], 0.0);
  EXPECT_NEAR(shape.thickness[3], 4e-6, 1e-18);
  EXPECT_NEAR(shape.mean_thickness, 11e-6 / 4.0, 1e-18);
  EXPECT_NEAR(shape.max_thickness, 4e-6, 1e-18);
  EXPECT_DOUBLE_EQ(shape.coverage, 0.75);
  EXPECT_EQ(shape.columns, (std::array<int, 2>{2, 2}));
}

// A deposit block of 4 x 4 x 3 points of spacing 1 um on a substrate block of 4 x 4 x 2, both
// lattices on whole micrometres so that one voxel per point tiles them: no pore. Removing one
// deposit point leaves one void in 3 x 16 envelope voxels; a deposit point jetting at 100 m/s
// counts as gone; points outside the 4 um patch are not voxelised.
bodies::Bodies blocks(int missing, bool jet) {
  bodies::Bodies s;
  bodies::Points& P = s.points;
  const int per_layer = 16;
  P.resize(static_cast<std::size_t>(per_layer * 5 + 1));
  std::size_t p = 0;
  auto add = [&](double x, double y, double z) {
    P.position[0][p] = x;
    P.position[1][p] = y;
    P.position[2][p] = z;
    P.initial_z[p] = z;
    for (int d = 0; d < 3; ++d) P.half_width[d][p] = 0.5e-6;
    ++p;
  };
  bodies::BodyRange deposit, substrate;
  deposit.name = "particle";
  deposit.spacing = substrate.spacing = 1e-6;
  deposit.begin = 0;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) add((i - 1.5) * 1e-6, (j - 1.5) * 1e-6, (k + 0.5) * 1e-6);
  add(8e-6, 0.0, 0.5e-6);  // outside the patch: not voxelised
  deposit.end = p;
  substrate.name = "substrate";
  substrate.begin = p;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) add((i - 1.5) * 1e-6, (j - 1.5) * 1e-6, -(k + 0.5) * 1e-6);
  substrate.end = p;
  s.bodies = {deposit, substrate};
  if (missing >= 0) P.position[2][missing] = 1.0;  // far above, and fast: see below
  if (missing >= 0) P.velocity[2][missing] = 1000.0;
  if (jet) P.velocity[0][40] = 100.0;  // a top-layer point
  return s;
}

TEST(DepositMetrics, VoxelisesALatticeOfPointsWithoutPores) {
  const bodies::Bodies s = blocks(-1, false);
  const DepositVoxels v = voxelise_deposit(s, {true, false}, 1, {4e-6, 4e-6}, 1e-6, 60.0, 0.0);
  EXPECT_EQ(v.count[0], 4);
  EXPECT_EQ(v.count[1], 4);
  // From the substrate's top layer's bottom (-1 um) to the deposit's top (3 um).
  EXPECT_NEAR(v.origin[2], -1e-6, 1e-18);
  EXPECT_EQ(v.count[2], 4);
  const DepositShape shape = deposit_shape(v, 0.0);
  EXPECT_EQ(shape.porosity, 0.0);
  EXPECT_NEAR(shape.mean_thickness, 3e-6, 1e-15);
  EXPECT_DOUBLE_EQ(shape.coverage, 1.0);
}

TEST(DepositMetrics, AMissingPointIsAPoreAndAJetIsNotDeposit) {
  // Point 5: (i, j, k) = (1, 1, 0), in the bottom deposit layer: a void between deposit above
  // it and the substrate below.
  const DepositShape one_pore = deposit_shape(
      voxelise_deposit(blocks(5, false), {true, false}, 1, {4e-6, 4e-6}, 1e-6, 60.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(one_pore.porosity, 1.0 / 48.0);
  // Point 40: (0, 2, 2), in the top layer: its column's top drops to 2 um, no pore.
  const DepositShape jet = deposit_shape(
      voxelise_deposit(blocks(-1, true), {true, false}, 1, {4e-6, 4e-6}, 1e-6, 60.0, 0.0), 0.0);
  EXPECT_EQ(jet.porosity, 0.0);
  EXPECT_NEAR(jet.thickness[8], 2e-6, 1e-15);
  EXPECT_NEAR(jet.mean_thickness, (15 * 3e-6 + 2e-6) / 16.0, 1e-15);
  // A body that is not deposit (it rebounded) adds nothing.
  const DepositShape none = deposit_shape(
      voxelise_deposit(blocks(-1, false), {false, false}, 1, {4e-6, 4e-6}, 1e-6, 60.0, 0.0), 0.0);
  EXPECT_EQ(none.coverage, 0.0);
  EXPECT_EQ(none.mean_thickness, 0.0);
}

TEST(DepositMetrics, DepositionEfficiencyIsTheBondedShareOfTheSprayedMass) {
  EXPECT_DOUBLE_EQ(deposition_efficiency({1.0, 2.0, 3.0, 4.0}, {true, false, true, false}), 0.4);
  EXPECT_EQ(deposition_efficiency({}, {}), 0.0);
}

}  // namespace
}  // namespace coldspray::metrics
