// The bonded verdict of a body that hit another: decided from its motion over a window at the
// end of the run, not from one instant (docs/bonding.md, "The verdict"). Pure functions of a
// time series; run/verdict_series.hpp samples it during a run.
#pragma once

#include <span>
#include <string_view>

namespace coldspray::metrics {

// One instant of a moving body.
struct VerdictSample {
  double time = 0.0;                 // s
  double separation_velocity = 0.0;  // from the substrate, m/s; > 0 moving away from it
  double bonded_area = 0.0;          // m^2
};

enum class Outcome { Bonded, Rebounded, Undecided };

// "bonded", "rebounded", "undecided".
std::string_view outcome_name(Outcome outcome);

// metrics.verdict_window and metrics.bonded_separation_speed.
struct VerdictRule {
  double window = 20e-9;   // s: the verdict reads the last `window` of the series
  double threshold = 2.0;  // m/s: bonded needs a mean separation velocity at most this
  bool bonding = true;     // the bonding model is on; off, no bond can form: rebounded at once
};

struct Verdict {
  Outcome outcome = Outcome::Undecided;
  // The time mean of the separation velocity over the window (over the series, if it is shorter
  // than the window), m/s.
  double separation_speed = 0.0;
  double margin = 0.0;       // threshold - separation_speed, m/s: > 0 on the bonded side
  double settling = 0.0;     // the window's second half's mean minus its first half's, m/s
  double bonded_area = 0.0;  // at the end, m^2
  double window = 0.0;       // the time the means cover, s
};

// The verdict on a series in time order, its last sample at the end of the run. In this order:
// rebounded when the bonding model is off (no bond can form, rule.bonding); undecided when the
// series is shorter than the window, or the means of the window's halves differ by more than the
// threshold (the body still accelerates, is pulled back or is in its impact; a NaN separation
// velocity counts as that); rebounded when there is no bonded area at the end; when the mean
// exceeds the threshold, rebounded if the bonded area fell and undecided if it held (a kept bond
// does not let go: the body is still relaxing on it); bonded when the bonded area held (never fell,
// within kAreaTolerance, below its value at the window's start); undecided otherwise.
Verdict decide(std::span<const VerdictSample> series, const VerdictRule& rule);

// The relative fall of bonded area within the window that still counts as holding: the area of a
// bonded point follows its volume and radius, which ring elastically (docs/bonding.md).
inline constexpr double kAreaTolerance = 0.01;

}  // namespace coldspray::metrics
