// The step's force loop that visits each pair of neighbours once (pd/pair_forces.hpp) against
// the plain per-point sums over whole families (force_density, pd/forces.hpp), on the quarter
// Cu-on-Cu impact (plastic flow, contact, ghosts across two symmetry planes) after 60 steps; and
// its schedule: every pair of real points lies within one block or two neighbouring ones, so the
// two colours of blocks never write the same point at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "pd/forces.hpp"
#include "pd/pair_forces.hpp"
#include "pd_example_run.hpp"

namespace coldspray::pd {
namespace {

State quarter_impact(int steps) {
  return testing::run_example("verification/pd-quarter-impact.yaml",
                              {{"symmetry.x", "0 um"}, {"symmetry.y", "0 um"}}, steps);
}

TEST(PeridynamicPairForces, EqualThePerPointSums) {
  State s = quarter_impact(60);
  ASSERT_GT(s.ghosts.size(), 0u);
  pair_forces(s);
  double bonds = 0.0, control = 0.0, largest_bond = 0.0, largest_control = 0.0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const ForceDensity f = force_density(s, i);
    bonds = std::max(bonds, (s.pair_bonds[i].head<3>() - f.bonds).norm());
    control = std::max(control, (s.pair_control[i].head<3>() - f.control).norm());
    largest_bond = std::max(largest_bond, f.bonds.norm());
    largest_control = std::max(largest_control, f.control.norm());
    EXPECT_EQ(s.pair_bonds[i][3], 0.0);
  }
  EXPECT_GT(largest_control, 0.0);
  EXPECT_LT(bonds, 1e-12 * largest_bond);
  EXPECT_LT(control, 1e-12 * largest_control);
}

TEST(PeridynamicPairForces, PairsSpanAtMostTwoNeighbouringBlocks) {
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
