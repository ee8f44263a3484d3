#include "metrics/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coldspray::metrics {

namespace {

using Series = std::span<const VerdictSample>;
using Field = double VerdictSample::*;

// The series' piecewise-linear interpolant of `field` at t, within its span.
double value_at(Series s, double t, Field field) {
  const auto after = std::upper_bound(s.begin(), s.end(), t,
                                      [](double x, const VerdictSample& v) { return x < v.time; });
  if (after == s.begin()) return (*after).*field;
  if (after == s.end()) return s.back().*field;
  const VerdictSample& a = *(after - 1);
  const VerdictSample& b = *after;
  const double w = (t - a.time) / (b.time - a.time);
  return a.*field + w * (b.*field - a.*field);
}

// The time mean of the interpolant of `field` over [a, b], within the series' span.
double mean_over(Series s, double a, double b, Field field) {
  double integral = 0.0;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const VerdictSample &p = s[i], &q = s[i + 1];
    const double lo = std::max(a, p.time), hi = std::min(b, q.time);
    if (!(hi > lo)) continue;
    auto at = [&](double t) {
      return p.*field + (t - p.time) / (q.time - p.time) * (q.*field - p.*field);
    };
    integral += 0.5 * (hi - lo) * (at(lo) + at(hi));
  }
  return integral / (b - a);
}

}  // namespace

std::string_view outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::Bonded:
      return "bonded";
    case Outcome::Rebounded:
      return "rebounded";
    case Outcome::Undecided:
      break;
  }
  return "undecided";
}

Verdict decide(Series series, const VerdictRule& rule) {
  Verdict v;
  if (series.empty()) {
    v.separation_speed = v.margin = v.settling = std::numeric_limits<double>::quiet_NaN();
    return v;
  }
  const double end = series.back().time;
  const bool covered = series.front().time <= end - rule.window * (1.0 - 1e-9);
  const double start = covered ? end - rule.window : series.front().time;
  const double middle = 0.5 * (start + end);
  const Field velocity = &VerdictSample::separation_velocity;
  v.window = end - start;
  v.bonded_area = series.back().bonded_area;
  v.separation_speed =
      v.window > 0.0 ? mean_over(series, start, end, velocity) : series.back().separation_velocity;
  v.margin = rule.threshold - v.separation_speed;
  v.settling = v.window > 0.0 ? mean_over(series, middle, end, velocity) -
                                    mean_over(series, start, middle, velocity)
                              : std::numeric_limits<double>::quiet_NaN();

  double lowest_area = v.bonded_area;
  for (const VerdictSample& s : series)
    if (s.time > start) lowest_area = std::min(lowest_area, s.bonded_area);
  const double start_area = value_at(series, start, &VerdictSample::bonded_area);
  const bool held = lowest_area >= (1.0 - kAreaTolerance) * start_area;

  // Settled first: a body still in its impact may yet bond (bonds form during it), and a bond,
  // once formed, holds (mpm/contact.hpp), so no bonded area decides only once the motion settles.
  if (!rule.bonding)
    v.outcome = Outcome::Rebounded;
  else if (!covered || !(std::abs(v.settling) <= rule.threshold))
    v.outcome = Outcome::Undecided;
  else if (!(v.bonded_area > 0.0))
    v.outcome = Outcome::Rebounded;
  else if (v.separation_speed > rule.threshold)
    // Moving away while its bond holds: a kept bond does not let go (no debonding law yet), so
    // the particle is still relaxing on it, not leaving (14 um at 1200 m/s: 2.07 m/s over 60-80
    // ns, falling from 5.1 to 1.5 m/s).
    v.outcome = held ? Outcome::Undecided : Outcome::Rebounded;
  else
    v.outcome = held ? Outcome::Bonded : Outcome::Undecided;
  return v;
}

}  // namespace coldspray::metrics
