// The step's force loop that visits each pair of neighbours once (pd/pair_forces.hpp) against
// the plain per-point sums over whole families (force_density, pd/forces.hpp), on the quarter
// Cu-on-Cu impact (plastic flow, contact, ghosts across two symmetry planes) after 60 steps; and
// its schedule: every pair of real points lies within one block or two neighbouring ones, so the
// two colours of blocks never write the same point at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "pd/control_along_flow.hpp"
#include "pd/deformation.hpp"
#include "pd/forces.hpp"
#include "pd/pair_forces.hpp"
#include "pd_example_run.hpp"

namespace coldspray::pd {
namespace {

State quarter_impact(int steps, const std::string& control_stiffness = "elastic") {
  return testing::run_example("verification/pd-quarter-impact.yaml",
                              {{"symmetry.x", "0 um"},
                               {"symmetry.y", "0 um"},
                               {"peridynamics.control_stiffness", control_stiffness}},
                              steps);
}

class PeridynamicPairForces : public ::testing::TestWithParam<std::string> {};

// With the elastic control and with the control softened along the flow (whose projections
// differ from point to point and from one end of a bond to the other).
TEST_P(PeridynamicPairForces, EqualThePerPointSums) {
  State s = quarter_impact(60, GetParam());
  ASSERT_GT(s.ghosts.size(), 0u);
  if (GetParam() == "flow") {
    ASSERT_GT(std::count_if(s.flow_softening.begin(), s.flow_softening.end(),
                            [](double a) { return a > 0.0; }),
              100);
  }
  // The per-point sums on the state before the pair loop, which advances the pairs' penalty
  // displacements, with the slip fits the pair loop finds (their own test is below).
  State before = s;
  pair_forces(s);
  before.slip_fit = s.slip_fit;
  std::vector<ForceDensity> reference;
  for (std::size_t i = 0; i < s.points.size(); ++i) reference.push_back(force_density(before, i));
  double bonds = 0.0, control = 0.0, largest_bond = 0.0, largest_control = 0.0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const ForceDensity& f = reference[i];
    bonds = std::max(bonds, (s.pair_bonds[i].head<3>() - f.bonds).norm());
    control = std::max(control, (s.pair_control[i].head<3>() - f.control_rate).norm());
    largest_bond = std::max(largest_bond, f.bonds.norm());
    largest_control = std::max(largest_control, f.control_rate.norm());
    EXPECT_EQ(s.pair_bonds[i][3], 0.0);
  }
  EXPECT_GT(largest_control, 0.0);
  EXPECT_LT(bonds, 1e-12 * largest_bond);
  EXPECT_LT(control, 1e-12 * largest_control);
}

// With the control along the flow, the pair loop's slip fits D (pd/pair_forces.cpp) against the
// fit of half the pairs' slip rates summed over each whole family: D_i = [sum omega beta V_j
// (slip_ij / 2) (x) q(xi)] M_i^-1, slip_ij the parts of zdot_i and zdot_j the ends' flow softens.
TEST(PeridynamicPairForcesAlongFlow, SlipFitsAreTheFitsOfHalfTheSlipRates) {
  State s = quarter_impact(60, "flow");
  const State before = s;
  pair_forces(s);
  const Neighbours& N = before.neighbours;
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < N.real; ++i) {
    const BondWeights weights = bond_weights(before, N.body[i]);
    QuadraticMap sum = QuadraticMap::Zero();
    for_each_bond(
        before.families, N, weights, i,
        [&](std::size_t bond, std::size_t j, const Eigen::Vector3d& xi, double, double w) {
          const Monomials q = monomials(xi, weights.delta);
          const Eigen::Vector4d V = N.velocity[j] - N.velocity[i];
          const Eigen::Vector4d Y = N.position[j] - N.position[i];
          const Eigen::Vector4d e = control_displacement(before, i, j, bond);
          const Eigen::Vector4d zdot_i = V - before.velocity_fit[i] * q;
          const Eigen::Vector4d zdot_j = V + before.velocity_fit[j] * reversed(q);
          const Eigen::Vector4d slip =
              softened_part(before.flow_direction[i], before.flow_softening[i], Y, zdot_i, e) +
              softened_part(before.flow_direction[j], before.flow_softening[j], Y, zdot_j, e);
          sum += (0.5 * w) * slip * q.transpose();
        });
    const QuadraticMap D = sum * before.moment_inverse[i];
    worst = std::max(worst, (D - s.slip_fit[i]).norm());
    largest = std::max(largest, D.norm());
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(worst, 1e-12 * largest);
}

INSTANTIATE_TEST_SUITE_P(ControlStiffness, PeridynamicPairForces,
                         ::testing::Values("elastic", "flow"));

TEST(PeridynamicPairSchedule, PairsSpanAtMostTwoNeighbouringBlocks) {
  const State s = quarter_impact(0);
  const PairSchedule& p = s.pairs;
  ASSERT_GE(p.block.size(), 5u);  // at least four blocks: both colours run side by side
  auto block_of = [&](std::size_t i) {
    return std::upper_bound(p.block.begin(), p.block.end(), i) - p.block.begin() - 1;
  };
  for (std::size_t i = 0; i < s.neighbours.real; ++i)
    for (std::size_t b = s.families.begin[i]; b < s.families.begin[i + 1]; ++b) {
      const std::size_t j = s.families.neighbour[b];
      EXPECT_EQ(b >= p.first_pair[i], j > i);
      if (j > i && j < s.neighbours.real) {
        const auto span = block_of(j) - block_of(i);
        ASSERT_TRUE(span == 0 || span == 1) << i << " " << j;
      }
    }
}

}  // namespace
}  // namespace coldspray::pd
