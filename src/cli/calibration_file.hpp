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
#include "studies/calibration.hpp"

namespace coldspray::cli {

struct CalibrationFile {
  std::string path;
  std::string name;
  std::string material;
  std::string substrate_material;  // empty: the particle's
  std::string model = "energy";    // energy | strain: which two parameters x1, x2 are
  case_file::Geometry geometry = case_file::Geometry::Axisymmetric;
  double end_time = 80e-9;
  std::optional<double> floor;
  case_file::Debond debond;          // the cases' bonding.debond (the debonding law)
  case_file::ImpactMetrics metrics;  // the cases' metrics section: the verdict's window, ...
  studies::CalibrationPlan plan;
  // Where values were given, "FILE:LINE:COLUMN", so that a problem found in a generated case
  // is reported there: per grid, per size, and the parameters.
  std::vector<std::string> grid_where, size_where;
  std::string parameters_where, material_where, file_where;
};

CalibrationFile read_calibration_file(const std::string& path);

// The impact case of one run of the calibration (cli/impact_case.hpp), checked like a case file;
// errors name the calibration file's line that gave the value.
case_file::Case calibration_case(const CalibrationFile& file, const studies::CalibrationRun& run);

}  // namespace coldspray::cli
