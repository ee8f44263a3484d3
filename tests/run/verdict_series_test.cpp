// The verdict's series on a state set by hand: the separation velocity is the moving body's v_rest
// less the substrate's, both without their fast points, signed positive away from the substrate;
// samples fall due at 200 per window from just before the last window, and at the end.
#include "run/verdict_series.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::run {
namespace {

constexpr double kNs = 1e-9;

// A particle that came down, a substrate at rest, and a body that came up, three points each in
// 3D, volume 1e-18 m^3 (area 1e-12 m^2): the third point of each moves fast (jetted), so v_rest is
// the mean of the first two.
bodies::Bodies three_bodies() {
  bodies::Bodies s;
  s.geometry = case_file::Geometry::ThreeD;
  s.points.resize(9);
  const double v0[3] = {-800.0, 0.0, 800.0};
  const double vz[9] = {3.0, 1.0, 0.0, 0.5, 1.5, 100.0, -2.0, -4.0, 0.0};
  const double vx[9] = {0.0, 0.0, 500.0, 0.0, 0.0, 0.0, 0.0, 0.0, 500.0};
  const char* names[3] = {"particle", "substrate", "riser"};
  for (std::size_t b = 0; b < 3; ++b) {
    bodies::BodyRange r;
    r.name = names[b];
    r.begin = 3 * b;
    r.end = 3 * b + 3;
    r.initial_velocity = {0.0, 0.0, v0[b]};
    s.bodies.push_back(r);
  }
  for (std::size_t p = 0; p < 9; ++p) {
    s.points.mass[p] = p < 3 ? 1e-15 : 2e-15;
    s.points.volume0[p] = 1e-18;
    s.points.J[p] = 1.0;
    s.points.velocity[0][p] = vx[p];
    s.points.velocity[2][p] = vz[p];
  }
  s.points.touched[0] = 1;  // the particle's first point keeps a bond to the substrate
  s.points.bond[0] = 1.5;
  s.points.bonded_to[0] = 2;
  s.bonding = true;
  s.dt = 0.03 * kNs;
  return s;
}

case_file::Case eighty_ns() {
  case_file::Case c;
  c.solver.end_time = 80.0 * kNs;
  return c;
}

// v_rest: particle (3 + 1) / 2 = 2 m/s; substrate (0.5 + 1.5) / 2 = 1 m/s (its rim jet at 100 m/s
// left out); riser (-2 - 4) / 2 = -3 m/s. Away from the substrate: the particle +(2 - 1) = 1 m/s,
// the riser, which came up, -(-3 - 1) = 4 m/s.
TEST(VerdictSeries, SeparationIsFromTheSubstrateAndAway) {
  bodies::Bodies s = three_bodies();
  const case_file::Case c = eighty_ns();
  const StepRule rule(c, /*undeformed_step=*/0.0);
  VerdictSeries series(c.metrics, s);
  // From end - window - 2 (interval + dt) = 80 - 20 - 2 (0.1 + 0.03) = 59.74 ns on.
  s.time = 59.70 * kNs;
  EXPECT_FALSE(series.due(s, rule));
  int samples = 0;
  for (s.time = 59.75 * kNs; !rule.finished(s); s.time = std::min(s.time + s.dt, rule.end)) {
    if (!series.due(s, rule)) continue;
    series.sample(s);
    ++samples;
  }
  series.sample(s);  // at 80 ns, as the run's last step
  ++samples;
  // 59.75 ns (due: nothing was sampled before), then one per 0.1 ns mark from 59.8 to 79.9 ns
  // (202; the steps of 0.03 ns are shorter), and 80 ns: 204 samples, under the 208 the rings
  // hold.
  EXPECT_EQ(samples, 204);

  const auto verdicts = series.verdicts();
  ASSERT_EQ(verdicts.size(), 3u);
  ASSERT_TRUE(verdicts[0] && verdicts[2]);
  EXPECT_FALSE(verdicts[1]);  // the substrate has none
  EXPECT_NEAR(verdicts[0]->separation_speed, 1.0, 1e-12);
  EXPECT_NEAR(verdicts[0]->margin, 1.0, 1e-12);
  EXPECT_NEAR(verdicts[0]->bonded_area, 1e-12, 1e-24);
  EXPECT_NEAR(verdicts[0]->window, 20.0 * kNs, 1e-18);
  EXPECT_EQ(verdicts[0]->outcome, metrics::Outcome::Bonded);
  EXPECT_NEAR(verdicts[2]->separation_speed, 4.0, 1e-12);
  EXPECT_EQ(verdicts[2]->outcome, metrics::Outcome::Rebounded);  // no bonded area
  EXPECT_FALSE(series.undecided());
}

// A run shorter than the window is sampled from its start, and undecided.
TEST(VerdictSeries, AShortRunIsUndecided) {
  bodies::Bodies s = three_bodies();
  case_file::Case c = eighty_ns();
  c.solver.end_time = 10.0 * kNs;
  const StepRule rule(c, /*undeformed_step=*/0.0);
  VerdictSeries series(c.metrics, s);
  for (s.time = 0.0; s.time <= 10.0 * kNs; s.time += 0.1 * kNs) {
    EXPECT_TRUE(series.due(s, rule));
    series.sample(s);
  }
  EXPECT_TRUE(series.undecided());
  EXPECT_EQ(series.verdicts()[0]->outcome, metrics::Outcome::Undecided);
  EXPECT_NEAR(series.verdicts()[0]->separation_speed, 1.0, 1e-12);
}

}  // namespace
}  // namespace coldspray::run
