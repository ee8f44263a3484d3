// Threshold search on synthetic predicates: evaluation counts, bracketing outside the initial
// range, floors and ceilings, the cache, and non-monotone results.
#include "studies/bisection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace coldspray::studies {
namespace {

constexpr double kThreshold = 783.4;

// "An impact at v bonds", counting its calls.
struct Bonds {
  int calls = 0;
  bool operator()(double v) {
    ++calls;
    return v >= kThreshold;
  }
};

void expect_brackets_threshold(const ThresholdResult& r, double tol) {
  ASSERT_EQ(r.status, ThresholdStatus::Found) << r.message;
  EXPECT_TRUE(r.found());
  EXPECT_LE(r.upper - r.lower, tol);
  EXPECT_LT(r.lower, kThreshold);
  EXPECT_GE(r.upper, kThreshold);
  EXPECT_EQ(r.threshold, r.upper);
}

// [500, 1000] brackets 783.4: 2 ends, then ceil(log2(500 / 1)) = 9 halvings to width <= 1.
TEST(StudiesBisection, FindsASyntheticThresholdWithinTol) {
  Bonds p;
  const ThresholdResult r = find_threshold(std::ref(p), 500.0, 1000.0, 1.0, 40);
  expect_brackets_threshold(r, 1.0);
  EXPECT_EQ(r.evaluations.size(), 11u);
  EXPECT_EQ(r.predicate_calls, 11);
  EXPECT_EQ(p.calls, 11);
  EXPECT_EQ(r.evaluations[0].value, 500.0);
  EXPECT_FALSE(r.evaluations[0].result);
  EXPECT_EQ(r.evaluations[1].value, 1000.0);
  EXPECT_TRUE(r.evaluations[1].result);
  EXPECT_EQ(r.evaluations[2].value, 750.0);
  EXPECT_EQ(r.evaluations[3].value, 875.0);
  // 750 F, 875 T, 812.5 T, 781.25 F, 796.875 T, 789.0625 T, 785.15625 T, 783.203125 F,
  // 784.1796875 T.
  EXPECT_EQ(r.upper, 784.1796875);
  EXPECT_EQ(r.lower, 783.203125);
}

// Both ends false: step up by 200 to 500, 700, 900 (true), then 8 halvings of [700, 900].
TEST(StudiesBisection, StepsUpWhenTheRangeIsBelowTheThreshold) {
  Bonds p;
  const ThresholdResult r = find_threshold(std::ref(p), 100.0, 300.0, 1.0, 40);
  expect_brackets_threshold(r, 1.0);
  EXPECT_EQ(r.evaluations[2].value, 500.0);
  EXPECT_EQ(r.evaluations[4].value, 900.0);
  EXPECT_EQ(r.predicate_calls, 2 + 3 + 8);
}

// Both ends true: step down by 100 to 800, 700 (false), then 7 halvings of [700, 800].
TEST(StudiesBisection, StepsDownWhenTheRangeIsAboveTheThreshold) {
  Bonds p;
  const ThresholdResult r = find_threshold(std::ref(p), 900.0, 1000.0, 1.0, 40);
  expect_brackets_threshold(r, 1.0);
  EXPECT_EQ(r.evaluations[3].value, 700.0);
  EXPECT_EQ(r.predicate_calls, 2 + 2 + 7);
}

TEST(StudiesBisection, ReportsNoBracketAtTheFloorOrCeiling) {
  ThresholdLimits limits;
  limits.floor = 0.0;
  limits.ceiling = 1200.0;
  const ThresholdResult all_true =
      find_threshold([](double) { return true; }, 300.0, 500.0, 1.0, 40, nullptr, limits);
  EXPECT_EQ(all_true.status, ThresholdStatus::NotBracketed);
  EXPECT_EQ(all_true.predicate_calls, 4);  // 300, 500, 100, 0
  EXPECT_EQ(all_true.evaluations.back().value, 0.0);
  EXPECT_EQ(all_true.threshold, 0.0);  // the lowest true seen
  EXPECT_TRUE(std::isnan(all_true.lower));

  const ThresholdResult all_false =
      find_threshold([](double) { return false; }, 300.0, 500.0, 1.0, 40, nullptr, limits);
  EXPECT_EQ(all_false.status, ThresholdStatus::NotBracketed);
  EXPECT_EQ(all_false.evaluations.back().value, 1200.0);  // 700, 900, 1100, then the ceiling
  EXPECT_EQ(all_false.predicate_calls, 6);
  EXPECT_TRUE(std::isnan(all_false.threshold));

  // Without limits the budget ends the stepping.
  const ThresholdResult budget = find_threshold([](double) { return false; }, 0.0, 1.0, 0.1, 5);
  EXPECT_EQ(budget.status, ThresholdStatus::NotBracketed);
  EXPECT_EQ(budget.predicate_calls, 5);
}

TEST(StudiesBisection, StopsAtTheEvaluationLimitWithTheBracket) {
  Bonds p;
  const ThresholdResult r = find_threshold(std::ref(p), 500.0, 1000.0, 1.0, 6);
  EXPECT_EQ(r.status, ThresholdStatus::EvaluationLimit);
  EXPECT_EQ(p.calls, 6);
  EXPECT_LT(r.lower, kThreshold);
  EXPECT_GE(r.upper, kThreshold);
  EXPECT_NEAR(r.upper - r.lower, 500.0 / 16.0, 1e-12);
}

TEST(StudiesBisection, ReusesCachedResults) {
  Bonds p;
  ThresholdCache cache;
  const ThresholdResult first = find_threshold(std::ref(p), 500.0, 1000.0, 1.0, 40, &cache);
  EXPECT_EQ(cache.size(), 11u);
  // The same search again: no simulation at all, the same answer.
  const ThresholdResult again = find_threshold(std::ref(p), 500.0, 1000.0, 1.0, 40, &cache);
  EXPECT_EQ(p.calls, 11);
  EXPECT_EQ(again.predicate_calls, 0);
  EXPECT_EQ(again.evaluations.size(), 11u);
  for (const ThresholdEvaluation& e : again.evaluations) EXPECT_TRUE(e.cached);
  EXPECT_EQ(again.threshold, first.threshold);
  // A finer tolerance evaluates only the 3 new halvings; values within 1e-9 relative match.
  const ThresholdResult finer =
      find_threshold(std::ref(p), 500.0 * (1.0 + 1e-12), 1000.0, 0.15, 40, &cache);
  expect_brackets_threshold(finer, 0.15);
  EXPECT_EQ(finer.predicate_calls, 3);
  EXPECT_EQ(finer.evaluations[0].value, 500.0);  // recorded at the stored value
  EXPECT_TRUE(finer.evaluations[0].cached);
  EXPECT_EQ(p.calls, 14);

  EXPECT_TRUE(cache.find(750.0 * (1.0 + 5e-10)).has_value());
  EXPECT_FALSE(cache.find(750.0 * (1.0 + 5e-9)).has_value());
}

TEST(StudiesBisection, ReportsATrueBelowAFalse) {
  // Bonds at the low end but not at the high end.
  const ThresholdResult r =
      find_threshold([](double v) { return v < 600.0; }, 500.0, 1000.0, 1.0, 40);
  EXPECT_EQ(r.status, ThresholdStatus::NonMonotone);
  ASSERT_TRUE(r.conflict.has_value());
  EXPECT_EQ(r.conflict->first, 500.0);
  EXPECT_EQ(r.conflict->second, 1000.0);
  EXPECT_EQ(r.predicate_calls, 2);
  EXPECT_FALSE(r.message.empty());
}

TEST(StudiesBisection, ReportsAConflictWithCachedResults) {
  // Bonds from 783.4 but rebounds in (890, 910): the first search never samples the window.
  auto noisy = [](double v) { return v >= kThreshold && !(v > 890.0 && v < 910.0); };
  ThresholdCache cache;
  EXPECT_TRUE(find_threshold(noisy, 500.0, 1000.0, 1.0, 40, &cache).found());
  // A second search from 895 sees a rebound above velocities known to bond.
  const ThresholdResult r = find_threshold(noisy, 895.0, 1000.0, 1.0, 40, &cache);
  EXPECT_EQ(r.status, ThresholdStatus::NonMonotone);
  ASSERT_TRUE(r.conflict.has_value());
  EXPECT_EQ(r.conflict->first, 784.1796875);
  EXPECT_EQ(r.conflict->second, 895.0);
  EXPECT_EQ(r.predicate_calls, 1);
}

// A guide that knows where the threshold is cuts at it, kept 0.4 tol inside the bracket:
// 500, 1000, then 783.4 (T) and 783.4 - 0.4 (F): width 0.4 <= 1 in 4 evaluations, against 11.
TEST(StudiesBisection, AGuideCutsAtItsGuess) {
  Bonds p;
  auto exact = [](double, double) { return kThreshold; };
  const ThresholdResult r = find_threshold(std::ref(p), 500.0, 1000.0, 1.0, 40, nullptr, {}, exact);
  expect_brackets_threshold(r, 1.0);
  EXPECT_EQ(r.predicate_calls, 4);
  EXPECT_EQ(r.evaluations[2].value, kThreshold);
  EXPECT_DOUBLE_EQ(r.evaluations[3].value, kThreshold - 0.4);
}

// A guide stuck at the bracket's low end would creep up by 0.4 tol a cut: after two cuts that
// kept more than half the bracket, a midpoint cut, so at most three evaluations halve it (here 15
// in all against bisection's 11; without the safeguard the creep would take over 700).
TEST(StudiesBisection, AMidpointCutFollowsTwoSlowGuidedCuts) {
  Bonds p;
  auto creeping = [](double lo, double) { return lo; };
  const ThresholdResult r =
      find_threshold(std::ref(p), 500.0, 1000.0, 1.0, 60, nullptr, {}, creeping);
  expect_brackets_threshold(r, 1.0);
  EXPECT_EQ(r.predicate_calls, 15);
  // No guess (NaN): the midpoint, as without a guide.
  Bonds q;
  auto none = [](double, double) { return std::nan(""); };
  EXPECT_EQ(find_threshold(std::ref(q), 500.0, 1000.0, 1.0, 40, nullptr, {}, none).predicate_calls,
            11);
}

TEST(StudiesBisection, RejectsBadArguments) {
  auto p = [](double v) { return v > 1.0; };
  EXPECT_THROW(find_threshold(p, 2.0, 1.0, 0.1, 10), std::invalid_argument);
  EXPECT_THROW(find_threshold(p, 0.0, 2.0, 0.0, 10), std::invalid_argument);
  EXPECT_THROW(find_threshold(p, 0.0, 2.0, 0.1, 1), std::invalid_argument);
  EXPECT_THROW(find_threshold(p, 0.0, 2.0, 0.1, 10, nullptr, {1.0, 5.0}), std::invalid_argument);
  EXPECT_EQ(to_string(ThresholdStatus::NonMonotone), "non-monotone");
}

}  // namespace
}  // namespace coldspray::studies
