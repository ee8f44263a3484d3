// The calibration file of `coldspray calibrate` (docs/studies.md): which material, model, grid
// configurations, particle sizes, parameter rectangle, classification tolerances and fit. Read
// with the case reader's schema machinery, so a problem is an InputError naming FILE:LINE:COLUMN
// and the key, as in case files.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "case/case.hpp"
#include "case/load.hpp"
#include "setups/impact_case.hpp"
#include "studies/activation_calibration.hpp"
#include "studies/calibration.hpp"

namespace coldspray::setups {

struct CalibrationFile {
  std::string path;
  std::string name;
  std::string material;
  std::string substrate_material;  // empty: the particle's
  std::string model = "energy";    // energy | strain: which two parameters x1, x2 are
  case_file::Geometry geometry = case_file::Geometry::Axisymmetric;
  SetUp setup = SetUp::Similar;       // the impacts' set-up (setups/impact_case.hpp)
  std::optional<double> end_time;     // unset: the set-up's
  bool verdict_window_given = false;  // metrics.verdict_window given: not the set-up's
  std::optional<double> floor;
  std::optional<double> critical_penetration;  // the cases' bonding.critical_penetration
  case_file::Debond debond;                    // the cases' bonding.debond (the debonding law)
  case_file::ImpactMetrics metrics;  // the cases' metrics section: the verdict's window, ...
  studies::CalibrationPlan plan;     // its grids and sizes serve `calibrates: critical-penetration`
  // calibrates: critical-penetration (studies/activation_calibration.hpp) instead of the model's
  // two parameters, each size's runs at its velocity times (1 -+ speed_step).
  bool activation = false;
  double speed_step = 0.02;
  // Where values were given, "FILE:LINE:COLUMN", so that a problem found in a generated case
  // is reported there: per grid, per size, and the parameters.
  std::vector<std::string> grid_where, size_where;
  std::string parameters_where, material_where, file_where;
};

CalibrationFile read_calibration_file(const std::string& path);

studies::ActivationPlan activation_plan(const CalibrationFile& file);
// The impact of one run of `calibrates: critical-penetration`, checked like a case file.
case_file::Case activation_case(const CalibrationFile& file, const studies::ActivationRun& run);

// The impact case of one run of the calibration (setups/impact_case.hpp), checked like a case file;
// errors name the calibration file's line that gave the value.
case_file::Case calibration_case(const CalibrationFile& file, const studies::CalibrationRun& run);

}  // namespace coldspray::setups
