// The run's end under solver.stop_when_separated (run/step_rule.hpp): the first free step brings
// it to one verdict window later; a contact before then gives back the end it had; off, nothing
// moves it.
#include "run/step_rule.hpp"

#include <gtest/gtest.h>

namespace coldspray::run {
namespace {

constexpr double kNs = 1e-9;

StepRule hundred_ns(bool stop) {
  case_file::Case c;
  c.solver.end_time = 100.0 * kNs;
  c.solver.stop_when_separated = stop;
  return StepRule(c, /*undeformed_step=*/0.0);
}

TEST(StepRule, SeparationEndsTheRunOneWindowLater) {
  StepRule rule = hundred_ns(true);
  rule.follow_separation(false, 10.0 * kNs);
  EXPECT_DOUBLE_EQ(rule.end, 100.0 * kNs);
  EXPECT_LT(rule.separated_since, 0.0);

  rule.follow_separation(true, 30.0 * kNs);  // free from here: the 20 ns window after it
  EXPECT_DOUBLE_EQ(rule.end, 50.0 * kNs);
  EXPECT_DOUBLE_EQ(rule.separated_since, 30.0 * kNs);
  rule.follow_separation(true, 31.0 * kNs);  // still free: the end stays
  EXPECT_DOUBLE_EQ(rule.end, 50.0 * kNs);

  rule.follow_separation(false, 35.0 * kNs);  // touched again: the case's end is back
  EXPECT_DOUBLE_EQ(rule.end, 100.0 * kNs);
  EXPECT_LT(rule.separated_since, 0.0);

  rule.follow_separation(true, 90.0 * kNs);  // free too late to end before the case's end
  EXPECT_DOUBLE_EQ(rule.end, 100.0 * kNs);
}

TEST(StepRule, WithoutTheKeySeparationMovesNothing) {
  StepRule rule = hundred_ns(false);
  rule.follow_separation(true, 30.0 * kNs);
  EXPECT_DOUBLE_EQ(rule.end, 100.0 * kNs);
  EXPECT_LT(rule.separated_since, 0.0);
}

}  // namespace
}  // namespace coldspray::run
