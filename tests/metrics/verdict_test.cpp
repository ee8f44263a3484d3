// The verdict on synthetic series sampled every 0.1 ns, against means worked out by hand: a
// stuck body that rings, one that leaves, one still slowing down, one whose bond lets go, a run
// shorter than the window.
#include "metrics/verdict.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace coldspray::metrics {
namespace {

constexpr double kNs = 1e-9;

// Samples (t, v(t), area(t)) every 0.1 ns from `from` to `to` ns, both included.
std::vector<VerdictSample> sampled(double from, double to, const std::function<double(double)>& v,
                                   const std::function<double(double)>& area) {
  std::vector<VerdictSample> series;
  const int n = static_cast<int>(std::lround((to - from) / 0.1));
  for (int i = 0; i <= n; ++i) {
    const double t = (from + 0.1 * i) * kNs;
    series.push_back({t, v(t), area(t)});
  }
  return series;
}

const auto kHeld = [](double) { return 1e-10; };  // 100 um^2 of bonded area throughout
constexpr VerdictRule kRule{20.0 * kNs, 2.0};     // the defaults: 20 ns, 2 m/s

// A stuck body ringing at +-4 m/s with a 12 ns period, v = 4 sin(2 pi t / 12 ns), read over the
// last 20 ns of 80. Over [t1, t2] its mean is 4 (cos w t1 - cos w t2) / (w (t2 - t1)): with
// w t = 10 pi, 35 pi / 3 and 40 pi / 3 at 60, 70 and 80 ns (cosines 1, 1/2, -1/2),
// the window's mean is 4 * 1.5 / (10 pi / 3) = 1.8 / pi = 0.5730 m/s, its halves' 4 * 0.5 /
// (5 pi / 3) = 0.3820 and 4 * 1 / (5 pi / 3) = 0.7639 m/s.
TEST(Verdict, ARingingStuckBodyIsBonded) {
  const double w = 2.0 * std::numbers::pi / (12.0 * kNs);
  const auto series = sampled(
      0.0, 80.0, [w](double t) { return 4.0 * std::sin(w * t); }, kHeld);
  const Verdict v = decide(series, kRule);
  EXPECT_EQ(v.outcome, Outcome::Bonded);
  EXPECT_NEAR(v.separation_speed, 1.8 / std::numbers::pi, 2e-4);  // trapezoids of 0.1 ns
  EXPECT_NEAR(v.margin, 2.0 - 1.8 / std::numbers::pi, 2e-4);
  EXPECT_NEAR(v.settling, 1.2 / std::numbers::pi, 2e-4);
  EXPECT_NEAR(v.window, 20.0 * kNs, 1e-15);
  EXPECT_EQ(v.bonded_area, 1e-10);
  // An instantaneous rule decides by phase: at 80 ns the body moves at 4 sin(4 pi / 3) m/s.
  EXPECT_NEAR(series.back().separation_velocity, -2.0 * std::sqrt(3.0), 1e-9);
}

// A body leaving at a steady 20 m/s as its bonded area falls (from 1e-10 to 0.5e-10 m^2): mean
// 20, margin 2 - 20 = -18 m/s, settled, rebounded. Had its area held, the kept bond would still
// hold it: undecided.
TEST(Verdict, ABodyLeavingSteadilyRebounds) {
  const auto falling = [](double t) { return 1e-10 * (1.0 - 0.5 * (t / kNs - 50.0) / 30.0); };
  const auto series = sampled(
      50.0, 80.0, [](double) { return 20.0; }, falling);
  const Verdict v = decide(series, kRule);
  EXPECT_EQ(v.outcome, Outcome::Rebounded);
  EXPECT_EQ(decide(sampled(
                       50.0, 80.0, [](double) { return 20.0; }, kHeld),
                   kRule)
                .outcome,
            Outcome::Undecided);
  EXPECT_NEAR(v.separation_speed, 20.0, 1e-12);
  EXPECT_NEAR(v.margin, -18.0, 1e-12);
  EXPECT_NEAR(v.settling, 0.0, 1e-12);
}

// Slowing down through the window, v = 10 - (t - 60 ns) m/s/ns: mean 0 over [60, 80] ns, but
// the halves' means are +5 and -5 m/s, 10 apart: not settled, whatever the mean says.
TEST(Verdict, ABodyStillSlowingDownIsUndecided) {
  const auto series = sampled(
      40.0, 80.0, [](double t) { return 10.0 - (t / kNs - 60.0); }, kHeld);
  const Verdict v = decide(series, kRule);
  EXPECT_EQ(v.outcome, Outcome::Undecided);
  EXPECT_NEAR(v.separation_speed, 0.0, 1e-9);
  EXPECT_NEAR(v.margin, 2.0, 1e-9);
  EXPECT_NEAR(v.settling, -10.0, 1e-9);
  // Half as steep, the halves differ by 5 m/s: still undecided; a tenth as steep, by 1 m/s:
  // settled at mean 0, bonded.
  auto slope = [](double k) { return [k](double t) { return k * (10.0 - (t / kNs - 60.0)); }; };
  EXPECT_EQ(decide(sampled(40.0, 80.0, slope(0.5), kHeld), kRule).outcome, Outcome::Undecided);
  EXPECT_EQ(decide(sampled(40.0, 80.0, slope(0.1), kHeld), kRule).outcome, Outcome::Bonded);
}

// At rest, but the bonded area falls from 100 to 50 um^2 over the window: the bond is coming
// apart, undecided; with no bonded area left at the end, rebounded. A fall within
// kAreaTolerance (the elastic breathing of the bonded points) still holds.
TEST(Verdict, TheBondedAreaMustHold) {
  const auto at_rest = [](double) { return 0.0; };
  const auto falling = [](double t) { return 1e-10 * (1.0 - 0.5 * (t / kNs - 60.0) / 20.0); };
  EXPECT_EQ(decide(sampled(50.0, 80.0, at_rest, falling), kRule).outcome, Outcome::Undecided);
  const auto gone = [](double t) { return t < 79.0 * kNs ? 1e-10 : 0.0; };
  const Verdict v = decide(sampled(50.0, 80.0, at_rest, gone), kRule);
  EXPECT_EQ(v.outcome, Outcome::Rebounded);
  EXPECT_EQ(v.bonded_area, 0.0);
  EXPECT_NEAR(v.margin, 2.0, 1e-12);  // the margin is the motion's, reported all the same
  const auto breathing = [](double t) {
    return 1e-10 * (1.0 + 0.4 * kAreaTolerance * std::sin(t / kNs));
  };
  EXPECT_EQ(decide(sampled(50.0, 80.0, at_rest, breathing), kRule).outcome, Outcome::Bonded);
}

// A run of 10 ns against a 20 ns window cannot settle: undecided, the mean over the 10 ns run
// reported, its window the 10 ns. Without bonded area it is not bonded, however short.
TEST(Verdict, ARunShorterThanTheWindowIsUndecided) {
  const auto series = sampled(
      0.0, 10.0, [](double) { return 0.5; }, kHeld);
  const Verdict v = decide(series, kRule);
  EXPECT_EQ(v.outcome, Outcome::Undecided);
  EXPECT_NEAR(v.separation_speed, 0.5, 1e-12);
  EXPECT_NEAR(v.window, 10.0 * kNs, 1e-15);
  // Without a bond too: a run shorter than its window may still be in the impact, where a bond
  // can yet form.
  const auto none = [](double) { return 0.0; };
  const auto half = [](double) { return 0.5; };
  EXPECT_EQ(decide(sampled(0.0, 10.0, half, none), kRule).outcome, Outcome::Undecided);
}

// With the bonding model off no bond can form: rebounded at once, settled or not.
TEST(Verdict, WithoutBondingNothingBonds) {
  VerdictRule off = kRule;
  off.bonding = false;
  const auto none = [](double) { return 0.0; };
  const auto half = [](double) { return 0.5; };
  EXPECT_EQ(decide(sampled(0.0, 10.0, half, none), off).outcome, Outcome::Rebounded);
  EXPECT_EQ(decide(sampled(0.0, 10.0, half, none), kRule).outcome, Outcome::Undecided);
}

// Samples before the window do not count: a body that came in at -800 m/s and then crept away at
// 1 m/s through the window is bonded; the window starts between two samples, read from the
// interpolant, so irregular sample times give the mean of the piecewise-linear series.
TEST(Verdict, OnlyTheWindowCounts) {
  std::vector<VerdictSample> series = {{0.0, -800.0, 0.0}, {59.95 * kNs, 0.0, 1e-10}};
  for (double t = 60.05; t < 80.0; t += 0.37) series.push_back({t * kNs, 1.0, 1e-10});
  series.push_back({80.0 * kNs, 1.0, 1e-10});
  const Verdict v = decide(series, kRule);
  EXPECT_EQ(v.outcome, Outcome::Bonded);
  // 0 at 59.95 ns, 1 m/s from 60.05 ns: over [60, 60.05] the interpolant rises from 0.5 to 1,
  // so the mean is 1 - 0.05 * 0.25 / 20 m/s.
  EXPECT_NEAR(v.separation_speed, 1.0 - 0.05 * 0.25 / 20.0, 1e-12);
}

TEST(Verdict, OutcomesHaveNames) {
  EXPECT_EQ(outcome_name(Outcome::Bonded), "bonded");
  EXPECT_EQ(outcome_name(Outcome::Rebounded), "rebounded");
  EXPECT_EQ(outcome_name(Outcome::Undecided), "undecided");
}

}  // namespace
}  // namespace coldspray::metrics
