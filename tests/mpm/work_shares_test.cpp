// WorkShares moves contiguous ranges of items towards equal times: checked on synthetic costs
// whose balanced split is known by hand.
#include "mpm/work_shares.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace coldspray::mpm {
namespace {

// Records for each share the summed cost of its items, as a thread's timer would.
void time_shares(WorkShares& w, const std::vector<double>& cost) {
  for (int k = 0; k < w.shares(); ++k) {
    double t = 0.0;
    for (std::size_t i = w.first(k); i < w.first(k + 1); ++i) t += cost[i];
    w.record(k, t);
  }
}

TEST(WorkShares, StartsEvenAndKeepsItsRangesWhilePreparedAlike) {
  WorkShares w;
  w.prepare(3, 10);
  ASSERT_EQ(w.shares(), 3);
  EXPECT_EQ(w.first(0), 0u);
  EXPECT_EQ(w.first(1), 3u);
  EXPECT_EQ(w.first(2), 6u);
  EXPECT_EQ(w.first(3), 10u);
  w.record(0, 3.0);
  w.record(1, 1.0);
  w.record(2, 1.0);
  w.rebalance();
  const std::size_t moved = w.first(1);
  EXPECT_LT(moved, 3u);
  w.prepare(3, 10);  // same shares and items: the balance is kept
  EXPECT_EQ(w.first(1), moved);
  w.prepare(2, 10);  // a new thread count starts even again
  EXPECT_EQ(w.first(1), 5u);
}

// The boundaries after `steps` steps of timing the shares' costs and rebalancing.
std::vector<std::size_t> balanced(const std::vector<double>& cost, int shares, int steps) {
  WorkShares w;
  w.prepare(shares, cost.size());
  for (int step = 0; step < steps; ++step) {
    time_shares(w, cost);
    w.rebalance();
  }
  std::vector<std::size_t> first;
  for (int k = 0; k <= shares; ++k) first.push_back(w.first(k));
  return first;
}

TEST(WorkShares, TwoSharesConvergeToEqualCost) {
  // Items 0-299 cost 3, the rest 1: total 1600, so the balanced boundary is where 800 is reached,
  // at item 800 / 3 = 266.7.
  std::vector<double> cost(1000, 1.0);
  for (int i = 0; i < 300; ++i) cost[i] = 3.0;
  const std::vector<std::size_t> first = balanced(cost, 2, 40);
  EXPECT_EQ(first[0], 0u);
  EXPECT_NEAR(static_cast<double>(first[1]), 266.7, 1.0);
  EXPECT_EQ(first[2], 1000u);
}

TEST(WorkShares, FourSharesOfAStepCostConverge) {
  // Items 0-599 cost 1, 600-999 cost 2: total 1400, 350 per share. The cost reaches 350 at item
  // 350, 700 at 600 + 100 / 2 = 650 and 1050 at 600 + 450 / 2 = 825.
  std::vector<double> cost(1000, 1.0);
  for (int i = 600; i < 1000; ++i) cost[i] = 2.0;
  const std::vector<std::size_t> first = balanced(cost, 4, 60);
  EXPECT_NEAR(static_cast<double>(first[1]), 350.0, 1.0);
  EXPECT_NEAR(static_cast<double>(first[2]), 650.0, 1.0);
  EXPECT_NEAR(static_cast<double>(first[3]), 825.0, 1.0);
}

TEST(WorkShares, WithoutTimesTheRangesStay) {
  WorkShares w;
  w.prepare(2, 8);
  w.rebalance();  // nothing recorded yet
  EXPECT_EQ(w.first(1), 4u);
  w.prepare(1, 8);
  w.record(0, 1.0);
  w.rebalance();
  EXPECT_EQ(w.first(1), 8u);
}

}  // namespace
}  // namespace coldspray::mpm
