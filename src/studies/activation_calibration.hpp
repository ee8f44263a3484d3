// The calibration of bonding's activation, the critical penetration (docs/bonding.md,
// "Activation"; docs/studies.md, "Calibrating the activation"). Each size impacts at its
// experimental critical velocity v_c times (1 - step) and (1 + step), with the critical
// penetration 0 (no bonds yet, the contact unbonded, as before any activation), until the
// particle has left the contact (setups/impact_case.hpp, kContactTimes d / v); between the two runs
// its largest penetration follows a power law,
// p(v) = p_c (v / v_c)^b. A critical penetration delta predicts vcrit = v_c (delta / p_c)^(1/b)
// for each size; the calibration is the delta whose worst size errs least in log v (the sizes'
// errors then straddle zero). Nothing is fitted per size.
#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "case/case.hpp"
#include "studies/calibration.hpp"

namespace coldspray::studies {

struct ActivationPlan {
  std::vector<std::string> grids;  // as written: "D/40", "0.7um/0.175um"
  std::vector<CalibrationSize> sizes;
  double step = 0.02;  // the runs at v_c (1 -+ step)
};

// One impact: DIR/<grid>/<size>-v<V>ms.
struct ActivationRun {
  std::size_t grid = 0, size = 0;
  double speed = 0.0;  // m/s
  std::filesystem::path folder;
};
std::vector<ActivationRun> activation_runs(const ActivationPlan& plan,
                                           const std::filesystem::path& out_dir);

using ActivationCaseMaker = std::function<case_file::Case(const ActivationRun&)>;

// Runs this rank's unfinished impacts (resumable, parallel, failures recorded, as a sweep); every
// case is loaded first, so that bad input stops the study before anything runs.
CalibrationCounts run_activation_calibration(const ActivationPlan& plan,
                                             const ActivationCaseMaker& make_case,
                                             const CalibrationRunOptions& options);

// p(v) = at_velocity (v / v_c)^exponent through (v1, p1) and (v2, p2); NaN where they do not
// give a rising law (p1, p2 > 0, v1 != v2).
struct PenetrationLaw {
  double at_velocity = std::numeric_limits<double>::quiet_NaN();  // p_c
  double exponent = std::numeric_limits<double>::quiet_NaN();     // b
  bool usable() const { return at_velocity > 0.0 && exponent > 0.0; }
};
PenetrationLaw penetration_law(double v_c, double v1, double p1, double v2, double p2);

// v_c (delta / p_c)^(1/b): where the law reaches delta.
double predicted_vcrit(const PenetrationLaw& law, double v_c, double critical);

// The delta that minimises max over the laws of |ln(vcrit_i / v_c,i)|: each error
// (ln delta - ln p_c,i) / b_i rises with delta, so the least worst error is where the largest and
// the smallest sum to zero (bisection in ln delta). Needs usable laws.
double minimax_critical_penetration(const std::vector<PenetrationLaw>& laws);

struct ActivationGridResult {
  std::string grid;
  std::vector<PenetrationLaw> laws;  // per size
  std::vector<double> predicted;     // vcrit per size with the calibrated delta, m/s
  std::optional<double> critical_penetration;
  std::string diagnosis;  // why there is none, else empty
};

// Reads the runs on disk; writes DIR/runs.csv and DIR/calibration.json.
std::vector<ActivationGridResult> analyse_activation(const ActivationPlan& plan,
                                                     const std::filesystem::path& out_dir,
                                                     const std::string& name);

}  // namespace coldspray::studies
